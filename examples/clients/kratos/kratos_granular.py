"""Kratos DEM runs a granular scene of rotbench's (docs/clients.md, "The silo in Kratos DEM").

kratos_dem.py hands a granular spec here, with the rotational and translational schemes of its
client file. Written from the spec, nothing by hand:
- each shape a cluster file: rotbench's spheres in the principal frame, its moments per unit mass,
  and the volume that gives its mass at the spec's density (Kratos takes the mass as density x volume);
- the stones on a lattice in the spec's packing box (widened upwards when the box holds too few
  sites), each with a shape drawn with equal odds and a uniformly random orientation, from a
  generator seeded with the packing's seed: Kratos's own packing of the same box, not rotbench's;
- the contact law DEM_D_Hertz_viscous_Coulomb (Hertz, damping from the restitution coefficient,
  Coulomb friction) between stones and with every wall, one wall material per wall friction;
- every face of every wall stage as a RigidFace3D4N; a face absent from the current stage is moved
  10 m below the domain, and put back when its stage begins (the silo's shutter, the orifice's rim);
- stones that leave the domain are deleted by Kratos's bounding box.
At each sample step every stone's central node gives its row: position, ORIENTATION, VELOCITY and
the world ANGULAR_VELOCITY, at the end of that step.
"""
import json
import math
import os
import random
import sys

AWAY = 10.0  # m below the domain for a face outside its stage


def g(v):
    return repr(float(v))


def reach(shape):  # the largest distance of the shape's surface from its centre of mass (m)
    return max(math.sqrt(sum(c * c for c in s[:3])) + s[3] for s in shape["spheres"])


def random_quaternion(rng):  # uniform on the unit sphere of quaternions (Shoemake), w first
    u1, u2, u3 = rng.random(), rng.random(), rng.random()
    a, b = math.sqrt(1 - u1), math.sqrt(u1)
    return [b * math.cos(2 * math.pi * u3), a * math.sin(2 * math.pi * u2), a * math.cos(2 * math.pi * u2),
            b * math.sin(2 * math.pi * u3)]


def packing(spec):  # [(shape, position, q)] on a lattice of the largest shape's bounding diameter
    stones, shapes = spec["stones"], spec["shapes"]
    rng = random.Random(stones["seed"])
    largest = max(reach(sh) for sh in shapes)
    lo, hi = stones["box"]
    pitch = 2.0 * largest * 1.01
    counts = [max(1, int((hi[i] - lo[i] - 2 * largest) / pitch) + 1) for i in range(3)]
    while counts[0] * counts[1] * counts[2] < stones["count"]:
        counts[2] += 1  # upwards: the walls stand 1 m above the box (the domain's spare)
    sites = [[lo[0] + largest + i * pitch, lo[1] + largest + j * pitch, lo[2] + largest + k * pitch]
             for k in range(counts[2]) for j in range(counts[1]) for i in range(counts[0])]
    rng.shuffle(sites)
    sites = sorted(sites[:stones["count"]], key=lambda p: (p[2], p[1], p[0]))
    return [(rng.randrange(len(shapes)), p, random_quaternion(rng)) for p in sites]


def write_model(spec, rotational, translational):
    m, shapes, stages = spec["material"], spec["shapes"], spec["walls"]
    stones = packing(spec)
    for k, sh in enumerate(shapes):
        extent = 2 * reach(sh)
        with open("shape%d.clu" % k, "w") as f:
            f.write("Name\nshape%d\n\nBegin centers_and_radii\n" % k)
            for s in sh["spheres"]:
                f.write("%s %s %s %s\n" % tuple(g(c) for c in s))
            f.write("End centers_and_radii\n\nParticle_center_and_diameter\n0.0 0.0 0.0 %s\n\n" % g(extent))
            f.write("Size\n%s\n\nVolume\n%s\n\nInertia per unit mass\n" % (g(extent), g(sh["mass"] / m["density"])))
            f.write("".join("%s\n" % g(i / sh["mass"]) for i in sh["inertia_body"]))
    empty = "Begin ModelPartData\nEnd ModelPartData\n\n"
    with open("siloDEM.mdpa", "w") as f:
        f.write(empty + "Begin Properties 1\nEnd Properties\n")
    with open("siloDEM_Clusters.mdpa", "w") as f:  # ORIENTATION is written x, y, z, w
        f.write(empty + "".join("Begin Properties %d\nEnd Properties\n" % (k + 1) for k in range(len(shapes))))
        f.write("\nBegin Nodes\n" + "".join("%d %s %s %s\n" % (n + 1, *map(g, p)) for n, (_, p, _) in enumerate(stones)))
        f.write("End Nodes\n\nBegin Elements Cluster3D\n")
        f.write("".join("%d %d %d\n" % (n + 1, k + 1, n + 1) for n, (k, _, _) in enumerate(stones)) + "End Elements\n")
        f.write("\nBegin NodalData CHARACTERISTIC_LENGTH\n")
        for n, (k, _, _) in enumerate(stones):
            f.write("%d 0 %s\n" % (n + 1, g(2 * reach(shapes[k]))))  # the cluster file's Size: scale 1
        f.write("End NodalData\n\nBegin NodalData ORIENTATION\n")
        f.write("".join("%d 0 [4] (%s, %s, %s, %s)\n" % (n + 1, g(q[1]), g(q[2]), g(q[3]), g(q[0]))
                        for n, (_, _, q) in enumerate(stones)) + "End NodalData\n")
        for k in range(len(shapes)):
            members = [n + 1 for n, (kk, _, _) in enumerate(stones) if kk == k]
            ids = "".join("%d\n" % i for i in members)
            f.write("\nBegin SubModelPart shape%d\nBegin SubModelPartNodes\n%sEnd SubModelPartNodes\n"
                    "Begin SubModelPartElements\n%sEnd SubModelPartElements\nEnd SubModelPart\n" % (k, ids, ids))
    # Every face of every stage, once; a wall material per friction coefficient.
    faces, frictions = [], []
    for stage in stages:
        for face in stage["faces"]:
            key = json.dumps(face, sort_keys=True)
            if key not in (json.dumps(x, sort_keys=True) for x in faces):
                faces.append(face)
            if face["friction"] not in frictions:
                frictions.append(face["friction"])
    with open("siloDEM_FEM_boundary.mdpa", "w") as f:
        f.write(empty + "".join("Begin Properties %d\nEnd Properties\n" % (100 + j) for j in range(len(frictions))))
        f.write("\nBegin Nodes\n")
        for i, face in enumerate(faces):
            for c, p in enumerate(face["corners"]):
                f.write("%d %s %s %s\n" % (4 * i + c + 1, *map(g, p)))
        f.write("End Nodes\n\nBegin Conditions RigidFace3D4N\n")
        for i, face in enumerate(faces):
            f.write("%d %d %d %d %d %d\n" % (i + 1, 100 + frictions.index(face["friction"]), *(4 * i + c + 1 for c in range(4))))
        f.write("End Conditions\n")
        for j, mu in enumerate(frictions):
            members = [i for i, face in enumerate(faces) if face["friction"] == mu]
            f.write("\nBegin SubModelPart walls%d\nBegin SubModelPartNodes\n%sEnd SubModelPartNodes\n"
                    "Begin SubModelPartConditions\n%sEnd SubModelPartConditions\nEnd SubModelPart\n"
                    % (j, "".join("%d\n" % (4 * i + c + 1) for i in members for c in range(4)),
                       "".join("%d\n" % (i + 1) for i in members)))

    def law(mu):
        return {"DEM_DISCONTINUUM_CONSTITUTIVE_LAW_NAME": "DEM_D_Hertz_viscous_Coulomb", "PARTICLE_COHESION": 0.0,
                "STATIC_FRICTION": mu, "DYNAMIC_FRICTION": mu, "FRICTION_DECAY": 500.0,
                "COEFFICIENT_OF_RESTITUTION": m["restitution"], "ROLLING_FRICTION": 0.0, "ROLLING_FRICTION_WITH_WALLS": 0.0}

    materials = [{"material_name": "stone%d" % k, "material_id": k + 1, "Variables": {
        "PARTICLE_DENSITY": m["density"], "YOUNG_MODULUS": m["young"], "POISSON_RATIO": m["poisson"],
        "CLUSTER_FILE_NAME": "shape%d.clu" % k, "BREAKABLE_CLUSTER": False, "PARTICLE_MATERIAL": 1}} for k in range(len(shapes))]
    materials += [{"material_name": "wall%d" % j, "material_id": 100 + j, "Variables": {
        "YOUNG_MODULUS": m["young"], "POISSON_RATIO": m["poisson"], "COMPUTE_WEAR": False}} for j in range(len(frictions))]
    relations = [{"material_names_list": ["stone%d" % a, "stone%d" % b], "material_ids_list": [a + 1, b + 1],
                  "Variables": law(m["friction"])} for a in range(len(shapes)) for b in range(a, len(shapes))]
    relations += [{"material_names_list": ["stone%d" % a, "wall%d" % j], "material_ids_list": [a + 1, 100 + j],
                   "Variables": law(mu)} for a in range(len(shapes)) for j, mu in enumerate(frictions)]
    table = [["ClusterPart.shape%d" % k, "stone%d" % k] for k in range(len(shapes))]
    table += [["RigidFacePart.walls%d" % j, "wall%d" % j] for j in range(len(frictions))]
    with open("MaterialsDEM.json", "w") as f:
        json.dump({"materials": materials, "material_relations": relations, "material_assignation_table": table}, f)
    lo, hi = spec["domain"]
    smallest = min(s[3] for sh in shapes for s in sh["spheres"])
    parameters = {
        "problem_name": "silo", "Dimension": 3, "dem_inlet_option": False,
        "BoundingBoxOption": True, "BoundingBoxEnlargementFactor": 1.0, "BoundingBoxStartTime": 0.0,
        "BoundingBoxMinX": lo[0], "BoundingBoxMinY": lo[1], "BoundingBoxMinZ": lo[2],
        "BoundingBoxMaxX": hi[0], "BoundingBoxMaxY": hi[1], "BoundingBoxMaxZ": hi[2],
        "GravityX": spec["gravity"][0], "GravityY": spec["gravity"][1], "GravityZ": spec["gravity"][2],
        "RotationOption": True, "RollingFrictionOption": False, "GlobalDamping": 0.0,
        "solver_settings": {"strategy": "sphere_strategy", "RemoveBallsInitiallyTouchingWalls": False,
                            "material_import_settings": {"materials_filename": "MaterialsDEM.json"}},
        "ElementType": "SphericPartDEMElement3D",
        "TranslationalIntegrationScheme": translational, "RotationalIntegrationScheme": rotational,
        "MaxTimeStep": spec["dt"], "FinalTime": spec["t_end"],
        # A search every 10 steps, each reaching a tenth of the smallest sphere's radius further.
        "NeighbourSearchFrequency": 10, "DeltaOption": "Absolute", "SearchTolerance": 0.1 * smallest,
        "search_tolerance_against_walls": 0.1 * smallest,
        "GraphExportFreq": 1e30, "VelTrapGraphExportFreq": 1e30, "OutputTimeStep": 1e30, "do_print_results_option": False}
    return stones, faces, parameters


def run(spec_path, out_path, rotational, translational):
    spec = json.load(open(spec_path))
    if spec["material"]["restitution"] <= 0.0:  # Kratos's Hertz law takes log(e)
        print("kratos_granular.py: Kratos DEM 10.4.4 cannot run a restitution coefficient of 0 (its contact search "
              "fails within the first second of the small silo); compare the codes at "
              "--set silo_discharge.restitution=0.051, as for LIGGGHTS", file=sys.stderr)
        sys.exit(3)  # declined: these parameters are not Kratos's (docs/clients.md)
    stones, faces, parameters = write_model(spec, rotational, translational)
    import KratosMultiphysics as KM
    from KratosMultiphysics.DEMApplication.DEM_analysis_stage import DEMAnalysisStage
    KM.Logger.GetDefaultOutput().SetSeverity(KM.Logger.Severity.WARNING)
    stage = DEMAnalysisStage(KM.Model(), KM.Parameters(json.dumps(parameters)))
    stage.Initialize()

    # Kratos numbers the stones its own way: each is known again by where it starts.
    index = {}
    for element in stage.cluster_model_part.Elements:
        node = element.GetNode(0)
        n = min(range(len(stones)), key=lambda s: sum((a - b) ** 2 for a, b in zip(stones[s][1], (node.X, node.Y, node.Z))))
        index[element.Id] = n
    if sorted(index.values()) != list(range(len(stones))):
        raise SystemExit("kratos_granular.py: Kratos holds %d stones, not the %d written" % (len(index), len(stones)))
    # Each face is known again by its four corners (faces of different stages share corner places).
    key = lambda points: tuple(sorted(tuple(round(c, 12) for c in p) for p in points))
    face_of = {key(face["corners"]): i for i, face in enumerate(faces)}
    face_nodes = {}  # face -> its condition's nodes, in the order of its corners
    for condition in stage.rigid_face_model_part.Conditions:
        nodes = list(condition.GetNodes())
        i = face_of[key([(n.X, n.Y, n.Z) for n in nodes])]
        place = {tuple(round(c, 12) for c in (n.X, n.Y, n.Z)): n for n in nodes}
        face_nodes[i] = [place[tuple(round(c, 12) for c in p)] for p in faces[i]["corners"]]
    if len(face_nodes) != len(faces):
        raise SystemExit("kratos_granular.py: Kratos holds %d wall faces, not the %d written" % (len(face_nodes), len(faces)))
    stage_faces = [{json.dumps(f, sort_keys=True) for f in st["faces"]} for st in spec["walls"]]
    below = spec["domain"][0][2] - AWAY

    def show(s):  # the walls of stage s in place, every other face below the domain
        for i, face in enumerate(faces):
            present = json.dumps(face, sort_keys=True) in stage_faces[s]
            for node, p in zip(face_nodes[i], face["corners"]):
                node.X, node.Y, node.Z = p[0], p[1], p[2] if present else below

    dt, steps, first, stride = spec["dt"], spec["steps"], spec["sample_first"], spec["sample_stride"]
    starts = [int(round(st["from"] / dt)) for st in spec["walls"]]
    current = 0
    show(0)
    lo, hi = spec["domain"]

    def sample(out, k):  # every stone still in the domain, in stone order, at t = k dt
        rows = []
        for element in stage.cluster_model_part.Elements:
            node = element.GetNode(0)
            if not all(lo[i] <= c <= hi[i] for i, c in enumerate((node.X, node.Y, node.Z))):
                continue  # gone from the domain (Kratos's bounding box deletes its spheres)
            q = node.GetSolutionStepValue(KM.ORIENTATION)
            v, w = node.GetSolutionStepValue(KM.VELOCITY), node.GetSolutionStepValue(KM.ANGULAR_VELOCITY)
            n = index[element.Id]
            rows.append((n, [node.X, node.Y, node.Z, q.W, q.X, q.Y, q.Z, v[0], v[1], v[2], w[0], w[1], w[2]]))
        if not rows:  # every stone has left the domain: the time alone
            out.write(g(k * dt) + "\n")
        for n, r in sorted(rows):
            out.write("%s,%d,%d,%s\n" % (g(k * dt), n, stones[n][0], ",".join(g(c) for c in r)))

    with open(out_path, "w") as out:
        out.write(spec["columns"] + "\n")
        if first == 0:
            sample(out, 0)
        for k in range(1, steps + 1):
            if current + 1 < len(starts) and k - 1 >= starts[current + 1]:
                current += 1
                show(current)
            stage.time = stage._AdvanceTime()
            stage.InitializeSolutionStep()
            stage._GetSolver().SolveSolutionStep()
            stage.FinalizeSolutionStep()
            if k >= first and (k - first) % stride == 0:
                sample(out, k)
    stage.Finalize()
    # Kratos 10.4.4 dies of SIGSEGV or a heap check while Python tears down a model with clusters and
    # walls, after Finalize (seen on every run here): leave at once, the samples written and closed.
    sys.stdout.flush()
    os._exit(0)
