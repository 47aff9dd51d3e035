#!/usr/bin/python3
"""The multi-surface (iwan) clay in a coupled run, monotonic and cyclic,
against the closed form of a rigid disc twisted in a ring
(doc/derivations/torsion_ring_masing.py; doc/cyclic-loading.md section 4).

Scene: disc a = 0.5 m (rigid, tied material 1) in a ring to b = 5 m, one
cell of height 1 m, harmonic n = 0 antisymmetric (torsion only); clay
G0 = 3000 kPa, s_u = 10 kPa, gamma_ref = 0.01, 20 surfaces; twist
controlled. Torsion is statically determinate, so the reference is exact for
the model's own tangent polygon.

Checks, with their reasons:
  - the virgin T(theta) at every step below 0.8 of the failure twist within
    1e-4 of (T1): the FE error of w(r) on the 24 graded cells (measured
    2.6e-5 at most; it is the mesh's, the solver converges to 1e-10);
  - Newton needs at most 7 updates per step (the consistent tangent; 2-3
    measured);
  - cyclic, Targets = +-0.0015 and 2 cycles of 10 steps a segment: every
    step on Masing's branch (T2) from its turning point within 1e-4 of the
    peak torque (same mesh error);
  - the loops close: cycle 2's row equals cycle 1's to 1e-9 (a Masing
    material returns to the same state; the solver tolerance 1e-10);
  - the cycle table's secant stiffness, dissipated energy and damping
    ratio against the same trapezoid sums over the reference torques at
    the same twists, within 2e-3 (the loop area is the difference of two
    branches, 0.4 of W_s, so the mesh error of T enters about 1/0.4 x 4
    sampled points; measured below);
  - the twist at zero load against (T2) at T = 0 within 2 % of the
    twist there (interpolated linearly between two steps on a curved
    branch: the chord's error; measured);
  - one surface is one von Mises element of G0 and s_u: in pure shear it
    is Tresca, so its path equals a tresca run's to 1e-9 of the torque,
    beyond failure too (two independent return mappings);
  - a tresca ring cycled below first yield gets the one-line note that
    its loops dissipate nothing;
  - a measured degradation table (iwan, table=...) instead of the
    hyperbola: its model is the table's polygon, so the same closed form
    holds with that polygon. The table is the hyperbola read at 7 strains
    (4 digits), so the strains and their gradients are those of the
    hyperbola's run: the virgin T(theta) below 0.8 of its failure twist
    within the same 1e-4 (the mesh's error);
  - the multi-surface sand (iwan-sand, c' = 2 kPa, phi' = 30, psi = 0,
    R_f = 0.9, 20 surfaces) from an isotropic p'0 = 20 kPa (Surcharge,
    K0 = 1): in pure shear at a constant mean stress it is the clay's
    polygon with s_u = tau_f = p'0 sin phi + c cos phi and gamma_ref =
    tau_f / (R_f G0) (doc/derivations/multi_surface_sand.md section 1), so
    the same closed form holds: the virgin T(theta) below 0.8 of the
    failure twist within the same 1e-4, on 48 graded cells (its R_f = 0.9
    bends the polygon more than the clay's 1/3 does, and 24 cells gave
    2.7e-4, 48 cells 4.8e-5: the mesh's error).
Usage: iwan_torsion_ring.py FOURIER_SSI_EXE SOURCE_DIR WORK_DIR
"""
import csv
import math
import os
import shutil
import subprocess
import sys

exe, source_dir, work = sys.argv[1:4]
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(source_dir, "doc", "derivations"))
from relative_checks import finish, that as check  # noqa: E402
from torsion_ring_masing import TorsionRing  # noqa: E402

shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)

SCENE = """
subsection Discretization
  set Harmonics         = 0
  set Family            = antisymmetric
  set Polynomial degree = 2
end
subsection Mesh
  set Type              = rectangle
  set R breakpoints     = 0, 0.5, 5
  set R cells           = 2, 24
  set R growth          = 1, 1.12
  set Z breakpoints     = -0.5, 0.5
  set Z cells           = 1
  set Material regions  = 1: 0, 0.5, -0.5, 0.5
end
subsection Materials
  set Materials = 0: G=3000, nu=0.3; 1: G=3000, nu=0.3
end
subsection Soil plasticity
  set Laws = {law}
end
subsection Rigid foundation
  set Enabled             = true
  set Tie                 = material
  set Id                  = 1
  set Reference elevation = 0
  set Vertical force      = 0
  set Torque              = 1
end
subsection Load path
  set Control           = displacement
  set Controlled motion = twist
  set Load steps        = 10
  set Tolerance         = 1e-10
{path}
end
subsection Boundary conditions
  set Dirichlet = 1: u=0, v=0, w=0; 2: v=0; 3: v=0
end
subsection Output
  set Directory = {name}
  set Write vtu = false
end
"""
IWAN = "0: iwan, su=10, gref=0.01, surfaces={n}"


def run(name, law, path, extra=""):
    open(os.path.join(work, name + ".prm"), "w").write(
        SCENE.format(law=law, path=path, name=name) + extra)
    r = subprocess.run([exe, name + ".prm"], cwd=work, capture_output=True,
                       text=True)
    if r.returncode != 0:
        sys.exit(name + " failed: " + r.stderr)
    rows = list(csv.DictReader(open(os.path.join(work, name,
                                                 "load-displacement.csv"))))
    return r.stdout, rows


def virgin_error(closed_form, rows):
    """The largest relative error of T(theta) against (T1) below 0.8 of
    the failure twist, and that twist."""
    failure = closed_form.virgin_twist(closed_form.failure_torque *
                                       (1 - 1e-12))
    worst = max(abs(float(r["T_kNm"]) /
                    closed_form.torque_at((0., 0.), float(r["twist_rad"])) -
                    1.)
                for r in rows if float(r["twist_rad"]) < 0.8 * failure)
    return worst, failure


ring = TorsionRing(3000., 10., 0.01, 20, 0.5, 5., 1.)
failure_twist = ring.virgin_twist(ring.failure_torque * (1 - 1e-12))

# 1. The virgin curve.
log, rows = run("monotonic", IWAN.format(n=20), "  set Target = 0.004")
worst, _ = virgin_error(ring, rows)
check(worst <= 1e-4, "virgin T(theta) below 0.8 of the failure twist "
      "within 1e-4 of the closed form (worst %.2e)" % worst)
updates = max(int(r["iterations"]) for r in rows)
check(updates <= 7, "at most 7 Newton updates per step (%d)" % updates)

# 2. Two cycles between +-0.0015.
amplitude = 0.0015
log, rows = run("cyclic", IWAN.format(n=20),
                "  set Targets = %g, %g\n  set Cycles = 2" % (amplitude,
                                                               -amplitude))
peak = ring.torque_at((0., 0.), amplitude)
turning, reference = (0., 0.), []
segment_of = [int(r["segment"]) for r in rows]
for i, r in enumerate(rows):
    theta = float(r["twist_rad"])
    reference.append(ring.torque_at(turning, theta))
    last_of_segment = i + 1 == len(rows) or segment_of[i + 1] != segment_of[i]
    if last_of_segment:
        turning = (theta, reference[-1])
worst = max(abs(float(r["T_kNm"]) - t) for r, t in zip(rows, reference))
check(worst <= 1e-4 * peak, "every step on Masing's branches within 1e-4 "
      "of the peak torque (worst %.2e)" % (worst / peak))
check(segment_of == [s for s in range(1, 6) for _ in range(10)],
      "load-displacement.csv numbers the 5 segments of 10 steps")

cycles = list(csv.DictReader(open(os.path.join(work, "cyclic",
                                               "load-cycles.csv"))))
check(len(cycles) == 2, "two cycles in load-cycles.csv")
same = all(abs(float(cycles[1][k]) - float(cycles[0][k])) <=
           1e-9 * max(1., abs(float(cycles[0][k])))
           for k in cycles[0] if k != "cycle" and cycles[0][k] != "")
check(same, "cycle 2 repeats cycle 1 to 1e-9 (the loop closes)")

# The reference loop by the same sums over the same twists: A (end of
# segment 1, step 10) -> B (end of 2) -> A' (end of 3).
points = [(float(rows[i]["twist_rad"]), reference[i]) for i in range(9, 30)]
area = sum(0.5 * (t1 + t2) * (u2 - u1)
           for (u1, t1), (u2, t2) in zip(points[:-1], points[1:]))
(u_b, t_b), (u_e, t_e) = points[10], points[20]
stored = 0.5 * (0.5 * abs(t_e - t_b)) * (0.5 * abs(u_e - u_b))
xi = area / (4. * 3.141592653589793 * stored)
row = cycles[0]
for name, value, ref in [
        ("secant stiffness", float(row["secant_stiffness_kNm_per_rad"]),
         (t_e - t_b) / (u_e - u_b)),
        ("dissipated energy", float(row["dissipated_energy_kJ"]), area),
        ("damping ratio", float(row["damping_ratio"]), xi)]:
    check(abs(value / ref - 1.) <= 2e-3, "%s %.6g against %.6g (%.1e)" %
          (name, value, ref, value / ref - 1.))
zero_twist = ring.twist_from((-amplitude, -peak), 0.)
got = float(row["zero_load_twist_rad"])
check(abs(got - zero_twist) <= 0.02 * abs(zero_twist),
      "twist at zero load %.5g rad against %.5g rad" % (got, zero_twist))
check("cycle 1: T " in log and "damping ratio" in log,
      "the log prints a line per cycle")

# 3. One surface is Tresca in pure shear.
_, single = run("single_surface", IWAN.format(n=1), "  set Target = 0.004")
_, tresca = run("tresca", "0: tresca, su=10", "  set Target = 0.004")
worst = max(abs(float(a["T_kNm"]) - float(b["T_kNm"]))
            for a, b in zip(single, tresca))
check(len(single) == len(tresca) and worst <= 1e-9 * ring.failure_torque,
      "iwan with 1 surface = tresca to 1e-9 of the torque (%.1e)" %
      (worst / ring.failure_torque))

# 4. Tresca below first yield: loops without hysteresis.
log, _ = run("tresca_elastic", "0: tresca, su=10",
             "  set Targets = 0.0002, -0.0002\n  set Cycles = 1")
check("note: cycle 1 dissipates nothing" in log,
      "a tresca loop below first yield gets the note")

# 5. A measured degradation curve (strain : G/G0) instead of the hyperbola.
TABLE = [(1e-6, 1.), (1e-4, 0.9901), (3e-4, 0.9709), (1e-3, 0.9091),
         (2e-3, 0.8333), (3e-3, 0.7692), (4e-3, 0.7143)]
table_ring = TorsionRing(3000., 10., None, None, 0.5, 5., 1., table=TABLE)
table_failure = table_ring.virgin_twist(table_ring.failure_torque *
                                        (1 - 1e-12))
law = "0: iwan, su=10, table=" + " ".join("%g:%g" % p for p in TABLE)
_, rows = run("table", law, "  set Target = %.6g" % (1.25 * table_failure))
worst, _ = virgin_error(table_ring, rows)
check(worst <= 1e-4, "table: virgin T(theta) below 0.8 of the failure twist "
      "(%.4g rad) within 1e-4 of the closed form (worst %.2e)"
      % (table_failure, worst))

# 6. The multi-surface sand: the clay's closed form with s_u = tau_f.
P0, C, PHI, RF = 20., 2., math.radians(30.), 0.9
TAU_F = P0 * math.sin(PHI) + C * math.cos(PHI)
sand_ring = TorsionRing(3000., TAU_F, TAU_F / (RF * 3000.), 20, 0.5, 5., 1.)
sand_failure = sand_ring.virgin_twist(sand_ring.failure_torque * (1 - 1e-12))
GEOSTATIC = """
subsection Mesh
  set R cells  = 2, 48
  set R growth = 1, 1.058
end
subsection Materials
  set Ground surface elevation = 0.5
end
subsection Initial stress
  set Surcharge = 20
  set K0        = 1
end
"""
_, rows = run("sand", "0: iwan-sand, c=2, phi=30, psi=0, rf=0.9, surfaces=20",
              "  set Target = %.6g" % (1.25 * sand_failure), GEOSTATIC)
worst, _ = virgin_error(sand_ring, rows)
check(worst <= 1e-4, "iwan-sand: virgin T(theta) below 0.8 of the failure "
      "twist (%.4g rad) within 1e-4 of the clay's closed form with s_u = "
      "tau_f = %.4g kPa (worst %.2e)" % (sand_failure, TAU_F, worst))

finish()
