#!/usr/bin/env python3
"""A test client (docs/clients.md) whose program is rotbench itself: it reads the scene spec,
exports a built-in scheme's trajectory with `rotbench trajectory`, and hands it back in the
client's columns, so that its runs must equal the built-in's bit for bit. With a fault it
misbehaves as a broken code would, for the tests of failed client runs.

usage: rotbench_client.py ROTBENCH SCHEME [FAULT] scene.json trajectory.csv
FAULT: --garbage, --huge (a trajectory.csv of 4 MB), --short, --nan, --hang, --crash, --litter (writes outside its directory's files),
       --decline-torque (declines every scene with a torque: exit 3, docs/clients.md)
"""
import json
import os
import signal
import subprocess
import sys
import time

args = sys.argv[1:]
rotbench, scheme = args[0], args[1]
fault = args[2] if args[2].startswith("--") else ""
spec_path, out_path = args[-2], args[-1]
with open(spec_path) as f:
    spec = json.load(f)

if fault == "--decline-torque" and spec["torque"]["law"] != "none":
    print("rotbench_client.py: this client takes no torque", file=sys.stderr)
    sys.exit(3)
if fault == "--hang":
    time.sleep(3600)
if fault == "--crash":
    os.kill(os.getpid(), signal.SIGSEGV)
if fault == "--huge":
    with open(out_path, "w") as f:
        f.write(spec["columns"] + "\n" + "1" * (4 << 20) + "\n")
    sys.exit(0)
if fault == "--garbage":
    with open(out_path, "w") as f:
        f.write("this is not a trajectory\n")
    sys.exit(0)

command = [rotbench, "trajectory", "--scene", spec["scene"], "--scheme", scheme, "--dt", repr(spec["dt"]),
           "--t-end", repr(spec["t_end"]), "--samples", str(spec["steps"]), "--out", "export.csv"]
for key, values in spec["params"].items():
    command += ["--set", "%s=%s" % (key, ",".join(repr(v) for v in values))]
subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
with open("export.csv") as f:
    rows = [line.rstrip("\n").split(",")[:8] for line in f][1:]
if fault == "--short":
    rows = rows[:-1]
if fault == "--nan":
    rows[len(rows) // 2][5] = "nan"
with open(out_path, "w") as f:
    f.write(spec["columns"] + "\n")
    for row in rows:
        f.write(",".join(row) + "\n")
