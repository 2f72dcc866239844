#!/usr/bin/env python3
"""The fourth adversarial round as a matrix the tests rerun (issue 50; docs/cli.md "Bad input"):
external programs that misbehave, forged and cut stores, hostile CI settings and extreme inputs,
each against the rotbench binary in a folder of its own.

usage: round4.py ROTBENCH BUILD_TESTS_DIR

Every case is judged on what an adversary looks for, whatever it expects of the case:
  hang         it did not finish within its time limit (killed);
  crash        a signal, exit status 4 (internal error) or "internal error" on stderr;
  silent pass  exit status 0 where the case must fail or be refused;
  outside      a file outside the output folder written, changed or removed (the case's folder
               and a sentinel folder are listed and hashed before and after), or a scratch folder
               of rotbench's left in TMPDIR, or a process left behind;
  message      the exit status or the message is not the one the case expects (one line, exit 2,
               for bad input).
Prints one line per case and the counts by problem; exits 1 if any case has a problem.
"""
import hashlib
import os
import signal
import stat
import subprocess
import sys
import tempfile
import textwrap
import time
from pathlib import Path

ROTBENCH = str(Path(sys.argv[1]).resolve())
PLUGINS = Path(sys.argv[2]).resolve()
SOURCE = Path(__file__).resolve().parents[2]
CONTACT_CLIENT = SOURCE / "tests" / "clients" / "contact_client.py"
ONE_BODY_CLIENT = SOURCE / "tests" / "clients" / "rotbench_client.py"


def listing(root):  # every file under root with its hash (links as their target text)
    seen = {}
    for path in sorted(Path(root).rglob("*")):
        try:
            mode = path.lstat().st_mode
        except FileNotFoundError:
            continue
        if stat.S_ISLNK(mode):
            seen[str(path)] = "link:" + os.readlink(path)
        elif stat.S_ISREG(mode):
            seen[str(path)] = hashlib.sha256(path.read_bytes()).hexdigest()
        elif stat.S_ISDIR(mode):
            seen[str(path)] = "dir"
        else:
            seen[str(path)] = "special"
    return seen


class Case:
    def __init__(self, name, args, expect, message="", setup=None, env=None, seconds=60, stdout=None, check=None, output="out"):
        self.name, self.args, self.expect, self.message, self.output = name, args, expect, message, output
        self.setup, self.env, self.seconds, self.stdout, self.check = setup, env or {}, seconds, stdout, check


def write(path, text, mode=0o644):
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    Path(path).write_text(text)
    os.chmod(path, mode)


def client_file(work, name, program, scenes='["sphere_pair"]', extra='claims = "direct"\n'):
    args = ", ".join('"%s"' % a for a in program)
    write(work / (name + ".toml"), 'id = "%s"\nprogram = [%s]\nscenes = %s\n%s' % (name, args, scenes, extra))
    return str(work / (name + ".toml"))


def bad_program(work, body):  # a Python program run as a client: `body` gets spec, out (paths) and rows of a good run
    write(work / "bad.py", "import json, os, subprocess, sys, time, signal\nspec_path, out = sys.argv[-2], sys.argv[-1]\n"
          "subprocess.run(['python3', %r, spec_path, 'good.csv'], check=True)\nrows = open('good.csv').read().splitlines()\n" % str(CONTACT_CLIENT)
          + textwrap.dedent(body))
    return client_file(work, "bad", ["python3", str(work / "bad.py")])


def contact_check(body, message, expect="fail"):
    return Case("contact client: " + message, lambda w: ["--client", bad_program(w, body), "client", "check", w / "bad.toml",
                                                          "--scene", "sphere_pair", "--set", "t_end=0.002"], expect, message)


def cases():
    out = lambda w: str(w / "out")
    quick = lambda w: ["run", "--scenes", "asymmetric_free", "--schemes", "direct,no_squish", "--quick", "--out", str(w / "base"), "--quiet"]
    yield from [
        # Clients that write what is not a trajectory: one failed run, a line saying why.
        contact_check("open(out, 'w').write('garbage\\n')", "expected the header"),
        contact_check("open(out, 'w').write(rows[0] + '\\n' + '1,' * (1 << 20) + '\\n')", "is larger than"),
        contact_check("os.mkfifo(out)", "not a regular file"),
        contact_check("os.symlink('/etc/passwd', out)", "not a regular file"),
        contact_check("os.mkdir(out)", "not a regular file"),
        contact_check("os.kill(os.getpid(), signal.SIGSEGV)", "crashed: signal 11"),
        contact_check("open(out, 'w').write('\\n'.join(rows[:-1]) + '\\n')", "rows; 42 are due"),
        contact_check("rows[5] = rows[5].split(',', 2)[0] + ',7,' + rows[5].split(',', 2)[2]\nopen(out, 'w').write('\\n'.join(rows) + '\\n')",
                      "body 7 where body 0 is due"),
        contact_check("rows[5] = 'nan,' + rows[5].split(',', 1)[1]\nopen(out, 'w').write('\\n'.join(rows) + '\\n')", "t = nan where step 2"),
        contact_check("rows[3] = ','.join(rows[3].split(',')[:14])\nopen(out, 'w').write('\\n'.join(rows) + '\\n')", "expected 15 fields"),
        contact_check("r = rows[9].split(','); r[8:12] = ['0'] * 4; rows[9] = ','.join(r)\nopen(out, 'w').write('\\n'.join(rows) + '\\n')",
                      "blew up"),
        contact_check("sys.stderr.write('\\x1b[31mred\\x07\\n'); sys.exit(5)", "exited with status 5"),
        contact_check("print('no', file=sys.stderr); sys.exit(3)", "FAIL: declined: no"),
        Case("client: a program that hangs is stopped by its time limit, the sweep goes on",
             lambda w: ["--client", client_file(w, "sleeper", ["python3", "-c", "import time; time.sleep(600)"]), "run", "--scenes",
                        "sphere_pair", "--schemes", "sleeper", "--quick", "--run-timeout", "2", "--out", out(w)], "ok", "FAILED", seconds=120),
        Case("client: a grandchild that calls setsid and sleeps is gone after the run",
             lambda w: ["--client", client_file(w, "escaper", ["python3", str(w / "escape.py")]), "client", "check", w / "escaper.toml",
                        "--scene", "sphere_pair", "--set", "t_end=0.002"], "fail", "FAIL",
             setup=lambda w: write(w / "escape.py", "import os, time\nif os.fork() == 0:\n    os.setsid()\n"
                                                    "    os.execvp('sleep', ['sleep', '4321'])\ntime.sleep(0.2)\n")),
        Case("client: a program path with a slash that does not exist is refused at load",
             lambda w: ["--client", client_file(w, "missing", ["./nowhere.py"]), "list"], "refused", "nowhere.py"),
        Case("client: a program that is not executable is refused at load",
             lambda w: ["--client", client_file(w, "noexec", [str(w / "plain.txt")]), "list"], "refused", "plain.txt",
             setup=lambda w: write(w / "plain.txt", "not a program\n")),
        Case("client: a folder named {dir} is substituted once, and the client runs",
             lambda w: ["--client", client_file(w / "{dir}", "braces", ["python3", "{dir}/c.py"]), "client", "check",
                        w / "{dir}" / "braces.toml", "--scene", "sphere_pair", "--set", "t_end=0.002"], "ok", "ok:",
             setup=lambda w: write(w / "{dir}" / "c.py", Path(CONTACT_CLIENT).read_text())),
        Case("client: control characters in a client's summary do not reach the terminal",
             lambda w: ["--client", client_file(w, "noisy", ["python3", str(CONTACT_CLIENT)], extra='claims = "direct"\nsummary = "a\\u001b[2Jb"\n'),
                        "list"], "ok", check=lambda r: "\x1b" not in r.stdout + r.stderr or "escape character reached the terminal"),
        Case("client: a contact client's stability search whose program writes garbage fails that case, the study goes on",
             lambda w: ["--client", bad_program(w, "open(out, 'w').write('garbage\\n')"), "stability", "--scenes", "sphere_pair", "--schemes",
                        "bad,direct", "--zeta", "0", "--out", out(w), "--quiet"], "ok", seconds=180,
             check=lambda r: "failed" in (Path(r.work) / "out" / "stability.csv").read_text() or "no failed row"),
        # Plug-ins that return nothing, or are not plug-ins.
        *[Case("plug-in: %s is refused in one line" % so, lambda w, so=so: ["--plugin", str(PLUGINS / so), "list"], "refused")
          for so in ("libtest_plugin_null_build.so", "libtest_plugin_null_schemes.so", "libtest_plugin_null_abi.so",
                     "libtest_plugin_wrong_abi.so", "libtest_plugin_not_a_plugin.so")],
        Case("plug-in: /dev/zero is refused", lambda w: ["--plugin", "/dev/zero", "list"], "refused"),
        Case("plug-in: a FIFO is refused without waiting", lambda w: ["--plugin", str(w / "fifo.so"), "list"], "refused",
             setup=lambda w: os.mkfifo(w / "fifo.so"), seconds=20),
        Case("plug-in: a sparse 3 GB file is refused before it is read", lambda w: ["--plugin", str(w / "big.so"), "list"], "refused",
             setup=lambda w: sparse(w / "big.so", 3 << 30), seconds=20),
        Case("plug-in: schemes that crash, hang or throw are failed runs, the sweep goes on",
             lambda w: ["--plugin", str(PLUGINS / "test_plugin_crashing.so"), "run", "--scenes", "asymmetric_free", "--quick",
                        "--run-timeout", "5", "--out", out(w), "--quiet"], "ok", seconds=300),
        # Stores that were cut, forged or are not files.
        Case("report: a runs.jsonl of garbage is refused", lambda w: ["report", str(w / "base")], "refused", "runs.jsonl",
             setup=lambda w: (run(quick(w)), write(w / "base" / "runs.jsonl", "garbage\n"))),
        Case("report: a runs.jsonl cut in the middle of a line is refused", lambda w: ["report", str(w / "base")], "refused", "runs.jsonl",
             setup=lambda w: (run(quick(w)), cut(w / "base" / "runs.jsonl"))),
        Case("report: a runs.jsonl that is a FIFO is refused without waiting", lambda w: ["report", str(w / "base")], "refused", seconds=20,
             setup=lambda w: (run(quick(w)), os.remove(w / "base" / "runs.jsonl"), os.mkfifo(w / "base" / "runs.jsonl"))),
        Case("report: a stability.jsonl of garbage is refused", lambda w: ["report", str(w / "base")], "refused", "stability.jsonl",
             setup=lambda w: (run(quick(w)), write(w / "base" / "stability.jsonl", "{}\n"))),
        Case("compare: NEW without one of BASE's schemes is a regression", lambda w: ["compare", str(w / "base"), str(w / "new")], "fail",
             setup=lambda w: (run(quick(w)), run(["run", "--scenes", "asymmetric_free", "--schemes", "direct", "--quick", "--out",
                                                   str(w / "new"), "--quiet"]))),
        Case("merge: a shard whose runs hold another dt than its plan is refused",
             lambda w: ["merge", str(w / "s1"), str(w / "s2"), "--out", out(w)], "refused",
             setup=lambda w: (run(["run", "--scenes", "asymmetric_free", "--schemes", "direct", "--quick", "--shard", "1/2", "--out", str(w / "s1"),
                                   "--quiet"]),
                              run(["run", "--scenes", "asymmetric_free", "--schemes", "direct", "--quick", "--shard", "2/2", "--out", str(w / "s2"),
                                   "--quiet"]),
                              edit(w / "s2" / "runs.jsonl", '"dt":0.05', '"dt":0.0501'))),
        # CI settings an attacker controls.
        Case("gate: GITHUB_STEP_SUMMARY naming a FIFO is refused before the gate runs", lambda w: ["gate", str(SOURCE / "gates" / "default.toml"),
                                                                                                   "--quick", "--schemes", "direct"],
             "refused", "GITHUB_STEP_SUMMARY", setup=lambda w: os.mkfifo(w / "summary"), env={"GITHUB_STEP_SUMMARY": "summary"}, seconds=30),
        Case("gate: a check name with a line break cannot inject a workflow command",
             lambda w: ["gate", str(w / "evil.toml"), "--quick", "--schemes", "direct"], "any",
             setup=lambda w: write(w / "evil.toml", '[[check]]\nname = "x\\n::error::owned"\nscene = "asymmetric_free"\nschemes = ["direct"]\n'
                                                    'min_order = 1.5\nwhy = "y"\n'),
             check=lambda r: not any(line.startswith("::error::owned") for line in r.stdout.splitlines()) or "an injected ::error line"),
        Case("report: a gnuplot that never exits is stopped, the report is written", lambda w: ["report", str(w / "base")], "ok", seconds=300,
             setup=lambda w: (run(quick(w)), write(w / "bin" / "gnuplot", "#!/bin/sh\nexec sleep 3600\n", 0o755)),
             env={"PATH": "{work}/bin:" + os.environ["PATH"]}, output="base"),
        # Extreme numbers.
        Case("advise: --mass 1e-300 ends in bounded time (one scheme)",
             lambda w: ["advise", "--inertia", "1,2,3", "--mass", "1e-300", "--stiffness", "1e6", "--tolerance", "1e-3", "--schemes", "direct",
                        "--out", out(w)], "any", seconds=180),
        Case("advise: --mass 1e-300 over every scheme ends within a minute (the reference fails once, not per rung)",
             lambda w: ["advise", "--inertia", "1,2,3", "--mass", "1e-300", "--stiffness", "1e6", "--tolerance", "1e-3", "--out", out(w)],
             "any", seconds=60),
        Case("advise: --zeta 1e300 is refused naming --zeta", lambda w: ["advise", "--inertia", "1,2,3", "--mass", "1", "--stiffness", "1e6",
                                                                         "--tolerance", "1e-3", "--zeta", "1e300", "--out", out(w)],
             "refused", "--zeta"),
        Case("advise: --inertia with a NaN is refused", lambda w: ["advise", "--inertia", "1,nan,3", "--mass", "1", "--stiffness", "1e6",
                                                                   "--tolerance", "1e-3", "--out", out(w)], "refused", "--inertia"),
        Case("list: a full standard output is an error", lambda w: ["list"], "fail", stdout="/dev/full"),
        Case("run: an argument with a line break is refused", lambda w: ["run", "--scenes", "asym\nmetric_free", "--out", out(w)], "refused"),
        Case("run: a cache others may write is neither read nor written", lambda w: quick(w), "ok", "ROTBENCH_CACHE",
             setup=lambda w: (w / "cache").mkdir(mode=0o777) or os.chmod(w / "cache", 0o777), env={"ROTBENCH_CACHE": "{work}/cache"},
             check=lambda r: not any((Path(r.work) / "cache").iterdir()) or "the shared cache was written", output="base"),
    ]


def run(args):
    subprocess.run([ROTBENCH] + [str(a) for a in args], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def sparse(path, size):
    with open(path, "wb") as f:
        f.truncate(size)


def cut(path):
    text = Path(path).read_bytes()
    Path(path).write_bytes(text[: len(text) // 2])


def edit(path, old, new):
    text = Path(path).read_text()
    if old not in text:
        raise SystemExit("round4.py: the setup did not find %r in %s" % (old, path))
    Path(path).write_text(text.replace(old, new, 1))


def marked_processes(mark):  # processes whose environment holds rotbench's run mark of this case
    found = []
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            if ("ROTBENCH_CASE=" + mark).encode() in Path("/proc", pid, "environ").read_bytes():
                found.append(pid)
        except OSError:
            pass
    return found


def judge(case, root):
    work = root / case.name.split(":")[0].replace(" ", "_")
    work = Path(tempfile.mkdtemp(prefix=work.name + "-", dir=root))
    (work / "tmp").mkdir()
    sentinel = root / "sentinel"
    if case.setup:
        case.setup(work)
    args = [ROTBENCH] + [str(a) for a in case.args(work)]  # writes the client files the case names
    mine = str(work / case.output)  # the output folder: rotbench's to write
    before = {k: v for k, v in listing(work).items() if not k.startswith(mine)}
    before_sentinel = listing(sentinel)
    env = dict(os.environ, TMPDIR=str(work / "tmp"), ROTBENCH_CASE=work.name)
    env.update({k: v.replace("{work}", str(work)) for k, v in case.env.items()})
    stdout = open(case.stdout, "w") if case.stdout else subprocess.PIPE
    started = time.monotonic()
    proc = subprocess.Popen(args, cwd=work, env=env, stdout=stdout, stderr=subprocess.PIPE, text=True, errors="replace", start_new_session=True)
    try:
        out, err = proc.communicate(timeout=case.seconds)
        status = proc.returncode
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        return "hang", "not done after %d s" % case.seconds
    seconds = time.monotonic() - started
    result = type("Result", (), {"stdout": out or "", "stderr": err or "", "status": status, "work": str(work)})
    if status < 0 or status == 4 or "internal error" in result.stderr:
        return "crash", "status %d: %s" % (status, result.stderr.strip()[-200:])
    after = {k: v for k, v in listing(work).items() if not k.startswith(mine)}
    changed = sorted({k for k, _ in set(before.items()) ^ set(after.items())})
    left = [p for p in (work / "tmp").iterdir()]
    survivors = marked_processes(work.name)
    for pid in survivors:
        os.kill(int(pid), signal.SIGKILL)
    if listing(sentinel) != before_sentinel or changed or left or survivors:
        return "outside", "changed %s, left %s, processes %s" % (changed[:3], [p.name for p in left][:3], survivors)
    if case.expect in ("refused", "fail") and status == 0:
        return "silent pass", "exit 0: %s" % result.stdout.strip()[-200:]
    if case.expect == "refused" and (status != 2 or result.stderr.count("\n") != 1):
        return "message", "status %d, stderr %r" % (status, result.stderr[-300:])
    if case.expect == "fail" and status != 1 and not (case.stdout and status != 0):
        return "message", "status %d: %s" % (status, (result.stdout + result.stderr).strip()[-200:])
    if case.expect == "ok" and status != 0:
        return "message", "status %d: %s" % (status, (result.stdout + result.stderr).strip()[-300:])
    if case.message and case.message not in result.stdout + result.stderr:
        return "message", "no %r in: %s" % (case.message, (result.stdout + result.stderr).strip()[-300:])
    if case.check:
        verdict = case.check(result)
        if verdict is not True:
            return "message", verdict
    return "", "%.1f s" % seconds


def main():
    problems = {}
    with tempfile.TemporaryDirectory(prefix="rotbench-round4-") as root:
        root = Path(root)
        write(root / "sentinel" / "keep.txt", "a file rotbench did not write\n")
        all_cases = list(cases())
        for case in all_cases:
            problem, detail = judge(case, root)
            problems[problem] = problems.get(problem, 0) + 1
            print("%-12s %s (%s)" % (problem or "ok", case.name, detail), flush=True)
    bad = {k: v for k, v in problems.items() if k}
    print("%d cases: %d ok; %s" % (len(all_cases), problems.get("", 0),
                                   ", ".join("%d %s" % (v, k) for k, v in sorted(bad.items())) or "no problem"))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
