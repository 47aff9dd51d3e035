#!/usr/bin/python3
"""The bundled prm/disc-gap.prm (a coulomb interface, 9 harmonics, 4
displacement steps) run as shipped by the program on 1 rank and under
mpirun on 2 ranks (harmonics distributed over the ranks,
doc/nonlinear-interfaces.md section 5 "Under MPI") with Write 3D vtu,
Write vtu and Interface state 3D on:

(1) both runs exit 0 and write load-displacement.csv, interface-state.csv,
    results.csv, solution-3d.vtu, interface-state-3d.vtu,
    interface-state-3d-step4.vtu with its .pvd and the last
    step's VTU of each harmonic once (rank 0 writes them whole: no per-rank
    pieces, the 2-rank log names the distribution);
(2) the curves agree: every column of load-displacement.csv except the
    iteration count, residual and wall time to 1e-7 relative to the largest
    magnitude of its kind (forces and moments together, motions together:
    a column that is round-off, like V here, is measured against the
    load, not against itself; both runs converge to a force residual
    below 1e-10 of the load; their iterates differ by round-off, amplified
    by the open modes' conditioning: 1e-7 is three decades above the
    iteration tolerance and far below a lost or doubled harmonic's share);
    the stick/slip/open counts exactly;
(3) the interface state (traction, relative displacement at every point,
    theta sample and step) to the same 1e-7 of the largest traction resp.
    relative displacement, the positions to 1e-7 of the largest, the states
    exactly;
(4) each harmonic's VTU fields (displacement and stress amplitudes) to two
    Float32 units in the last place (2.4e-7) of the field's largest
    |value|: the VTU stores Float32, so iterates that differ by round-off
    may round to neighbouring Float32 values; a harmonic written from
    another rank's field, or from an earlier step, differs by far more;
    the same bound for the revolved interface surface (Float64, so the
    bound is loose there: the states must be equal and the tractions
    within it).
Usage: coupled_output_same.py "MPIEXEC;-np;2;..." FOURIER_SSI_EXE SOURCE_DIR
       WORK_DIR
"""
import os
import sys

import rank_runs

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                ".."))
from vtu_reader import data_arrays  # noqa: E402

TOLERANCE = 1e-7
FLOAT32_TOLERANCE = 2.4e-7
HARMONIC_VTUS = [f"solution-n{n}-symmetric-cycle0.vtu" for n in range(9)]


def compare_vtu(name, one, two):
    """Failures: fields of two VTUs that differ by more than two Float32
    units of the field's largest |value|."""
    failures = 0
    a, b = data_arrays(one), data_arrays(two)
    for field in sorted(a):
        if field in ("connectivity", "offsets", "types"):
            continue
        x, y = a[field][1], b.get(field, (0, []))[1]
        scale = max(max(abs(v) for v in x), 1e-300)
        error = (max(abs(p - q) for p, q in zip(x, y)) / scale
                 if len(x) == len(y) else float("inf"))
        ok = error <= FLOAT32_TOLERANCE
        if not ok or field in ("U_radial", "sigma_r"):
            print(f"  {'ok  ' if ok else 'FAIL'} {name} {field}: max "
                  f"difference {error:.2e} of its largest |value| "
                  f"{scale:.6g} (tol {FLOAT32_TOLERANCE})")
        failures += not ok
    return failures


def compare(name, one, two, exact, skip, kinds):
    """kinds: column -> its kind; the scale is the largest |value| of the
    columns of that kind (a column of its own kind if not listed)."""
    failures = 0
    if len(one) != len(two):
        print(f"  FAIL {name}: {len(two)} rows on 2 ranks, {len(one)} on 1")
        return 1
    largest = {}
    for column in one[0].keys():
        if column in skip or column in exact:
            continue
        kind = kinds.get(column, column)
        largest[kind] = max(largest.get(kind, 0.),
                            max(abs(float(a[column])) for a in one))
    for column in one[0].keys():
        if column in skip:
            continue
        if column in exact:
            differ = sum(a[column] != b[column] for a, b in zip(one, two))
            ok = differ == 0
            print(f"  {'ok  ' if ok else 'FAIL'} {name} {column}: "
                  f"{differ} rows differ (exact)")
            failures += not ok
            continue
        x = [float(a[column]) for a in one]
        y = [float(b[column]) for b in two]
        scale = max(largest[kinds.get(column, column)], 1e-300)
        error = max(abs(a - b) for a, b in zip(x, y)) / scale
        ok = error <= TOLERANCE
        print(f"  {'ok  ' if ok else 'FAIL'} {name} {column}: max difference "
              f"{error:.2e} of the largest |value| of its kind {scale:.6g} "
              f"(tol {TOLERANCE})")
        failures += not ok
    return failures


def main():
    outputs = rank_runs.on_one_and_two_ranks(
        sys.argv, "prm/disc-gap.prm", ("\nsubsection Output\n  set Directory = out\n"
         "  set Write 3D vtu = true\n  set Write vtu = true\n"
         "  set Interface state 3D = true\nend\n"),
        "harmonics distributed over 2 MPI ranks")
    failures = rank_runs.wrote_exactly(
        outputs, {"load-displacement.csv", "interface-state.csv",
                "results.csv", "solution-3d.vtu", "interface-state-3d.vtu",
                "interface-state-3d-step4.vtu", "interface-state-3d.pvd"} |
        set(HARMONIC_VTUS))
    failures += compare("load-displacement.csv",
                        rank_runs.table(os.path.join(outputs[1], "load-displacement.csv")),
                        rank_runs.table(os.path.join(outputs[2], "load-displacement.csv")),
                        exact={"step", "stick", "slip", "open", "harmonics",
                               "converged"},
                        skip={"iterations", "residual", "time_s"},
                        kinds={"load_factor": "factor", "V_kN": "force",
                               "H_kN": "force", "M_kNm": "force",
                               "T_kNm": "force", "vertical_m": "motion",
                               "horizontal_m": "motion",
                               "rotation_rad": "motion",
                               "twist_rad": "motion"})
    failures += compare("interface-state.csv",
                        rank_runs.table(os.path.join(outputs[1], "interface-state.csv")),
                        rank_runs.table(os.path.join(outputs[2], "interface-state.csv")),
                        exact={"step", "point", "state"}, skip=set(),
                        kinds={"r_m": "position", "z_m": "position",
                               "normal_r": "normal", "normal_z": "normal",
                               "t_s_kPa": "traction", "t_n_kPa": "traction",
                               "t_theta_kPa": "traction",
                               "d_s_m": "relative", "d_n_m": "relative",
                               "d_theta_m": "relative"})
    for vtu in HARMONIC_VTUS + ["interface-state-3d-step4.vtu"]:
        failures += compare_vtu(vtu, os.path.join(outputs[1], vtu),
                                os.path.join(outputs[2], vtu))
    print(f"{'FAILED' if failures else 'passed'}: {failures} failure(s)")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
