#!/usr/bin/python3
"""Refinement cycles with Adaptivity/Strategy = kelly on coupled scenes
(doc/accuracy-vs-time.md, "Coupled scenes"): the meshes a run writes
(mesh-cycle<k>.vtu) are nested, refined where the mechanism is, keep a
one-cell slice a slice and keep interface twins conforming; every step on
them is in equilibrium.

(1) The rough footing on Tresca clay (prm/footing-capacity.prm, 4 steps to
    w = -0.04 m, 3 cycles): the cells grow from cycle to cycle; every vertex
    of a mesh is a vertex of the next (refinement only) and the meshes cover
    the same area (to 1e-12 relative: sums of products of exact binary
    breakpoints); the most refined cells touch the footing's edge (r = 1,
    z = 0), where the velocity of a footing's collapse jumps; every step's
    residual is within Load path/Tolerance of the load (equilibrium).
(2) The rigid pile in a one-cell slice (prm/pile-capacity.prm, n <= 2, 3
    steps, 2 cycles): every cell of the refined mesh still spans the slice's
    whole height (10 m): the fields do not vary in z, so the cells are cut
    in r only.
(3) The free-head pile with its shaft on interface line 5
    (prm/pile-free-head.prm, coarser, n <= 2, 2 steps, 2 cycles): the shaft
    r = 0.5 m has the same vertices seen from the pile's cells (material 1)
    and from the soil's (material 0), on each mesh: the interface pairs stay
    conforming.
Usage: coupled_adaptive_meshes.py FOURIER_SSI_EXE SOURCE_DIR WORK_DIR
"""
import csv
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtu_reader import data_arrays  # noqa: E402

exe, source_dir, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
passed = failed = 0


def check(ok, what):
    global passed, failed
    print(("  ok   " if ok else "  FAIL ") + what)
    passed += ok
    failed += not ok


def run(name, scene, extra):
    text = open(os.path.join(source_dir, scene)).read() + extra + """
subsection Adaptivity
  set Strategy        = kelly
  set Refine fraction = 0.6
end
subsection Output
  set Directory = %s
  set Write vtu = true
end
""" % name
    open(os.path.join(work, name + ".prm"), "w").write(text)
    result = subprocess.run([exe, name + ".prm"], cwd=work,
                            capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(name + " failed: " + result.stderr)
    return result.stdout


def rows(name):
    with open(os.path.join(work, name, "results.csv")) as f:
        return list(csv.DictReader(f))


def cells(name, cycle):
    """(corners, material, level) per cell of mesh-cycle<cycle>.vtu: the
    four corners of each patch of DataOut, in deal.II's vertex order."""
    arrays = data_arrays(os.path.join(work, name,
                                      "mesh-cycle%d.vtu" % cycle))
    points = arrays["Points"][1]
    material = arrays["material_id"][1]
    level = arrays["refinement_level"][1]
    result = []
    for c in range(len(points) // 12):
        corners = [(points[12 * c + 3 * v], points[12 * c + 3 * v + 1])
                   for v in range(4)]
        result.append((corners, material[4 * c], level[4 * c]))
    return result


def vertices(mesh):
    return {(round(x, 9), round(z, 9)) for corners, _, _ in mesh
            for x, z in corners}


def area(corners):
    (x0, z0), (x1, z1), (x2, z2) = corners[0], corners[1], corners[2]
    return abs((x1 - x0) * (z2 - z0) - (x2 - x0) * (z1 - z0))


# (1) The footing.
footing = """
subsection Load path
  set Load steps = 4
  set Target     = -0.04
end
subsection Discretization
  set Refinement cycles = 3
end
"""
log = run("footing", "prm/footing-capacity.prm", footing)
meshes = [cells("footing", k) for k in range(3)]
counts = [len(m) for m in meshes]
check(counts[0] < counts[1] < counts[2],
      "footing: cells grow per cycle: %s" % counts)
for k in range(2):
    missing = vertices(meshes[k]) - vertices(meshes[k + 1])
    check(not missing, "footing: every vertex of mesh %d is one of mesh %d "
          "(%d missing)" % (k, k + 1, len(missing)))
    a, b = (sum(area(c) for c, _, _ in m) for m in meshes[k:k + 2])
    check(abs(a - b) <= 1e-12 * a, "footing: meshes %d and %d cover the "
          "same area: %.15g vs %.15g m^2" % (k, k + 1, a, b))
finest = max(level for _, _, level in meshes[2])
at_edge = [corners for corners, _, level in meshes[2] if level == finest]
touching = [c for c in at_edge if any(abs(x - 1.) < 1e-9 and abs(z) < 1e-9
                                      for x, z in c)]
check(bool(touching), "footing: %d of the %d most refined cells (level %d) touch "
      "the footing's edge (1, 0)" % (len(touching), len(at_edge), finest))
residuals = [float(r["value"]) for r in rows("footing")
             if r["quantity"] == "step_residual"]
check(len(residuals) >= 4 and max(residuals) <= 1e-8,
      "footing: every step of the last mesh in equilibrium, |R| / |load| "
      "<= 1e-8 (Tolerance): largest %.2g over %d steps"
      % (max(residuals), len(residuals)))
cycle_lines = [line for line in log.splitlines() if line.startswith("cycle")]
check(len(cycle_lines) == 3 and "capacity_V" in cycle_lines[-1],
      "footing: one log line per cycle with its capacity")

# (2) The one-cell slice.
slice_ = """
subsection Discretization
  set Harmonics = 0, 1, 2
  set Refinement cycles = 2
end
subsection Load path
  set Load steps = 3
  set Target     = 0.01
end
"""
run("slice", "prm/pile-capacity.prm", slice_)
refined = cells("slice", 1)
heights = [max(z for _, z in c) - min(z for _, z in c) for c, _, _ in refined]
check(len(refined) > len(cells("slice", 0)) and
      min(heights) > 10. - 1e-9,
      "slice: %d cells after refinement, each spanning the 10 m height "
      "(smallest %.6g m)" % (len(refined), min(heights)))

# (3) Interface twins.
free_head = """
subsection Discretization
  set Harmonics = 0, 1, 2
  set Refinement cycles = 2
end
subsection Mesh
  set R cells = 2, 8
  set Z cells = 2, 4
end
subsection Load path
  set Load steps = 2
  set Target     = 0.01
end
subsection Output
  set Soil reaction depths =
end
"""
run("twins", "prm/pile-free-head.prm", free_head)
for k in range(2):
    mesh = cells("twins", k)
    sides = [{round(z, 9) for c, m, _ in mesh if m == material
              for x, z in c if abs(x - 0.5) < 1e-9 and -10. - 1e-9 < z < 1e-9}
             for material in (1, 0)]
    check(sides[0] == sides[1] and len(sides[0]) >= 5,
          "twins: mesh %d: the shaft's %d vertices seen from the pile and "
          "from the soil agree" % (k, len(sides[0])))
check(len(cells("twins", 1)) > len(cells("twins", 0)),
      "twins: the second mesh is refined")
print("%d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
