#!/bin/bash
# The implicit VUIDs the Vulkan specification's own toolchain writes for a registry:
# every core version and every extension supported for `vulkan`, through
# Vulkan-Docs' `scripts/genvk.py ... validinc`, one VUID per line, sorted.
#
#   bash scripts/toolchain-vuids.sh DOCS OUT
#
# DOCS is a Vulkan-Docs tree at the registry's tag (its scripts/, xml/ and config/ are
# enough; python3 alone runs them). Reproduces ../shared/registry/1.4.330's list from
# the v1.4.330 tag byte for byte; made tests/registries/1.4.360's from v1.4.360.
set -euo pipefail
out=$(realpath -m "$2")
cd "$1"
args=$(python3 - <<'P'
import xml.etree.ElementTree as ET
r = ET.parse('xml/vk.xml').getroot()
a = ['-feature ' + f.get('name') for f in r.findall('feature')
     if 'vulkan' in f.get('api', '').split(',')]
a += ['-extension ' + e.get('name') for e in r.find('extensions')
      if 'vulkan' in e.get('supported', '').split(',')]
print(' '.join(a))
P
)
rm -rf gen && mkdir -p gen/generated
# shellcheck disable=SC2086 # one word per option
python3 scripts/genvk.py $args -registry xml/vk.xml -genpath gen/generated -o gen/validity validinc >gen/log 2>&1
cat gen/validity/protos/* gen/validity/structs/* | grep -o 'VUID-[A-Za-z0-9_:-]*' | sort -u >"$out"
