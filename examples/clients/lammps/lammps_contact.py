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
force here. The scene's contact is bonded and a granular contact only pushes, so the adapter
presses the spheres together: each is pulled toward the other along the line of their centres by
a constant force F0 (fix addforce with variables), from an overlap F0 / Kn, the equilibrium of that
pull and the spring, and writes the positions shifted back by half that overlap each. About that
equilibrium the contact is the scene's as long as it stays closed: F0 is chosen so that the
overlap is 3000 times the perturbation's amplitude, which the energy criterion of a stability
search (growth by 1e6, amplitude by 1e3) does not reach. The pull is central, as the contact's
push is, so the two cancel across the contact too (a pull fixed along x would buckle the pair:
the pair's rotation grew 25-fold in energy per 100 steps of 1e-4 s, measured).

Neither code keeps a sphere's orientation. The adapter composes the rotations the code's own
tangential history integrates, exp(dt w^(n+1/2)) with w^(n+1/2) = w^n + dt/2 T^n / I (fix
nve/sphere's half kick, from the dumped angular velocity and torque), onto each sphere's q0.
A sphere whose moment is not 0.4 m r^2 (the codes'), or a body that is not a sphere, is declined:
exit status 3. Python 3 stdlib only; everything is written in the current directory.
"""
import json
import math
import sys

sys.dont_write_bytecode = True  # nothing left beside the adapter
from lammps_common import dump_frames, run_lmp

code, spec_path, out_path = sys.argv[1], sys.argv[2], sys.argv[3]
if code not in ("lammps", "liggghts"):
    sys.exit("lammps_contact.py: the code is lammps or liggghts, not %r" % code)
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
        decline("the code gives a sphere the moment 0.4 m r^2 = %s, not %s" % (g(0.4 * m * r * r), b["inertia_body"]))
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
