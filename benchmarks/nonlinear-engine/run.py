#!/usr/bin/python3
"""Newton against the initial-stiffness iteration for stiff coulomb
interfaces (doc/nonlinear-interfaces.md section 5b): the disc in a ring of
prm/disc-gap.prm with harmonics n = 0..32 and a tensionless Coulomb interface
(mu = tan(phi) = 0.3, c = 0, sigma_t = 0), kn = ks = kappa G / r0 for
kappa = kn r0 / G = 1e2 ... 1e8 (G = 38462 kPa, r0 = 0.5 m), 4 displacement
steps to ubar = 1e-3 m; and the exact `contact, c=0, phi=...` interface
(augmented Lagrangian, no kn) with Newton and 65 samples, one row.

    /usr/bin/python3 benchmarks/nonlinear-engine/run.py [BUILD_DIR] [MAIN_EXE] [RUNS]
    /usr/bin/python3 benchmarks/nonlinear-engine/run.py [BUILD_DIR] - [RUNS] defaults

The second form runs this build only, on kappa = 1e6 and `contact` with
every Load path entry at its default (the solver and the samples chosen by
the scene, doc/nonlinear-interfaces.md section 5b), and writes
results-defaults.csv and results-defaults.md: the promise is at most 15
Newton updates in every step and at most 2 s for the whole run.

Four solvers side by side in this one invocation, RUNS times each
(default 3, medians; a case that fails or times out is run once):
  * newton65: this build, Stiffness = tangent, Theta samples = 65 =
    2 n_max + 1 (one sample per degree of freedom of the band-limited gap);
  * newton:  this build, Load path/Stiffness = tangent, Theta samples =
    4 (n_max + 1) = 132 (the default before Newton's default became
    2 n_max + 1; set explicitly so that the table stays reproducible);
  * initial: this build, Stiffness = initial, Acceleration = anderson (the
    same iteration as before, with the convergence test against the
    internal force scale);
  * main:    MAIN_EXE (default /work/main/build/fourier-ssi),
    Acceleration = anderson;
  * main65:  MAIN_EXE with Stiffness = tangent and 65 samples.
The fixed-point runs get Maximum iterations = 20000 per step and every run
a wall-clock limit of TIMEOUT s. Writes results.csv and results.md next to
this file. The machine is shared (2 cores): times carry the noise of other
jobs; the ratios are from runs made side by side.
"""
import csv
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.normpath(os.path.join(HERE, "..", ".."))
KAPPAS = (1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8)
SOLVERS = ("newton65", "newton", "initial", "main", "main65")
CONTACT = "contact"
TIMEOUT = 25.
G, R0 = 1e5 / 2.6, 0.5
FIELDS = ["kappa", "solver", "runs", "converged", "P_over_ubar_kN_per_m",
          "iterations_step1", "iterations_worst", "iterations_total",
          "multiplier_updates_total", "states_step1",
          "solve_time_s", "run_wall_s", "note"]


def scene(kappa, solver, out):
    text = open(os.path.join(SOURCE, "prm", "disc-gap.prm")).read()
    phi = math.degrees(math.atan(0.3))
    if kappa == CONTACT:
        law = "5: contact, c=0, phi=%.17g" % phi
    else:
        kn = kappa * G / R0
        law = "5: coulomb, kn=%.17g, ks=%.17g, c=0, phi=%.17g, " \
            "sigma_t=0" % (kn, kn, phi)
    text = re.sub(r"set Interfaces = [^\n]*", "set Interfaces = " + law, text)
    text = re.sub(r"set Directory *= [^\n]*", "set Directory = " + out, text)
    text += "\nsubsection Discretization\n  set Harmonics = %s\nend\n" % (
        ", ".join(str(n) for n in range(33)))
    if solver == "defaults":
        return text  # every Load path entry at its default
    text += "\nsubsection Load path\n  set Acceleration = anderson\n"
    if solver.startswith("newton") or solver == "main65":
        text += "  set Stiffness = tangent\n"
        if solver in ("newton65", "main65"):
            text += "  set Theta samples = 65\n"
        elif solver == "newton":
            text += "  set Theta samples = 132\n"
    else:
        text += "  set Maximum iterations = 20000\n"
        if solver == "initial":
            text += "  set Stiffness = initial\n"
    return text + "end\n"


def run_once(exe, kappa, solver, work):
    prm = os.path.join(work, "case.prm")
    with open(prm, "w") as f:
        f.write(scene(kappa, solver, os.path.join(work, "out")))
    start = time.time()
    try:
        p = subprocess.run([exe, prm], capture_output=True, text=True,
                           timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        return {"converged": False, "note": "timeout %.0f s" % TIMEOUT,
                "wall": time.time() - start}
    wall = time.time() - start
    log = p.stdout + p.stderr
    steps = re.findall(r"step \d+: factor ([-0-9.e+]+),.*? u ([-0-9.e+]+) m"
                       r".*?; (\d+) iterations; (?:interface )?stick/slip/open "
                       r"(\d+/\d+/\d+)",
                       log)
    solve = re.search(r"coupled solve: \d+ steps in ([0-9.e+-]+) s", log)
    if p.returncode != 0 or len(steps) != 4 or not solve:
        error = [l for l in log.splitlines() if "error:" in l]
        note = "not converged" if error and "did not converge" in error[0] \
            else (error[0][-80:] if error else "failed")
        return {"converged": False, "note": note, "wall": wall}
    # P / ubar of the last step from the CSV (12 digits; the log has 6).
    with open(os.path.join(work, "out", "load-displacement.csv")) as f:
        last = list(csv.DictReader(f))[-1]
    factor, u = float(last["load_factor"]), float(last["horizontal_m"])
    return {"converged": True, "P": factor / u,
            "it1": int(steps[0][2]),
            "worst": max(int(s[2]) for s in steps),
            "total": sum(int(s[2]) for s in steps),
            "updates": sum(int(n) for n in re.findall(
                r"(\d+) contact multiplier updates", log)),
            "states": steps[0][3], "solve": float(solve.group(1)),
            "wall": wall, "note": ""}


def summary_row(kappa, solver, results):
    """One row of results.csv: the first run's answers, median times."""
    ok = all(r["converged"] for r in results)
    r0 = results[0]
    row = {"kappa": label(kappa), "solver": solver, "runs": len(results),
           "converged": int(ok), "note": r0["note"],
           "run_wall_s": "%.2f" % statistics.median(r["wall"]
                                                     for r in results)}
    if ok:
        row.update({
            "P_over_ubar_kN_per_m": "%.12g" % r0["P"],
            "iterations_step1": r0["it1"], "iterations_worst": r0["worst"],
            "multiplier_updates_total": r0["updates"],
            "iterations_total": r0["total"], "states_step1": r0["states"],
            "solve_time_s": "%.3f" % statistics.median(r["solve"]
                                                        for r in results)})
    return row


def defaults(build, runs):
    """kappa = 1e6 and contact, every Load path entry at its default."""
    exe = os.path.join(build, "fourier-ssi")
    load, rows = [os.getloadavg()[0]], []
    with tempfile.TemporaryDirectory() as work:
        for kappa in (1e6, CONTACT):
            results = [run_once(exe, kappa, "defaults", work)
                       for _ in range(runs)]
            row = summary_row(kappa, "defaults", results)
            rows.append(row)
            print(row, flush=True)
    load.append(os.getloadavg()[0])
    with open(os.path.join(HERE, "results-defaults.csv"), "w",
              newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS)
        w.writeheader()
        w.writerows(rows)
    out = ["# The disc at kappa = 1e6 and with contact, every Load path "
           "entry at its default", "",
           "Generated by `benchmarks/nonlinear-engine/run.py BUILD - %d "
           "defaults` (%d runs each, medians) on HEAD %s. Disc in a ring "
           "(prm/disc-gap.prm), harmonics n = 0..32, tensionless Coulomb "
           "mu = 0.3 (kappa = kn r0 / G = 1e6) or `contact, c=0, phi=16.7`, "
           "4 displacement steps to ubar = 1e-3 m; nothing else set. Asked: "
           "at most 15 Newton updates in every step and at most 2 s for the "
           "whole run (start-up, mesh, factorizations, output). Load average "
           "%.1f at the start, %.1f at the end (2 cores)."
           % (runs, runs, commit_of(exe) or "?", load[0], load[1]), "",
           "| interface | converged | updates, step 1 / worst | solve [s] | "
           "whole run [s] | P/ubar [kN/m] | meets 15 updates, 2 s |",
           "|---|---|---|---|---|---|---|"]
    for r in rows:
        ok = r["converged"] and int(r["iterations_worst"]) <= 15 and \
            float(r["run_wall_s"]) <= 2.
        out.append("| %s | %s | %s | %s | %s | %s | %s |" % (
            "coulomb, kappa = 1e6" if r["kappa"] != CONTACT else "contact",
            "yes" if r["converged"] else r["note"],
            "%s / %s" % (r.get("iterations_step1", "-"),
                         r.get("iterations_worst", "-")),
            r.get("solve_time_s", "-"), r["run_wall_s"],
            r.get("P_over_ubar_kN_per_m", "-"), "yes" if ok else "NO"))
    with open(os.path.join(HERE, "results-defaults.md"), "w") as f:
        f.write("\n".join(out) + "\n")


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else os.path.join(SOURCE, "build")
    if len(sys.argv) > 4 and sys.argv[4] == "defaults":
        defaults(build, int(sys.argv[3]))
        return
    main_exe = sys.argv[2] if len(sys.argv) > 2 else \
        "/work/main/build/fourier-ssi"
    runs = int(sys.argv[3]) if len(sys.argv) > 3 else 3
    exes = {"newton65": os.path.join(build, "fourier-ssi"),
            "newton": os.path.join(build, "fourier-ssi"),
            "initial": os.path.join(build, "fourier-ssi"),
            "main": main_exe, "main65": main_exe}
    load = [os.getloadavg()[0]]
    rows = []
    with tempfile.TemporaryDirectory() as work:
        cases = [(k, s) for k in KAPPAS for s in SOLVERS] + \
            [(CONTACT, "newton65")]
        for kappa, solver in cases:
            if True:
                results = [run_once(exes[solver], kappa, solver, work)]
                if results[0]["converged"]:
                    results += [run_once(exes[solver], kappa, solver, work)
                                for _ in range(runs - 1)]
                row = summary_row(kappa, solver, results)
                rows.append(row)
                print(row, flush=True)
                write_csv(rows)
    load.append(os.getloadavg()[0])
    write_table(rows, runs, load, main_exe)


def write_csv(rows):
    """results.csv after every case: a run cut short keeps what it did."""
    with open(os.path.join(HERE, "results.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS)
        w.writeheader()
        w.writerows(rows)


def label(kappa):
    return kappa if kappa == CONTACT else "%g" % kappa


def commit_of(exe):
    """The HEAD of the source tree a build/fourier-ssi was built from."""
    tree = os.path.dirname(os.path.dirname(os.path.abspath(exe)))
    return subprocess.run(["git", "-C", tree, "rev-parse", "--short", "HEAD"],
                          capture_output=True, text=True).stdout.strip()


def write_table(rows, runs, load, main_exe):
    by = {(r["kappa"], r["solver"]): r for r in rows}
    main_commit = commit_of(main_exe)
    this_commit = commit_of(os.path.join(SOURCE, "build", "fourier-ssi"))
    out = ["# Newton vs the initial-stiffness iteration, stiff coulomb "
           "interfaces", "",
           "Generated by `benchmarks/nonlinear-engine/run.py` (%d runs per "
           "converging case, medians; one run where a case fails or times "
           "out after %.0f s). Disc in a ring (prm/disc-gap.prm), harmonics "
           "n = 0..32, tensionless Coulomb mu = 0.3, 4 displacement steps to "
           "ubar = 1e-3 m; kappa = kn r0 / G. newton65: Stiffness = tangent, "
           "Theta samples = 65 = 2 n_max + 1; newton: Stiffness = tangent, "
           "Theta samples = 132 = 4 (n_max + 1); "
           "initial: Stiffness = initial, Anderson, this build; main: the "
           "main build, Anderson. Fixed-point runs: Maximum iterations "
           "20000 per step. This build: HEAD %s with its changes; the main "
           "build: %s (HEAD %s). Iterations: step 1 / the worst step "
           "(steps 2-4 start from the secant predictor, exact for this "
           "positively homogeneous problem: where the multipliers carry "
           "kn they still take one Newton update per multiplier update). "
           "solve [s]: the coupled load steps; main / newton65: main's solve "
           "time over newton65's. Load average %.1f at the start, %.1f at "
           "the end (2 cores, shared)." % (runs, TIMEOUT, this_commit or "?",
                                          main_exe, main_commit or "?",
                                          load[0], load[1]), "",
           "Cells: Newton updates (or fixed-point iterations) in step 1 / "
           "in the worst step, and the solve time. main65: the main build "
           "with Stiffness = tangent and 65 samples.", "",
           "| kappa | newton65 | newton65 solve [s] | newton | newton solve "
           "[s] | initial | initial solve [s] | main | main solve [s] | "
           "main65 | main65 solve [s] | main / newton65 | P/ubar newton65 "
           "[kN/m] | P/ubar newton [kN/m] | P/ubar main65 [kN/m] |",
           "|" + "---|" * 15]
    for kappa in KAPPAS:
        k = label(kappa)
        cells = [k]
        for solver in SOLVERS:
            r = by[(k, solver)]
            if r["converged"]:
                cells += ["%s / %s" % (r["iterations_step1"],
                                       r["iterations_worst"]),
                          r["solve_time_s"]]
            else:
                cells += [r["note"], "-"]
        n, m = by[(k, "newton65")], by[(k, "main")]
        ratio = "%.1f" % (float(m["solve_time_s"]) /
                          max(float(n["solve_time_s"]), 1e-3)) \
            if n["converged"] and m["converged"] else "-"
        cells += [ratio] + [by[(k, s)].get("P_over_ubar_kN_per_m", "-")
                            for s in ("newton65", "newton", "main65")]
        out.append("| " + " | ".join(cells) + " |")
    c = by[(CONTACT, "newton65")]
    p5 = by[("100000", "newton65")].get("P_over_ubar_kN_per_m")
    p6 = by[("1e+06", "newton65")].get("P_over_ubar_kN_per_m")
    out += ["", "Exact contact (`contact, c=0, phi=16.7`, Newton, 65 "
            "samples) against the 1/kappa extrapolation of the penalty "
            "(newton65), P_inf = P(1e6) + (P(1e6) - P(1e5)) / 9:", "",
            "| interface | Newton updates, step 1 / worst | multiplier "
            "updates, all steps | solve [s] | P/ubar [kN/m] |",
            "|---|---|---|---|---|"]
    if c["converged"]:
        out.append("| contact | %s / %s | %s | %s | %s |" % (
            c["iterations_step1"], c["iterations_worst"],
            c["multiplier_updates_total"], c["solve_time_s"],
            c["P_over_ubar_kN_per_m"]))
    else:
        out.append("| contact | %s | - | - | - |" % c["note"])
    if p5 and p6:
        limit = float(p6) + (float(p6) - float(p5)) / 9.
        out.append("| penalty, 1/kappa -> 0 | - | - | - | %.9g |" % limit)
        if c["converged"]:
            out += ["", "contact vs extrapolated penalty: %.2e relative." % (
                abs(float(c["P_over_ubar_kN_per_m"]) - limit) / limit)]
    with open(os.path.join(HERE, "results.md"), "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
