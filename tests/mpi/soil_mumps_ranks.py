#!/usr/bin/python3
"""The coupled Newton tangent factorized by MUMPS over the ranks
(`Linear solver/Distributed = always`, doc/soil-plasticity.md section 3c):
prm/pile-capacity.prm cut to n = 0, 1, 2 and 4 displacement steps to
u = 0.02 d, Newton, run three ways:
  serial   1 rank, UMFPACK on the whole tangent (the default);
  mumps1   1 rank, Distributed = always: MUMPS on the whole tangent;
  mumps2   2 ranks, Distributed = always: each rank the block rows of its
           harmonics (rank 0 n = 0 and 2, rank 1 n = 1), MUMPS over both.
Checks:
(1) every run exits 0; the MUMPS runs name the distributed tangent and the
    ranks in their log;
(2) the scene yields (plastic samples at the last step, more than one
    Newton update per step after the first: else the tangent is not
    exercised);
(3) the same Newton update counts in every step, and every number of
    load-displacement.csv and results.csv within 1e-10 of the serial run:
    a force relative to the largest force, a motion to the largest motion
    (a rotation in rad times 1 m), any other number to its own largest
    value; the wall times, the converged residual and the largest yield
    value after the return mapping (round-off by construction) aside.
    Why 1e-10 and not the same text: the two factorizations order their
    pivots differently, so each Newton direction differs at the round-off
    of the tangent's factors; Newton converges quadratically, so the
    converged state keeps only the last update's share of that error
    (2e-14 measured on 1 and 2 ranks). A wrong factorization (a missing
    block row, a rank's rows misplaced) moves the curve by far more than
    1e-10 or changes the update counts.
With a fifth argument `iwan`, the slice is in multi-surface (iwan) clay
through one cycle (rank_runs.PILE_SLICE_N2_IWAN_CYCLE): the hysteretic
points' consistent tangent in the distributed matrix, and load-cycles.csv
(the loop's loads and motions on their families' scales, its energies,
stiffness and damping ratio each on its own largest value) within 1e-10
as well.
Usage: soil_mumps_ranks.py "MPIEXEC;-np;2;..." FOURIER_SSI_EXE SOURCE_DIR
       WORK_DIR [iwan]
"""
import os
import shutil
import sys

import rank_runs

OVERRIDES = {"tresca": rank_runs.PILE_SLICE_N2 % "tangent",
             "iwan": rank_runs.PILE_SLICE_N2_IWAN_CYCLE}

MUMPS = """
subsection Linear solver
  set Distributed = always
end
"""

TOLERANCE = 1e-10


# The scale each quantity is compared on: a force on the largest force, a
# motion on the largest motion (a rotation in rad times 1 m, the pile's
# diameter), a count or a factor on its own largest value. The rotation of
# a pile pushed sideways is round-off (1e-12 rad): it is compared on the
# motions' scale, not its own.
FAMILY = {"kN": "force", "kN.m": "force", "m": "motion", "rad": "motion"}
CURVE_UNITS = {"V_kN": "kN", "H_kN": "kN", "M_kNm": "kN.m", "T_kNm": "kN.m",
               "vertical_m": "m", "horizontal_m": "m", "rotation_rad": "rad",
               "twist_rad": "rad"}
# Round-off by construction, not compared: the wall times, the converged
# residual, and the largest yield value after the return mapping (f = 0 to
# 1e-14 kPa).
ROUND_OFF = {"time_s", "residual", "max_yield_kPa", "step_wall_time",
             "step_residual", "step_largest_yield_value"}


def largest_difference(one, two):
    """one, two: lists of (name, unit, value). max |a - b| over the scale of
    its family, with where it is; inf if the names differ."""
    if [n for n, _, _ in one] != [n for n, _, _ in two]:
        return float("inf"), "the rows"
    scale = {}
    for name, unit, value in one:
        family = FAMILY.get(unit, name)
        scale[family] = max(scale.get(family, 0.), abs(value))
    worst, where = 0., ""
    for index, ((name, unit, a), (_, _, b)) in enumerate(zip(one, two)):
        if name in ROUND_OFF:
            continue
        difference = abs(a - b) / (scale[FAMILY.get(unit, name)] or 1.)
        if difference > worst:
            worst, where = difference, f"{name} (cell {index})"
    return worst, where


def curve_cells(rows):
    cells = []
    for row in rows:
        for column, text in row.items():
            try:
                cells.append((column, CURVE_UNITS.get(column, "-"),
                              float(text)))
            except (TypeError, ValueError):
                pass
    return cells


def cycle_cells(rows):
    """load-cycles.csv's numbers with the unit of their column's suffix:
    a load at zero motion (or a motion at zero load: the pile's rotation is
    round-off again) on its family's scale, an energy, a stiffness or a
    damping ratio on its own largest value."""
    cells = []
    for row in rows:
        for column, text in row.items():
            unit = next((u for u in ("kN", "m", "rad")
                         if column.endswith("_" + u)), "-")
            try:
                cells.append((column, unit, float(text)))
            except (TypeError, ValueError):
                pass
    return cells


def result_cells(rows):
    cells = []
    for row in rows:
        try:
            cells.append((row["quantity"], row["unit"], float(row["value"])))
        except ValueError:
            pass
    return cells


def main():
    mpiexec, exe, source, work = sys.argv[1].split(";"), *sys.argv[2:5]
    law = sys.argv[5] if len(sys.argv) > 5 else "tresca"
    shutil.rmtree(work, ignore_errors=True)
    with open(os.path.join(source, "prm/pile-capacity.prm")) as f:
        scene = f.read() + OVERRIDES[law]
    runs = {"serial": ([], ""), "mumps1": ([], MUMPS),
            "mumps2": (mpiexec, MUMPS)}
    curves, results, cycles, failures = {}, {}, {}, 0
    for name, (launcher, appended) in runs.items():
        directory = os.path.join(work, name)
        os.makedirs(directory)
        prm = os.path.join(directory, "pile-capacity.prm")
        with open(prm, "w") as f:
            f.write(scene + appended)
        log = rank_runs.run(launcher + [exe, prm], directory)
        ranks = 2 if launcher else 1
        if appended:
            named = (f"coupled Newton tangent: one matrix distributed over "
                     f"{ranks} MPI rank(s)") in log
            print(f"  {'ok  ' if named else 'FAIL'} {name} names the "
                  f"distributed tangent on {ranks} rank(s)")
            failures += not named
        out = os.path.join(directory, "out")
        curves[name] = rank_runs.table(os.path.join(out,
                                                    "load-displacement.csv"))
        results[name] = rank_runs.table(os.path.join(out, "results.csv"))
        if law == "iwan":
            cycles[name] = rank_runs.table(os.path.join(out, "load-cycles.csv"))
    serial = curves["serial"]
    iterations = [int(row["iterations"]) for row in serial]
    plastic = int(serial[-1]["plastic"])
    ok = plastic > 0 and min(iterations[1:]) > 1
    print(f"  {'ok  ' if ok else 'FAIL'} the scene yields: {plastic} plastic "
          f"samples at the last step, Newton updates per step {iterations}")
    failures += not ok
    for name in ("mumps1", "mumps2"):
        counts = [int(row["iterations"]) for row in curves[name]]
        ok = counts == iterations
        print(f"  {'ok  ' if ok else 'FAIL'} {name}: Newton updates per step "
              f"{counts} (serial {iterations})")
        failures += not ok
        if not ok:
            continue
        worst, where = largest_difference(curve_cells(serial),
                                          curve_cells(curves[name]))
        ok = worst <= TOLERANCE
        print(f"  {'ok  ' if ok else 'FAIL'} {name}: load-displacement.csv "
              f"within {worst:.2e} of serial (bound {TOLERANCE:g}; at "
              f"{where})")
        failures += not ok
        worst, where = largest_difference(result_cells(results["serial"]),
                                          result_cells(results[name]))
        ok = worst <= TOLERANCE
        print(f"  {'ok  ' if ok else 'FAIL'} {name}: results.csv within "
              f"{worst:.2e} of serial (bound {TOLERANCE:g}; at {where})")
        failures += not ok
        if law == "iwan":
            worst, where = largest_difference(cycle_cells(cycles["serial"]),
                                              cycle_cells(cycles[name]))
            ok = worst <= TOLERANCE and len(cycles[name]) == 1
            print(f"  {'ok  ' if ok else 'FAIL'} {name}: load-cycles.csv "
                  f"({len(cycles[name])} cycle) within {worst:.2e} of serial "
                  f"(bound {TOLERANCE:g}; at {where})")
            failures += not ok
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
