#!/usr/bin/python3
"""The monopile's 6x6 mudline stiffness to 1e-3: its wall time against the
requirement "<= 5 s on 2 cores", and its terms against the references of
tests/scenes/monopile.stiffness.checks (a finer run of the same scene).

    /usr/bin/python3 benchmarks/monopile-stiffness/run.py [EXE] [RUNS]

EXE defaults to build/fourier-ssi of this tree, RUNS to 3. Runs, each in its
own temporary directory and one after the other:
  * prm/monopile.prm with tests/accuracy/monopile_stiffness_1e-3.prm
    appended (base mesh with half the cells, Target accuracy 1e-3,
    Stiffness matrix = true), RUNS times;
  * for comparison the shipped mesh with the same target and matrix, RUNS
    times.
Writes results.md next to this file (under a minute).
"""
import csv
import os
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.normpath(os.path.join(HERE, "..", ".."))
SCENE = os.path.join(SOURCE, "prm", "monopile.prm")
COARSE = os.path.join(SOURCE, "tests", "accuracy",
                      "monopile_stiffness_1e-3.prm")
REQUIRED_S = 5.
# The finer run of tests/scenes/monopile.stiffness.checks (1.28e6 DoFs per
# harmonic, estimates <= 2.5e-7); K_T: the shipped mesh's member 1.
REFERENCE = {"foundation_vertical_stiffness_normalised": 22.7510,
             "K_H": 18.8398, "K_M": 378.576, "K_MH": -53.3898,
             "K_T": 96187452.76}
SHIPPED_1E3 = """subsection Discretization
  set Target accuracy = 1e-3
end
subsection Rigid foundation
  set Stiffness matrix = true
end
"""


def run(exe, appended):
    """One run of the monopile with `appended`: (wall s, last rows)."""
    with tempfile.TemporaryDirectory() as work:
        with open(SCENE) as f:
            text = f.read()
        with open(os.path.join(work, "scene.prm"), "w") as f:
            f.write(text + "\n" + appended +
                    "\nsubsection Output\n  set Directory = out\nend\n")
        start = time.monotonic()
        subprocess.run([exe, "scene.prm"], cwd=work, check=True,
                       stdout=subprocess.DEVNULL)
        wall = time.monotonic() - start
        rows = {}
        with open(os.path.join(work, "out", "results.csv")) as f:
            for row in csv.DictReader(f):
                rows[row["quantity"]] = float(row["value"])
        return wall, rows


def main():
    exe = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        SOURCE, "build", "fourier-ssi")
    runs = int(sys.argv[2]) if len(sys.argv) > 2 else 3
    with open(COARSE) as f:
        coarse = f.read()
    load = os.getloadavg()[0]
    lines = []
    for name, appended in (("half the base cells", coarse),
                           ("shipped base mesh", SHIPPED_1E3)):
        walls, rows = [], {}
        for _ in range(runs):
            wall, rows = run(exe, appended)
            walls.append(wall)
        worst = max(abs(rows[k] - v) / abs(v) for k, v in REFERENCE.items())
        estimate = max(rows[k + "_error"] for k in
                       ("K_V", "K_H", "K_M", "K_MH", "K_T"))
        lines.append(
            f"| {name} | {statistics.median(walls):.2f} | {max(walls):.2f} "
            f"| {estimate:.1e} | {worst:.1e} "
            f"| {'yes' if statistics.median(walls) <= REQUIRED_S else 'no'} |")
    with open(os.path.join(HERE, "results.md"), "w") as f:
        f.write(f"""# The monopile's 6x6 stiffness to 1e-3

`/usr/bin/python3 benchmarks/monopile-stiffness/run.py` ({runs} runs per
row, one after the other; 1-minute load average {load:.1f} at the start;
2 cores). Whole process wall time, `Target accuracy = 1e-3`, `Stiffness
matrix = true` (the 6x6 matrix, its CSV and the SubDyn file written).
"largest estimate": the largest error bar the run prints (relative);
"largest true error": the largest distance of K_V, K_H, K_M, K_MH, K_T
from the finer run of tests/scenes/monopile.stiffness.checks (K_T: the
shipped mesh's member 1). Requirement: <= {REQUIRED_S:g} s.

| base mesh | median [s] | largest [s] | largest estimate | largest true error | <= {REQUIRED_S:g} s |
|---|---|---|---|---|---|
""" + "\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
