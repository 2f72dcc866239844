#!/usr/bin/env python3
"""rotbench client adapter for a contact of LAMMPS's granular pair style `gran/hooke/history`
under `fix nve/sphere` (docs/clients.md, "Contact scenes").

usage: lammps_contact.py scene.json trajectory.csv

Two spheres (atom_style sphere) in the scene's linear spring-dashpot contact: LAMMPS's normal
spring Kn and tangential history spring Kt are the scene's stiffnesses; its damping forces are
meff gamma v (meff = m1 m2 / (m1 + m2)), so gamma_n = c_n / meff and gamma_t = c_t / meff with
dampflag 1; the friction limit xmu is its largest, 10000 times the normal force, far above any tangential force here. The scene's contact is bonded and a
granular contact only pushes, so the adapter presses the spheres together: each is pulled toward
the other along the line of their centres by a constant force F0 (fix addforce with variables),
from an overlap F0 / Kn, the equilibrium of that pull and the spring, and writes the positions
shifted back by half that overlap each. About that equilibrium the contact is the scene's as long
as it stays closed: F0 is chosen so that the overlap is 3000 times the perturbation's amplitude,
which the energy criterion of a stability search (growth by 1e6, amplitude by 1e3) does not
reach. The pull is central, as the contact's push is, so the two cancel across the contact too
(a pull fixed along x would buckle the pair: the pair's rotation grew 25-fold in energy per
100 steps of 1e-4 s, measured).

LAMMPS does not keep a sphere's orientation. The adapter composes the rotations LAMMPS's own
tangential history integrates, exp(dt w^(n+1/2)) with w^(n+1/2) = w^n + dt/2 T^n / I (fix
nve/sphere's half kick, from the dumped angular velocity and torque), onto each sphere's q0.
A sphere whose moment is not 0.4 m r^2 (LAMMPS's), or a body that is not a sphere, is declined:
exit status 3. Python 3 stdlib only; everything is written in the current directory.
"""
import json
import math
import sys

sys.dont_write_bytecode = True  # nothing left beside the adapter
from lammps_common import dump_frames, run_lmp

spec_path, out_path = sys.argv[1], sys.argv[2]
spec = json.load(open(spec_path))
g = lambda v: "%.17g" % v


def decline(why):
    print("lammps_contact.py: " + why, file=sys.stderr)
    sys.exit(3)


bodies, contact, dt, steps = spec["bodies"], spec["contact"], spec["dt"], spec["steps"]
for b in bodies:
    if b["shape"]["kind"] != "sphere":
        decline("a granular pair style takes spheres, not a body of kind '%s'" % b["shape"]["kind"])
    r, m = b["shape"]["size"][0], b["mass"]
    if any(abs(i - 0.4 * m * r * r) > 1e-12 * i for i in b["inertia_body"]):
        decline("LAMMPS gives a sphere the moment 0.4 m r^2 = %s, not %s" % (g(0.4 * m * r * r), b["inertia_body"]))
normal = contact["normal"]
if normal != [1.0, 0.0, 0.0] or any(abs(b["position"][1]) + abs(b["position"][2]) > 0 for b in bodies):
    decline("the spheres must touch along x (the scene's normal is %s)" % normal)
kn, kt, cn, ct = (contact[k] for k in ("normal_stiffness", "tangential_stiffness", "normal_damping", "tangential_damping"))
m1, m2 = bodies[0]["mass"], bodies[1]["mass"]
meff = m1 * m2 / (m1 + m2)
radii = [b["shape"]["size"][0] for b in bodies]

# The perturbation's amplitude, |relative velocity at the contact| / sqrt(Kn / meff); the preload's overlap 3000 times it.
rel = [bodies[1]["velocity"][k] - bodies[0]["velocity"][k] for k in range(3)]
spin = [abs(bodies[0]["omega_world"][k]) * radii[0] + abs(bodies[1]["omega_world"][k]) * radii[1] for k in range(3)]
amplitude = (math.sqrt(sum(v * v for v in rel)) + math.sqrt(sum(s * s for s in spin))) / math.sqrt(min(kn, kt) / meff)
overlap = 3000.0 * amplitude
if overlap > 0.01 * min(radii):
    decline("the preload's overlap %s would be more than 1 %% of a radius" % g(overlap))
force = kn * overlap
shift = [0.5 * overlap, -0.5 * overlap]  # body 0 moves +x, body 1 -x into the overlap

lines = ["units si", "atom_style sphere", "atom_modify map array", "boundary s s s", "comm_modify vel yes",
         "region box block -2 2 -2 2 -2 2", "create_box 1 box", "neighbor %s nsq" % g(0.5 * min(radii)),
         "neigh_modify every 1 delay 0 check no"]
for i, b in enumerate(bodies):
    x = [b["position"][0] + shift[i], b["position"][1], b["position"][2]]
    r = radii[i]
    lines += ["create_atoms 1 single %s %s %s units box" % tuple(map(g, x)),
              "set atom %d diameter %s density %s" % (i + 1, g(2 * r), g(b["mass"] / (4.0 / 3.0 * math.pi * r ** 3))),
              "set atom %d vx %s vy %s vz %s" % ((i + 1,) + tuple(map(g, b["velocity"]))),
              "set atom %d omega %s %s %s" % ((i + 1,) + tuple(map(g, b["omega_world"]))),
              "group b%d id %d" % (i, i + 1)]
lines += ["pair_style gran/hooke/history %s %s %s %s 10000 1" % (g(kn), g(kt), g(cn / meff), g(ct / meff)),
          "pair_coeff * *",
          # The pull along the line of the centres, as the contact's push: constant x would buckle the pair.
          "variable dx equal x[2]-x[1]", "variable dy equal y[2]-y[1]", "variable dz equal z[2]-z[1]",
          "variable pull equal %s/sqrt(v_dx*v_dx+v_dy*v_dy+v_dz*v_dz)" % g(force)]
lines += ["variable f%s%d equal %sv_pull*v_d%s" % (c, i, "" if i == 0 else "-", c) for i in range(2) for c in "xyz"]
lines += ["fix press0 b0 addforce v_fx0 v_fy0 v_fz0", "fix press1 b1 addforce v_fx1 v_fy1 v_fz1",
          "fix step all nve/sphere",
          "timestep %s" % g(dt),
          "thermo %d" % max(steps, 1),
          "dump states all custom 1 dump.states id x y z vx vy vz omegax omegay omegaz tqx tqy tqz",
          "dump_modify states sort id format float %.17g",
          "run %d" % steps]
run_lmp(lines)


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
