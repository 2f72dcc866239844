#!/usr/bin/env python3
"""rotbench client adapter for a granular scene in LIGGGHTS (docs/clients.md, "Granular scenes").

usage: liggghts_granular.py scene.json samples.csv   (liggghts_multisphere.py hands a granular spec here)

The stones are multisphere templates with rotbench's spheres, mass and principal inertia (`mass`,
`inertia_tensor`, `use_density`: no Monte Carlo estimate; the template frame is the principal
frame, its origin the centre of mass), one template per shape, drawn with equal numbers
(`particledistribution/discrete/numberbased`), inserted at rest with random orientations in the
spec's packing box (`insert/pack`, once, during the first step: LIGGGHTS's step k is taken as
t = k dt). The contact law is `gran model hertz tangential history limitForce on` between stones
and on the walls. The walls are STL meshes of the spec's faces, one atom type per friction
coefficient, under the single wall fix LIGGGHTS allows, which is redefined where the walls change
(the silo's bottom opens). The run is split where the walls change and where sampling starts;
from then on the spheres are dumped every `sample_stride` steps (17 significant digits), and each
stone's state is read from its spheres: its orientation from three of its spheres against the
template, its centre of mass from them, its angular velocity as LIGGGHTS gives every sphere of a
body, its velocity from a sphere's.
Python 3 stdlib only; everything stays in the current directory.
"""
import json
import os
import subprocess
import sys

g = lambda v: "%.17g" % v


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def unit(a):
    n = dot(a, a) ** 0.5
    return [c / n for c in a]


def frame(p0, p1, p2):  # an orthonormal frame from three points, as the columns e1, e2, e3
    e1 = unit(sub(p1, p0))
    v = sub(p2, p0)
    e2 = unit([v[i] - dot(v, e1) * e1[i] for i in range(3)])
    return e1, e2, cross(e1, e2)


def quat(m):  # rotation matrix -> unit quaternion, w first (Shepperd's method)
    t = m[0][0] + m[1][1] + m[2][2]
    if t > 0:
        s = 2 * (1 + t) ** 0.5
        return [s / 4, (m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s]
    i = max(range(3), key=lambda k: m[k][k])
    j, k = (i + 1) % 3, (i + 2) % 3
    s = 2 * (1 + m[i][i] - m[j][j] - m[k][k]) ** 0.5
    q = [0.0] * 4
    q[0] = (m[k][j] - m[j][k]) / s
    q[1 + i] = s / 4
    q[1 + j] = (m[j][i] + m[i][j]) / s
    q[1 + k] = (m[k][i] + m[i][k]) / s
    return q


def stl(name, faces):  # an ASCII STL of the rectangles, two triangles each
    lines = ["solid %s" % name]
    for f in faces:
        c = f["corners"]
        for tri in ((c[0], c[1], c[2]), (c[0], c[2], c[3])):
            lines += ["facet normal %s" % " ".join(g(v) for v in f["normal"]), "outer loop"]
            lines += ["vertex %s" % " ".join(g(v) for v in p) for p in tri]
            lines += ["endloop", "endfacet"]
    lines.append("endsolid %s" % name)
    open(name + ".stl", "w").write("\n".join(lines) + "\n")


def main(spec_path, out_path):
    spec = json.load(open(spec_path))
    m, shapes = spec["material"], spec["shapes"]
    if m["restitution"] <= 0.05:
        print("liggghts_granular.py: LIGGGHTS 3.8.0 refuses a restitution coefficient at or below 0.05 (this run asks %s); "
              "run both codes with --set silo_discharge.restitution=0.051" % g(m["restitution"]), file=sys.stderr)
        sys.exit(3)  # declined: these parameters are not LIGGGHTS's (docs/clients.md)
    frictions = sorted({f["friction"] for stage in spec["walls"] for f in stage["faces"]})
    types = 1 + len(frictions)  # 1: the stones; 2, 3, ...: the walls, by friction
    mu = [[m["friction"]] + frictions] + [[fr] + [0.0] * len(frictions) for fr in frictions]
    dt, steps, (lo, hi) = spec["dt"], spec["steps"], spec["domain"]
    box_lo, box_hi = spec["stones"]["box"]
    gravity = spec["gravity"]
    # LIGGGHTS takes primes above 10000 as seeds: the k-th prime after a number set by the packing's seed.
    def seed(k):
        n = 10007 + 10 ** 5 * (spec["stones"]["seed"] % 10 ** 4) + 1000 * k
        while any(n % d == 0 for d in range(2, int(n ** 0.5) + 1)):
            n += 1
        return n
    lines = ["atom_style granular", "atom_modify map array", "boundary f f f", "newton off", "communicate single vel yes", "units si",
             "region domain block %s units box" % " ".join(g(v) for v in (lo[0], hi[0], lo[1], hi[1], lo[2], hi[2])),
             # Neighbour lists with a skin of half the smallest sphere's radius.
             "create_box %d domain" % types, "neighbor %s bin" % g(0.5 * min(s[3] for sh in shapes for s in sh["spheres"])),
             "neigh_modify delay 0", "thermo_modify lost ignore norm no",
             "fix m1 all property/global youngsModulus peratomtype %s" % " ".join([g(m["young"])] * types),
             "fix m2 all property/global poissonsRatio peratomtype %s" % " ".join([g(m["poisson"])] * types),
             "fix m3 all property/global coefficientRestitution peratomtypepair %d %s" % (types, " ".join([g(m["restitution"])] * types * types)),
             "fix m4 all property/global coefficientFriction peratomtypepair %d %s" % (types, " ".join(g(v) for row in mu for v in row)),
             "pair_style gran model hertz tangential history limitForce on", "pair_coeff * *", "timestep %s" % g(dt),
             "fix gravity all gravity %s vector %s" % (g(dot(gravity, gravity) ** 0.5), " ".join(g(v) for v in unit(gravity)) if any(gravity) else "0 0 -1")]
    for k, sh in enumerate(shapes):
        I = sh["inertia_body"]
        spheres = " ".join(g(v) for s in sh["spheres"] for v in s)
        lines.append("fix t%d all particletemplate/multisphere %d atom_type 1 density constant %s nspheres %d ntry 1000000 spheres %s "
                     "type %d mass %s inertia_tensor %s 0 0 %s 0 %s use_density"
                     % (k + 1, seed(2 * k + 1), g(m["density"]), len(sh["spheres"]), spheres, k + 1, g(sh["mass"]), g(I[0]), g(I[1]), g(I[2])))
    lines += ["fix dist all particledistribution/discrete/numberbased %d %d %s"
              % (seed(101), len(shapes), " ".join("t%d %s" % (k + 1, g(1.0 / len(shapes))) for k in range(len(shapes)))),
              "fix ms all multisphere",
              "region packing block %s units box" % " ".join(g(v) for v in (box_lo[0], box_hi[0], box_lo[1], box_hi[1], box_lo[2], box_hi[2])),
              "fix insert all insert/pack seed %d distributiontemplate dist insert_every once overlapcheck yes all_in yes orientation random "
              "vel constant 0 0 0 omega constant 0 0 0 particles_in_region %d region packing ntry_mc 100000" % (seed(103), spec["stones"]["count"])]

    def walls(stage, n):  # the stage's meshes under the one wall fix
        names = []
        for k, fr in enumerate(frictions):
            faces = [f for f in stage["faces"] if f["friction"] == fr]
            if faces:
                names.append("w%d_%d" % (n, k))
                stl(names[-1], faces)
                lines.append("fix %s all mesh/surface file %s.stl type %d" % (names[-1], names[-1], k + 2))
        lines.append("fix walls all wall/gran model hertz tangential history mesh n_meshes %d meshes %s limitForce on"
                     % (len(names), " ".join(names)))
        return names

    # The run in pieces, split where the walls change and where the samples start.
    stage_steps = [round(stage["from"] / dt) for stage in spec["walls"]]
    first, stride = spec["sample_first"], spec["sample_stride"]
    cuts = sorted({s for s in stage_steps[1:] + [first] if 0 < s < steps} | {steps})
    meshes, done = walls(spec["walls"][0], 0), 0
    dump = ["dump samples all custom %d frame.*.dump id mol type x y z vx vy vz omegax omegay omegaz" % stride,
            'dump_modify samples sort id format "%d %d %d' + " %.17g" * 9 + '"']
    if first == 0:
        lines += dump
    for cut in cuts:
        lines.append("run %d" % (cut - done))
        done = cut
        if cut in stage_steps[1:]:
            lines += ["unfix walls"] + ["unfix %s" % name for name in meshes]
            meshes = walls(spec["walls"][stage_steps.index(cut)], stage_steps.index(cut))
        if cut == first:
            lines += dump
    open("in.silo", "w").write("\n".join(lines) + "\n")
    # Its screen output to a file, line by line: LIGGGHTS 3.8.0 dies of SIGSEGV with `-screen none`,
    # and an error it prints before MPI_Abort is lost from a buffered stream.
    with open("screen.txt", "w") as screen:
        status = subprocess.run(["stdbuf", "-oL", "liggghts", "-in", "in.silo", "-echo", "none", "-log", "none"], stdout=screen).returncode
    said = [line.strip() for line in open("screen.txt", errors="replace") if line.startswith(("ERROR", "Loop time of"))]
    if status != 0:
        sys.exit("liggghts_granular.py: LIGGGHTS exited with status %d: %s" % (status, said[-1] if said else "no error message"))
    for line in said:
        print("liggghts:", line, file=sys.stderr)
    inserted = sum(int(line.split()[5]) for line in open("screen.txt", errors="replace") if line.startswith("INFO: Particle insertion insert: inserted"))
    if inserted != spec["stones"]["count"]:
        sys.exit("liggghts_granular.py: LIGGGHTS inserted %d of the %d stones in the packing box" % (inserted, spec["stones"]["count"]))

    # Each frame: the spheres of each body (fix multisphere numbers the bodies in the atoms'
    # `mol`; a body's atoms have consecutive ids in template order) to stones; a body's shape is
    # told by its number of spheres.
    sizes = [len(sh["spheres"]) for sh in shapes]
    by_size = {n: k for k, n in enumerate(sizes)}
    if len(by_size) != len(sizes):
        sys.exit("liggghts_granular.py: two shapes have as many spheres; their bodies cannot be told apart in the dump")
    stones = {}  # body number -> stone number, in the order of their first appearance
    with open(out_path, "w") as out:
        out.write(spec["columns"] + "\n")
        for step in range(first, steps + 1, stride):
            name = "frame.%d.dump" % step
            if not os.path.exists(name):
                sys.exit("liggghts_granular.py: LIGGGHTS wrote no frame at step %d" % step)
            with open(name) as f:
                text = f.read().split("ITEM: ATOMS")[1].split("\n")[1:]
            bodies = {}
            for a in (r.split() for r in text if r.strip()):
                bodies.setdefault(int(a[1]), []).append(a)
            if not bodies:  # every stone has left the domain: the time alone
                out.write(repr(step * dt) + "\n")
            for body in sorted(bodies):
                atoms = sorted(bodies[body], key=lambda a: int(a[0]))
                n = len(atoms)
                if n not in by_size:
                    sys.exit("liggghts_granular.py: body %d has %d spheres, as no shape has" % (body, n))
                shape = by_size[n]
                rows = [[float(v) for v in a[3:]] for a in atoms]
                x = [r[0:3] for r in rows]
                c = [s[0:3] for s in shapes[shape]["spheres"]]
                k2 = max(range(2, n), key=lambda k: dot(cross(sub(c[1], c[0]), sub(c[k], c[0])), cross(sub(c[1], c[0]), sub(c[k], c[0]))))
                E, e = frame(x[0], x[1], x[k2]), frame(c[0], c[1], c[k2])
                R = [[sum(E[a][r] * e[a][s] for a in range(3)) for s in range(3)] for r in range(3)]
                Rc = [[dot(R[r], ck) for r in range(3)] for ck in c]
                X = [sum(x[k][r] - Rc[k][r] for k in range(n)) / n for r in range(3)]
                miss = max(dot(sub(x[k], [X[r] + Rc[k][r] for r in range(3)]), sub(x[k], [X[r] + Rc[k][r] for r in range(3)])) for k in range(n))
                if miss > 1e-14:
                    sys.exit("liggghts_granular.py: the spheres of body %d are not shape %d as given (off by %.3g m)" % (body, shape, miss ** 0.5))
                w = rows[0][6:9]
                V = sub(rows[0][3:6], cross(w, Rc[0]))
                stone = stones.setdefault(body, len(stones))
                out.write(",".join(repr(v) for v in [step * dt, stone, shape] + X + quat(R) + V + w) + "\n")
            os.remove(name)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
