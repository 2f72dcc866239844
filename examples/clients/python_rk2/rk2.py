#!/usr/bin/env python3
"""A complete minimal rotbench client (docs/clients.md): the explicit midpoint rule (RK2) on the
orientation q and the world angular momentum L of one rigid body,
    dq/dt = 1/2 (0, w) q,   w = R(q) I'^-1 R(q)^T L,   dL/dt = T(q),
with q renormalised after each step. Python 3 standard library only.

usage: rk2.py scene.json trajectory.csv
"""
import json
import sys


def qmul(a, b):
    return (a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
            a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
            a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
            a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0])


def rotate(q, v):  # body -> world
    return qmul(qmul(q, (0.0,) + tuple(v)), (q[0], -q[1], -q[2], -q[3]))[1:]


def unrotate(q, v):  # world -> body
    return rotate((q[0], -q[1], -q[2], -q[3]), v)


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


spec = json.load(open(sys.argv[1]))
inertia, dt, steps, torque = spec["inertia_body"], spec["dt"], spec["steps"], spec["torque"]


def omega(q, L):
    return rotate(q, [l / i for l, i in zip(unrotate(q, L), inertia)])


def torque_of(q):
    if torque["law"] == "none":
        return (0.0, 0.0, 0.0)
    if torque["law"] == "body_constant":
        return rotate(q, torque["torque_body"])
    if torque["law"] == "dipole":
        return cross(rotate(q, torque["dipole_body"]), torque["field_world"])
    sys.exit("rk2.py: unknown torque law " + torque["law"])


def rates(q, L):
    return [0.5 * c for c in qmul((0.0,) + tuple(omega(q, L)), q)], torque_of(q)


def normalised(q):
    n = sum(c * c for c in q) ** 0.5
    return tuple(c / n for c in q)


q, L = tuple(spec["q0"]), tuple(spec["L0_world"])
with open(sys.argv[2], "w") as out:
    out.write(spec["columns"] + "\n")
    for k in range(steps + 1):
        # repr: the shortest text that reads back to the same double (full precision)
        out.write(",".join(repr(float(v)) for v in (k * dt,) + q + tuple(omega(q, L))) + "\n")
        dq, dL = rates(q, L)
        qm = normalised([a + 0.5 * dt * b for a, b in zip(q, dq)])
        Lm = [a + 0.5 * dt * b for a, b in zip(L, dL)]
        dq, dL = rates(qm, Lm)
        q = normalised([a + dt * b for a, b in zip(q, dq)])
        L = tuple(a + dt * b for a, b in zip(L, dL))
