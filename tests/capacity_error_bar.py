#!/usr/bin/python3
"""tools/capacity.py on the rough circular footing of prm/footing-capacity.prm
(a = 1 m, s_u = 10 kPa) in two loadings of known limit, each on three
nested meshes coarser than the shipped one (R cells 2,3 / 4,6 / 8,12 and Z
cells 4 / 8 / 16, graded like the shipped mesh: growth 0.85^(10/4) = 0.666
toward the edge, 1.2^(14/6) = 1.53 outward, 0.85^(20/8) = 0.666 toward the
surface), which keeps the whole test at about 20 s CPU (34 s wall on the
shared machine):

(1) torsion (n = 0 antisymmetric, twisted to 0.02 rad): T_ult / (a^3 s_u) =
    2 pi / 3 = 2.0944, exact (doc/soil-plasticity.md section 5b);
(2) vertical (n = 0, pushed to w = 0.04 a): N_c = 6.05 (Eason & Shield
    1960, rough; a numerical solution given to three digits).

Checks, with their reasons (doc/verification/soil-plasticity.md section 8b):
- the printed interval value ± error contains the exact limit: what an
  error bar promises;
- the mesh bar over the true error of the finest mesh, |P_h - exact|, lies
  in [1, 3]: at least the error (a bar that covers it) and at most 3 times
  it (the safety factor of two-mesh estimates; a wider bar says little).
  Measured 1.30 (torsion) and 1.12 (vertical);
- a load-controlled scene is refused with one line naming the file and
  writes no CSV.
Usage: capacity_error_bar.py FOURIER_SSI_EXE SOURCE_DIR WORK_DIR
"""
import csv
import math
import os
import shutil
import subprocess
import sys

exe, source_dir, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
tool = os.path.join(source_dir, "tools", "capacity.py")
footing = os.path.join(source_dir, "prm", "footing-capacity.prm")
coarse_mesh = ["Mesh/R cells=4, 6", "Mesh/R growth=0.666, 1.53",
               "Mesh/Z cells=8", "Mesh/Z growth=0.666"]
failed = 0


def check(what, ok):
    global failed
    print(("  ok   " if ok else "  FAIL ") + what, flush=True)
    failed += 0 if ok else 1


def capacity(name, settings):
    """Run tools/capacity.py on the footing with `settings`; its CSV row."""
    arguments = [sys.executable, tool, footing, "--levels", "3", "--first",
                 "-1", "--exe", exe, "--work", os.path.join(work, name)]
    for s in coarse_mesh + settings:
        arguments += ["--set", s]
    subprocess.run(arguments, check=True)
    with open(os.path.join(work, name, "capacity.csv")) as f:
        return next(csv.DictReader(f))


def verify(name, row, exact):
    value, error = float(row["value"]), float(row["error"])
    check("%s: %.4f ± %.4f contains the exact %.4f" % (name, value, error, exact),
          abs(value - exact) <= error)
    true_error = abs(float(row["finest_mesh_value"]) - exact)
    effectivity = float(row["error_mesh"]) / true_error
    check("%s: mesh bar %.4f / true error of the finest mesh %.4f = %.2f in "
          "[1, 3]" % (name, float(row["error_mesh"]), true_error, effectivity),
          1.0 <= effectivity <= 3.0)


verify("torsion T/(a^3 s_u)",
       capacity("torsion", ["Discretization/Family=antisymmetric",
                            "Rigid foundation/Vertical force=0",
                            "Rigid foundation/Torque=1",
                            "Load path/Controlled motion=twist",
                            "Load path/Target=0.02",
                            "Load path/Load steps=10"]),
       2.0 * math.pi / 3.0)
verify("vertical N_c",
       capacity("vertical", ["Load path/Target=-0.04",
                             "Load path/Load steps=8"]),
       6.05)

# A load-controlled scene has no plateau to read: refused in one line.
bad = subprocess.run([sys.executable, tool, os.path.join(source_dir, "prm",
                                                         "pile.prm"),
                      "--exe", exe, "--work", os.path.join(work, "bad")],
                     capture_output=True, text=True)
lines = bad.stderr.strip().splitlines()
check("load-controlled scene refused: exit %d, one line naming the file: %s"
      % (bad.returncode, lines),
      bad.returncode != 0 and len(lines) == 1 and "pile.prm" in lines[0]
      and not os.path.exists(os.path.join(work, "bad", "capacity.csv")))

print("%d check(s) failed" % failed if failed else "all checks passed")
sys.exit(1 if failed else 0)
