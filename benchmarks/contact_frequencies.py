#!/usr/bin/env python3
"""The contact a client's program makes, measured against the scene's (docs/findings.md, "Where
the codes go unstable"): the normal and the tangential-rotational frequencies and decay rates of a
small-amplitude run of sphere_pair, at a step 170 times below Peng's, against the scene's own.

For two spheres of mass m, radius r and moment 0.4 m r^2 joined at their touching points by a
normal spring k_n and a tangential one k_t (seed 004, eq. 29), the relative displacement of the
touching points moves in two modes only: along the normal at sqrt(2 k_n / m), and across it at
sqrt(k_t A) with A = 1/m1 + 1/m2 + r1^2/I1 + r2^2/I2 = 7/m (the rotations take part); every other
mode leaves the contact unstretched. Each component of the displacement is then one sinusoid,
whose period is read from the zero crossings (interpolated) of its rate over the run. Damped
(zeta = 0.1 here), each mode decays as exp(-c A t / 2) with c the scene's dashpot and A = 2/m along
the normal, 7/m across it: the rate is fitted to the log of the rate's peaks by least squares.

usage: contact_frequencies.py ROTBENCH CLIENT.toml [more client files]
Runs each client's program as rotbench would (`rotbench client scene`, then the program on it, in
a temporary directory) and prints a Markdown table. Python 3 stdlib only.
"""
import csv
import json
import math
import subprocess
import sys
import tempfile
import tomllib
from pathlib import Path


def crossings_period(times, values):  # mean period from the first to the last upward zero crossing
    ups = [t0 + (t1 - t0) * (-v0) / (v1 - v0) for t0, t1, v0, v1 in zip(times, times[1:], values, values[1:]) if v0 < 0 <= v1]
    return (ups[-1] - ups[0]) / (len(ups) - 1) if len(ups) >= 3 else math.nan


def slope(times, values):  # least-squares slope
    n = len(times)
    mt, mv = sum(times) / n, sum(values) / n
    return sum((t - mt) * (v - mv) for t, v in zip(times, values)) / sum((t - mt) ** 2 for t in times)


def contact_motion(rotbench, program, zeta):
    """The scene's spec and, at each step, the touching points' relative displacement and velocity
    along the normal (x) and across it (y), to first order in the rotations."""
    with tempfile.TemporaryDirectory() as work:
        subprocess.run([rotbench, "client", "scene", "sphere_pair", "--dt", "1e-6", "--set", "t_end=0.01", "--set", "zeta=%r" % zeta,
                        "--out", "scene.json"], cwd=work, check=True, stderr=subprocess.DEVNULL)
        spec = json.loads(Path(work, "scene.json").read_text())
        subprocess.run(program + ["scene.json", "trajectory.csv"], cwd=work, check=True)
        rows = [list(map(float, r)) for r in list(csv.reader(open(Path(work, "trajectory.csv"))))[1:]]
    b0, b1 = spec["bodies"]
    r = b0["shape"]["size"][0]
    motion = []
    for r0, r1 in zip(rows[0::2], rows[1::2]):
        # y1 - y0 - r (theta_0 + theta_1)_z across, theta from the quaternions' vector parts.
        motion.append((r0[0], r1[2] - r0[2] - (b1["position"][0] - b0["position"][0]), r1[5] - r0[5],
                       r1[3] - r0[3] - r * 2.0 * (r0[11] + r1[11]), r1[6] - r0[6] - r * (r0[14] + r1[14])))
    return spec, motion


def measure(rotbench, client_file):
    client = tomllib.loads(Path(client_file).read_text())
    program = [a.replace("{dir}", str(Path(client_file).resolve().parent)) for a in client["program"]]
    spec, motion = contact_motion(rotbench, program, 0.0)
    b0 = spec["bodies"][0]
    m, r, inertia = b0["mass"], b0["shape"]["size"][0], b0["inertia_body"][0]
    inverse = {"normal": 2.0 / m, "across": 2.0 / m + 2.0 * r * r / inertia}  # 1/mu of each mode; across: 7/m
    law = spec["contact"]
    times = [row[0] for row in motion]
    found = {}
    # From the relative velocity, whose mean is nil whatever static offset a code's tangential
    # history keeps from the material points' displacement.
    for mode, column, k in (("normal", 2, law["normal_stiffness"]), ("across", 4, law["tangential_stiffness"])):
        w = 2 * math.pi / crossings_period(times, [row[column] for row in motion])
        found[mode] = [w, math.sqrt(k * inverse[mode])]
    # The damping at zeta = 0.1: the peaks of |u'| decay as exp(-c / (2 mu) t); fitted while they
    # are above 1/20 of the first (below, the constant that rolling adds where a code's contact
    # point is not the scene's touching point, as LIGGGHTS's, would bias it).
    spec, motion = contact_motion(rotbench, program, 0.1)
    law = spec["contact"]
    for mode, column, c in (("normal", 2, law["normal_damping"]), ("across", 4, law["tangential_damping"])):
        v = [abs(row[column]) for row in motion]
        peaks = [(times[n], math.log(v[n])) for n in range(1, len(v) - 1) if v[n - 1] < v[n] >= v[n + 1] and v[n] > 0.05 * max(v)]
        found[mode] += [-slope(*zip(*peaks)), 0.5 * c * inverse[mode]]
    return client["id"], found


def main():
    rotbench, files = str(Path(sys.argv[1]).resolve()), sys.argv[2:]
    print("| client | mode | frequency (rad/s) | scene's sqrt(k / mu) | ratio | decay at zeta 0.1 (1/s) | scene's c / (2 mu) | ratio |")
    print("|---|---|---:|---:|---:|---:|---:|---:|")
    for f in files:
        name, found = measure(rotbench, f)
        for mode, (w, w0, g, g0) in found.items():
            print("| %s | %s | %.6g | %.6g | %.6f | %.5g | %.5g | %.4f |" % (name, mode, w, w0, w / w0, g, g0, g / g0))


if __name__ == "__main__":
    main()
