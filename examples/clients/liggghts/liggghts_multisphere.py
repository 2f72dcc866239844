#!/usr/bin/env python3
"""rotbench client adapter for LIGGGHTS's `fix multisphere` (docs/clients.md).

usage: liggghts_multisphere.py scene.json trajectory.csv
(a granular scene's spec goes to liggghts_granular.py, which writes samples.csv)

The body is a multisphere template of six small spheres at +-a along its principal axes, given
the scene's mass and its principal inertia tensor (`mass`, `inertia_tensor`, `use_density`: no
Monte Carlo estimate), inserted once with `orientation constant q0` and `omega constant w`.
LIGGGHTS inserts it during step 1, so the dump of step k + 1 holds the state at t = k dt; the
run makes N + 1 steps. A torque fixed in the body or a dipole's is a set of force couples on the
spheres (fix addforce). Positions and velocities of the spheres are dumped with 17 significant
digits, and the orientation's columns and the world angular velocity are read from the pairs, as
for LAMMPS. Python 3 stdlib only; everything stays in the current directory.
"""
import json
import os
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ beside the adapter: nothing left outside the scratch directory
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from liggghts_granular import cross, quat, main as run_granular  # noqa: E402 (this folder's shared half)

spec_path, out_path = sys.argv[1], sys.argv[2]
spec = json.load(open(spec_path))
if spec["format"].startswith("rotbench-granular-scene"):  # a whole granular scene: its own adapter
    run_granular(spec_path, out_path)
    sys.exit(0)
A, r = 1.0, 0.1  # marker distance and sphere radius (m): the spheres never touch
g = lambda v: "%.17g" % v
I = spec["inertia_body"]
spheres = []
for k in range(3):
    for sign in (1, -1):
        p = [0.0, 0.0, 0.0]
        p[k] = sign * A
        spheres += p + [r]


def rot(q):  # body -> world rotation matrix of a unit quaternion (w, x, y, z)
    w, x, y, z = q
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]


# The torque as forces on the six spheres (atom ids 1..6 in template order, pair k at +-A c_k),
# in per-atom variables that fix addforce evaluates each step; `x[n]` reads atom n's position.
# Body torque tau'_k c_k: pair j carries +-tau'_k / (2 A) c_l, (j, l, k) cyclic, c_l read from
# pair l. Dipole (R mu') x B = sum_k mu'_k c_k x B: pair k carries +-mu'_k B / (2 A).
R0 = rot(spec["q0"])
torque = spec["torque"]
force = [[], [], []]  # per world axis, the terms of the per-atom force
if torque["law"] == "body_constant":
    tau = torque["torque_body"]
    for j, l, k in ((1, 2, 3), (2, 3, 1), (3, 1, 2)):
        for sign, atom in ((1, 2 * j - 1), (-1, 2 * j)):
            for i, axis in enumerate("xyz"):
                force[i].append("(id==%d)*%s*(%s[%d]-%s[%d])" % (atom, g(sign * tau[k - 1] / (4 * A * A)), axis, 2 * l - 1, axis, 2 * l))
    tau0 = [sum(R0[i][k] * tau[k] for k in range(3)) for i in range(3)]
elif torque["law"] == "dipole":
    mu, B = torque["dipole_body"], torque["field_world"]
    for k in range(3):
        for sign, atom in ((1, 2 * k + 1), (-1, 2 * k + 2)):
            for i in range(3):
                force[i].append("(id==%d)*%s" % (atom, g(sign * mu[k] * B[i] / (2 * A))))
    tau0 = cross([sum(R0[i][k] * mu[k] for k in range(3)) for i in range(3)], B)
elif torque["law"] == "none":
    tau0 = [0.0, 0.0, 0.0]
else:
    sys.exit("liggghts_multisphere.py: no force here for the torque law '%s'" % torque["law"])
# LIGGGHTS inserts the body during step 1 and ends that step with a half kick: it is inserted with
# L0 - dt/2 tau(q0), so that step 1 ends at (q0, L0) exactly as a step ending at t = 0 would.
L = [spec["L0_world"][i] - 0.5 * spec["dt"] * tau0[i] for i in range(3)]
L_body = [sum(R0[i][k] * L[i] for i in range(3)) for k in range(3)]
omega = [sum(R0[i][k] * L_body[k] / I[k] for k in range(3)) for i in range(3)]
lines = ["atom_style granular", "atom_modify map array", "boundary f f f", "newton off", "communicate single vel yes", "units si",
         "region domain block -10 10 -10 10 -10 10 units box", "create_box 1 domain", "neighbor 0.1 bin", "neigh_modify delay 0",
         "fix m1 all property/global youngsModulus peratomtype 1e7", "fix m2 all property/global poissonsRatio peratomtype 0.3",
         "fix m3 all property/global coefficientRestitution peratomtypepair 1 0.5",
         "fix m4 all property/global coefficientFriction peratomtypepair 1 0.5",
         "pair_style gran model hertz tangential history", "pair_coeff * *", "timestep %s" % g(spec["dt"])]
# The force fix before fix multisphere, as for LAMMPS's fix rigid (docs/clients.md).
if any(force):
    lines += ["variable f%s atom %s" % (axis, "+".join(terms) or "0") for axis, terms in zip("xyz", force)]
    lines.append("fix torque all addforce v_fx v_fy v_fz")
lines += [
         "fix pts all particletemplate/multisphere 15485863 atom_type 1 density constant 1000 nspheres 6 ntry 100000 spheres %s "
         "type 1 mass %s inertia_tensor %s 0 0 %s 0 %s use_density" % (" ".join(g(v) for v in spheres), g(spec["mass"]), g(I[0]), g(I[1]), g(I[2])),
         "fix pdd all particledistribution/discrete 32452843 1 pts 1.0", "fix ms all multisphere",
         "region ins block -1 1 -1 1 -1 1 units box",
         "fix ins all insert/pack seed 32452867 distributiontemplate pdd insert_every once overlapcheck yes orientation constant %s "
         "vel constant 0 0 0 omega constant %s particles_in_region 1 region ins" % (" ".join(g(v) for v in spec["q0"]), " ".join(g(v) for v in omega)),
         "dump d all custom 1 markers.dump id x y z vx vy vz",
         'dump_modify d sort id format "%d %.17g %.17g %.17g %.17g %.17g %.17g"', "thermo 0", "run %d" % (spec["steps"] + 1)]
open("in.rotbench", "w").write("\n".join(lines) + "\n")
# Not `-screen none`: LIGGGHTS 3.8.0 dies of SIGSEGV with it; its screen output is discarded instead.
subprocess.run(["liggghts", "-in", "in.rotbench", "-echo", "none", "-log", "none"], check=True, stdout=subprocess.DEVNULL)


with open("markers.dump") as dump, open(out_path, "w") as out:
    out.write(spec["columns"] + "\n")
    step = None
    for line in dump:
        if line.startswith("ITEM: TIMESTEP"):
            step = int(next(dump))
        elif line.startswith("ITEM: NUMBER OF ATOMS"):
            count = int(next(dump))
        elif line.startswith("ITEM: ATOMS") and count == 6:
            rows = [list(map(float, next(dump).split()[1:])) for _ in range(6)]
            cols = [[(rows[2 * k][i] - rows[2 * k + 1][i]) / (2 * A) for i in range(3)] for k in range(3)]
            rel = [[(rows[2 * k][3 + i] - rows[2 * k + 1][3 + i]) / (2 * A) for i in range(3)] for k in range(3)]
            w = [0.5 * sum(cross(cols[k], rel[k])[i] for k in range(3)) for i in range(3)]
            m = [[cols[j][i] for j in range(3)] for i in range(3)]
            out.write(",".join(repr(v) for v in [(step - 1) * spec["dt"]] + quat(m) + w) + "\n")
