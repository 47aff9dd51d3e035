#!/usr/bin/python3
"""Plastic soil on 1 vs 2 MPI ranks (doc/soil-plasticity.md section 3c):
the harmonics distributed over the ranks, Soil plasticity/Stiffness =
elastic (the initial-stiffness iteration, Aitken) and tangent (Newton: each
rank assembles the block rows of its harmonics, one rank factorizes the
coupled tangent).

    /usr/bin/python3 benchmarks/soil-plasticity/ranks.py [BUILD_DIR] [RUNS]
                                                   [STIFFNESS]

Every case is a bundled scene with a few entries overridden (an appended
subsection: later `set` lines win). 1 rank is the plain serial run (no
mpirun; the harmonics on 2 threads), 2 ranks `mpirun -np 2` as the tests
call it (each rank one thread, its own harmonics and every second soil
point; Open MPI busy-waits in a collective), and 2 ranks with
`--mca mpi_yield_when_idle 1` (a waiting rank gives its core up: on a
machine with more runnable processes than cores the busy wait takes the
core the other rank needs). The three are alternated RUNS times (default
3) in this one invocation; the table gives medians and the ratios to 1
rank. Both with one BLAS
thread per process (OPENBLAS_NUM_THREADS=1, as the tests: UMFPACK's
roundoff depends on it). Equality: whether load-displacement.csv of every
2-rank run has the same text as the first 1-rank run in every column but
the step times, and the largest difference of the load and the motion
relative to their largest value. The load average (1, 5, 15 min) before
and after each case is written with the table: the 2 cores are shared.
Writes ranks.csv and ranks.md (STIFFNESS = elastic, the default) or
ranks-newton.csv and ranks-newton.md (tangent) next to this file.
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

# (label, scene, harmonics, steps, target [m], load column, motion column,
#  Soil plasticity/Stiffness)
CASES = [
    ("pile capacity, n <= 8, as shipped (6 steps to u = 0.03 d)",
     "prm/pile-capacity.prm", "0, 1, 2, 3, 4, 5, 6, 7, 8", 6, "0.03",
     "H_kN", "horizontal_m", "elastic"),
    ("pile capacity, n <= 8, as shipped (6 steps to u = 0.03 d), Newton",
     "prm/pile-capacity.prm", "0, 1, 2, 3, 4, 5, 6, 7, 8", 6, "0.03",
     "H_kN", "horizontal_m", "tangent"),
]
# (label, ranks, extra mpirun options)
CONFIGURATIONS = [
    ("1 rank", 1, []),
    ("2 ranks", 2, []),
    ("2 ranks, yield when idle", 2, ["--mca", "mpi_yield_when_idle", "1"]),
]
FIELDS = ["case", "harmonics", "ranks", "runs", "converged", "steps",
          "iterations_total", "solve_time_s", "run_wall_s", "run_cpu_s",
          "same_text", "max_rel_diff_load", "max_rel_diff_motion", "load"]


def mpiexec(ranks):
    """mpirun -np RANKS as tests/mpi/CMakeLists.txt calls it."""
    command = ["mpirun", "-np", str(ranks), "-q", "--oversubscribe"]
    if os.getuid() == 0:
        command.append("--allow-run-as-root")
    return command


def load_average():
    with open("/proc/loadavg") as f:
        return " ".join(f.read().split()[:3])


def run_case(exe, case, work, launcher):
    label, scene, listed, steps, target, load, motion, stiffness = case
    with open(os.path.join(SOURCE, scene)) as f:
        text = f.read()
    out = os.path.join(work, "out")
    text += ("\nsubsection Discretization\n  set Harmonics = %s\nend\n"
             "subsection Load path\n  set Load steps = %d\n"
             "  set Target = %s\nend\n"
             "subsection Soil plasticity\n  set Stiffness = %s\nend\n"
             "subsection Output\n  set Directory = %s\nend\n"
             % (listed, steps, target, stiffness, out))
    prm = os.path.join(work, "case.prm")
    with open(prm, "w") as f:
        f.write(text)
    environment = dict(os.environ, OPENBLAS_NUM_THREADS="1",
                       OMP_NUM_THREADS="1")
    start = time.monotonic()
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    p = subprocess.run(list(launcher) + [exe, prm], capture_output=True,
                       text=True, env=environment)
    wall = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime -
                                                before.ru_stime)
    if p.returncode != 0:
        print(p.stdout[-2000:], p.stderr[-2000:])
        return None
    with open(os.path.join(out, "load-displacement.csv")) as f:
        rows = list(csv.DictReader(f))
    return {"iterations": sum(int(r["iterations"]) for r in rows),
            "time": sum(float(r["time_s"]) for r in rows),
            "steps": len(rows), "wall": wall, "cpu": cpu,
            "text": [{k: v for k, v in r.items() if k != "time_s"}
                     for r in rows],
            "load": [float(r[load]) for r in rows],
            "motion": [float(r[motion]) for r in rows]}


def max_relative_difference(a, b):
    if len(a) != len(b):
        return float("inf")
    scale = max(abs(x) for x in b)
    return max(abs(x - y) for x, y in zip(a, b)) / scale


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else os.path.join(SOURCE, "build")
    runs = int(sys.argv[2]) if len(sys.argv) > 2 else 3
    stiffness = sys.argv[3] if len(sys.argv) > 3 else "elastic"
    stem = "ranks" if stiffness == "elastic" else "ranks-newton"
    exe = os.path.join(build, "fourier-ssi")
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for case in [c for c in CASES if c[-1] == stiffness]:
            samples = {label: [] for label, _, _ in CONFIGURATIONS}
            loads = [load_average()]
            for _ in range(runs):
                for label, ranks, options in CONFIGURATIONS:
                    samples[label].append(run_case(
                        exe, case, work,
                        mpiexec(ranks) + options if ranks > 1 else ()))
            loads.append(load_average())
            reference = samples[CONFIGURATIONS[0][0]][0]
            for label, ranks, options in CONFIGURATIONS:
                ok = [s for s in samples[label] if s is not None]
                row = {"case": case[0],
                       "harmonics": len(case[2].split(",")),
                       "ranks": label, "runs": runs,
                       "converged": "yes" if len(ok) == runs else "no",
                       "load": " -> ".join(loads)}
                if ok:
                    row["steps"] = ok[0]["steps"]
                    row["iterations_total"] = ok[0]["iterations"]
                    for key, name in (("time", "solve_time_s"),
                                      ("wall", "run_wall_s"),
                                      ("cpu", "run_cpu_s")):
                        row[name] = statistics.median(s[key] for s in ok)
                    if reference is not None:
                        row["same_text"] = "yes" if all(
                            s["text"] == reference["text"] for s in ok) \
                            else "no"
                        row["max_rel_diff_load"] = max(
                            max_relative_difference(s["load"],
                                                    reference["load"])
                            for s in ok)
                        row["max_rel_diff_motion"] = max(
                            max_relative_difference(s["motion"],
                                                    reference["motion"])
                            for s in ok)
                print(row, flush=True)
                rows.append(row)
    with open(os.path.join(HERE, stem + ".csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS)
        w.writeheader()
        w.writerows(rows)
    one = {r["case"]: r for r in rows if r["ranks"] == CONFIGURATIONS[0][0]}
    with open(os.path.join(HERE, stem + ".md"), "w") as f:
        f.write(
            "# Plastic soil on 1 vs 2 MPI ranks (Stiffness = %s)\n\n"
            "Regenerate: `benchmarks/soil-plasticity/ranks.py build %d %s` "
            "(%d runs of "
            "each, alternated, medians). 1 rank: the serial run (harmonics "
            "on 2 threads); 2 ranks: `mpirun -np 2`, each rank its own "
            "harmonics on one thread and every second soil point (yield when "
            "idle: `--mca mpi_yield_when_idle 1`). Same text: load-displacement.csv "
            "(12 digits, every column but the step times) identical to the "
            "first 1-rank run. CPU: user + system of the process and its "
            "children (mpirun, the ranks). The load average (1, 5, 15 min) "
            "before and after each case: the 2 cores are shared.\n\n"
            "| case | harmonics | ranks | iterations | steps [s] | whole run "
            "[s] | CPU [s] | steps / 1 rank | whole run / 1 rank | same text "
            "| load "
            "agreement | motion agreement | load average |\n"
            "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n"
            % (stiffness, runs, stiffness, runs))
        for r in rows:
            if "steps" not in r:
                f.write("| %s | %d | %s | failed |||||||||\n"
                        % (r["case"], r["harmonics"], r["ranks"]))
                continue
            base = one.get(r["case"])
            ratio = (lambda key: "—" if r is base or base is None
                     or "steps" not in base
                     else "%.2f" % (r[key] / base[key]))
            f.write("| %s | %d | %s | %d | %.2f | %.2f | %.2f | %s | %s | %s "
                    "| %.1e | %.1e | %s |\n"
                    % (r["case"], r["harmonics"], r["ranks"],
                       r["iterations_total"], r["solve_time_s"],
                       r["run_wall_s"], r["run_cpu_s"],
                       ratio("solve_time_s"), ratio("run_wall_s"),
                       r.get("same_text", "?"),
                       r.get("max_rel_diff_load", float("nan")),
                       r.get("max_rel_diff_motion", float("nan")),
                       r["load"]))
    print("wrote", os.path.join(HERE, stem + ".md"))


if __name__ == "__main__":
    main()
