#!/usr/bin/env python3
"""rotbench client adapter for Kratos DEM's rotational schemes (docs/clients.md).

usage: kratos_dem.py ROTATIONAL TRANSLATIONAL scene.json trajectory.csv|samples.csv
  ROTATIONAL     Kratos's RotationalIntegrationScheme: Direct_Integration, Runge_Kutta or
                 Quaternion_Integration
  TRANSLATIONAL  its TranslationalIntegrationScheme: Velocity_Verlet (the seed's, run by Kratos's
                 IterativeSolverStrategy) or Symplectic_Euler (Kratos's default, run by the
                 ExplicitSolverStrategy)

The body is one Cluster3D (a cluster of six spheres at +-1 m on its principal axes) whose cluster
file gives the scene's principal moments per unit mass and a volume of 1 m^3, so the density is the
mass. Kratos reads the model part files written here, and DEM_analysis_stage runs the steps as
shipped. Torques reach the cluster as Kratos sums them, through the central node's
EXTERNAL_APPLIED_MOMENT, set from the orientation q_n before step n -> n+1 (docs/clients.md says
at which time level each scheme's own force evaluation sits). Every state is read at the end of
its step: orientation and world angular velocity of the same step. Runs in the interpreter that
has the KratosMultiphysics and KratosDEMApplication wheels (client files name the project's
venv); nothing is written outside the current directory.
"""
import json
import math
import os
import sys

ROTATIONAL = ("Direct_Integration", "Runge_Kutta", "Quaternion_Integration")
TRANSLATIONAL = ("Velocity_Verlet", "Symplectic_Euler")

rotational, translational, spec_path, out_path = sys.argv[1:5]
if rotational not in ROTATIONAL or translational not in TRANSLATIONAL:
    sys.exit("kratos_dem.py: unknown scheme pair %s / %s" % (rotational, translational))
# One thread: a single body has nothing to share, OpenMP threads spinning on a busy machine slow a
# step many times over (docs/clients.md), and a silo is timed per core.
os.environ["OMP_NUM_THREADS"] = "1"
spec = json.load(open(spec_path))
if spec["format"].startswith("rotbench-granular-scene"):  # a whole granular scene: its own module
    sys.dont_write_bytecode = True  # no __pycache__ beside the adapter: nothing left outside the scratch folder
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    from kratos_granular import run  # noqa: E402
    run(spec_path, out_path, rotational, translational)  # leaves the process itself (os._exit)
law = spec["torque"]
if law["law"] not in ("none", "body_constant", "dipole"):
    sys.exit("kratos_dem.py: no torque law '%s' here" % law["law"])

import KratosMultiphysics as KM  # noqa: E402  (after the argument checks: the import prints a banner)
from KratosMultiphysics.DEMApplication.DEM_analysis_stage import DEMAnalysisStage  # noqa: E402

KM.Logger.GetDefaultOutput().SetSeverity(KM.Logger.Severity.WARNING)


def rotate(q, v):  # body -> world, q = (w, x, y, z)
    w, x, y, z = q
    t = (2 * (y * v[2] - z * v[1]), 2 * (z * v[0] - x * v[2]), 2 * (x * v[1] - y * v[0]))
    return [v[0] + w * t[0] + y * t[2] - z * t[1],
            v[1] + w * t[1] + z * t[0] - x * t[2],
            v[2] + w * t[2] + x * t[1] - y * t[0]]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def torque(q):  # world frame, from the scene's law at orientation q
    if law["law"] == "none":
        return [0.0, 0.0, 0.0]
    if law["law"] == "body_constant":
        return rotate(q, law["torque_body"])
    return cross(rotate(q, law["dipole_body"]), law["field_world"])


def vec(v):
    return "[3] (%r, %r, %r)" % tuple(float(c) for c in v)


dt, steps, q0 = spec["dt"], spec["steps"], spec["q0"]
norm = math.sqrt(sum(c * c for c in q0))
q0 = [c / norm for c in q0]
size = 2.2  # the cluster's extent (m): spheres of radius 0.1 at +-1 m
inertia_per_mass = [i / spec["mass"] for i in spec["inertia_body"]]

with open("body.clu", "w") as f:
    f.write("Name\nbody\n\nBegin centers_and_radii\n")
    for sign in (1.0, -1.0):
        for axis in range(3):
            c = [0.0, 0.0, 0.0]
            c[axis] = sign
            f.write("%r %r %r 0.1\n" % tuple(c))
    f.write("End centers_and_radii\n\nParticle_center_and_diameter\n0.0 0.0 0.0 %r\n\n" % size)
    f.write("Size\n%r\n\nVolume\n1.0\n\nInertia per unit mass\n%r\n%r\n%r\n" % (size, *inertia_per_mass))

empty = "Begin ModelPartData\nEnd ModelPartData\n\nBegin Properties %d\nEnd Properties\n"
with open("bodyDEM.mdpa", "w") as f:
    f.write(empty % 1)
with open("bodyDEM_FEM_boundary.mdpa", "w") as f:
    f.write(empty % 2)
with open("bodyDEM_Clusters.mdpa", "w") as f:  # ORIENTATION is written x, y, z, w
    f.write(empty % 1 + "\nBegin Nodes\n1 0.0 0.0 0.0\nEnd Nodes\n\nBegin Elements Cluster3D\n1 1 1\nEnd Elements\n")
    f.write("\nBegin NodalData CHARACTERISTIC_LENGTH\n1 0 %r\nEnd NodalData\n" % size)
    f.write("\nBegin NodalData ORIENTATION\n1 0 [4] (%r, %r, %r, %r)\nEnd NodalData\n" % (q0[1], q0[2], q0[3], q0[0]))
    f.write("\nBegin NodalData ANGULAR_VELOCITY\n1 0 %s\nEnd NodalData\n" % vec(spec["omega0_world"]))
    f.write("\nBegin NodalData EXTERNAL_APPLIED_MOMENT\n1 0 %s\nEnd NodalData\n" % vec(torque(q0)))

material = {
    "materials": [{"material_name": "body", "material_id": 1, "Variables": {
        "PARTICLE_DENSITY": spec["mass"], "YOUNG_MODULUS": 1e7, "POISSON_RATIO": 0.25,
        "CLUSTER_FILE_NAME": "body.clu", "BREAKABLE_CLUSTER": False, "PARTICLE_MATERIAL": 1}}],
    "material_relations": [{"material_names_list": ["body", "body"], "material_ids_list": [1, 1], "Variables": {
        "DEM_DISCONTINUUM_CONSTITUTIVE_LAW_NAME": "DEM_D_Hertz_viscous_Coulomb", "PARTICLE_COHESION": 0.0,
        "STATIC_FRICTION": 0.5, "DYNAMIC_FRICTION": 0.5, "FRICTION_DECAY": 500, "COEFFICIENT_OF_RESTITUTION": 0.5,
        "ROLLING_FRICTION": 0.0, "ROLLING_FRICTION_WITH_WALLS": 0.0}}],
    "material_assignation_table": [["ClusterPart", "body"]]}
with open("MaterialsDEM.json", "w") as f:
    json.dump(material, f)

never = 1e30  # no search, no output: one body, no contact
parameters = {
    "problem_name": "body", "Dimension": 3, "dem_inlet_option": False, "BoundingBoxOption": False,
    "GravityX": 0.0, "GravityY": 0.0, "GravityZ": 0.0, "RotationOption": True,
    "solver_settings": {"strategy": "sphere_strategy",
                        "material_import_settings": {"materials_filename": "MaterialsDEM.json"}},
    "ElementType": "SphericPartDEMElement3D",
    "TranslationalIntegrationScheme": translational, "RotationalIntegrationScheme": rotational,
    "MaxTimeStep": dt, "FinalTime": spec["t_end"], "NeighbourSearchFrequency": 1 << 30,
    "GraphExportFreq": never, "VelTrapGraphExportFreq": never, "OutputTimeStep": never,
    "do_print_results_option": False}

stage = DEMAnalysisStage(KM.Model(), KM.Parameters(json.dumps(parameters)))
stage.Initialize()
node = next(iter(stage.cluster_model_part.Nodes))


def state():
    q = node.GetSolutionStepValue(KM.ORIENTATION)
    return [q.W, q.X, q.Y, q.Z], list(node.GetSolutionStepValue(KM.ANGULAR_VELOCITY))


with open(out_path, "w") as out:
    out.write(spec["columns"] + "\n")
    for k in range(steps + 1):
        q, w = state()
        out.write(",".join(repr(float(v)) for v in [k * dt] + q + w) + "\n")
        if k == steps:
            break
        node.SetSolutionStepValue(KM.EXTERNAL_APPLIED_MOMENT, KM.Array3(torque(q)))
        stage.time = stage._AdvanceTime()
        stage.InitializeSolutionStep()
        stage._GetSolver().SolveSolutionStep()
        stage.FinalizeSolutionStep()
stage.Finalize()
