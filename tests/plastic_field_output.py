#!/usr/bin/python3
"""The plastic field files of a plastic-soil run (doc/output-files.md, "The
plastic field") against the closed form of the thick Mohr-Coulomb cylinder
(prm/cylinder-mohr-coulomb.prm, doc/soil-plasticity.md section 7b; the
formulas of doc/derivations/cylinder_mohr_coulomb.py), and every file a
run writes parses.

Cylinder, steps 5 to 8 of the 8 load steps (p_s = s/8 p, load control), the
plane theta = 0 and the revolved 3D file:
  - the outer radius R of the cells with plastic strain lies within one
    cell width h = (b - a)/16 of the closed-form plastic radius rho(p_s):
    the field is one value per cell, so its edge lies on a cell face, and
    rho lies in the cell where the Gauss rows turn plastic;
  - every cell outside rho has zero plastic strain, exactly (an elastic
    sample keeps s_p = 0 bit for bit; Float32 keeps 0);
  - in the cells of the elastic ring (r >= R) the mean stresses sigma_r,
    sigma_theta, sigma_z against the r-weighted means over the cell of
    Lame's field at yield at rho, within the interpolation error of Q2 in
    a cell, h^2/8 |sigma''| (the stress is linear in a Q2 cell), plus 1e-6
    of the stress (Float32); measured 1.3e-5 to 6.5e-5 of the hoop stress,
    0.03 to 0.16 of that tolerance;
  - the bore displacement u_r(a) against the closed form u(a) within the
    change of u(a) when rho moves by h/4;
  - the log's count of plastic samples is load-displacement.csv's;
  - the 3D file holds Theta divisions sectors of every cell with the
    plane's values (n = 0: the same at every angle).
Pile slice (prm/pile-capacity.prm with Write vtu: the default last step,
planes 0 and 90, plus the 3D file): the log names the theta samples 0 and 90 of its 36, the
files parse (XML, the points and every field of every point), and the
loading plane moves and yields.
Usage: plastic_field_output.py FOURIER_SSI_EXE SOURCE_DIR WORK_DIR
"""
import csv
import math
import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtu_reader import data_arrays  # noqa: E402

exe, source_dir, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(source_dir, "doc", "derivations"))
import cylinder_mohr_coulomb as closed  # noqa: E402

shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
passed = failed = 0


def check(ok, what):
    global passed, failed
    ok = bool(ok)
    print(("  ok   " if ok else "  FAIL ") + what)
    passed += ok
    failed += not ok


def run(name, scene, extra):
    text = open(os.path.join(source_dir, scene)).read() + extra
    open(os.path.join(work, name + ".prm"), "w").write(text)
    result = subprocess.run([exe, name + ".prm"], cwd=work,
                            capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(name + " failed: " + result.stderr)
    return result.stdout


def cells_of(arrays, per):
    """Per patch (`per` own vertices: 4 in a plane): the vertex indices."""
    n = len(arrays["Points"][1]) // 3
    return [list(range(i, i + per)) for i in range(0, n, per)]


def parses(path):
    """The VTU is XML, and every field has a value per point."""
    ElementTree.parse(path)
    arrays = data_arrays(path)
    n_points = len(arrays["Points"][1]) // 3
    return n_points > 0 and all(
        len(arrays[name][1]) == n_points * arrays[name][0]
        for name in FIELDS)


FIELDS = ["displacement", "u_r", "u_theta", "u_z", "plastic_strain",
          "plastic_strain_increment", "plastic_points", "yielded_points",
          "yield_value", "sigma_r", "sigma_z", "sigma_theta", "tau_rz",
          "tau_ztheta", "tau_rtheta"]


def series_files(path):
    return [d.get("file") for d in ElementTree.parse(path).iter("DataSet")]


# The cylinder: a = 1, b = 2, c = 10 kPa, phi = 20 degrees, nu = 0.3.
a, b, c, phi, nu = 1.0, 2.0, 10.0, math.radians(20.), 0.3
h = (b - a) / 16
p_end = 10.689396576573305
steps = [5, 6, 7, 8]
log = run("cylinder", "prm/cylinder-mohr-coulomb.prm", """
subsection Output
  set Directory = cylinder
  set Write vtu = true
  set Plastic field steps = 5, 6, 7, 8
  set Plastic field planes = 0
  set Plastic field 3D = true
  set Theta divisions = 12
end
""")
folder = os.path.join(work, "cylinder")
rows = list(csv.DictReader(open(os.path.join(folder,
                                             "load-displacement.csv"))))


def lame(r, rho):
    """Tension-positive (sigma_r, sigma_theta, sigma_z) of the elastic ring
    at yield at rho (compression-positive s_r = A (b^2/r^2 - 1), s_t = -A
    (b^2/r^2 + 1), sigma_z = nu (sigma_r + sigma_theta))."""
    amplitude = closed.ring_amplitude(rho, c, phi)
    s_r = amplitude * (b * b / (r * r) - 1)
    s_t = -amplitude * (b * b / (r * r) + 1)
    return -s_r, -s_t, -nu * (s_r + s_t)


def cell_mean(r0, r1, rho, k, m=200):
    """The r-weighted mean of component k of lame() over [r0, r1]."""
    dr = (r1 - r0) / m
    total = weight = 0.
    for i in range(m + 1):
        r = r0 + i * dr
        w = (1 if i in (0, m) else (4 if i % 2 else 2)) * r
        total += w * lame(r, rho)[k]
        weight += w
    return total / weight


for step in steps:
    p = p_end * step / 8
    rho = closed.rho_of_p(p, c, phi)
    name = "plastic-field-theta0-step%d.vtu" % step
    arrays = data_arrays(os.path.join(folder, name))
    x = arrays["Points"][1]
    cells = cells_of(arrays, 4)
    strain = arrays["plastic_strain"][1]
    yielded = arrays["yielded_points"][1]
    ranges = [(min(x[3 * v] for v in cell), max(x[3 * v] for v in cell))
              for cell in cells]
    plastic = [i for i, cell in enumerate(cells) if yielded[cell[0]] > 0]
    outer = max(ranges[i][1] for i in plastic)
    check(abs(outer - rho) <= h,
          "step %d: plastic region to r = %.5f m, closed form rho = %.5f m "
          "(|difference| %.5f <= h = %.4f)" % (step, outer, rho,
                                               abs(outer - rho), h))
    outside = [i for i in range(len(cells)) if ranges[i][0] >= rho]
    check(len(outside) > 0 and
          all(strain[cells[i][0]] == 0. and yielded[cells[i][0]] == 0.
              for i in outside),
          "step %d: plastic strain exactly 0 in the %d cells beyond rho"
          % (step, len(outside)))
    ring = [i for i in range(len(cells)) if ranges[i][0] >= outer - 1e-12]
    worst = 0.
    amplitude = closed.ring_amplitude(rho, c, phi)
    for i in ring:
        r0, r1 = ranges[i]
        # Q2 interpolates the displacement to h^3, so the stress of a cell
        # (linear in it) to h^2/8 |sigma''|; |sigma''| of the ring's
        # sigma_r, sigma_theta is at most 6 A b^2 / r0^4 in the cell.
        tolerance = (h * h / 8 * 6 * amplitude * b * b / r0 ** 4 +
                     1e-6 * abs(cell_mean(r0, r1, rho, 1)))
        for k, field in enumerate(("sigma_r", "sigma_theta", "sigma_z")):
            value = arrays[field][1][cells[i][0]]
            worst = max(worst,
                        abs(value - cell_mean(r0, r1, rho, k)) / tolerance)
    check(len(ring) > 0 and worst <= 1.,
          "step %d: Lame stresses in the %d elastic cells, largest error "
          "%.3f of the tolerance (h^2/8 |sigma''| + 1e-6)"
          % (step, len(ring), worst))
    bore = [arrays["u_r"][1][v] for cell in cells for v in cell
            if abs(x[3 * v] - a) < 1e-9]
    exact_u = closed.u_bore(p, c, phi)
    check(bore and max(abs(u - exact_u) for u in bore) <= 1e-6 * exact_u +
          max(abs(closed.u_bore(closed.p_of_rho(rho + d, c, phi), c, phi) -
                  exact_u) for d in (-h / 4, h / 4)),
          "step %d: bore u_r = %.6e m, closed form %.6e m"
          % (step, bore[0], exact_u))
    counted = re.search(r"plastic field of step %d \((\d+) plastic of" % step,
                        log)
    check(counted and counted.group(1) == rows[step - 1]["plastic"],
          "step %d: the log's %s plastic samples are load-displacement.csv's"
          % (step, counted.group(1) if counted else "?"))
    revolved = data_arrays(os.path.join(folder,
                                        "plastic-field-3d-step%d.vtu" % step))
    check(len(revolved["Points"][1]) == 12 * 8 * 3 * len(cells) and
          sorted(set(revolved["plastic_strain"][1])) ==
          sorted(set(strain)),
          "step %d: 3D file, 12 sectors of %d cells with the plane's values"
          % (step, len(cells)))

written = sorted(f for f in os.listdir(folder) if f.startswith("plastic"))
check(all(parses(os.path.join(folder, f)) for f in written
          if f.endswith(".vtu")), "cylinder: %d VTU files parse"
      % sum(f.endswith(".vtu") for f in written))
check(series_files(os.path.join(folder, "plastic-field-theta0.pvd")) ==
      ["plastic-field-theta0-step%d.vtu" % s for s in steps] and
      series_files(os.path.join(folder, "plastic-field-3d.pvd")) ==
      ["plastic-field-3d-step%d.vtu" % s for s in steps],
      "cylinder: the .pvd series name the 4 steps in order")

# The pile slice as shipped (n <= 8, 36 theta samples), with the 3D file.
log = run("pile", "prm/pile-capacity.prm", """
subsection Output
  set Directory = pile
  set Write vtu = true
  set Plastic field 3D = true
end
""")
folder = os.path.join(work, "pile")
written = sorted(f for f in os.listdir(folder) if f.startswith("plastic"))
check(written == ["plastic-field-3d-step6.vtu", "plastic-field-3d.pvd",
                  "plastic-field-theta0-step6.vtu", "plastic-field-theta0.pvd",
                  "plastic-field-theta90-step6.vtu",
                  "plastic-field-theta90.pvd"],
      "pile: the last step's files: " + ", ".join(written))
check(all(parses(os.path.join(folder, f)) for f in written
          if f.endswith(".vtu")), "pile: every VTU parses")
check("(theta sample 0 deg)" in log and "(theta sample 90 deg)" in log and
      "36 theta samples" in log, "pile: the log names the samples 0, 90")
rows = list(csv.DictReader(open(os.path.join(folder,
                                             "load-displacement.csv"))))
counted = re.search(r"plastic field of step 6 \((\d+) plastic of", log)
check(counted and counted.group(1) == rows[-1]["plastic"],
      "pile: the log's plastic samples are load-displacement.csv's")
loading = data_arrays(os.path.join(folder, "plastic-field-theta0-step6.vtu"))
u_x = [abs(v) for v in loading["displacement"][1][0::3]]
check(max(u_x) > 0 and max(loading["plastic_strain"][1]) > 0,
      "pile: the loading plane moves (|u_x| <= %.4g m) and yields" % max(u_x))

print("%d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
