#!/usr/bin/env bash
# Instructions per body-step of every scheme, counted by callgrind (hardware counters are
# not available on the shared machines): the difference between 2S and S steps of N bodies,
# divided by N S. Deterministic: the same binary gives the same counts on any load.
# libm_instructions_per_body_step is the part spent inside libm (sin, cos, atan2, ...): the
# transcendentals of a scheme stepping one body at a time. (The packs' sin and cos are
# xsimd's, inlined into the scheme: callgrind cannot separate them.)
# Usage: benchmarks/instructions.sh [BUILD_DIR] [N] [S]   (defaults: build 1000 20)
set -euo pipefail
build=${1:-build}; n=${2:-1000}; s=${3:-20}
driver="$build/rotbench_step_driver"
count() {  # two numbers for one run: all its instructions (Ir), and those inside libm
    local out; out=$(mktemp)
    valgrind --tool=callgrind --callgrind-out-file="$out" "$driver" "$1" "$n" "$2" > /dev/null 2>&1
    local total libm
    total=$(awk '/^summary:/ {print $2}' "$out")
    libm=$(python3 - "$out" <<'PY'
import re, sys
# Self cost of the functions in libm: cost lines under an `ob=` naming libm, except the line
# after `calls=`, which is the inclusive cost of a call (callgrind format reference).
# Object names are compressed: "(id) name" the first time, "(id)" after, in ob= and cob= alike.
objects, current, total, call_cost = {}, "", 0, False
for line in open(sys.argv[1]):
    m = re.match(r"(c?ob)=(?:\((\d+)\))? ?(.*)", line.rstrip("\n"))
    if m:
        name = m.group(3) or objects.get(m.group(2), "")
        if m.group(2): objects[m.group(2)] = name
        if m.group(1) == "ob": current = name
    elif line.startswith("calls="):
        call_cost = True
    elif line[:1].isdigit() or line[:1] in "+-*":
        if not call_cost and "/libm.so" in current:
            total += int(line.split()[1])
        call_cost = False
print(total)
PY
)
    rm -f "$out"
    echo "$total $libm"
}
per_body_step() {  # the S extra steps' count (2S-step run minus S-step run) over N S
    awk -v a="$1" -v b="$2" -v n="$n" -v s="$s" 'BEGIN {printf "%.1f", (b - a) / (n * s)}'
}
schemes=$("$build/rotbench" list | awk '/^schemes:/ {on=1; next} /^scenes:/ {on=0} on && /^  [a-z_0-9]+ / {print $1}')
echo "scheme,instructions_per_body_step,ratio_to_direct,libm_instructions_per_body_step"
declare -A per libm
for scheme in $schemes; do
    read -r a a_libm < <(count "$scheme" "$s")
    read -r b b_libm < <(count "$scheme" $((2 * s)))
    per[$scheme]=$(per_body_step "$a" "$b")
    libm[$scheme]=$(per_body_step "$a_libm" "$b_libm")
done
for scheme in $schemes; do
    awk -v x="${per[$scheme]}" -v d="${per[direct]}" -v m="${libm[$scheme]}" -v name="$scheme" \
        'BEGIN {printf "%s,%s,%.3f,%s\n", name, x, x / d, m}'
done
