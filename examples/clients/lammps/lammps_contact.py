#!/usr/bin/env python3
"""rotbench client adapter for a contact of two spheres in LAMMPS (`pair_style gran/hooke/history`)
or in LIGGGHTS, LAMMPS's granular fork (`pair_style gran model hooke/stiffness tangential
history`), each under `fix nve/sphere` (docs/clients.md, "Contact scenes").

usage: lammps_contact.py lammps|liggghts scene.json trajectory.csv

Two spheres in the scene's linear spring-dashpot contact: the code's normal spring and tangential
history spring are the scene's stiffnesses, its dashpots the scene's: LAMMPS's are meff gamma v
(meff = m1 m2 / (m1 + m2)), so gamma = c / meff with dampflag 1; LIGGGHTS's are set absolutely
(`absolute_damping on`, gamman_abs = c_n, gammat_abs = c_t). The friction limit is the largest
each takes (LAMMPS's xmu 10000; LIGGGHTS's coefficientFriction 1e4), far above any tangential
force here. The bond is the central preload of ../contact_pair.py, each pull a `fix addforce`
with variables.

Neither code keeps a sphere's orientation. The adapter composes the rotations the code's own
tangential history integrates, exp(dt w^(n+1/2)) with w^(n+1/2) = w^n + dt/2 T^n / I (fix
nve/sphere's half kick, from the dumped angular velocity and torque), onto each sphere's q0.
A sphere whose moment is not 0.4 m r^2 (the codes'), or a body that is not a sphere, is declined:
exit status 3. Python 3 stdlib only; everything is written in the current directory.
"""
import json
import math
import os
import sys

sys.dont_write_bytecode = True  # nothing left beside the adapter
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from contact_pair import decline, preload_overlap, sphere_pair  # noqa: E402
from lammps_common import dump_frames, run_lmp  # noqa: E402

code, spec_path, out_path = sys.argv[1], sys.argv[2], sys.argv[3]
if code not in ("lammps", "liggghts"):
    sys.exit("lammps_contact.py: the code is lammps or liggghts, not %r" % code)
spec = json.load(open(spec_path))
g = lambda v: "%.17g" % v

bodies, contact, radii, meff = sphere_pair(spec, "a granular pair style")
for b, r in zip(bodies, radii):
    if any(abs(i - 0.4 * b["mass"] * r * r) > 1e-12 * i for i in b["inertia_body"]):
        decline("the code gives a sphere the moment 0.4 m r^2 = %s, not %s" % (g(0.4 * b["mass"] * r * r), b["inertia_body"]))
dt, steps = spec["dt"], spec["steps"]
kn, kt, cn, ct = (contact[k] for k in ("normal_stiffness", "tangential_stiffness", "normal_damping", "tangential_damping"))
overlap = preload_overlap(bodies, contact, radii, meff)
force = kn * overlap
shift = [0.5 * overlap, -0.5 * overlap]  # body 0 moves +x, body 1 -x into the overlap

# Both spheres from a data file: the codes' `set` differ (LIGGGHTS's cannot set an angular velocity).
atoms = ["%d 1 %s %s %s %s %s" % ((i + 1, g(2 * radii[i]), g(b["mass"] / (4.0 / 3.0 * math.pi * radii[i] ** 3)), g(b["position"][0] + shift[i]))
                                  + tuple(map(g, b["position"][1:]))) for i, b in enumerate(bodies)]
velocities = ["%d %s" % (i + 1, " ".join(map(g, b["velocity"] + b["omega_world"]))) for i, b in enumerate(bodies)]
open("pair.data", "w").write("rotbench %s\n\n2 atoms\n1 atom types\n-2 2 xlo xhi\n-2 2 ylo yhi\n-2 2 zlo zhi\n\nAtoms\n\n%s\n\nVelocities\n\n%s\n"
                             % (spec["scene"], "\n".join(atoms), "\n".join(velocities)))
if code == "lammps":
    lines = ["units si", "atom_style sphere", "atom_modify map array", "boundary s s s", "comm_modify vel yes", "read_data pair.data",
             "pair_style gran/hooke/history %s %s %s %s 10000 1" % (g(kn), g(kt), g(cn / meff), g(ct / meff)), "pair_coeff * *"]
    dump_format = ["dump_modify states sort id format float %.17g"]
else:
    # No atom sorting: past a blow-up the box grows until LIGGGHTS has too many sorting bins and stops.
    lines = ["units si", "atom_style granular", "atom_modify map array sort 0 0.0", "boundary m m m", "newton off",
             "communicate single vel yes", "read_data pair.data"]
    lines += ["fix %s all property/global %s peratomtypepair 1 %s" % (name, name, g(value))
              for name, value in (("kn", kn), ("kt", kt), ("gamman_abs", cn), ("gammat_abs", ct), ("coefficientFriction", 1e4))]
    lines += ["pair_style gran model hooke/stiffness tangential history absolute_damping on tangential_damping on", "pair_coeff * *"]
    dump_format = ['dump_modify states sort id format "%d' + " %.17g" * 12 + '"']
lines += ["neighbor %s nsq" % g(0.5 * min(radii)), "neigh_modify every 1 delay 0 check no",
          "group b0 id 1", "group b1 id 2",
          # The pull along the line of the centres, as the contact's push: constant x would buckle the pair.
          "variable dx equal x[2]-x[1]", "variable dy equal y[2]-y[1]", "variable dz equal z[2]-z[1]",
          "variable pull equal %s/sqrt(v_dx*v_dx+v_dy*v_dy+v_dz*v_dz)" % g(force)]
lines += ["variable f%s%d equal %sv_pull*v_d%s" % (c, i, "" if i == 0 else "-", c) for i in range(2) for c in "xyz"]
lines += ["fix press0 b0 addforce v_fx0 v_fy0 v_fz0", "fix press1 b1 addforce v_fx1 v_fy1 v_fz1",
          "fix step all nve/sphere",
          "timestep %s" % g(dt),
          "thermo %d" % max(steps, 1),
          "dump states all custom 1 dump.states id x y z vx vy vz omegax omegay omegaz tqx tqy tqz"] + dump_format + ["run %d" % steps]
run_lmp(lines, code)


def qmul(a, b):
    return [a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3], a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
            a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1], a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]]


def exp_rotation(theta):  # the unit quaternion of the rotation vector theta
    angle = math.sqrt(sum(t * t for t in theta))
    s = 0.5 if angle < 1e-8 else math.sin(0.5 * angle) / angle  # sin(a/2)/a -> 1/2, error a^2/48
    return [math.cos(0.5 * angle)] + [s * t for t in theta]


q = [list(b["q0"]) for b in bodies]
moment = [b["inertia_body"][0] for b in bodies]
with open(out_path, "w") as out:
    out.write(spec["columns"] + "\n")
    for n, atoms in dump_frames("dump.states", 2):
        for i, a in enumerate(atoms):
            x = [a[1] - shift[i], a[2], a[3]]
            out.write(",".join(map(g, [n * dt, i] + x + a[4:7] + q[i] + a[7:10])) + "\n")
            half = [a[7 + k] + 0.5 * dt * a[10 + k] / moment[i] for k in range(3)]
            q[i] = qmul(exp_rotation([dt * w for w in half]), q[i])
