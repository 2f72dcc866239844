#!/usr/bin/env bash
# The cost table of the report: for every scheme, per body-step,
#   ns_batched, ns_alone   Google Benchmark at N = 1e6 bodies (rotbench_bench): the batched
#                          loops, and the same scheme one body at a time; medians of 5
#                          repetitions, with their spread ((max - min) / median);
#   instr_batched, instr_alone   callgrind instruction counts (benchmarks/instructions.sh):
#                          N = 1000 bodies, and one body; deterministic, whatever the load;
#   and both ratios to `direct`. The load/store-only row is the floor of the batched loops.
# Usage: benchmarks/cost.sh BUILD_DIR OUT_DIR   (writes OUT_DIR/cost.csv; about 2 min)
set -euo pipefail
build=${1:?build dir}; out=${2:?output dir}
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$build/rotbench_bench" --benchmark_filter='/1000000$' --benchmark_min_time=0.2 --benchmark_repetitions=5 \
    --benchmark_format=csv > "$tmp/bench.csv" 2> /dev/null
"$here/instructions.sh" "$build" 1000 20 > "$tmp/batched.csv"
"$here/instructions.sh" "$build" 1 2000 > "$tmp/alone.csv"
python3 - "$tmp" "$out/cost.csv" <<'PY'
import csv, statistics, sys
tmp, target = sys.argv[1], sys.argv[2]
samples = {}
with open(f"{tmp}/bench.csv") as f:
    lines = f.read().splitlines()
header = next(i for i, l in enumerate(lines) if l.startswith("name,"))
for row in csv.DictReader(lines[header:]):
    name = row["name"]
    if not name.endswith("/1000000"):   # aggregates (_mean, _median, ...) are recomputed below
        continue
    samples.setdefault(name[: -len("/1000000")], []).append(float(row["ns_per_body_step"]))
def instr(path):
    with open(path) as f:
        return {r["scheme"]: float(r["instructions_per_body_step"]) for r in csv.DictReader(f)}
batched_i, alone_i = instr(f"{tmp}/batched.csv"), instr(f"{tmp}/alone.csv")
med = {k: statistics.median(v) for k, v in samples.items()}
spread = {k: (max(v) - min(v)) / statistics.median(v) for k, v in samples.items()}
cols = ["scheme", "ns_batched", "ns_batched_spread", "ns_alone", "ns_alone_spread", "speedup",
        "instr_batched", "instr_alone", "ns_ratio_to_direct", "instr_ratio_to_direct"]
with open(target + ".tmp", "w", newline="") as f:
    w = csv.writer(f, lineterminator="\n")
    w.writerow(cols)
    w.writerow(["load_store", med["load_store"], spread["load_store"], "", "", "", "", "", "", ""])
    for s in sorted(batched_i):
        b, a = med[f"batched/{s}"], med[f"one_at_a_time/{s}"]
        w.writerow([s, b, spread[f"batched/{s}"], a, spread[f"one_at_a_time/{s}"], a / b, batched_i[s], alone_i[s],
                    b / med["batched/direct"], batched_i[s] / batched_i["direct"]])
import os
os.replace(target + ".tmp", target)
PY
echo "wrote $out/cost.csv"
