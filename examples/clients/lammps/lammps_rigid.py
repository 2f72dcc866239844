#!/usr/bin/env python3
"""rotbench client adapter for LAMMPS's rigid-body integrators (docs/clients.md).

usage: lammps_rigid.py STYLE scene.json trajectory.csv
STYLE: rigid, rigid/small (Richardson iteration), rigid/nve, rigid/nve/small (NO_SQUISH)

The body is six massless-looking marker atoms at +-a along its principal axes (their centroid is
the centre of mass) whose mass, inertia tensor and angular momentum are given to LAMMPS through
the fix's `infile`, so any principal moments in any order and any q0 are taken as they are. A
dipole torque T = (R mu') x B is a pair of opposite charges on the body in a uniform field
(fix efield), exact for a uniform field; a torque fixed in the body is three force couples on the
marker pairs whose directions are read from the markers each step (fix addforce with variables). Positions and velocities are dumped at every step with
17 significant digits; the orientation's columns are read from the marker pairs and the world
angular velocity from their relative velocities: w = 1/2 sum_k c_k x u_k. Python 3 stdlib only;
everything is written in the current directory (rotbench's scratch directory).
"""
import json
import math
import sys

sys.dont_write_bytecode = True  # nothing left beside the adapter
from lammps_common import cross, dump_frames, matvec, rot, run_lmp

style, spec_path, out_path = sys.argv[1], sys.argv[2], sys.argv[3]
spec = json.load(open(spec_path))
A = 1.0  # marker distance (m): round-off of the read-back orientation is eps relative to it


def quat(m):  # rotation matrix -> unit quaternion, w first (Shepperd's method)
    t = m[0][0] + m[1][1] + m[2][2]
    if t > 0:
        s = 2 * math.sqrt(1 + t)
        return [s / 4, (m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s]
    i = max(range(3), key=lambda k: m[k][k])
    j, k = (i + 1) % 3, (i + 2) % 3
    s = 2 * math.sqrt(1 + m[i][i] - m[j][j] - m[k][k])
    q = [0.0] * 4
    q[0] = (m[k][j] - m[j][k]) / s
    q[1 + i] = s / 4
    q[1 + j] = (m[j][i] + m[i][j]) / s
    q[1 + k] = (m[k][i] + m[i][k]) / s
    return q


R0 = rot(spec["q0"])
inertia = spec["inertia_body"]
# The space-frame inertia tensor R0 diag(I') R0^T, as fix rigid's infile wants it.
I = [[sum(R0[i][k] * inertia[k] * R0[j][k] for k in range(3)) for j in range(3)] for i in range(3)]
L0 = spec["L0_world"]
atoms = []  # (x, y, z, charge)
for k in range(3):
    axis = [R0[i][k] for i in range(3)]
    atoms += [([A * c for c in axis], 0.0), ([-A * c for c in axis], 0.0)]
torque = spec["torque"]
field = [0.0, 0.0, 0.0]
couples = []  # (atom id, force variable names): a torque fixed in the body as couples on the marker pairs
if torque["law"] == "body_constant":
    # Pair j carries +-tau'_k / (2 A) c_l, with (j, l, k) cyclic: its torque 2 A c_j x f c_l is tau'_k c_k.
    # c_l = (x[2l-1] - x[2l]) / (2 A) is read from the markers as LAMMPS moves them.
    tau = torque["torque_body"]
    for j, l, k in ((1, 2, 3), (2, 3, 1), (3, 1, 2)):
        for sign, atom in ((1, 2 * j - 1), (-1, 2 * j)):
            names = []
            for axis in "xyz":
                name = "f%d%s" % (atom, axis)
                names.append(name)
                couples.append("variable %s equal %s*(%s[%d]-%s[%d])" % (
                    name, "%.17g" % (sign * tau[k - 1] / (4 * A * A)), axis, 2 * l - 1, axis, 2 * l))
            couples.append("group a%d id %d" % (atom, atom))
            couples.append("fix couple%d a%d addforce v_%s v_%s v_%s" % ((atom, atom) + tuple(names)))
elif torque["law"] == "dipole":
    mu = matvec(R0, torque["dipole_body"])
    size = math.sqrt(sum(c * c for c in mu))
    if size > 0:  # +-q at +-A/2 along mu: q A = |mu|
        atoms += [([0.5 * A * c / size for c in mu], size / A), ([-0.5 * A * c / size for c in mu], -size / A)]
    field = torque["field_world"]
elif torque["law"] != "none":
    sys.exit("lammps_rigid.py: no LAMMPS fix here for the torque law '%s'" % torque["law"])

g = lambda v: "%.17g" % v
with open("body.rigid", "w") as f:
    f.write("1\n1 %s 0 0 0 %s %s %s %s %s %s 0 0 0 %s %s %s 0 0 0\n" % (
        g(spec["mass"]), g(I[0][0]), g(I[1][1]), g(I[2][2]), g(I[0][1]), g(I[0][2]), g(I[1][2]), g(L0[0]), g(L0[1]), g(L0[2])))
bodystyle = "molecule" if style.endswith("small") else "single"
lines = ["units si", "atom_style full", "boundary f f f", "region box block -10 10 -10 10 -10 10",
         "create_box 1 box", "mass 1 %s" % g(spec["mass"] / len(atoms))]
lines += ["create_atoms 1 single %s %s %s" % tuple(g(c) for c in x) for x, _ in atoms]
lines += ["set atom %d charge %s" % (n + 1, g(q)) for n, (_, q) in enumerate(atoms)]
lines += ["set atom * mol 1", "pair_style zero 1.0", "pair_coeff * *", "neigh_modify exclude molecule/intra all",
          "comm_modify cutoff %s" % g(4 * A)]  # rigid/small wants the whole body within the ghost cutoff
# Every force fix before the rigid fix: one defined after it is missing from the torque the rigid
# fix sums at set-up, and the whole run is then first order (docs/clients.md).
if any(field):
    lines.append("fix field all efield %s %s %s" % tuple(g(c) for c in field))
lines += couples
lines.append("fix body all %s %s infile body.rigid" % (style, bodystyle))
lines += ["timestep %s" % g(spec["dt"]), "thermo 0",
          "dump d all custom 1 markers.dump id x y z vx vy vz",
          'dump_modify d sort id format float %.17g', "run %d" % spec["steps"]]
run_lmp(lines)

with open(out_path, "w") as out:
    out.write(spec["columns"] + "\n")
    for step, atom_rows in dump_frames("markers.dump", len(atoms)):
        rows = [r[1:] for r in atom_rows]  # without the id
        cols = [[(rows[2 * k][i] - rows[2 * k + 1][i]) / (2 * A) for i in range(3)] for k in range(3)]
        rel = [[(rows[2 * k][3 + i] - rows[2 * k + 1][3 + i]) / (2 * A) for i in range(3)] for k in range(3)]
        w = [0.5 * sum(cross(cols[k], rel[k])[i] for k in range(3)) for i in range(3)]
        m = [[cols[j][i] for j in range(3)] for i in range(3)]
        out.write(",".join(repr(v) for v in [step * spec["dt"]] + quat(m) + w) + "\n")
