#!/usr/bin/python3
"""A swipe through a frictional interface on elastic soil (doc/offshore-
foundations.md section 7, "Swipe tests"): a rigid block (r < 1 m, 0.2 m high, Tie =
material) on a cohesionless coulomb interface (z = 0; phi = 20 deg, c = 0,
tensionless, kn = ks = 1e6 kPa/m) over elastic soil (G = 1000 kPa, nu =
0.3), preloaded by V0 = 100 kN, then pushed along x to u = 0.1 m in 10
steps with w held where the preload left it. The scene has no soil points:
the coupled tangent solver drives the interface alone (doc/driver.md).

Reference (Coulomb's law, independent of the soil): |t_s| <= t_n tan(phi)
at every sample, so H <= |V| tan(phi) at every step; once every sample
slips along x, H = |V| tan(phi) with V the vertical load of that step. The
soil's radial shear under the preload turns the first slips off x, so H / |V|
approaches tan(phi) along the path (measured: 2.2e-2, 3.3e-4, 4.8e-6, ...
below it, 1e-11 from the seventh step on). Checks:
(1) the run exits 0 and says it runs the coupled tangent with no soil
    points;
(2) w stays at the preload's value at every driven step (the swipe's
    multiplier keeps it; bound 1e-12 of the largest |w|: round-off);
(3) H / |V| <= tan(phi) (1 + 1e-6) at every driven step (Coulomb's bound
    on the interface's resultant; the applied H equals it up to the step's
    residual, 1e-10 of the force scale, which the slip makes as large as
    |G| ~ kn u pi a^2 = 3e5 kN: up to 3e-5 kN against H = 35 kN, 1e-6;
    measured at most 5e-8);
(4) at the last step no sample sticks and |H / |V| - tan(phi)| <= 1e-6
    tan(phi) (the same margin; measured 1e-11);
(5) V changes along the swipe (the multiplier acts) and stays compressive.
With a fourth argument, the MPI launcher ("mpiexec;-np;2;..."), the same
scene runs on 2 ranks too (rank 0 owns n = 0, which carries w and e_V;
rank 1 owns n = 1, which carries u), after checks 1-5 on the serial run:
(6) the 2-rank run writes the same load-displacement.csv text in every
    column but the wall time, exactly: the interface's relative
    displacements of each harmonic come from its owner and are summed with
    zeros from the other rank, the 2x2 of the swipe reads the summed rigid
    motions, and one rank factorizes and solves the coupled tangent for
    both (doc/soil-plasticity.md section 3c).
Usage: swipe_interface_elastic_soil.py FOURIER_SSI_EXE SOURCE_DIR WORK_DIR
       [MPIEXEC]
"""
import csv
import math
import os
import shutil
import subprocess
import sys

exe, source_dir, work = sys.argv[1:4]
launcher = sys.argv[4].split(";") if len(sys.argv) > 4 else None
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
failed = 0

SCENE = """
subsection Mesh
  set R breakpoints    = 0, 1, 4
  set R cells          = 4, 4
  set R growth         = 1, 1.3
  set Z breakpoints    = -4, 0, 0.2
  set Z cells          = 6, 1
  set Z growth         = 0.8, 1
  set Material regions = 1: 0, 1, 0, 0.2
  set Removed regions  = 1, 4, 0, 0.2
  set Interface lines  = 5: z=0, r=0..1
end
subsection Boundary conditions
  set Dirichlet = 1: u=0, v=0, w=0; 2: u=0, v=0, w=0
end
subsection Interfaces
  set Interfaces = 5: coulomb, kn=1e6, ks=1e6, phi=20
end
subsection Output
  set Directory = out
end
subsection Rigid foundation
  set Enabled             = true
  set Tie                 = material
  set Id                  = 1
  set Horizontal force    = 1
  set Held vertical force = -100
  set Held motions        = w
end
subsection Materials
  set Materials = 0: G=1000, nu=0.3; 1: G=1000, nu=0.3
end
subsection Discretization
  set Harmonics = 0, 1
end
subsection Load path
  set Control           = displacement
  set Controlled motion = horizontal
  set Target            = 0.1
  set Load steps        = 10
  set Tolerance         = 1e-10
end
"""


def check(what, ok):
    global failed
    print(("  ok   " if ok else "  FAIL ") + what)
    failed += 0 if ok else 1


open(os.path.join(work, "scene.prm"), "w").write(SCENE)
p = subprocess.run([exe, "scene.prm"], cwd=work, text=True,
                   stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
print(p.stdout)
check("the run exits 0", p.returncode == 0)
check("the log names the coupled tangent with no soil points",
      "on the coupled tangent (a swipe; no soil points)" in p.stdout)
with open(os.path.join(work, "out", "load-displacement.csv")) as f:
    rows = list(csv.DictReader(f))
held = [r for r in rows if float(r["held_fraction"]) == 1. and
        float(r["load_factor"]) == 0.]
driven = [r for r in rows if float(r["load_factor"]) != 0.]
check("%d held and %d driven steps" % (len(held), len(driven)),
      len(held) > 0 and len(driven) == 10)
w0 = float(held[-1]["vertical_m"])
largest = max(abs(float(r["vertical_m"])) for r in rows)
drift = max(abs(float(r["vertical_m"]) - w0) for r in driven)
check("w held at the preload's %.6g m: largest drift %.3g m <= 1e-12 x %.3g"
      % (w0, drift, largest), drift <= 1e-12 * largest)
ratios = [float(r["H_kN"]) / abs(float(r["V_kN"])) for r in driven]
tan_phi = math.tan(math.radians(20.))
check("H / |V| <= tan 20 deg (1 + 1e-6) at every driven step (largest "
      "%.12f vs %.12f)" % (max(ratios), tan_phi),
      max(ratios) <= tan_phi * (1. + 1e-6))
last = driven[-1]
check("last step: no sample sticks (stick/slip/open %s/%s/%s)"
      % (last["stick"], last["slip"], last["open"]), int(last["stick"]) == 0)
check("last step: H / |V| = %.12f vs tan 20 deg = %.12f (rel. %.2g <= 1e-6)"
      % (ratios[-1], tan_phi, abs(ratios[-1] - tan_phi) / tan_phi),
      abs(ratios[-1] - tan_phi) <= 1e-6 * tan_phi)
Vs = [float(r["V_kN"]) for r in driven]
check("V moves along the swipe (%.6g to %.6g kN) and stays compressive"
      % (Vs[0], Vs[-1]), max(Vs) < 0. and max(Vs) - min(Vs) > 1e-6 * 100.)
if launcher:
    two = os.path.join(work, "ranks2")
    os.makedirs(two)
    p = subprocess.run(launcher + [exe, os.path.join(work, "scene.prm")],
                       cwd=two, text=True, stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT)
    check("the 2-rank run exits 0 with its harmonics over 2 ranks",
          p.returncode == 0 and "distributed over 2 MPI ranks" in p.stdout)
    if p.returncode == 0:
        with open(os.path.join(two, "out", "load-displacement.csv")) as f:
            rows2 = list(csv.DictReader(f))
        differ = [(i, k) for i, (a, b) in enumerate(zip(rows, rows2))
                  for k in a if k != "time_s" and a[k] != b[k]]
        check("2 ranks: %d rows as on 1 rank (%d), %d cells differ (exact)"
              % (len(rows2), len(rows), len(differ)),
              len(rows2) == len(rows) and not differ)
print("%d check(s) failed" % failed if failed else "all checks passed")
sys.exit(1 if failed else 0)
