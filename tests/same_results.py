#!/usr/bin/env python3
"""Whether two output folders hold the same results, bit for bit, timing aside.

    tests/same_results.py ROTBENCH BASE NEW

Compares results.csv, orders.csv, local_orders.csv, stability.csv, stability_spin.csv and
answer.csv of BASE and NEW (any but results.csv may be absent from both; each may be gzipped, FILE.csv.gz). Values are
compared as text: rotbench writes the shortest form that reads back to the same double, so
equal text is equal bits. Timing is left out: the metrics that `ROTBENCH list --metrics`
calls `timing`, and answer.csv's cpu_seconds. Prints one line per difference (at most 20)
and exits 1 when there is any, 2 on bad input, 0 when the folders agree.
"""
import csv
import gzip
import subprocess
import sys
from pathlib import Path

# The key columns of each file: a row is matched by them, and every other column compared.
KEYS = {
    "results.csv": ["scene", "scheme", "dt", "metric"],
    "orders.csv": ["scene", "scheme", "metric"],
    "local_orders.csv": ["scene", "scheme", "metric", "dt_coarse", "dt_fine"],
    "stability.csv": ["scene", "scheme", "zeta"],
    "stability_spin.csv": ["scene", "scheme", "omega_max"],
    "answer.csv": ["tolerance", "scene", "scheme"],
}
TIMING_COLUMNS = {"answer.csv": {"cpu_seconds"}}


def timing_metrics(rotbench):
    out = subprocess.run([rotbench, "list", "--metrics"], check=True, capture_output=True, text=True).stdout
    rows = [line.split() for line in out.splitlines()]
    return {row[0] for row in rows if len(row) >= 3 and row[2] == "timing"}


def located(folder, name):
    """The file `name` of `folder`, or its gzip form (the committed sample keeps its CSVs small)."""
    for candidate in (folder / name, folder / (name + ".gz")):
        if candidate.is_file():
            return candidate
    return None


def read(path, name, timing):
    opener = gzip.open if path.suffix == ".gz" else open
    with opener(path, "rt", newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    table = {}
    for row in rows:
        if name == "results.csv" and row["metric"] in timing:
            continue
        key = tuple(row[k] for k in KEYS[name])
        if key in table:
            raise ValueError(f"{path}: the row {key} appears twice")
        table[key] = {c: v for c, v in row.items() if c not in KEYS[name] and c not in TIMING_COLUMNS.get(name, ())}
    return rows[0].keys() if rows else [], table


def compare(base, new, timing):
    """(rows compared, differences) between the output folders base and new."""
    differences, compared = [], 0
    for name in KEYS:
        base_file, new_file = located(base, name), located(new, name)
        if not base_file and not new_file:
            continue
        if not base_file or not new_file:
            differences.append(f"{name}: present in only one folder")
            continue
        base_columns, a = read(base_file, name, timing)
        new_columns, b = read(new_file, name, timing)
        if list(base_columns) != list(new_columns):
            differences.append(f"{name}: columns {list(base_columns)} became {list(new_columns)}")
        for key in sorted(a.keys() - b.keys()):
            differences.append(f"{name}: {','.join(key)} is gone")
        for key in sorted(b.keys() - a.keys()):
            differences.append(f"{name}: {','.join(key)} is new")
        for key in sorted(a.keys() & b.keys()):
            compared += 1
            for column, value in a[key].items():
                if b[key].get(column) != value:
                    differences.append(f"{name}: {','.join(key)}: {column} {value} became {b[key].get(column)}")
    return compared, differences


def main(argv):
    if len(argv) != 4:
        print("usage: same_results.py ROTBENCH BASE NEW", file=sys.stderr)
        return 2
    rotbench, base, new = argv[1], Path(argv[2]), Path(argv[3])
    if not located(base, "results.csv") or not located(new, "results.csv"):
        print(f"same_results: {base} and {new} must both hold results.csv", file=sys.stderr)
        return 2
    timing = timing_metrics(rotbench)
    if "ns_per_step" not in timing:
        print(f"same_results: `{rotbench} list --metrics` names no timing metric", file=sys.stderr)
        return 2
    try:
        compared, differences = compare(base, new, timing)
    except (OSError, ValueError, KeyError, csv.Error) as e:
        print(f"same_results: {e}", file=sys.stderr)
        return 2
    for line in differences[:20]:
        print(line)
    if len(differences) > 20:
        print(f"... and {len(differences) - 20} more")
    print(f"same_results: {compared} rows compared, {len(differences)} differences")
    return 1 if differences else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
