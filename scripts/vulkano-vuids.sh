#!/usr/bin/env bash
# Counts the valid-usage rules vulkano checks by hand, against tuff's report: every
# quoted "VUID-..." string in vulkano's published source (the crate from crates.io,
# fetched by cargo into a scratch project) that names a rule of tuff's emitted API
# in generated/validation.json, by category, beside what tuff settles. The stricter
# count is that of VALIDATION.md's second table.
#
# Usage: bash scripts/vulkano-vuids.sh [VERSION]   (default 0.35.2)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
version="${1:-0.35.2}"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
mkdir -p "$scratch/src"
printf '[package]\nname = "count"\nversion = "0.0.0"\nedition = "2021"\n[dependencies]\nvulkano = "=%s"\n' \
    "$version" >"$scratch/Cargo.toml"
echo 'fn main() {}' >"$scratch/src/main.rs"
cargo fetch -q --manifest-path "$scratch/Cargo.toml"
src="$(cargo metadata -q --format-version 1 --manifest-path "$scratch/Cargo.toml" |
    python3 -c 'import json,sys; m=json.load(sys.stdin); print(next(p["manifest_path"] for p in m["packages"] if p["name"]=="vulkano"))')"
python3 - "$(dirname "$src")/src" "$root/generated/validation.json" "$version" <<'EOF'
import glob, json, re, sys
source, report, version = sys.argv[1:]
quoted = set()
for path in glob.glob(f"{source}/**/*.rs", recursive=True):
    quoted |= set(re.findall(r'"(VUID-[^"\s]+)"', open(path, errors="ignore").read()))
rules = json.load(open(report))["rules"]
print(f"| Count | Category | vulkano {version} quotes | tuff dynamic | tuff static |")
print("|---|---|---|---|---|")
for label, keep in [("emitted API", lambda r: r["emitted"]),
                    ("stricter count", lambda r: r["emitted"] and r.get("strict", False))]:
    for category in ["creation", "usage", "implicit"]:
        mine = [r for r in rules if keep(r) and r["category"] == category]
        ids = {r["vuid"] for r in mine}
        dynamic = sum(r["status"] == "dynamic" for r in mine)
        static = sum(r["status"] == "static" for r in mine)
        print(f"| {label} | {category} | {len(quoted & ids)} | {dynamic} | {static} |")
EOF
