#!/usr/bin/python3
"""Cost of the coupled nonlinear-interface iteration (doc/nonlinear-interfaces.md
section 9): iterations and wall time per load step vs the number of harmonics
and the acceleration (none, Aitken, Anderson), for the bundled scenes
prm/disc-gap.prm and prm/pile-lateral-slip.prm.

    /usr/bin/python3 benchmarks/nonlinear-interfaces/run.py [BUILD_DIR] [RUNS]
    /usr/bin/python3 benchmarks/nonlinear-interfaces/run.py [BUILD_DIR] [RUNS] ranks

The second form measures only 1 vs 2 MPI ranks (the harmonics distributed
over the ranks, doc/nonlinear-interfaces.md section 5 "Under MPI"): the full
lateral-pile curve with its 7 harmonics, the disc with 17 harmonics listed,
and the disc grown from n = 1 to 17 harmonics during the solve; 1 rank is the plain serial run
(no mpirun), 2 ranks `mpirun -np 2`, side by side in one invocation. Its rows
replace the earlier rank rows of results.csv (the other rows are kept), and
results.md gets both tables. The load average (`uptime`) at the start and
end of the measurement is written with the table.

Every case is the bundled scene with a few entries overridden (an appended
subsection: later `set` lines win), run RUNS times (default 3) in this one
invocation; the table gives medians. Writes results.csv (one row per case,
medians) and results.md (the table with ratios to Aitken) next to this file.
The machine is shared (2 cores): times carry the noise of other jobs, the
ratios are from runs made side by side.
"""
import csv
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.normpath(os.path.join(HERE, "..", ".."))


def harmonics(n_max):
    return ", ".join(str(n) for n in range(n_max + 1))


# (label, scene, n_max, steps, target [m], acceleration)
CASES = []
for n_max in (4, 8, 16):
    for acc in ("none", "aitken", "anderson"):
        CASES.append(("disc-gap", "prm/disc-gap.prm", n_max, 4, "1e-3", acc))
for n_max in (3, 6, 10):
    for acc in ("aitken", "anderson"):
        CASES.append(("pile, 4 steps to 0.02 m", "prm/pile-lateral-slip.prm",
                      n_max, 4, "0.02", acc))
for acc in ("none", "aitken", "anderson"):
    CASES.append(("pile, full curve (20 steps to 0.1 m)",
                  "prm/pile-lateral-slip.prm", 6, 20, "0.1", acc))


# 1 vs 2 MPI ranks: (label, scene, listed harmonics, Maximum harmonic,
# steps, target [m]); Aitken.
RANK_CASES = [
    ("pile, full curve (20 steps to 0.1 m)", "prm/pile-lateral-slip.prm",
     harmonics(6), 0, 20, "0.1"),
    ("disc-gap", "prm/disc-gap.prm", harmonics(16), 0, 4, "1e-3"),
    ("disc-gap, grown from n = 1 (Maximum harmonic 16)", "prm/disc-gap.prm",
     "1", 16, 4, "1e-3"),
]
RANK_FIELDS = ["case", "harmonics", "acceleration", "ranks", "runs",
               "converged", "steps", "iterations_total", "solve_time_s",
               "run_wall_s", "run_cpu_s", "max_rel_diff_H", "max_rel_diff_u",
               "load"]


def mpiexec(ranks):
    """mpirun -np RANKS as tests/mpi/CMakeLists.txt calls it."""
    command = ["mpirun", "-np", str(ranks), "-q", "--oversubscribe"]
    if os.getuid() == 0:
        command.append("--allow-run-as-root")
    return command


def run_case(exe, scene, n_max, steps, target, acc, work, listed=None,
             maximum_harmonic=0, launcher=()):
    with open(os.path.join(SOURCE, scene)) as f:
        text = f.read()
    out = os.path.join(work, "out")
    text += (
        "\nsubsection Discretization\n  set Harmonics = %s\nend\n"
        "subsection Load path\n  set Load steps = %d\n"
        "  set Target = %s\n  set Acceleration = %s\n"
        "  set Maximum harmonic = %d\nend\n"
        "subsection Output\n  set Directory = %s\nend\n"
        % (listed or harmonics(n_max), steps, target, acc, maximum_harmonic,
           out)
    )
    prm = os.path.join(work, "case.prm")
    with open(prm, "w") as f:
        f.write(text)
    start = time.monotonic()
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    p = subprocess.run(list(launcher) + [exe, prm], capture_output=True,
                       text=True)
    wall = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime -
                                                before.ru_stime)
    if p.returncode != 0:
        return None
    with open(os.path.join(out, "load-displacement.csv")) as f:
        rows = list(csv.DictReader(f))
    its = [int(r["iterations"]) for r in rows]
    times = [float(r["time_s"]) for r in rows]
    return {"iterations": sum(its), "max_iterations": max(its),
            "time": sum(times), "steps": len(rows), "wall": wall,
            "cpu": cpu,
            "H": [float(r["H_kN"]) for r in rows],
            "u": [float(r["horizontal_m"]) for r in rows],
            "harmonics": int(rows[-1]["harmonics"])}


def load_average():
    with open("/proc/loadavg") as f:
        return " ".join(f.read().split()[:3])


def max_relative_difference(a, b):
    if len(a) != len(b):
        return float("inf")
    scale = max(abs(x) for x in b)
    return max(abs(x - y) for x, y in zip(a, b)) / scale


def run_ranks(exe, runs):
    """1 vs 2 ranks, side by side: run k of 1 rank, then run k of 2 ranks."""
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for label, scene, listed, maximum, steps, target in RANK_CASES:
            samples = {1: [], 2: []}
            loads = [load_average()]
            for _ in range(runs):
                for ranks in (1, 2):
                    samples[ranks].append(run_case(
                        exe, scene, 0, steps, target, "aitken", work,
                        listed=listed, maximum_harmonic=maximum,
                        launcher=mpiexec(2) if ranks == 2 else ()))
            loads.append(load_average())
            reference = samples[1][0]
            for ranks in (1, 2):
                ok = [s for s in samples[ranks] if s is not None]
                row = {"case": label, "acceleration": "aitken",
                       "ranks": ranks, "runs": runs,
                       "converged": "yes" if len(ok) == runs else "no",
                       "load": " -> ".join(loads)}
                if ok:
                    row["harmonics"] = ok[0]["harmonics"]
                    row["steps"] = ok[0]["steps"]
                    row["iterations_total"] = ok[0]["iterations"]
                    row["solve_time_s"] = statistics.median(
                        s["time"] for s in ok)
                    row["run_wall_s"] = statistics.median(
                        s["wall"] for s in ok)
                    row["run_cpu_s"] = statistics.median(
                        s["cpu"] for s in ok)
                    if reference is not None:
                        row["max_rel_diff_H"] = max(max_relative_difference(
                            s["H"], reference["H"]) for s in ok)
                        row["max_rel_diff_u"] = max(max_relative_difference(
                            s["u"], reference["u"]) for s in ok)
                print(row, flush=True)
                rows.append(row)
    return rows


def read_csv():
    """The committed rows: (acceleration rows, rank rows), numbers parsed."""
    path = os.path.join(HERE, "results.csv")
    if not os.path.exists(path):
        return [], []
    with open(path) as f:
        rows = list(csv.DictReader(f))
    for row in rows:
        for key, value in list(row.items()):
            if value in ("", None):
                del row[key]
                continue
            try:
                number = float(value)
                row[key] = int(number) if number.is_integer() and \
                    key not in ("solve_time_s", "run_wall_s") else number
            except ValueError:
                pass
    return ([r for r in rows if not r.get("ranks")],
            [r for r in rows if r.get("ranks")])


def write_csv(results, rank_rows):
    fields = ["case", "n_max", "harmonics", "acceleration", "runs", "converged",
              "steps", "iterations_total", "iterations_per_step",
              "max_iterations_step", "solve_time_s", "time_per_step_s",
              "run_wall_s"]
    fields += [f for f in RANK_FIELDS if f not in fields]
    with open(os.path.join(HERE, "results.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        w.writerows(results)
        w.writerows(rank_rows)


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else os.path.join(SOURCE, "build")
    runs = int(sys.argv[2]) if len(sys.argv) > 2 else 3
    exe = os.path.join(build, "fourier-ssi")
    if len(sys.argv) > 3 and sys.argv[3] == "ranks":
        results, _ = read_csv()
        rank_rows = run_ranks(exe, runs)
        write_csv(results, rank_rows)
        write_table(results, runs, rank_rows)
        return
    _, rank_rows = read_csv()
    results = []
    with tempfile.TemporaryDirectory() as work:
        for label, scene, n_max, steps, target, acc in CASES:
            samples = [run_case(exe, scene, n_max, steps, target, acc, work)
                       for _ in range(runs)]
            ok = [s for s in samples if s is not None]
            row = {"case": label, "n_max": n_max, "harmonics": n_max + 1,
                   "acceleration": acc, "runs": runs,
                   "converged": "yes" if len(ok) == runs else "no"}
            if ok:
                row["steps"] = ok[0]["steps"]
                row["iterations_total"] = ok[0]["iterations"]
                row["iterations_per_step"] = ok[0]["iterations"] / ok[0]["steps"]
                row["max_iterations_step"] = ok[0]["max_iterations"]
                row["solve_time_s"] = statistics.median(s["time"] for s in ok)
                row["time_per_step_s"] = row["solve_time_s"] / row["steps"]
                row["run_wall_s"] = statistics.median(s["wall"] for s in ok)
            print(row, flush=True)
            results.append(row)
    write_csv(results, rank_rows)
    write_table(results, runs, rank_rows)


def rank_table(rank_rows):
    """1 vs 2 ranks, with the 2-rank/1-rank ratios and the agreement."""
    if not rank_rows:
        return []
    lines = [
        "",
        "## 1 vs 2 MPI ranks (harmonics distributed over the ranks)",
        "",
        "`run.py BUILD RUNS ranks`: 1 rank is the serial run (no mpirun, "
        "harmonics on 2 threads for the factorization and condensation), "
        "2 ranks `mpirun -np 2` (each rank 1 thread, its own harmonics); "
        "Aitken, %d runs each, alternated, medians. The machine is shared "
        "with other jobs (builds): the load average (1, 5, 15 min) before "
        "and after each case is in the last column. Agreement: the largest "
        "difference of H and u over the curve between any 2-rank run and "
        "the first 1-rank run, relative to the largest value. CPU: user + "
        "system time of the process and its children (mpirun, the ranks)."
        % rank_rows[0]["runs"],
        "",
        "| case | harmonics | ranks | iterations | steps [s] | whole run "
        "[s] | CPU, all ranks [s] | steps 2/1 | whole run 2/1 | H agreement "
        "| u agreement | load |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    one = {r["case"]: r for r in rank_rows if r["ranks"] == 1}
    for r in rank_rows:
        if r["converged"] != "yes":
            lines.append("| %s | | %d | did not converge | | | | | | | | %s |"
                         % (r["case"], r["ranks"], r["load"]))
            continue
        ref = one.get(r["case"])
        ratio_steps = ratio_wall = "—"
        if ref and ref["converged"] == "yes" and r["ranks"] == 2:
            ratio_steps = "%.2f" % (r["solve_time_s"] / ref["solve_time_s"])
            ratio_wall = "%.2f" % (r["run_wall_s"] / ref["run_wall_s"])
        lines.append("| %s | %d | %d | %d | %.2f | %.2f | %.2f | %s | %s | "
                     "%.1e | %.1e | %s |"
                     % (r["case"], r["harmonics"], r["ranks"],
                        r["iterations_total"], r["solve_time_s"],
                        r["run_wall_s"], r.get("run_cpu_s", float("nan")),
                        ratio_steps, ratio_wall,
                        r.get("max_rel_diff_H", float("nan")),
                        r.get("max_rel_diff_u", float("nan")), r["load"]))
    return lines


def write_table(results, runs, rank_rows=()):
    aitken = {(r["case"], r["n_max"]): r for r in results
              if r["acceleration"] == "aitken" and r["converged"] == "yes"}
    lines = [
        "# Coupled nonlinear-interface iteration: cost per load step",
        "",
        "Generated by `benchmarks/nonlinear-interfaces/run.py` (%d runs per "
        "case, medians of the coupled-solve wall time; %d cores, shared "
        "machine). Iterations are deterministic (the same in every run). "
        "Tolerance 1e-10 on the force residual. steps [s]: the load steps "
        "only; whole run [s]: the process (mesh, assembly, factorization, "
        "condensation onto the interface, steps, output)." % (runs, os.cpu_count()),
        "",
        "| case | harmonics | acceleration | steps | iterations / step | max "
        "in a step | steps [s] | per step [s] | steps vs Aitken | whole run [s] |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r in results:
        if r["converged"] != "yes":
            lines.append("| %s | %d | %s | — | did not converge (step cut "
                         "4 times, stopped) | | | | | |"
                         % (r["case"], r["harmonics"], r["acceleration"]))
            continue
        ref = aitken.get((r["case"], r["n_max"]))
        ratio = "%.2f" % (r["solve_time_s"] / ref["solve_time_s"]) if ref else "—"
        lines.append("| %s | %d | %s | %d | %.1f | %d | %.2f | %.3f | %s | %.2f |"
                     % (r["case"], r["harmonics"], r["acceleration"],
                        r["steps"], r["iterations_per_step"],
                        r["max_iterations_step"], r["solve_time_s"],
                        r["time_per_step_s"], ratio, r["run_wall_s"]))
    lines += rank_table(list(rank_rows))
    with open(os.path.join(HERE, "results.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
