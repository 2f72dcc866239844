#!/usr/bin/env python3
"""A test client for the contact scenes (docs/clients.md, "Contact scenes"): velocity Verlet on the
scene's own law, as a contact client's program would run it, written from scene.json alone. For
spheres only (their angular velocity needs no gyroscopic term). With a fault it misbehaves.

usage: contact_client.py [FAULT] scene.json trajectory.csv
FAULT: --still (every row the initial state), --swapped (body 1's row first), --garbage,
       --nan (every state after t = 0 not finite), --decline (exit 3)
"""
import json
import math
import sys

args = sys.argv[1:]
fault = args[0] if args[0].startswith("--") else ""
spec = json.load(open(args[-2]))
out_path = args[-1]
if fault == "--decline":
    print("contact_client.py: declined, as asked", file=sys.stderr)
    sys.exit(3)
if fault == "--garbage":
    open(out_path, "w").write("no trajectory here\n")
    sys.exit(0)
bodies, law, dt, steps = spec["bodies"], spec["contact"], spec["dt"], spec["steps"]
if any(b["shape"]["kind"] != "sphere" for b in bodies):
    sys.exit("contact_client.py: spheres only")


def rot(q, v):  # q v q* for a unit quaternion (w, x, y, z)
    w, x, y, z = q
    t = [2 * (y * v[2] - z * v[1]), 2 * (z * v[0] - x * v[2]), 2 * (x * v[1] - y * v[0])]
    return [v[0] + w * t[0] + y * t[2] - z * t[1], v[1] + w * t[1] + z * t[0] - x * t[2], v[2] + w * t[2] + x * t[1] - y * t[0]]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def qmul(a, b):
    return [a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3], a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
            a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1], a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]]


def forces(x, v, q, w):  # seed 004 eq. 29 along the fixed normal: F_2 = -(k_n u_n + k_t u_t) - (c_n u'_n + c_t u'_t)
    arm = [rot(q[i], bodies[i]["anchor_body"]) for i in range(2)]
    u = [x[1][k] + arm[1][k] - x[0][k] - arm[0][k] for k in range(3)]
    du = [v[1][k] + cross(w[1], arm[1])[k] - v[0][k] - cross(w[0], arm[0])[k] for k in range(3)]
    n = law["normal"]
    un, dun = sum(a * b for a, b in zip(u, n)), sum(a * b for a, b in zip(du, n))
    f2 = [-(law["normal_stiffness"] * un * n[k] + law["tangential_stiffness"] * (u[k] - un * n[k]))
          - (law["normal_damping"] * dun * n[k] + law["tangential_damping"] * (du[k] - dun * n[k])) for k in range(3)]
    f = [[-a for a in f2], f2]
    return f, [cross(arm[i], f[i]) for i in range(2)]


x = [list(b["position"]) for b in bodies]
v = [list(b["velocity"]) for b in bodies]
q = [list(b["q0"]) for b in bodies]
w = [list(b["omega_world"]) for b in bodies]
m = [b["mass"] for b in bodies]
moment = [b["inertia_body"][0] for b in bodies]
initial = [x[i] + v[i] + q[i] + w[i] for i in range(2)]
f, t = forces(x, v, q, w)
with open(out_path, "w") as out:
    out.write(spec["columns"] + "\n")
    for n in range(steps + 1):
        rows = [x[i] + v[i] + q[i] + w[i] for i in range(2)]
        if fault == "--still":
            rows = initial
        if fault == "--nan" and n > 0:
            rows = [[math.nan] * 13] * 2
        order = [1, 0] if fault == "--swapped" else [0, 1]
        for i in order:
            out.write(",".join(repr(c) for c in [n * dt, i] + rows[i]) + "\n")
        for i in range(2):
            v[i] = [v[i][k] + 0.5 * dt * f[i][k] / m[i] for k in range(3)]
            x[i] = [x[i][k] + dt * v[i][k] for k in range(3)]
            w[i] = [w[i][k] + 0.5 * dt * t[i][k] / moment[i] for k in range(3)]
            theta = [dt * c for c in w[i]]
            angle = math.sqrt(sum(c * c for c in theta))
            if not math.isfinite(angle):  # blown up: so is its orientation
                q[i] = [math.nan] * 4
                continue
            s = 0.5 if angle < 1e-8 else math.sin(0.5 * angle) / angle
            q[i] = qmul([math.cos(0.5 * angle)] + [s * c for c in theta], q[i])
        f, t = forces(x, v, q, w)
        for i in range(2):
            v[i] = [v[i][k] + 0.5 * dt * f[i][k] / m[i] for k in range(3)]
            w[i] = [w[i][k] + 0.5 * dt * t[i][k] / moment[i] for k in range(3)]
