#!/usr/bin/python3
"""Plastic soil with its harmonics distributed over MPI ranks
(doc/soil-plasticity.md section 3c): the bundled prm/pile-capacity.prm (the
rigid pile in a Tresca layer) cut to n = 0, 1, 2 and 4 displacement steps
to u = 0.02 d with Soil plasticity/Stiffness = STIFFNESS (elastic: the
initial-stiffness iteration, Aitken; tangent: Newton on the coupled
tangent), run by the program on 1 rank and under mpirun on 2 ranks (rank 0
owns n = 0 and 2, rank 1 owns n = 1: the loaded and controlled harmonic).
Checks:

(1) both runs exit 0 and write load-displacement.csv and results.csv once
    (rank 0), and the 2-rank log names the distribution;
(2) the scene exercises the coupling: the last step has plastic samples
    and every step after the first takes more than one iteration (else the
    comparison would not see the per-iteration exchange);
(3) the two runs write the SAME TEXT in every column of
    load-displacement.csv and every row of results.csv except the wall
    times (unit s). Exact, not a tolerance: each strain amplitude (of the
    rank's own harmonics) and each theta integral of the plastic stress (of
    the rank's own points) is computed by one rank with the serial run's
    arithmetic and summed over the ranks with zeros from the others
    (x + 0 = x); every rank then assembles the out-of-balance load, tests
    convergence and takes the Aitken update redundantly on those bits;
    per-harmonic norms and motions are added in the harmonics' order as the
    serial run adds them; each harmonic's back-substitution is the same
    sparse direct solve on its owner (one BLAS thread per process in both
    runs: OPENBLAS_NUM_THREADS=1, set by the ctest). A reduction in another
    order would show here in the last of the 12 digits written. Newton
    (tangent) adds: each point's softening integrals from its rank and
    each block row of the coupled tangent from its harmonic's owner, summed
    over the ranks (exact, x + 0 = x), one rank's factorization and solve
    broadcast, the load correction K_h du_h from h's owner: the same
    iteration counts (a column of load-displacement.csv) and the same
    digits, or the sum or the solve is not the serial one.
With STIFFNESS = swipe, the scene is a swipe test (doc/offshore-
foundations.md section 7) on prm/footing-capacity.prm (the rough footing on
Tresca soil) cut to n = 0, 1: V = -90 kN (about V_ult / 2) held in 4
steps, then u driven to 0.004 m in 4 Newton steps with w held where the
preload left it (rank 0 owns n = 0, which carries w and the swipe's unit
load e_V; rank 1 owns n = 1, which carries u). The swipe's multiplier mu
comes from a 2x2 system on the summed rigid motions, and K_t^-1 e_V from
the one factorizing rank: the same text again, or a rank read e_V or the
motions apart from the others. The scene must yield and V must move (mu
acts) for the comparison to see the swipe.
With STIFFNESS = growth, the pile listing n = 1 only with Maximum
harmonic = 3 and Newton (doc/soil-plasticity.md section 3e): the soil's
stress calls for n = 3 at the first step, the set grows on both runs
(n = 3 on rank 1), and the text must again be the same: the spectrum is
summed over the ranks (every rank takes the same decision) and the added
harmonic runs the distributed Newton above.
With STIFFNESS = iwan (or iwan-sand), the same pile slice in multi-surface
(iwan) clay (or sand)
through one cycle (u = +0.02, -0.02, +0.02 m, Newton): each point's
back-stresses live on the rank that owns the point, and the loop's
load-cycles.csv (its dissipated energy and damping ratio) must be the same
text as well.  The cycle must reverse H and dissipate energy.
With a sixth argument, the scene is prm/pile-adhesion.prm (plastic soil
and a coulomb shaft, doc/soil-plasticity.md section 6b) with that interface
law: the relative displacements are summed over the ranks too, and
interface-state.csv must also be written once and be the same text.
Usage: soil_output_same.py "MPIEXEC;-np;2;..." FOURIER_SSI_EXE SOURCE_DIR
       WORK_DIR STIFFNESS|swipe|growth|iwan|iwan-sand [INTERFACE_LAW]
"""
import os
import sys

import rank_runs

OVERRIDES = rank_runs.PILE_SLICE_N2

SWIPE = """
subsection Discretization
  set Harmonics = 0, 1
end
subsection Rigid foundation
  set Vertical force      = 0
  set Horizontal force    = 1
  set Held vertical force = -90
  set Held motions        = w
end
subsection Soil plasticity
  set Stiffness = tangent
end
subsection Load path
  set Theta samples     = 8
  set Controlled motion = horizontal
  set Target            = 0.004
  set Load steps        = 4
end
subsection Output
  set Directory = out
end
"""


GROWTH = """
subsection Discretization
  set Harmonics = 1
end
subsection Load path
  set Load steps       = 4
  set Target           = 0.02
  set Maximum harmonic = 3
end
subsection Soil plasticity
  set Stiffness = tangent
end
subsection Output
  set Directory = out
end
"""


def same_text(name, one, two, skip_row, skip_columns):
    """Rows compared as text, cell by cell; returns the number of failures."""
    if len(one) != len(two):
        print(f"  FAIL {name}: {len(two)} rows on 2 ranks, {len(one)} on 1")
        return 1
    differ = []
    compared = 0
    for a, b in zip(one, two):
        if skip_row(a):
            continue
        for column in a.keys():
            if column in skip_columns:
                continue
            compared += 1
            if a[column] != b[column]:
                differ.append(f"{column}: {a[column]} vs {b[column]}")
    ok = not differ and compared > 0
    print(f"  {'ok  ' if ok else 'FAIL'} {name}: {compared} cells compared, "
          f"{len(differ)} differ (exact){': ' if differ else ''}"
          f"{'; '.join(differ[:5])}")
    return 0 if ok else 1


def main():
    scene, overrides, files = ("prm/pile-capacity.prm",
                               OVERRIDES % sys.argv[5],
                               {"load-displacement.csv", "results.csv"})
    distribution = ("harmonics distributed over 2 MPI ranks: rank 0 "
                    "n=0 symmetric n=2 symmetric; rank 1 n=1 symmetric")
    swipe = sys.argv[5] == "swipe"
    if swipe:
        scene, overrides = "prm/footing-capacity.prm", SWIPE
        distribution = ("harmonics distributed over 2 MPI ranks: rank 0 "
                        "n=0 symmetric; rank 1 n=1 symmetric")
    growth = sys.argv[5] == "growth"
    if growth:
        overrides = GROWTH
        distribution = ("harmonics distributed over 2 MPI ranks: rank 0 "
                        "n=1 symmetric; rank 1")
    iwan = sys.argv[5] in ("iwan", "iwan-sand")
    if iwan:
        overrides = (rank_runs.PILE_SLICE_N2_IWAN_CYCLE if sys.argv[5] == "iwan"
                     else rank_runs.PILE_SLICE_N2_IWAN_SAND_CYCLE)
        files.add("load-cycles.csv")
    if len(sys.argv) > 6:
        scene = "prm/pile-adhesion.prm"
        overrides += ("subsection Interfaces\n  set Interfaces = %s\nend\n"
                      % sys.argv[6])
        files.add("interface-state.csv")
    outputs = rank_runs.on_one_and_two_ranks(sys.argv[:5], scene, overrides,
                                             distribution)
    failures = rank_runs.wrote_exactly(outputs, files)
    curve = {r: rank_runs.table(os.path.join(outputs[r], "load-displacement.csv"))
             for r in (1, 2)}
    iterations = [int(row["iterations"]) for row in curve[1]]
    plastic = int(curve[1][-1]["plastic"])
    ok = plastic > 0 and min(iterations[1:]) > 1
    print(f"  {'ok  ' if ok else 'FAIL'} the scene yields: {plastic} plastic "
          f"samples at the last step, iterations per step {iterations}")
    failures += not ok
    if swipe:
        V = [float(row["V_kN"]) for row in curve[1]
             if float(row["load_factor"]) != 0.]
        ok = len(V) == 4 and max(V) - min(V) > 1.
        print(f"  {'ok  ' if ok else 'FAIL'} the swipe moves V: "
              f"{V[0] if V else 0:.6g} to {V[-1] if V else 0:.6g} kN over "
              f"{len(V)} driven steps")
        failures += not ok
    if growth:
        solved = [int(row["harmonics"]) for row in curve[1]]
        ok = solved[-1] == 2
        print(f"  {'ok  ' if ok else 'FAIL'} the set grows: harmonics per "
              f"step {solved}")
        failures += not ok
    if iwan:
        cycles = {r: rank_runs.table(os.path.join(outputs[r], "load-cycles.csv"))
                  for r in (1, 2)}
        H = [float(row["H_kN"]) for row in curve[1]]
        damping = [float(row["damping_ratio"]) for row in cycles[1]]
        ok = min(H) < 0 < max(H) and len(damping) == 1 and damping[0] > 0
        print(f"  {'ok  ' if ok else 'FAIL'} the cycle reverses H "
              f"({min(H):.6g} to {max(H):.6g} kN) and dissipates: damping "
              f"ratio {damping}")
        failures += not ok
        failures += same_text("load-cycles.csv", cycles[1], cycles[2],
                              lambda row: False, set())
    failures += same_text("load-displacement.csv", curve[1], curve[2],
                          lambda row: False, {"time_s"})
    failures += same_text(
        "results.csv",
        rank_runs.table(os.path.join(outputs[1], "results.csv")),
        rank_runs.table(os.path.join(outputs[2], "results.csv")),
        lambda row: row["unit"] == "s", set())
    if "interface-state.csv" in files:
        failures += same_text(
            "interface-state.csv",
            rank_runs.table(os.path.join(outputs[1], "interface-state.csv")),
            rank_runs.table(os.path.join(outputs[2], "interface-state.csv")),
            lambda row: False, set())
    print(f"{'FAILED' if failures else 'passed'}: {failures} failure(s)")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
