#!/usr/bin/env bash
# Instructions per body-step of every scheme, counted by callgrind (hardware counters are
# not available on the shared machines): the difference between 2S and S steps of N bodies,
# divided by N S. Deterministic: the same binary gives the same counts on any load.
# Usage: benchmarks/instructions.sh [BUILD_DIR] [N] [S]   (defaults: build 1000 20)
set -euo pipefail
build=${1:-build}; n=${2:-1000}; s=${3:-20}
driver="$build/rotbench_step_driver"
count() {  # total instructions (Ir) of one run
    local out; out=$(mktemp)
    valgrind --tool=callgrind --callgrind-out-file="$out" "$driver" "$1" "$n" "$2" > /dev/null 2>&1
    awk '/^summary:/ {print $2}' "$out"; rm -f "$out"
}
schemes=$("$build/rotbench" list | awk '/^schemes:/ {on=1; next} /^scenes:/ {on=0} on && /^  [a-z_0-9]+ / {print $1}')
echo "scheme,instructions_per_body_step,ratio_to_direct"
declare -A per
for scheme in $schemes; do
    a=$(count "$scheme" "$s"); b=$(count "$scheme" $((2 * s)))
    per[$scheme]=$(awk -v a="$a" -v b="$b" -v n="$n" -v s="$s" 'BEGIN {printf "%.1f", (b - a) / (n * s)}')
done
for scheme in $schemes; do
    awk -v x="${per[$scheme]}" -v d="${per[direct]}" -v name="$scheme" 'BEGIN {printf "%s,%s,%.3f\n", name, x, x / d}'
done
