#!/usr/bin/env python3
"""rotbench client adapter for LAMMPS's `fix nve/asphere` (docs/clients.md).

usage: lammps_asphere.py scene.json trajectory.csv

The body is one ellipsoid (atom_style ellipsoid). LAMMPS takes an ellipsoid's principal moments
from its mass and semi-axes a, b, c: I_a = m (b^2 + c^2) / 5 and so on. So the semi-axes are
solved for from the scene's moments, a^2 = 5 (I_b + I_c - I_a) / (2 m), and a body whose moments
no ellipsoid has (one of them at least the sum of the other two) is declined: exit status 3.

A torque is added each step by a Python callback (fix python/invoke, post_force) that reads the
orientation and writes the torque through LAMMPS's C library, so that it is T(q) at the step's
own orientation: T = (R mu') x B for a dipole in a uniform field, T = R tau' for a torque fixed in
the body. LAMMPS 20220106 (Debian 12) does not call that callback at set-up, so its first half
kick would miss T(q0): the adapter hands LAMMPS the angular momentum L0 + dt/2 T(q0), which is
what the first half kick makes of L0, and writes L0 itself at t = 0. The orientation and angular
momentum are dumped at every step with 17 significant digits; w = R I'^-1 R^T L. Python 3 stdlib
only; everything is written in the current directory (rotbench's scratch directory).
"""
import json
import math
import os
import sys

sys.dont_write_bytecode = True  # nothing left beside the adapter
from lammps_common import dump_frames, matvec, rot, run_lmp, torque_of

spec_path, out_path = sys.argv[1], sys.argv[2]
spec = json.load(open(spec_path))
g = lambda v: "%.17g" % v


mass, moments, q0, L0, dt = spec["mass"], spec["inertia_body"], spec["q0"], spec["L0_world"], spec["dt"]
law = spec["torque"]
if law["law"] not in ("none", "dipole", "body_constant"):
    print("lammps_asphere.py: no torque here for the law '%s'" % law["law"], file=sys.stderr)
    sys.exit(3)
squares = [5.0 * (moments[(k + 1) % 3] + moments[(k + 2) % 3] - moments[k]) / (2.0 * mass) for k in range(3)]
if min(squares) <= 0.0:
    print("lammps_asphere.py: no ellipsoid has the principal moments %s (each must be below the sum of the other two)"
          % ", ".join(g(i) for i in moments), file=sys.stderr)
    sys.exit(3)  # declined: a body fix nve/asphere cannot represent (docs/clients.md)
diameters = [2.0 * math.sqrt(s) for s in squares]

# set quat takes an axis and an angle in degrees.
vector = math.sqrt(q0[1] ** 2 + q0[2] ** 2 + q0[3] ** 2)
axis = [c / vector for c in q0[1:]] if vector > 0 else [0.0, 0.0, 1.0]
angle = math.degrees(2.0 * math.atan2(vector, q0[0]))
first_kick = [L0[i] + 0.5 * dt * t for i, t in enumerate(torque_of(q0, law))]

here = os.path.dirname(os.path.abspath(__file__))
with open("torque.py", "w") as f:  # the callback: reads q, adds T(q) to the torque LAMMPS sums
    f.write("import ctypes, json, sys\n"
            "sys.dont_write_bytecode = True\n"
            "sys.path.insert(0, %r)\n" % here +
            "from lammps_common import torque_of\n"
            "law = json.loads(%r)\n" % json.dumps(law) +
            "lib = ctypes.CDLL('liblammps.so.0')\n"
            "lib.lammps_extract_atom.restype = ctypes.POINTER(ctypes.POINTER(ctypes.c_double))\n"
            "lib.lammps_extract_compute.restype = ctypes.POINTER(ctypes.POINTER(ctypes.c_double))\n"
            "pointer = ctypes.pythonapi.PyCapsule_GetPointer\n"
            "pointer.restype, pointer.argtypes = ctypes.c_void_p, [ctypes.py_object, ctypes.c_char_p]\n"
            "def add_torque(capsule, vflag):\n"
            "    handle = ctypes.c_void_p(pointer(capsule, None))\n"
            "    q = lib.lammps_extract_compute(handle, b'q', 1, 2)[0]\n"
            "    t = lib.lammps_extract_atom(handle, b'torque')[0]\n"
            "    for i, c in enumerate(torque_of([q[0], q[1], q[2], q[3]], law)):\n"
            "        t[i] += c\n")
lines = ["units si", "atom_style ellipsoid", "boundary f f f", "region box block -10 10 -10 10 -10 10", "create_box 1 box",
         "create_atoms 1 single 0 0 0", "set atom 1 mass %s" % g(mass), "set atom 1 shape %s %s %s" % tuple(g(d) for d in diameters),
         "set atom 1 quat %s %s %s %s" % (g(axis[0]), g(axis[1]), g(axis[2]), g(angle)),
         "set atom 1 angmom %s %s %s" % tuple(g(c) for c in first_kick), "pair_style zero 1.0", "pair_coeff * *",
         "compute q all property/atom quatw quati quatj quatk"]
if law["law"] != "none":
    lines += ["python add_torque file torque.py", "fix torque all python/invoke 1 post_force add_torque"]
lines += ["fix body all nve/asphere", "timestep %s" % g(dt), "thermo 0",
          "dump d all custom 1 body.dump c_q[1] c_q[2] c_q[3] c_q[4] angmomx angmomy angmomz",
          "dump_modify d format float %.17g", "run %d" % spec["steps"]]
run_lmp(lines)

with open(out_path, "w") as out:
    out.write(spec["columns"] + "\n")
    for step, (values,) in dump_frames("body.dump", 1):
        q, L = values[:4], (L0 if step == 0 else values[4:])
        R = rot(q)
        body = [sum(R[j][i] * L[j] for j in range(3)) / moments[i] for i in range(3)]
        out.write(",".join(repr(v) for v in [step * dt] + q + matvec(R, body)) + "\n")
