#!/usr/bin/env python3
"""rotbench client adapter for a contact of two spheres in Kratos DEM (docs/clients.md, "Contact scenes").

usage: kratos_contact.py ROTATIONAL TRANSLATIONAL scene.json trajectory.csv
  (the schemes as for kratos_dem.py)

Each sphere is a Cluster3D of one sphere at its centre, so that Kratos integrates its orientation
with the rotational scheme judged on the free bodies; the two touch through Kratos's linear law
DEM_D_Linear_viscous_Coulomb. That law takes no stiffness: it makes Kn = 1.432 pi 0.31225 R E*
(R = r1 r2 / (r1 + r2), E* = E / (2 (1 - nu^2)) for one material) and Kt = 4 G* Kn / E*, which
is Kn when nu = 0; so nu = 0 and E is solved from the scene's k_n (k_t = k_n in every contact
scene; another k_t is declined). Its dashpots are 2 gamma sqrt(meff K), one gamma for both
(c_t = c_n in every contact scene), and gamma is not taken either: Kratos finds it from a
restitution coefficient e by bisection to 1e-4 in gamma (and takes 0 above e = 0.999). The
adapter gives the e that Kratos's own map sends to gamma = c_n / (2 sqrt(meff k_n)), so the
damping is the scene's within that bisection (docs/clients.md gives the error). Coulomb's limit is
1e20 times the normal force.

The pair is bonded by the central preload of ../contact_pair.py, the spheres made larger by half
its overlap at the scene's positions (Kratos's contact point is mid-overlap). The pull is in the
model file too, since Velocity_Verlet's first move takes the forces Kratos computes while it
initialises (without it the pair starts with a kick, which the stability search counts as growth).
Runs in the interpreter with the Kratos wheels (the client file names the project's venv); nothing
is written outside the current directory.
"""
import json
import math
import os
import sys

ROTATIONAL = ("Direct_Integration", "Runge_Kutta", "Quaternion_Integration")
TRANSLATIONAL = ("Velocity_Verlet", "Symplectic_Euler")

rotational, translational, spec_path, out_path = sys.argv[1:5]
if rotational not in ROTATIONAL or translational not in TRANSLATIONAL:
    sys.exit("kratos_contact.py: unknown scheme pair %s / %s" % (rotational, translational))
os.environ["OMP_NUM_THREADS"] = "1"  # two bodies: nothing to share (kratos_dem.py)
sys.dont_write_bytecode = True  # nothing left beside the adapter
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from contact_pair import decline, preload_overlap, sphere_pair  # noqa: E402

spec = json.load(open(spec_path))
g = lambda v: repr(float(v))
bodies, contact, radii, meff = sphere_pair(spec, "the linear law")
dt, steps = spec["dt"], spec["steps"]
kn, kt, cn, ct = (contact[k] for k in ("normal_stiffness", "tangential_stiffness", "normal_damping", "tangential_damping"))
if kt != kn or ct != cn:
    decline("Kratos's linear law with one material has k_t = k_n and c_t = c_n only when nu = 0; the scene has %s, %s"
            % (g(kt), g(ct)))
gamma = cn / (2.0 * math.sqrt(meff * kn))
if gamma > 1.0 / math.sqrt(2.0):
    decline("a damping ratio gamma = %s above 1/sqrt(2), where Kratos's restitution map changes branch" % g(gamma))
# The restitution coefficient whose gamma is the scene's, by Kratos's own map for the linear law
# (sphere_strategy.py, coeff_of_rest_diff); Kratos inverts it by bisection to 1e-4 in gamma.
restitution = 1.0 if gamma == 0 else math.exp(-gamma / math.sqrt(1 - gamma * gamma) * (
    math.pi - math.atan(2 * gamma * math.sqrt(1 - gamma * gamma) / (1 - 2 * gamma * gamma))))
if gamma > 0 and restitution > 0.999:
    decline("a damping ratio gamma = %s: its restitution coefficient %s is above 0.999, which Kratos takes as undamped"
            % (g(gamma), g(restitution)))
overlap = preload_overlap(bodies, contact, radii, meff)
force = kn * overlap
# Kratos puts the contact point in the middle of the overlap: spheres larger by half of it, at the
# scene's own positions, touch at the scene's point, r from each centre (as yade_contact.py does).
radii = [r + 0.5 * overlap for r in radii]
equiv_radius = radii[0] * radii[1] / (radii[0] + radii[1])
young = 2.0 * kn / (1.432 * math.pi * 0.31225 * equiv_radius)  # E* = E / 2 at nu = 0

import KratosMultiphysics as KM  # noqa: E402  (after the checks: the import prints a banner)
from KratosMultiphysics.DEMApplication.DEM_analysis_stage import DEMAnalysisStage  # noqa: E402

KM.Logger.GetDefaultOutput().SetSeverity(KM.Logger.Severity.WARNING)

density = 1000.0  # the clusters' volume carries the mass
empty = "Begin ModelPartData\nEnd ModelPartData\n\n"
for i, b in enumerate(bodies):
    with open("body%d.clu" % i, "w") as f:
        f.write("Name\nbody%d\n\nBegin centers_and_radii\n0.0 0.0 0.0 %s\nEnd centers_and_radii\n\n" % (i, g(radii[i])))
        f.write("Particle_center_and_diameter\n0.0 0.0 0.0 %s\n\nSize\n%s\n\n" % (g(2 * radii[i]), g(2 * radii[i])))
        f.write("Volume\n%s\n\nInertia per unit mass\n%s\n" % (g(b["mass"] / density), "\n".join(g(c / b["mass"]) for c in b["inertia_body"])))
with open("pairDEM.mdpa", "w") as f:
    f.write(empty + "Begin Properties 1\nEnd Properties\n")
with open("pairDEM_FEM_boundary.mdpa", "w") as f:
    f.write(empty + "Begin Properties 100\nEnd Properties\n")
with open("pairDEM_Clusters.mdpa", "w") as f:  # ORIENTATION is written x, y, z, w
    f.write(empty + "Begin Properties 1\nEnd Properties\nBegin Properties 2\nEnd Properties\n\nBegin Nodes\n")
    f.write("".join("%d %s %s %s\n" % (i + 1, *map(g, b["position"])) for i, b in enumerate(bodies)))
    f.write("End Nodes\n\nBegin Elements Cluster3D\n1 1 1\n2 2 2\nEnd Elements\n")
    for name, values in (("CHARACTERISTIC_LENGTH", [[2 * r] for r in radii]),
                         ("ORIENTATION", [b["q0"][1:] + b["q0"][:1] for b in bodies]),
                         ("VELOCITY", [b["velocity"] for b in bodies]),
                         ("ANGULAR_VELOCITY", [b["omega_world"] for b in bodies]),
                         # The pull from the start: Velocity_Verlet's first move takes the forces Kratos
                         # computes while it initialises.
                         ("EXTERNAL_APPLIED_FORCE", [[force, 0.0, 0.0], [-force, 0.0, 0.0]])):
        f.write("\nBegin NodalData %s\n" % name)
        for i, v in enumerate(values):
            f.write("%d 0 %s\n" % (i + 1, g(v[0]) if len(v) == 1 else "[%d] (%s)" % (len(v), ", ".join(map(g, v)))))
        f.write("End NodalData\n")
    for i in range(2):
        f.write("\nBegin SubModelPart body%d\nBegin SubModelPartNodes\n%d\nEnd SubModelPartNodes\n"
                "Begin SubModelPartElements\n%d\nEnd SubModelPartElements\nEnd SubModelPart\n" % (i, i + 1, i + 1))

law = {"DEM_DISCONTINUUM_CONSTITUTIVE_LAW_NAME": "DEM_D_Linear_viscous_Coulomb", "PARTICLE_COHESION": 0.0,
       "STATIC_FRICTION": 1e20, "DYNAMIC_FRICTION": 1e20, "FRICTION_DECAY": 0.0, "COEFFICIENT_OF_RESTITUTION": restitution,
       "ROLLING_FRICTION": 0.0, "ROLLING_FRICTION_WITH_WALLS": 0.0}
materials = [{"material_name": "body%d" % i, "material_id": i + 1, "Variables": {
    "PARTICLE_DENSITY": density, "YOUNG_MODULUS": young, "POISSON_RATIO": 0.0,
    "CLUSTER_FILE_NAME": "body%d.clu" % i, "BREAKABLE_CLUSTER": False, "PARTICLE_MATERIAL": 1}} for i in range(2)]
relations = [{"material_names_list": ["body%d" % a, "body%d" % b], "material_ids_list": [a + 1, b + 1], "Variables": law}
             for a in range(2) for b in range(a, 2)]
with open("MaterialsDEM.json", "w") as f:
    json.dump({"materials": materials, "material_relations": relations,
               "material_assignation_table": [["ClusterPart.body%d" % i, "body%d" % i] for i in range(2)]}, f)

never = 1e30
parameters = {
    "problem_name": "pair", "Dimension": 3, "dem_inlet_option": False, "BoundingBoxOption": False,
    "GravityX": 0.0, "GravityY": 0.0, "GravityZ": 0.0, "RotationOption": True, "RollingFrictionOption": False,
    "GlobalDamping": 0.0,
    "solver_settings": {"strategy": "sphere_strategy", "material_import_settings": {"materials_filename": "MaterialsDEM.json"}},
    "ElementType": "SphericPartDEMElement3D",
    "TranslationalIntegrationScheme": translational, "RotationalIntegrationScheme": rotational,
    "MaxTimeStep": dt, "FinalTime": spec["t_end"], "NeighbourSearchFrequency": 1,
    "DeltaOption": "Absolute", "SearchTolerance": 0.5 * min(radii),
    "GraphExportFreq": never, "VelTrapGraphExportFreq": never, "OutputTimeStep": never, "do_print_results_option": False}

stage = DEMAnalysisStage(KM.Model(), KM.Parameters(json.dumps(parameters)))
stage.Initialize()
nodes = sorted(stage.cluster_model_part.Nodes, key=lambda n: n.X)


def pull(at):  # each centre toward the other, along the line of centres at positions `at`
    d = [at[1][c] - at[0][c] for c in range(3)]
    length = math.sqrt(sum(c * c for c in d))
    f = [force * c / length for c in d]
    nodes[0].SetSolutionStepValue(KM.EXTERNAL_APPLIED_FORCE, KM.Array3(f))
    nodes[1].SetSolutionStepValue(KM.EXTERNAL_APPLIED_FORCE, KM.Array3([-c for c in f]))


history = []  # (positions, velocities) of the last two steps


def where_forces_act(k):
    """The positions at which Kratos evaluates the contact during the coming step. Symplectic_Euler
    takes the forces before it moves, at x_n. Velocity_Verlet moves first, to x_n + dt v_n + dt^2/2
    a_n, with a_n the acceleration of x_n, found from the last step as Verlet makes it:
    a_(n-1) = 2 (x_n - x_(n-1) - dt v_(n-1)) / dt^2, a_n = 2 (v_n - v_(n-1)) / dt - a_(n-1). The pull
    must be taken there too: taken at x_n it lags the contact's push by a step, and a run's energy
    error falls at first order, not second (docs/clients.md)."""
    x = [[n.X, n.Y, n.Z] for n in nodes]
    v = [list(n.GetSolutionStepValue(KM.VELOCITY)) for n in nodes]
    history.append((x, v))
    del history[:-2]
    if translational == "Symplectic_Euler":
        return x
    if k == 0:  # a_0: the preload's equilibrium, but for the dashpots
        return [[x[i][c] + dt * v[i][c] for c in range(3)] for i in range(2)]
    (x0, v0), (x1, v1) = history
    at = []
    for i in range(2):
        a_before = [2.0 * (x1[i][c] - x0[i][c] - dt * v0[i][c]) / (dt * dt) for c in range(3)]
        a_now = [2.0 * (v1[i][c] - v0[i][c]) / dt - a_before[c] for c in range(3)]
        at.append([x1[i][c] + dt * v1[i][c] + 0.5 * dt * dt * a_now[c] for c in range(3)])
    return at


with open(out_path, "w") as out:
    out.write(spec["columns"] + "\n")
    for k in range(steps + 1):
        for i, node in enumerate(nodes):
            q = node.GetSolutionStepValue(KM.ORIENTATION)
            v, w = node.GetSolutionStepValue(KM.VELOCITY), node.GetSolutionStepValue(KM.ANGULAR_VELOCITY)
            row = [k * dt, i, node.X, node.Y, node.Z, v[0], v[1], v[2], q.W, q.X, q.Y, q.Z, w[0], w[1], w[2]]
            out.write(",".join("%d" % c if j == 1 else g(c) for j, c in enumerate(row)) + "\n")
        if k == steps:
            break
        pull(where_forces_act(k))
        stage.time = stage._AdvanceTime()
        stage.InitializeSolutionStep()
        stage._GetSolver().SolveSolutionStep()
        stage.FinalizeSolutionStep()
sys.stdout.flush()
os._exit(0)  # Kratos 10.4.4 may crash tearing down a model with clusters (kratos_granular.py)
