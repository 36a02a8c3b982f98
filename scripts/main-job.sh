#!/usr/bin/env bash
# The main job: regenerate generated/ and its validation coverage report from the
# pinned registry (vk.xml and validusage.json at the repository root).
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/install-deps.sh
[ -f "$HOME/.cargo/env" ] && . "$HOME/.cargo/env"

cargo run --release -q -p tuff-gen
echo "main-job: coverage report in generated/VALIDATION.md, generated/validation.json and generated/validation.svg"
