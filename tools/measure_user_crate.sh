#!/usr/bin/env bash
# The user-crate rows of docs/build-shape.md: a release rebuild of tools/user_crate after a
# one-line edit of one binary, for a method resolved by name (`by_name`), the same problem
# naming the method's type (`named_type`), and five problem types by name (`five_problems`).
# Each figure is the median of three edits. Run it with nothing else running.
#
#   bash tools/measure_user_crate.sh
set -euo pipefail
cd "$(dirname "$0")/user_crate"
cargo build --release -q # the library and the first build of every binary, not timed
for bin in by_name named_type five_problems; do
    file=src/bin/$bin.rs
    cp "$file" "/tmp/$bin.rs.orig"
    times=()
    for edit in 1 2 3; do
        sed -i "s|// edit [0-9]*|// edit $edit|" "$file"
        start=$(date +%s.%N)
        cargo build --release -q --bin "$bin"
        times+=("$(echo "$(date +%s.%N) - $start" | bc -l)")
    done
    cp "/tmp/$bin.rs.orig" "$file"
    median=$(printf '%s\n' "${times[@]}" | sort -g | sed -n 2p)
    printf '%-14s rebuild after a one-line edit: median %.2f s (%s)\n' "$bin" "$median" \
        "$(printf '%.2f ' "${times[@]}")"
done
