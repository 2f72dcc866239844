#!/usr/bin/env python3
"""rotbench client adapter for a contact of two spheres in Yade (docs/clients.md, "Contact scenes"):
Law2_ScGeom_ViscElPhys_Basic, Yade's linear spring-dashpot, under NewtonIntegrator.

usage: yade_contact.py scene.json trajectory.csv

The spheres are ViscElMat with kn, ks, cn, cs given explicitly; Yade joins two materials' values as
springs in series (1 / (1/a + 1/b)), so each sphere's are twice the scene's. The friction angle is
atan(1e4), far above any tangential force here. The bond is the central preload of
../contact_pair.py (a PyRunner adds the pull every step, before the integrator). Yade puts the
contact point in the middle of the overlap, so each sphere is made larger by half the overlap at
the scene's own position: the contact point is then the scene's touching point, r from each
centre, and the moments are set as given (a sphere shifted into the overlap instead would turn on
a lever r - overlap/2: the tangential frequency 0.07 % low, measured).

Yade's leapfrog keeps velocities at half steps; a PyRunner after the contact law and before the
integrator writes each step's row with the whole-step values v(t) = v(t - dt/2) + dt/2 F(t) / m (and
so for w), and at the first step sets v(-dt/2) = v0 - dt/2 F(0) / m. The orientation is Yade's own.
Python 3 stdlib only; the Yade script and its output stay in the current directory.
"""
import json
import os
import sys

sys.dont_write_bytecode = True  # nothing left beside the adapter
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from contact_pair import preload_overlap, sphere_pair  # noqa: E402
from yade_common import NAME_TMP, run_yade  # noqa: E402

spec_path, out_path = sys.argv[1], sys.argv[2]
spec = json.load(open(spec_path))
bodies, contact, radii, meff = sphere_pair(spec, "a ViscElMat contact here")
overlap = preload_overlap(bodies, contact, radii, meff)

script = NAME_TMP + r'''
import json
import math
spec = json.load(open(%(spec)r))
overlap = %(overlap)r
dt, steps, law = spec["dt"], spec["steps"], spec["contact"]
pull = law["normal_stiffness"] * overlap
ids = []
for i, b in enumerate(spec["bodies"]):
    mat = O.materials.append(ViscElMat(kn=2 * law["normal_stiffness"], ks=2 * law["tangential_stiffness"], cn=2 * law["normal_damping"],
                                       cs=2 * law["tangential_damping"], frictionAngle=math.atan(1e4), density=1000))
    p = b["position"]
    s = utils.sphere(tuple(p), b["shape"]["size"][0] + 0.5 * overlap, material=mat)
    ids.append(O.bodies.append(s))
    s.state.mass = b["mass"]
    s.state.inertia = Vector3(*b["inertia_body"])
    s.state.ori = Quaternion(*b["q0"])
    s.state.vel = Vector3(*b["velocity"])
    s.state.angVel = Vector3(*b["omega_world"])
out = open(%(out)r, "w")
out.write(spec["columns"] + "\n")


def step():
    n = O.iter
    a, b = O.bodies[ids[0]].state, O.bodies[ids[1]].state
    d = b.pos - a.pos
    O.forces.addF(ids[0], pull / d.norm() * d)
    O.forces.addF(ids[1], -pull / d.norm() * d)
    for i, body in enumerate((a, b)):
        f, t = O.forces.f(ids[i]), O.forces.t(ids[i])
        inertia = body.inertia
        if n == 0:  # the leapfrog's start: v(-dt/2), w(-dt/2)
            body.vel = body.vel - 0.5 * dt * f / body.mass
            body.angVel = body.angVel - 0.5 * dt * Vector3(t[0] / inertia[0], t[1] / inertia[1], t[2] / inertia[2])
        v = body.vel + 0.5 * dt * f / body.mass
        w = body.angVel + 0.5 * dt * Vector3(t[0] / inertia[0], t[1] / inertia[1], t[2] / inertia[2])
        q = body.ori
        out.write(",".join(repr(float(c)) for c in [n * dt, i, body.pos[0], body.pos[1], body.pos[2], v[0], v[1], v[2], q[3], q[0], q[1], q[2], w[0], w[1], w[2]]) + "\n")


O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
             InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [Ip2_ViscElMat_ViscElMat_ViscElPhys()], [Law2_ScGeom_ViscElPhys_Basic()]),
             PyRunner(command="step()", iterPeriod=1, initRun=True),
             NewtonIntegrator(gravity=(0, 0, 0), damping=0)]
O.dt = dt
O.run(steps + 1, True)
out.close()
''' % {"spec": spec_path, "overlap": overlap, "out": out_path}
run_yade(script)
