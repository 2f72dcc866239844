#!/usr/bin/env python3
"""The cost table of the report (OUT_DIR/cost.csv), per body-step of every scheme:

  instr_batched, instr_alone   callgrind instruction counts: 1000 bodies stepped together, and
                               one body; exact and repeatable whatever the machine's load.
                               libm_instr_alone: those of instr_alone inside libm.
  ns_batched, ns_alone         Google Benchmark (rotbench_bench) at 1e6 bodies with random
                               states and torques read from memory: batched, and one body at a
                               time through the scheme interface; the least of the repetitions
                               (the other tenants of a shared machine only ever add time) and
                               their spread (max - min) / least. A scheme of more than 5000
                               instructions per body-step is timed at 1e5 bodies (`bodies`):
                               moving its state is then well under 1 % of its step.
  memory_share                 load_store's batched time (the same loops computing nothing) over
                               the scheme's.
  public, public_ratio_batched,  for a scheme with a public code's counterpart (a plug-in scheme named
  public_ratio_alone,          `<scheme>__<code>`; BUILD_DIR/rotbench_public_counterparts.so is loaded by
  public_ratio_runs_differ     default: LAMMPS's, HOOMD-blue's and Yade's arithmetic written anew), its id
                               and the counterpart's time over the scheme's, batched and alone (above 1:
                               rotbench is faster), and how much the batched ratio differs between the
                               tables. Of several counterparts, the fastest one body at a time.
  speedup_runs_differ,         how much the speed-up and batched / direct differ between two
  ns_ratio_runs_differ         consecutive cost tables, |table 1 / table 2 - 1|: the
                               repeatability of the figures, stated rather than assumed.

Quick (the default, about 25 s): the counts, then two timing tables, one benchmark process
each, 2 repetitions of every benchmark in random interleaved order. --thorough: the
repeatability study, 10 processes of 3 repetitions, the two
tables being the odd and the even processes (docs/performance.md says why; several minutes).

Progress goes to stderr: a status line on a terminal, a line every 5 s otherwise, nothing
with --quiet. --plugin PATH (repeatable) costs a plug-in's schemes beside the built-in ones.

Usage: benchmarks/cost.py [--thorough] [--quiet] [--plugin PATH]... BUILD_DIR OUT_DIR
"""
import argparse
import concurrent.futures
import csv
import io
import os
import re
import subprocess
import sys
import tempfile
import time

SLOW_INSTRUCTIONS = 5000
COLUMNS = ["scheme", "bodies", "ns_batched", "ns_batched_spread", "ns_alone", "ns_alone_spread", "speedup",
           "instr_batched", "instr_alone", "ns_ratio_to_direct", "instr_ratio_to_direct", "libm_instr_alone",
           "memory_share", "speedup_runs_differ", "ns_ratio_runs_differ", "public", "public_ratio_batched",
           "public_ratio_alone", "public_ratio_runs_differ", "mode"]
PUBLIC_COUNTERPARTS = "rotbench_public_counterparts.so"


class Progress:
    """Counts, the item in flight and an ETA: rewritten in place on a terminal, a line every
    5 s otherwise, nothing when quiet."""

    def __init__(self, quiet):
        self.quiet, self.tty = quiet, sys.stderr.isatty()
        self.last_line = 0.0

    def show(self, stage, done, total, current, started):
        if self.quiet:
            return
        now = time.monotonic()
        eta = (now - started) / done * (total - done) if done else float("nan")
        text = f"cost: {stage} {done}/{total}, {current}" + (f", about {eta:.0f} s left" if done else "")
        if self.tty:
            sys.stderr.write("\r\033[K" + text)
            sys.stderr.flush()
        elif now - self.last_line >= 5.0:
            sys.stderr.write(text + "\n")
            self.last_line = now

    def end(self, text):
        if self.quiet:
            return
        sys.stderr.write(("\r\033[K" if self.tty else "") + text + "\n")


def fail(message):
    sys.stderr.write(f"cost: {message}\n")
    sys.exit(2)


def run(command, **kwargs):
    """A command's stdout; its stderr's last line as the error when it fails. A list of
    arguments, never a shell: paths are passed as they are."""
    done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, **kwargs)
    if done.returncode != 0:
        lines = done.stderr.strip().splitlines()
        fail(f"{os.path.basename(command[0])} failed: {lines[-1] if lines else f'exit {done.returncode}'}")
    return done.stdout


# Self cost of the functions in libm: cost lines under an `ob=` naming libm, except the line
# after `calls=`, which is the inclusive cost of a call (callgrind's format). Object names are
# compressed: "(id) name" the first time, "(id)" after, in ob= and cob= alike.
def callgrind_counts(path):
    objects, current, total, libm, call_cost = {}, "", 0, 0, False
    with open(path) as f:
        for line in f:
            m = re.match(r"(c?ob)=(?:\((\d+)\))? ?(.*)", line.rstrip("\n"))
            if m:
                name = m.group(3) or objects.get(m.group(2), "")
                if m.group(2):
                    objects[m.group(2)] = name
                if m.group(1) == "ob":
                    current = name
            elif line.startswith("summary:"):
                total = int(line.split()[1])
            elif line.startswith("calls="):
                call_cost = True
            elif line[:1].isdigit() or line[:1] in "+-*":
                if not call_cost and "/libm.so" in current:
                    libm += int(line.split()[1])
                call_cost = False
    return total, libm


def count_instructions(driver, plugin_args, scheme, sizes, tmp):
    """Per body-step for each (bodies, steps): (all instructions, those in libm)."""
    out = os.path.join(tmp, f"callgrind.{scheme}")
    command = ["valgrind", "--tool=callgrind", "--collect-atstart=no", f"--callgrind-out-file={out}", driver,
               *plugin_args, scheme]
    for n, s in sizes:
        command += [str(n), str(s)]
    run(command)
    result = []
    for k, (n, s) in enumerate(sizes, start=1):
        total, libm = callgrind_counts(f"{out}.{k}")
        result.append((total / (n * s), libm / (n * s)))
    return result


def best_counterparts(schemes, ns_alone):
    """Each scheme's public counterpart `<scheme>__<code>`; of several (NO_SQUISH: LAMMPS and
    HOOMD-blue), the best: the least time one body at a time, as those codes step their bodies.

    >>> best_counterparts(["a", "a__x", "a__y", "b", "c__z"], {"a": 1, "a__x": 3, "a__y": 2, "b": 1, "c__z": 1})
    {'a': 'a__y'}
    """
    groups = {}
    for p in schemes:
        if "__" in p and p.split("__")[0] in schemes:
            groups.setdefault(p.split("__")[0], []).append(p)
    return {s: min(ps, key=lambda p: ns_alone[p]) for s, ps in groups.items()}


def bench_table(bench, plugin_args, names, repetitions, progress, stage):
    """One benchmark process: name -> its repetitions (ns per body-step)."""
    pattern = "^(" + "|".join(re.escape(n) for n in names) + ")$"
    found, expected, done, started = {}, len(names) * repetitions, 0, time.monotonic()
    command = [bench, *plugin_args, f"--benchmark_filter={pattern}", "--benchmark_min_time=0.02",
               f"--benchmark_repetitions={repetitions}", "--benchmark_enable_random_interleaving=true",
               "--benchmark_report_aggregates_only=false", "--benchmark_format=csv"]
    with subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True) as p:
        header = None
        for line in p.stdout:
            if line.startswith("name,"):
                header = line
                continue
            if header is None:
                continue
            row = next(csv.DictReader(io.StringIO(header + line)))
            if row["name"] in names:  # not an aggregate (_mean, _median, ...): those are recomputed here
                found.setdefault(row["name"], []).append(float(row["ns_per_body_step"]))
                done += 1
                progress.show(stage, done, expected, row["name"], started)
    if p.returncode != 0:
        fail(f"{os.path.basename(bench)} failed with exit {p.returncode}")
    missing = [n for n in names if n not in found]
    if missing:
        fail(f"the benchmark did not report {', '.join(missing)}")
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build")
    parser.add_argument("out")
    parser.add_argument("--thorough", action="store_true", help="the many-process repeatability study (minutes)")
    parser.add_argument("--quiet", action="store_true", help="no progress")
    parser.add_argument("--plugin", action="append", default=[], metavar="PATH", help="a plug-in's schemes too")
    parser.add_argument("--no-public", action="store_true", help=f"without BUILD_DIR/{PUBLIC_COUNTERPARTS}")
    args = parser.parse_args()
    bench, driver = os.path.join(args.build, "rotbench_bench"), os.path.join(args.build, "rotbench_step_driver")
    for tool in (bench, driver):
        if not os.access(tool, os.X_OK):
            fail(f"no {tool}: build first (./setup.sh build)")
    if os.path.exists(args.out) and not os.path.isdir(args.out):
        fail(f"{args.out} exists and is not a directory")
    plugins = list(args.plugin)
    public = os.path.join(args.build, PUBLIC_COUNTERPARTS)
    if not args.no_public and os.path.exists(public):
        plugins.append(public)
    plugin_args = [a for p in plugins for a in ("--plugin", os.path.abspath(p))]
    schemes = run([driver, *plugin_args, "--list"]).split()
    if "direct" not in schemes:
        fail("no scheme `direct` registered: the ratios are to it")
    progress = Progress(args.quiet)
    os.makedirs(args.out, exist_ok=True)

    with tempfile.TemporaryDirectory() as tmp:
        sizes = [(1, 2000), (1000, 20)] if args.thorough else [(1, 500), (1000, 5)]
        counts, started = {}, time.monotonic()
        with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 1) as pool:
            jobs = {pool.submit(count_instructions, driver, plugin_args, s, sizes, tmp): s for s in schemes}
            for job in concurrent.futures.as_completed(jobs):
                counts[jobs[job]] = job.result()
                progress.show("instruction counts", len(counts), len(schemes), jobs[job], started)
    alone = {s: counts[s][0] for s in schemes}
    batched_i = {s: counts[s][1][0] for s in schemes}

    size = {s: 100000 if alone[s][0] > SLOW_INSTRUCTIONS else 1000000 for s in schemes}
    names = ["load_store/1000000"] + [f"{kind}/{s}/{size[s]}" for s in schemes for kind in ("batched", "one_at_a_time")]
    tables = []
    if args.thorough:
        halves = [{}, {}]
        for k in range(10):
            part = bench_table(bench, plugin_args, names, 3, progress, f"timing, process {k + 1} of 10,")
            for name, values in part.items():
                halves[k % 2].setdefault(name, []).extend(values)
        tables = halves
    else:
        for k in range(2):
            tables.append(bench_table(bench, plugin_args, names, 2, progress, f"timing, table {k + 1} of 2,"))
    pooled = {n: tables[0][n] + tables[1][n] for n in names}

    def least(table, kind, s):
        return min(table[f"{kind}/{s}/{size[s]}"])

    def speedup(table, s):
        return least(table, "one_at_a_time", s) / least(table, "batched", s)

    def ns_ratio(table, s):
        return least(table, "batched", s) / least(table, "batched", "direct")

    def differ(f, s, *more):
        return abs(f(tables[0], s, *more) / f(tables[1], s, *more) - 1)

    def public_ratio(table, s, p, kind="batched"):
        return least(table, kind, p) / least(table, kind, s)

    counterpart = best_counterparts(schemes, {s: min(pooled[f"one_at_a_time/{s}/{size[s]}"]) for s in schemes})

    def spread(values):
        return (max(values) - min(values)) / min(values)

    floor = min(pooled["load_store/1000000"])
    target = os.path.join(args.out, "cost.csv")
    mode = "thorough" if args.thorough else "quick"
    rows = [["load_store", 1000000, floor, spread(pooled["load_store/1000000"])] + [""] * (len(COLUMNS) - 5) + [mode]]
    direct_ns = min(pooled[f"batched/direct/{size['direct']}"])
    for s in sorted(schemes):
        b, a = min(pooled[f"batched/{s}/{size[s]}"]), min(pooled[f"one_at_a_time/{s}/{size[s]}"])
        rows.append([s, size[s], b, spread(pooled[f"batched/{s}/{size[s]}"]), a, spread(pooled[f"one_at_a_time/{s}/{size[s]}"]),
                     a / b, batched_i[s], alone[s][0], b / direct_ns, batched_i[s] / batched_i["direct"], alone[s][1],
                     floor / b if size[s] == 1000000 else "", differ(speedup, s), differ(ns_ratio, s)]
                    + ([counterpart[s], public_ratio(pooled, s, counterpart[s]),
                        public_ratio(pooled, s, counterpart[s], "one_at_a_time"), differ(public_ratio, s, counterpart[s])]
                       if s in counterpart else ["", "", "", ""]) + [mode])
    fd, temporary = tempfile.mkstemp(dir=args.out, prefix=".cost.csv.")  # beside the target: os.replace is atomic
    try:
        with os.fdopen(fd, "w", newline="") as f:
            w = csv.writer(f, lineterminator="\n")
            w.writerow(COLUMNS)
            w.writerows(rows)
        os.replace(temporary, target)
    except BaseException:
        os.unlink(temporary)
        raise
    progress.end(f"wrote {target} ({time.monotonic() - started:.0f} s)")


if __name__ == "__main__":
    try:
        main()
    except KeyboardInterrupt:
        sys.exit(130)
