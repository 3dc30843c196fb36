#!/usr/bin/env bash
# A newcomer's first ten minutes, measured (docs/build-shape.md): from a fresh clone of this
# repository's HEAD, with the crates already downloaded (only compiling counts), the wall
# time of the README's two commands, the largest memory of one compiler (or test) process,
# and the size of target/ after both. Run it with nothing else running.
#
#   bash tools/measure_build.sh [DIR]      (DIR: where to clone, default /tmp/stormer-fresh)
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
dir=${1:-/tmp/stormer-fresh}
rm -rf "$dir"
git clone -q "$repo" "$dir"
cd "$dir"
cargo fetch -q

measure() { # label, command...: wall seconds and the peak resident size of one child process
    local label=$1
    shift
    /usr/bin/time -f "%e %M" -o /tmp/measure_build.time "$@" >/tmp/measure_build.out 2>&1 || {
        tail -30 /tmp/measure_build.out
        echo "$label failed"
        exit 1
    }
    read -r seconds kib </tmp/measure_build.time
    printf '%-40s %7.1f min  peak process %5.2f GB\n' "$label" "$(echo "$seconds / 60" | bc -l)" \
        "$(echo "$kib / 1048576" | bc -l)"
}

measure "cargo run --release -- tour" cargo run --release -- tour
measure "cargo test --workspace" cargo test --workspace
grep -E '^test result' /tmp/measure_build.out | awk '{p += $4; f += $6; i += $8} END {print p " passed, " f " failed, " i " ignored"}'
du -sh target target/debug target/release | sed 's/^/target size: /'
cargo metadata --format-version 1 --no-deps | python3 -c '
import json, sys
m = json.load(sys.stdin)
print("test binaries:", sum(1 for p in m["packages"] for t in p["targets"] if "test" in t["kind"]))'
