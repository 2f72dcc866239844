#!/usr/bin/env python3
"""Which integrator defects rotbench's gate detects, and which physical_validation's integrator
check detects, on the same trajectories (docs/findings.md, "The anchor checker beside rotbench").

physical_validation (Merz & Shirts; the check GROMACS's physical-validation suite runs) holds that
the fluctuation of a conserved quantity scales as dt^2: for runs at dt_1 > dt_2 it computes
max |1 - (rmsd_1 / rmsd_2) / (dt_1 / dt_2)^2| over the energy time series, and GROMACS's suite calls
a deviation above 0.1 a failure. rotbench's verdict is its gate's: each scheme held to its claims
(orders of the angular-velocity error, momentum, energy) on the free and dipole scenes.

Both read one `rotbench run` per scheme set: the energy series of asymmetric_free (torque-free) and
dipole_top (conservative torque) at the coarsest and finest of two steps, which rotbench writes to
series/ (every 0.1 s and 0.05 s). The schemes: Yade's first-order aspherical leapfrog, Kratos DEM's
four clients, a plug-in that claims second order and delivers first (tests/plugins), the no_gyro
control and three sound schemes.

Needs physical_validation in the project's venv (pinned in benchmarks/requirements-validation.txt;
not a dependency of rotbench), yade for its client, and the Kratos wheels:
  .venv/bin/pip install -r benchmarks/requirements-validation.txt
  .venv/bin/python3 benchmarks/physical_validation_table.py BUILD_DIR OUT_DIR
Writes OUT_DIR/physical_validation.csv and prints the table as Markdown.
"""
import csv
import os
import subprocess
import sys

import numpy as np
import physical_validation as pv

TOLERANCE = 0.1  # GROMACS's physical-validation integrator test fails a deviation above 0.1
SCENES = {"asymmetric_free": ("0.04", "0.01"), "dipole_top": ("0.01", "0.0025")}

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.join(here, "..")
# (scheme id, what it is, the defect it carries or "sound")
SCHEMES = [
    ("yade_exact_aspherical", "Yade 2023.02a, exactAsphericalRot", "first order (claims Fincham's second)"),
    ("kratos_quaternion", "Kratos DEM Quaternion_Integration", "first order in q and world w (claims 2)"),
    ("kratos_direct", "Kratos DEM Direct_Integration (Velocity_Verlet)", "none against its claim (first order by design)"),
    ("kratos_runge_kutta", "Kratos DEM Runge_Kutta", "none (munjiza_rk4's map)"),
    ("kratos_direct_default", "Kratos DEM Direct_Integration (Symplectic_Euler)", "none against its claim (first order)"),
    ("zvw_end_velocity", "plug-in tests/plugins/end_velocity_zvw", "first order (claims 2)"),
    ("no_gyro", "rotbench's negative control", "no gyroscopic term: not a rigid body's motion"),
    ("richardson", "LAMMPS fix rigid's map", "sound"),
    ("no_squish", "NO_SQUISH (symplectic)", "sound"),
    ("zvw_corrected", "the seed's quaternion scheme", "sound"),
]
CLIENTS = ["examples/clients/yade/exact.toml"] + [
    "examples/clients/kratos/%s.toml" % n for n in ("quaternion", "direct", "runge_kutta", "direct_default")]
GATE = """[claims]
schemes = [%s]
free = ["asymmetric_free", "tumbling_brick"]
torque = ["dipole_top"]
"""


def deviation(series):  # {dt: energy series}: physical_validation's max_deviation, NaN if undefined
    sims = []
    for dt, energy in series.items():
        data = pv.data.SimulationData(dt=float(dt), observables=pv.data.ObservableData(constant_of_motion=energy))
        sims.append(data)
    try:
        with np.errstate(all="ignore"):
            return float(pv.integrator.convergence(sims, verbose=False))
    except Exception as e:  # a constant series (no fluctuation at all) has no ratio
        print("physical_validation: %s" % e, file=sys.stderr)
        return float("nan")


def energy_series(run_dir, scene, scheme, dt):
    path = os.path.join(run_dir, "series", "energy_%s_%s_dt%s.csv" % (scene, scheme, dt))
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return np.array([float(r["energy_error"]) for r in rows])


def main(build, out):
    rotbench = os.path.join(build, "rotbench")
    plugin = os.path.join(build, "tests", "test_plugin_end_velocity_zvw.so")
    loads = ["--plugin", plugin]
    for c in CLIENTS:
        loads += ["--client", os.path.join(root, c)]
    ids = [s[0] for s in SCHEMES]
    os.makedirs(out, exist_ok=True)
    gate_file = os.path.join(out, "gate.toml")
    with open(gate_file, "w") as f:
        f.write(GATE % ", ".join('"%s"' % i for i in ids))
    gate_out = os.path.join(out, "gate")
    subprocess.run([rotbench] + loads + ["gate", gate_file, "--out", gate_out, "--overwrite"], stdout=subprocess.DEVNULL)
    failed = {}
    with open(os.path.join(gate_out, "gate.csv")) as f:
        for row in csv.DictReader(f):
            if row["outcome"] not in ("pass", "skipped"):
                failed.setdefault(row["scheme"], []).append("%s on %s" % (row["check"], row["scene"]))
    rows = []
    for scene, dts in SCENES.items():
        run_dir = os.path.join(out, "run_" + scene)
        subprocess.run([rotbench] + loads + ["run", "--scenes", scene, "--schemes", ",".join(ids), "--dt", ",".join(dts),
                        "--out", run_dir, "--overwrite"], stdout=subprocess.DEVNULL, check=True)
        for scheme, _, _ in SCHEMES:
            dev = deviation({dt: energy_series(run_dir, scene, scheme, dt) for dt in dts})
            rows.append((scheme, scene, dev))
    with open(os.path.join(out, "physical_validation.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["scheme", "scene", "pv_deviation", "pv_detects", "rotbench_detects"])
        for scheme, scene, dev in rows:
            w.writerow([scheme, scene, repr(dev), dev > TOLERANCE if dev == dev else "undefined", scheme in failed])
    print("| scheme | what it is | defect | physical_validation: deviation, asymmetric_free / dipole_top | "
          "detects (> %g) | rotbench's gate |" % TOLERANCE)
    print("|---|---|---|---|---|---|")
    for scheme, what, defect in SCHEMES:
        devs = [d for s, _, d in rows if s == scheme]
        verdict = ["undefined" if d != d else ("yes" if d > TOLERANCE else "no") for d in devs]
        gate = "fails: " + "; ".join(failed[scheme]) if scheme in failed else "passes"
        print("| `%s` | %s | %s | %s | %s | %s |" % (scheme, what, defect, " / ".join("%.3g" % d for d in devs),
                                                  " / ".join(verdict), gate))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
