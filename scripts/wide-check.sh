#!/usr/bin/env bash
# Wide-configuration check: regenerate the tuff crate from inputs other than the
# pinned ones, each into an empty folder, and `cargo check` the result with
# every feature on. It guards the generator outside the emitted subset: a change that
# breaks what another registry or a wider config emits fails here.
#
# Configurations (one line each in the table below):
#   1.4.309        the newest registry with validusage.json, the pinned config's
#                  extensions (core and the scenes' eight)
#   1.4.330        a newer one without validusage.json (implicit rules derived), whose
#                  core versions are split into internal feature blocks; same config
#   all-1.4.309,   the pinned config itself (every extension ash has) on each newer
#   all-1.4.330    registry: what 1.4 promoted is named by the alias ash has, the
#                  items ash lacks are defined by the crate (the delta) or left out,
#                  each with its reason (gen.log).
#   core14-1.4.309, the same with api_version = "1.4": Vulkan 1.4's commands through
#   core14-1.4.330  the crate's own table (ash has none), its items named as ash names
#                  them, what ash lacks defined by the crate (the delta), clippy-clean
#                  (-D warnings); what it cannot define left out (gen.log).
#
# (The pinned config itself emits every extension ash 0.38 has, so the committed crate
# is the every-extension check; scripts/test.sh builds it with all_extensions.)
#
# Usage: bash scripts/wide-check.sh [NAME ...]   (default: all)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
registry="$root/../shared/registry"
scratch="$(mktemp -d)"
[ -n "${WIDE_KEEP:-}" ] && echo "wide-check: scratch kept in $scratch" || trap 'rm -rf "$scratch"' EXIT
# One target folder for every configuration, so ash and friends build once.
export CARGO_TARGET_DIR="$root/target/wide"

cargo build -q --manifest-path "$root/Cargo.toml" -p tuff-gen
gen="$CARGO_TARGET_DIR/debug/tuff-gen"

# Each configuration is generated into an empty folder, which tuff-gen makes a crate
# that builds where it is (its hand-written modules copied in, the runtime named by
# path), and checked there alone, against the workspace's lock file (so against the
# workspace's ash), offline.
check() {
    local name="$1" dir="$scratch/$1"
    shift
    mkdir -p "$dir"
    local start=$SECONDS
    "$gen" "$@" --out "$dir/tuff" >"$dir/gen.log" 2>&1 || {
        cat "$dir/gen.log"
        echo "wide-check: $name: tuff-gen failed" >&2
        return 1
    }
    cp "$root/Cargo.lock" "$dir/tuff/"
    # The 1.4 crate is clippy's too (issue: 1.4 as a supported target); the others are
    # compiled only.
    local cmd=(check -q --offline --manifest-path "$dir/tuff/Cargo.toml"
        --features all_extensions,runtime_implicit_validations,multi_thread)
    case "$name" in
    core14-*) cmd=(clippy "${cmd[@]:1}" -- -D warnings) ;;
    esac
    if ! cargo "${cmd[@]}" 2>"$dir/check.log"; then
        grep -E '^error' "$dir/check.log" | sort | uniq -c | sort -rn | head -20 >&2
        echo "wide-check: $name: the generated crate does not compile ($(grep -c '^error' "$dir/check.log") errors)" >&2
        return 1
    fi
    echo "wide-check: $name: ok ($(find "$dir/tuff/src/generated" -name "*.rs" -exec cat {} + | wc -l) generated lines, $(grep -c 'left out' "$dir/gen.log") left out, $((SECONDS - start)) s)"
}

names=("$@")
[ ${#names[@]} -gt 0 ] || names=(1.4.309)
status=0
for name in "${names[@]}"; do
    case "$name" in
    1.4.309 | 1.4.330)
        # The pinned config's own extensions, not every one: what a newer registry
        # adds beyond ash's is the version-bump work, not this check's. 1.4.330 has
        # no validusage.json: its implicit rules are derived.
        cfg="$scratch/scenes.toml"
        sed -e 's/^all_extensions = true/all_extensions = false/' \
            -e "s#\"reference/vk.xml\"#\"$root/reference/vk.xml\"#" \
            -e "s#\"examples/src\"#\"$root/examples/src\"#" \
            "$root/tuff-gen.toml" >"$cfg"
        check "$name" --registry "$registry/$name/vk.xml" --config "$cfg" || status=1
        ;;
    all-1.4.309 | all-1.4.330)
        # The pinned config as it is: every extension ash has, from a newer registry.
        version="${name#all-}"
        cfg="$scratch/all.toml"
        sed -e "s#\"reference/vk.xml\"#\"$root/reference/vk.xml\"#" \
            -e "s#\"examples/src\"#\"$root/examples/src\"#" \
            "$root/tuff-gen.toml" >"$cfg"
        check "$name" --registry "$registry/$version/vk.xml" --config "$cfg" || status=1
        ;;
    core14-1.4.309 | core14-1.4.330)
        # Vulkan 1.4 as the core version (api_version = "1.4"), every extension ash
        # has: ash has no function table for 1.4, so its commands go through the
        # one the generated crate defines (DeviceFnV1_4), typed by ash's names.
        version="${name#core14-}"
        cfg="$scratch/core14.toml"
        sed -e 's/^api_version = "1.3"/api_version = "1.4"/' \
            -e "s#\"reference/vk.xml\"#\"$root/reference/vk.xml\"#" \
            -e "s#\"examples/src\"#\"$root/examples/src\"#" \
            "$root/tuff-gen.toml" >"$cfg"
        check "$name" --registry "$registry/$version/vk.xml" --config "$cfg" || status=1
        ;;
    *)
        echo "wide-check: unknown configuration $name (known: 1.4.309, 1.4.330, all-1.4.309, all-1.4.330, core14-1.4.309, core14-1.4.330)" >&2
        status=1
        ;;
    esac
done
exit $status
