"""Every non-timing value of scheme A equals that of scheme B in a results.csv, to the bit
(the shortest round-trip text of a double names its bits)."""
import csv
import sys

path, a, b = sys.argv[1:4]
timing = lambda m: m.startswith("cpu_seconds") or m in ("ns_per_step", "timing_repeats")
values = {a: {}, b: {}}
with open(path, newline="") as f:
    for row in csv.DictReader(f):
        if row["scheme"] in values and not timing(row["metric"]):
            values[row["scheme"]][(row["scene"], row["dt"], row["metric"])] = row["value"]
if not values[a] or values[a] != values[b]:
    differing = [k for k in values[a] if values[b].get(k) != values[a][k]]
    print(f"{len(differing)} of {len(values[a])} values differ between {a} and {b}, e.g. {differing[:3]}")
    sys.exit(1)
print(f"{len(values[a])} values of {a} and {b} are identical")
