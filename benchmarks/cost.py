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
  public_ratio_runs_differ     default: LAMMPS's, HOOMD-blue's, Yade's and Kratos's arithmetic written anew), its id
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
with --quiet. --plugin PATH (repeatable) costs a plug-in's schemes beside the built-in ones;
--schemes A,B costs only those (and direct, which the ratios are to).

A scheme whose process crashes, exits, throws or runs past --timeout (default 300 s) is not
costed: its row keeps only its id and `failure` (why), and the other schemes are costed as
usual. The benchmark, which times every scheme in one process, is then run again without it.

Usage: benchmarks/cost.py [--thorough] [--quiet] [--plugin PATH]... [--schemes A,B] [--timeout S] BUILD_DIR OUT_DIR
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
import threading
import time

SLOW_INSTRUCTIONS = 5000
COLUMNS = ["scheme", "bodies", "ns_batched", "ns_batched_spread", "ns_alone", "ns_alone_spread", "speedup",
           "instr_batched", "instr_alone", "ns_ratio_to_direct", "instr_ratio_to_direct", "libm_instr_alone",
           "memory_share", "speedup_runs_differ", "ns_ratio_runs_differ", "public", "public_ratio_batched",
           "public_ratio_alone", "public_ratio_runs_differ", "mode", "failure"]
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


class Failed(Exception):
    """A tool's process that failed on one scheme: why, in one line."""


def why(name, returncode, stderr):
    """One line, no commas (cost.csv's readers split on them): the signal that killed the
    process, else the last line of its stderr, else its exit status.

    >>> why("bench", -11, "==1== valgrind's words")
    'bench killed by signal 11'
    >>> why("bench", 1, "a\\nterminate called: x, y\\n")
    'bench failed: terminate called: x; y'
    >>> why("bench", 7, "")
    'bench exited with 7'
    """
    lines = stderr.strip().splitlines()
    text = (f"{name} killed by signal {-returncode}" if returncode < 0 else
            f"{name} failed: {lines[-1]}" if lines else f"{name} exited with {returncode}")
    return text.replace(",", ";")


def run(command, timeout=None):
    """A command's stdout; Failed when it fails or runs past `timeout` s. A list of arguments,
    never a shell: paths are passed as they are."""
    name = os.path.basename(command[0])
    try:
        done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, errors="replace",
                              timeout=timeout)
    except subprocess.TimeoutExpired:
        raise Failed(f"{name} ran past {timeout:g} s")
    if done.returncode != 0:
        raise Failed(why(name, done.returncode, done.stderr))
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


def count_instructions(driver, plugin_args, scheme, sizes, tmp, timeout):
    """Per body-step for each (bodies, steps): (all instructions, those in libm)."""
    out = os.path.join(tmp, f"callgrind.{scheme}")
    # --vgdb=no: no gdbserver, whose pipes in /tmp a killed valgrind would leave behind.
    command = ["valgrind", "--tool=callgrind", "--vgdb=no", "--collect-atstart=no", f"--callgrind-out-file={out}", driver,
               *plugin_args, scheme]
    for n, s in sizes:
        command += [str(n), str(s)]
    run(command, timeout)
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


def bench_process(bench, plugin_args, names, repetitions, timeout, on_row):
    """One benchmark process over `names`: name -> its repetitions (ns per body-step), and why
    the process failed (None when it did not)."""
    pattern = "^(" + "|".join(re.escape(n) for n in names) + ")$"
    found = {}
    command = [bench, *plugin_args, f"--benchmark_filter={pattern}", "--benchmark_min_time=0.02",
               f"--benchmark_repetitions={repetitions}", "--benchmark_enable_random_interleaving=true",
               "--benchmark_report_aggregates_only=false", "--benchmark_format=csv"]
    with tempfile.TemporaryFile("w+", errors="replace") as err, \
            subprocess.Popen(command, stdout=subprocess.PIPE, stderr=err, text=True, errors="replace") as p:
        hung = []

        def kill():
            hung.append(True)
            p.kill()

        timer = threading.Timer(timeout, kill)  # a hang is killed, and named below
        timer.start()
        try:
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
                    on_row(row["name"])
            p.wait()
        finally:
            timer.cancel()
        err.seek(0)
        failure = (None if p.returncode == 0 else f"{os.path.basename(bench)} ran past {timeout:g} s" if hung
                   else why(os.path.basename(bench), p.returncode, err.read()))
    return found, failure


def bench_table(bench, plugin_args, names, repetitions, progress, stage, timeout, failed):
    """Every benchmark of `names`: name -> its repetitions (ns per body-step). When the process
    fails, the benchmarks it did not report are run again one process each; a scheme whose own
    process fails goes into `failed` (scheme -> why) and out of the table."""
    expected, done, started = len(names) * repetitions, [0], time.monotonic()

    def on_row(name):
        done[0] += 1
        progress.show(stage, done[0], expected, name, started)

    found, failure = bench_process(bench, plugin_args, names, repetitions, timeout, on_row)
    missing = [n for n in names if len(found.get(n, [])) < repetitions]
    if failure is None and missing:
        failure = f"the benchmark did not report {' '.join(missing)}"
    if failure is None:
        return found
    for name in missing:
        alone, failure = bench_process(bench, plugin_args, [name], repetitions, timeout, on_row)
        if failure is None and len(alone.get(name, [])) < repetitions:
            failure = f"the benchmark did not report {name}"
        if failure is None:
            found[name] = alone[name]
        elif name.startswith("load_store/"):
            fail(failure)
        else:
            failed.setdefault(name.split("/")[1], failure)
    return {n: v for n, v in found.items() if n == "load_store/1000000" or n.split("/")[1] not in failed}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build")
    parser.add_argument("out")
    parser.add_argument("--thorough", action="store_true", help="the many-process repeatability study (minutes)")
    parser.add_argument("--quiet", action="store_true", help="no progress")
    parser.add_argument("--plugin", action="append", default=[], metavar="PATH", help="a plug-in's schemes too")
    parser.add_argument("--no-public", action="store_true", help=f"without BUILD_DIR/{PUBLIC_COUNTERPARTS}")
    parser.add_argument("--schemes", metavar="A,B", help="only these schemes (and direct, and their public counterparts)")
    parser.add_argument("--timeout", type=float, default=300.0, metavar="S", help="a scheme's process is stopped after S s")
    args = parser.parse_args()
    if not args.timeout > 0:
        fail(f"--timeout must be positive, got {args.timeout:g}")
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
    try:
        schemes = run([driver, *plugin_args, "--list"], args.timeout).split()
    except Failed as e:
        fail(str(e))
    if "direct" not in schemes:
        fail("no scheme `direct` registered: the ratios are to it")
    if args.schemes is not None:
        wanted = set(args.schemes.split(",")) | {"direct"}
        unknown = sorted(wanted - set(schemes))
        if unknown:
            fail(f"--schemes: no scheme {', '.join(unknown)} (rotbench_step_driver --list names them)")
        schemes = [s for s in schemes if s in wanted or s.split("__")[0] in wanted]
    failed = {}  # scheme -> why it could not be costed
    progress = Progress(args.quiet)
    os.makedirs(args.out, exist_ok=True)

    with tempfile.TemporaryDirectory() as tmp:
        sizes = [(1, 2000), (1000, 20)] if args.thorough else [(1, 500), (1000, 5)]
        counts, started = {}, time.monotonic()
        with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 1) as pool:
            jobs = {pool.submit(count_instructions, driver, plugin_args, s, sizes, tmp, args.timeout): s for s in schemes}
            for done, job in enumerate(concurrent.futures.as_completed(jobs), start=1):
                try:
                    counts[jobs[job]] = job.result()
                except Failed as e:
                    failed[jobs[job]] = str(e)
                progress.show("instruction counts", done, len(schemes), jobs[job], started)

    def costed(schemes):
        """The schemes not failed so far; stops when direct, the ratios' base, has failed."""
        if "direct" in failed:
            fail(f"direct could not be costed: {failed['direct']}")
        return [s for s in schemes if s not in failed]

    schemes = costed(schemes)
    alone = {s: counts[s][0] for s in schemes}
    batched_i = {s: counts[s][1][0] for s in schemes}

    size = {s: 100000 if alone[s][0] > SLOW_INSTRUCTIONS else 1000000 for s in schemes}
    def names():  # of the schemes not failed so far
        return ["load_store/1000000"] + [f"{kind}/{s}/{size[s]}" for s in schemes if s not in failed
                                         for kind in ("batched", "one_at_a_time")]

    def table(repetitions, stage):
        return bench_table(bench, plugin_args, names(), repetitions, progress, stage, args.timeout, failed)

    tables = []
    if args.thorough:
        halves = [{}, {}]
        for k in range(10):
            for name, values in table(3, f"timing, process {k + 1} of 10,").items():
                halves[k % 2].setdefault(name, []).extend(values)
        tables = halves
    else:
        for k in range(2):
            tables.append(table(2, f"timing, table {k + 1} of 2,"))
    schemes = costed(schemes)
    pooled = {n: tables[0][n] + tables[1][n] for n in names()}

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
    rows = [["load_store", 1000000, floor, spread(pooled["load_store/1000000"])] + [""] * (len(COLUMNS) - 6) + [mode, ""]]
    direct_ns = min(pooled[f"batched/direct/{size['direct']}"])
    for s in sorted(schemes):
        b, a = min(pooled[f"batched/{s}/{size[s]}"]), min(pooled[f"one_at_a_time/{s}/{size[s]}"])
        rows.append([s, size[s], b, spread(pooled[f"batched/{s}/{size[s]}"]), a, spread(pooled[f"one_at_a_time/{s}/{size[s]}"]),
                     a / b, batched_i[s], alone[s][0], b / direct_ns, batched_i[s] / batched_i["direct"], alone[s][1],
                     floor / b if size[s] == 1000000 else "", differ(speedup, s), differ(ns_ratio, s)]
                    + ([counterpart[s], public_ratio(pooled, s, counterpart[s]),
                        public_ratio(pooled, s, counterpart[s], "one_at_a_time"), differ(public_ratio, s, counterpart[s])]
                       if s in counterpart else ["", "", "", ""]) + [mode, ""])
    for s in sorted(failed):
        rows.append([s] + [""] * (len(COLUMNS) - 3) + [mode, failed[s]])
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
