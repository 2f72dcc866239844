#!/usr/bin/env python3
"""rotbench client adapter for Yade's NewtonIntegrator (docs/clients.md).

usage: yade_newton.py exact|spherical scene.json trajectory.csv
  exact      NewtonIntegrator(exactAsphericalRot=True): the aspherical leapfrog on the world
             angular momentum L, which Yade keeps at half steps;
  spherical  exactAsphericalRot=False: the angular velocity stepped with T / I' componentwise, as
             for a sphere (no precession: a known-defective rotation for an aspherical body).

The body is one aspherical sphere whose mass, principal moments and orientation are set as they
are; a dipole torque is added every step from its law by a PyRunner before the integrator. The
leapfrog's half-step values are put at whole steps: Yade starts from L(-dt/2) = L0 - dt/2 T(q0)
(from w(-dt/2) for `spherical`), and each row takes L(t) = L(t - dt/2) + dt/2 T(q(t)). Python 3
stdlib only; the Yade script and its output stay in the current directory.
"""
import json
import sys

sys.dont_write_bytecode = True  # nothing left beside the adapter
from yade_common import NAME_TMP, run_yade

mode, spec_path, out_path = sys.argv[1], sys.argv[2], sys.argv[3]
spec = json.load(open(spec_path))
if spec["torque"]["law"] not in ("none", "body_constant", "dipole"):
    sys.exit("yade_newton.py: Yade cannot take the torque law '%s' here" % spec["torque"]["law"])

script = NAME_TMP + r'''
import json
spec = json.load(open(%(spec)r))
exact = %(exact)r
dt, inertia, law = spec["dt"], spec["inertia_body"], spec["torque"]


def R(q):  # body -> world, from Yade's quaternion
    return q.toRotationMatrix()


def torque(q):
    if law["law"] == "none":
        return Vector3(0, 0, 0)
    if law["law"] == "body_constant":
        return R(q) * Vector3(*law["torque_body"])
    return (R(q) * Vector3(*law["dipole_body"])).cross(Vector3(*law["field_world"]))


def omega_world(q, L):  # w = R I'^-1 R^T L
    m = R(q)
    lb = m.transpose() * L
    return m * Vector3(lb[0] / inertia[0], lb[1] / inertia[1], lb[2] / inertia[2])


b = utils.sphere((0, 0, 0), 1.0)
O.bodies.append(b)
b.aspherical = True
s = b.state
s.mass = spec["mass"]
s.inertia = Vector3(*inertia)
s.ori = Quaternion(*spec["q0"])
T0 = torque(s.ori)
if exact:
    s.angMom = Vector3(*spec["L0_world"]) - 0.5 * dt * T0
else:
    s.angVel = Vector3(*spec["omega0_world"]) - 0.5 * dt * Vector3(*[T0[i] / inertia[i] for i in range(3)])
out = open(%(out)r, "w")
out.write(spec["columns"] + "\n")


def row(step):
    q, T = s.ori, torque(s.ori)
    if exact:
        w = omega_world(q, s.angMom + 0.5 * dt * T)
    else:
        w = s.angVel + 0.5 * dt * Vector3(*[T[i] / inertia[i] for i in range(3)])
    out.write(",".join(repr(float(v)) for v in (step * dt, q[3], q[0], q[1], q[2], w[0], w[1], w[2])) + "\n")


def apply_torque():
    O.forces.addT(0, torque(s.ori))


row(0)
O.engines = [ForceResetter(), PyRunner(command="apply_torque()", iterPeriod=1, initRun=True),
             NewtonIntegrator(gravity=(0, 0, 0), damping=0, exactAsphericalRot=exact),
             PyRunner(command="row(O.iter + 1)", iterPeriod=1, initRun=True)]
O.dt = dt
O.run(spec["steps"], True)
out.close()
''' % {"spec": spec_path, "exact": mode == "exact", "out": out_path}
run_yade(script)
