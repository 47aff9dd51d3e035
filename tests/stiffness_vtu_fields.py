#!/usr/bin/python3
"""A stiffness scene writes the fields it computes: the unit-H and unit-M
solutions appear in the VTU of the stiffness harmonic (n = 1 symmetric), and
the unit-H field is the one whose foundation motion the log reports.

Check: the largest radial amplitude of the unit-H field over the footing's
nodes equals the printed U_h of the unit-H case (I_H * a / (G a^2) for H =
1, i.e. u = I_H H / (G a)); the rigid foundation translates and rotates, so
the maximum over the whole body is U_h + |Theta| * (largest lever arm), and
it must be at least U_h. We check the two exact consequences that do not
depend on the mesh: (1) the field exists with the three components and is
not zero; (2) on the footing's nodes at the reference elevation (r < a), where
the rigid motion is U = U_h + Theta (z - z_ref) = U_h, its radial amplitude
equals U_h = I_H H / (G a) (H = 1) from results.csv to 1e-6 relative (the
VTU stores Float32).
Usage: stiffness_vtu_fields.py FOURIER_SSI_EXE SOURCE_DIR WORK_DIR
"""
import csv
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtu_reader import data_arrays  # noqa: E402

exe, source_dir, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
scene = open(os.path.join(source_dir, "prm/embedded-footing.prm")).read()
scene += """
subsection Discretization
  set Refinement cycles = 1
end
subsection Output
  set Directory = out
  set Write vtu = true
end
"""
open(os.path.join(work, "scene.prm"), "w").write(scene)
run = subprocess.run([exe, "scene.prm"], cwd=work, capture_output=True,
                     text=True)
if run.returncode != 0:
    sys.exit("run failed: " + run.stderr)


vtu = os.path.join(work, "out", "solution-n1-symmetric-cycle0.vtu")
arrays = data_arrays(vtu)
failed = 0
for name in ("unit_H_U_radial", "unit_H_V_axial", "unit_H_W_circumferential",
             "unit_M_U_radial", "unit_M_V_axial", "unit_M_W_circumferential"):
    ok = name in arrays and max(abs(v) for v in arrays[name][1]) > 0.
    print(("  ok   " if ok else "  FAIL ") + name + " written and not zero")
    failed += not ok

rows = {r["quantity"]: float(r["value"])
        for r in csv.DictReader(open(os.path.join(work, "out", "results.csv")))
        if r["n"] == "1" and r["family"] == "symmetric"}
# The unit-H case: u_H = I_H * H / (G a) with H = 1 (thesis eq. 4.2).
parameters = dict(re.findall(r"set (Reference shear modulus|Reference length)"
                             r"\s*=\s*([0-9.eE+-]+)", scene))
G = float(parameters.get("Reference shear modulus", 1.))
a = float(parameters.get("Reference length", 1.))
u_h = rows["I_H"] / (G * a)
# Points: the VTU's node coordinates; the footing's nodes lie on the
# reference elevation z_ref at r <= a, where the unit-H field's radial
# amplitude is U = U_h + Theta (z - z_ref) = U_h exactly.
points = arrays["Points"][1] if "Points" in arrays else None
z_ref = float(re.search(r"set Reference elevation\s*=\s*([0-9.eE+-]+)",
                        scene).group(1)) if "Reference elevation" in scene \
    else 0.
U = arrays["unit_H_U_radial"][1]
at_reference = [U[i] for i in range(len(U))
                if abs(points[3 * i + 1] - z_ref) < 1e-12 and
                points[3 * i] < a * (1 - 1e-9) and points[3 * i] > 1e-12]
error = max(abs(v - u_h) for v in at_reference) / abs(u_h) \
    if at_reference else float("inf")
ok = error < 1e-6
print(("  ok   " if ok else "  FAIL ") +
      "unit-H radial amplitude on the footing at z_ref = %g vs U_h = I_H/(G a)"
      " = %.10g: relative error %.3g over %d nodes (tol 1e-6: the VTU stores Float32)"
      % (z_ref, u_h, error, len(at_reference)))
failed += not ok
print("%d passed, %d failed" % (7 - failed, failed))
sys.exit(1 if failed else 0)
