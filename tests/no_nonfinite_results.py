#!/usr/bin/python3
"""No result file holds `nan` or `inf` (doc/output-files.md): a part of an
error bar that was not estimated has no row in results.csv, and a ratio
whose normaliser is zero is an empty field of its CSV.

Each case is a bundled scene with entries appended, made to hit one of the
places where a value is not defined:
  plateau_unbounded   footing-capacity pushed only 1e-4 m, elastic: the
                      last three steps do not bend over, so the
                      plateau's error is unbounded (exit 0; no
                      capacity_V_plateau_error row, the capacity's row
                      is there);
  stiffness_one_mesh  surface-disc-stiffness on one mesh (Refinement
                      cycles = 1): no mesh error of K_V (no K_V_error row,
                      K_V there), the 6x6 CSV's error_bar fields empty;
  target_one_mesh     footing-capacity with a target whose second mesh
                      exceeds Maximum DoFs: one mesh solved, so no mesh
                      error (exit 3, the target not reached; no
                      capacity_V_error_mesh row);
  sand_mudline        pile-sand with a soil-reaction depth at the mudline,
                      where sigma'_v = 0: its normalised fields are empty.
For every case: the exit code expected; every field of every CSV (and every
word of the SubDyn file) that looks like a number is finite: no `nan`,
`inf`, `NaN` or `Infinity` token anywhere; results.csv's values all parse as
finite floats; the rows named above present or absent as said.
Usage: no_nonfinite_results.py FOURIER_SSI_EXE SOURCE_DIR WORK_DIR
"""
import csv
import math
import os
import re
import shutil
import subprocess
import sys

exe, source_dir, work = sys.argv[1:4]
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from relative_checks import finish, that  # noqa: E402

shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
environment = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
OUTPUT = "\nsubsection Output\n  set Directory = out\nend\n"
NON_FINITE = re.compile(r"(?i)(?<![a-z_])(nan|inf|infinity)(?![a-z_])")

# name: (scene, appended entries, exit code, rows present, rows absent)
CASES = {
    "plateau_unbounded": (
        "prm/footing-capacity.prm",
        "subsection Load path\n  set Target = -1e-4\n  set Load steps = 3\n"
        "end\n", 0,
        ["capacity_V"], ["capacity_V_plateau_error"]),
    "stiffness_one_mesh": (
        "prm/surface-disc-stiffness.prm",
        "subsection Discretization\n  set Target accuracy =\n"
        "  set Refinement cycles = 1\nend\n"
        "subsection Mesh\n  set R cells = 2, 8\n  set Z cells = 8\nend\n", 0,
        ["K_V"], ["K_V_error"]),
    "target_one_mesh": (
        "prm/footing-capacity.prm",
        "subsection Discretization\n  set Target accuracy = 1e-3\nend\n"
        "subsection Adaptivity\n  set Maximum DoFs = 5000\nend\n", 3,
        ["capacity_V"], ["capacity_V_error_mesh"]),
    "sand_mudline": (
        "prm/pile-sand.prm",
        "subsection Load path\n  set Target = 0.005\n  set Load steps = 2\n"
        "end\nsubsection Output\n  set Soil reaction depths = 0, 1\nend\n",
        0, [], []),
}




for name, (scene, extra, code, present, absent) in CASES.items():
    folder = os.path.join(work, name)
    os.makedirs(folder)
    text = open(os.path.join(source_dir, scene)).read()
    open(os.path.join(folder, "scene.prm"), "w").write(text + OUTPUT + extra)
    run = subprocess.run([exe, "scene.prm"], cwd=folder, env=environment,
                         capture_output=True, text=True)
    print("%s:" % name)
    that(run.returncode == code,
     "exit %d (got %d: %s)" % (code, run.returncode,
                                     run.stderr.strip()[-200:]))
    out = os.path.join(folder, "out")
    files = sorted(f for f in os.listdir(out)
                   if f.endswith((".csv", ".dat", ".txt"))) \
        if os.path.isdir(out) else []
    that("results.csv" in files,
     "results.csv written")
    for f in files:
        bad = [line.strip() for line in open(os.path.join(out, f))
               if NON_FINITE.search(line)]
        that(not bad,
     "%s: no nan or inf token (%s)" % (f, bad[:2]))
    if "results.csv" not in files:
        continue
    rows = list(csv.DictReader(open(os.path.join(out, "results.csv"))))
    values = []
    for row in rows:
        try:
            values.append(float(row["value"]))
        except ValueError:
            values.append(float("nan"))
    that(all(math.isfinite(v) for v in values),
     "results.csv: all %d values finite" % len(rows))
    quantities = {row["quantity"] for row in rows}
    for q in present:
        that(q in quantities,
     "row %s present" % q)
    for q in absent:
        that(q not in quantities,
     "row %s absent (not estimated)" % q)
    if name == "sand_mudline":
        curves = list(csv.reader(open(os.path.join(
            out, "soil-reaction-curves.csv"))))
        header, body = curves[0], curves[1:]
        column = header.index("p/(s D) [-]")
        at_mudline = [r for r in body if float(r[header.index("depth [m]")])
                      == 0.]
        that(at_mudline and all(r[column] == "" for r in at_mudline),
     "soil-reaction curves at the mudline: p/(s D) empty where "
              "sigma'_v = 0 (%d rows)" % len(at_mudline))
finish()
