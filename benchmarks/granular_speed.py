#!/usr/bin/env python3
"""rotbench's granular step beside LIGGGHTS's, on one silo: CPU seconds per sphere-step, for the
filling and for the discharge apart (docs/performance.md).

Both codes run the silo rotbench describes (the spec a granular client gets, docs/clients.md):
the same stones, material, walls, dt and duration; LIGGGHTS through the shipped adapter
(examples/clients/liggghts/liggghts_granular.py) with no samples written, rotbench with
`rotbench trajectory` and `richardson` (LIGGGHTS's map). They run at the same time, one process
each on its own core, so that both see the same machine. CPU time is each process's own (user +
system, from wait4). rotbench's filling is a run that stops at the opening, its discharge the
full run less that; LIGGGHTS's run is split at the opening, and its CPU time is shared out
between the pieces as its own loop times are. Packings differ (LIGGGHTS draws its own), so each
code's figure is over its own number of spheres.

The table goes to OUT_DIR/granular_speed.csv, where `rotbench report OUT_DIR` shows it in its cost
section (as benchmarks/cost.py's cost.csv).

With --kratos PYTHON, Kratos DEM (the seed's code, examples/clients/kratos, Quaternion_Integration
under Velocity_Verlet) runs the same silo too, after the other two and alone on the machine: a run
to the opening and a whole run, the discharge being their difference, each its process's CPU time.

Usage: benchmarks/granular_speed.py [--quick] [--t-end S] [--seed N] [--kratos PYTHON] BUILD_DIR OUT_DIR
  --quick   the small silo of examples/small_silo.toml, seconds; the default is
            the silo itself, about 5 CPU-minutes for rotbench and 12 for LIGGGHTS
  --kratos  the interpreter with Kratos's wheels (the project's venv: .venv/bin/python3)
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile
import threading

here = os.path.dirname(os.path.abspath(__file__))
adapter = os.path.join(here, "..", "examples", "clients", "liggghts", "liggghts_granular.py")
kratos_adapter = os.path.join(here, "..", "examples", "clients", "kratos", "kratos_dem.py")


def cpu_of(args, cwd, log=None):  # (CPU seconds of the process, its stderr); exits on failure
    with open(log or os.devnull, "w") as err:
        p = subprocess.Popen(args, cwd=cwd, stdout=subprocess.DEVNULL, stderr=err)
        _, status, usage = os.wait4(p.pid, 0)
    if status != 0:
        sys.exit("granular_speed.py: %s failed (status %d)%s" % (args[0], status, ": see " + log if log else ""))
    return usage.ru_utime + usage.ru_stime


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--t-end", type=float)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--kratos")
    parser.add_argument("build")
    parser.add_argument("out")
    a = parser.parse_args()
    rotbench = os.path.join(os.path.abspath(a.build), "rotbench")
    kratos = os.path.abspath(a.kratos) if a.kratos else None  # its runs start in their own folders
    settings = ["--set", "silo_discharge.restitution=0.051", "--set", "silo_discharge.seed=%d" % a.seed]
    if a.t_end:
        settings += ["--set", "silo_discharge.t_end=%r" % a.t_end]
    quick = ["--config", os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "examples", "small_silo.toml")] if a.quick else []
    with tempfile.TemporaryDirectory(prefix="granular_speed_") as scratch:
        # The spec, from rotbench itself: a client whose program keeps it (its run then fails: no samples).
        spec_path = os.path.join(scratch, "spec.json")
        with open(os.path.join(scratch, "keep.toml"), "w") as f:
            program = ["python3", "-c", "import shutil, sys; shutil.copy(sys.argv[2], sys.argv[1])", spec_path]
            f.write('id = "keep_spec"\nprogram = %s\nscenes = ["silo_discharge"]\nclaims = "richardson"\n' % json.dumps(program))
        subprocess.run([rotbench, "--client", os.path.join(scratch, "keep.toml"), "run", "--schemes", "keep_spec", "--scenes",
                        "silo_discharge", "--dt", "2e-5", "--out", os.path.join(scratch, "spec_run")] + quick + settings,
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        spec = json.load(open(spec_path))
        dt, steps, opening = spec["dt"], spec["steps"], spec["walls"][1]["from"]
        fill_steps = round(opening / dt)
        spec["sample_first"] = steps + spec["sample_stride"]  # no samples: the step alone
        ligg = os.path.join(scratch, "liggghts")
        os.mkdir(ligg)
        json.dump(spec, open(os.path.join(ligg, "scene.json"), "w"))

        result = {}

        def run_liggghts():
            log = os.path.join(scratch, "liggghts.err")
            cpu = cpu_of(["python3", adapter, "scene.json", "samples.csv"], ligg, log)
            loops = [line.split() for line in open(log) if line.startswith("liggghts: Loop time of")]
            wall = [float(w[4]) for w in loops]
            atoms = int(loops[-1][loops[-1].index("atoms,") - 1])
            result["liggghts"] = (cpu * wall[0] / sum(wall), cpu * wall[1] / sum(wall), atoms)

        def run_rotbench():
            trajectory = [rotbench, "trajectory", "--scene", "silo_discharge", "--scheme", "richardson", "--dt", repr(dt), "--samples", "10"]
            for key, values in spec["params"].items():
                if key != "t_end":
                    trajectory += ["--set", "%s=%s" % (key, ",".join(repr(v) for v in values))]
            fill = cpu_of(trajectory + ["--t-end", repr(opening), "--out", os.path.join(scratch, "fill.csv")], scratch)
            whole = cpu_of(trajectory + ["--t-end", repr(spec["t_end"]), "--out", os.path.join(scratch, "whole.csv")], scratch)
            result["rotbench"] = (fill, whole - fill, spec["stones"]["spheres"])

        def run_kratos():
            cpu = []
            for name, n in (("kratos_fill", fill_steps), ("kratos_whole", steps)):
                folder = os.path.join(scratch, name)
                os.mkdir(folder)
                piece = dict(spec, steps=n, t_end=n * dt, sample_first=n + 1)
                json.dump(piece, open(os.path.join(folder, "scene.json"), "w"))
                cpu.append(cpu_of([kratos, kratos_adapter, "Quaternion_Integration", "Velocity_Verlet", "scene.json", "samples.csv"],
                                  folder, os.path.join(scratch, name + ".err")))
            result["kratos"] = (cpu[0], cpu[1] - cpu[0], spec["stones"]["spheres"])

        threads = [threading.Thread(target=run_liggghts), threading.Thread(target=run_rotbench)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        if a.kratos:
            run_kratos()
    rows = []
    for code in ("rotbench", "liggghts") + (("kratos",) if a.kratos else ()):
        if code not in result:
            sys.exit("granular_speed.py: %s did not finish" % code)
        fill, discharge, spheres = result[code]
        for phase, cpu, n in (("fill", fill, fill_steps), ("discharge", discharge, steps - fill_steps)):
            rows.append({"code": code, "phase": phase, "t_end": spec["t_end"], "steps": n, "spheres": spheres, "cpu_s": "%.4g" % cpu,
                         "cpu_per_sphere_step": "%.4g" % (cpu / (n * spheres))})
    os.makedirs(a.out, exist_ok=True)
    fd, temporary = tempfile.mkstemp(dir=a.out, prefix=".granular_speed.csv.")  # beside the target: os.replace is atomic
    try:
        with os.fdopen(fd, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0]), lineterminator="\n")
            w.writeheader()
            w.writerows(rows)
        os.replace(temporary, os.path.join(a.out, "granular_speed.csv"))
    except BaseException:
        os.unlink(temporary)
        raise
    for phase in ("fill", "discharge"):
        r, l = (float(next(x for x in rows if x["code"] == c and x["phase"] == phase)["cpu_per_sphere_step"]) for c in ("rotbench", "liggghts"))
        print("%-9s rotbench %.3g, LIGGGHTS %.3g CPU-s per sphere-step: rotbench / LIGGGHTS = %.2f" % (phase, r, l, r / l))
        if a.kratos:
            k = float(next(x for x in rows if x["code"] == "kratos" and x["phase"] == phase)["cpu_per_sphere_step"])
            print("%-9s Kratos %.3g CPU-s per sphere-step: rotbench / Kratos = %.3f" % (phase, k, r / k))


if __name__ == "__main__":
    main()
