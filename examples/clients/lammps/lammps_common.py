"""What the LAMMPS adapters share (docs/clients.md): rotations, a scene's torque at an orientation
(also for the callback lammps_asphere.py hands LAMMPS), running `lmp` (or `liggghts`) and reading its dump.
Python 3 stdlib only."""
import subprocess
import sys


def rot(q):  # body -> world rotation matrix of a unit quaternion (w, x, y, z)
    w, x, y, z = q
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]


def matvec(m, v):
    return [sum(m[i][j] * v[j] for j in range(3)) for i in range(3)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def torque_of(q, law):  # the scene's torque (scene.json's "torque") at orientation q, world frame
    if law["law"] == "dipole":
        return cross(matvec(rot(q), law["dipole_body"]), law["field_world"])
    if law["law"] == "body_constant":
        return matvec(rot(q), law["torque_body"])
    return [0.0, 0.0, 0.0]


def run_lmp(lines, code="lammps"):  # writes the input script and runs lmp (or LIGGGHTS) on it; on failure exits with its last words
    open("in.rotbench", "w").write("\n".join(lines) + "\n")
    program = ["lmp", "-nocite"] if code == "lammps" else ["liggghts", "-echo", "none"]
    # Line-buffered: an MPI abort would otherwise lose the error line still in the buffer.
    lammps = subprocess.run(["stdbuf", "-oL"] + program + ["-in", "in.rotbench", "-log", "none"], stderr=subprocess.PIPE,
                            stdout=subprocess.PIPE, text=True, errors="replace")
    if lammps.returncode != 0:
        said = [line.strip() for line in (lammps.stdout + lammps.stderr).splitlines() if line.strip()]
        errors = [line for line in said if line.startswith("ERROR")]
        sys.exit("%s exited with status %d: %s" % (program[0], lammps.returncode, " | ".join(errors[-1:] or said[-3:]) or "nothing said"))


def dump_frames(path, atoms):  # (step, one list of numbers per atom) for each frame of a custom dump
    with open(path) as dump:
        step = None
        for line in dump:
            if line.startswith("ITEM: TIMESTEP"):
                step = int(next(dump))
            elif line.startswith("ITEM: ATOMS"):
                yield step, [list(map(float, next(dump).split())) for _ in range(atoms)]
