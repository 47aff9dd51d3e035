#!/usr/bin/python3
"""Cost of the coupled plastic-soil iteration (doc/soil-plasticity.md
section 8), in one invocation:

1. iterations and time per load step vs the number of harmonics, Newton on
   the coupled tangent (Soil plasticity/Stiffness = tangent, the default)
   against the initial-stiffness iteration (= elastic), on the bundled scene
   prm/pile-capacity.prm (the rigid pile in a Tresca layer, smooth shaft)
   shortened to 4 steps to u = 0.02 m = 0.02 d (past first yield, onto the
   plateau);
2. the bundled capacity curves as shipped, each to its plateau (the
   goal: 60 s each on 2 cores).

    /usr/bin/python3 benchmarks/soil-plasticity/run.py [BUILD_DIR] [RUNS]
                                                       [CURVE_RUNS]

Every case of 1 is the bundled scene with a few entries overridden (an
appended subsection: later `set` lines win); every case runs RUNS times
(default 3; the curves of 2 CURVE_RUNS times, default 1: the disc takes
minutes); the tables give medians, and the 1-minute load average of the
machine before every case (2 shared cores: times carry the noise of other
jobs). Writes results.csv, curves.csv and results.md next to this file.
"""
import csv
import os
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.normpath(os.path.join(HERE, "..", ".."))
SCENE = "prm/pile-capacity.prm"
STEPS, TARGET = 4, "0.02"
# H_ult = N_p s_u d L with s_u = 10 kPa, d = 1 m, L = 10 m.
FORCE_SCALE = 100.0


def harmonics(n_max):
    return ", ".join(str(n) for n in range(n_max + 1))


# The bundled capacity curves: scene, the published limit it approaches,
# and the normalisation of its load (N = load / scale).
CURVES = [
    ("prm/pile-capacity.prm", "H_kN", 100.0, "N_p (smooth 9.14-9.20)"),
    ("prm/footing-capacity.prm", "V_kN", 31.4159265, "N_c (rough 6.05)"),
    ("prm/disc-tresca.prm", "H_kN", 10.0, "P/(s_u D) (rough 11.94)"),
    ("prm/pile-adhesion.prm", "H_kN", 100.0,
     "N_p (adhesion 0.5 s_u: 10.82, coulomb shaft)"),
]


def run_case(exe, n_max, work, stiffness="tangent", scene=SCENE,
             shortened=True):
    with open(os.path.join(SOURCE, scene)) as f:
        text = f.read()
    out = os.path.join(work, "out")
    if shortened:
        text += (
            "\nsubsection Discretization\n  set Harmonics = %s\nend\n"
            "subsection Load path\n  set Load steps = %d\n"
            "  set Target = %s\nend\n" % (harmonics(n_max), STEPS, TARGET))
    text += ("\nsubsection Soil plasticity\n  set Stiffness = %s\nend\n"
             "subsection Output\n  set Directory = %s\nend\n"
             % (stiffness, out))
    prm = os.path.join(work, "case.prm")
    with open(prm, "w") as f:
        f.write(text)
    start = time.monotonic()
    p = subprocess.run([exe, prm], capture_output=True, text=True)
    wall = time.monotonic() - start
    if p.returncode != 0:
        return None
    with open(os.path.join(out, "load-displacement.csv")) as f:
        rows = list(csv.DictReader(f))
    its = [int(r["iterations"]) for r in rows]
    times = [float(r["time_s"]) for r in rows]
    return {"iterations": sum(its), "steps": len(rows),
            "time": sum(times), "wall": wall, "rows": rows,
            "Np": abs(float(rows[-1]["H_kN"])) / FORCE_SCALE}


def medians(samples, keys):
    return {k: statistics.median(s[k] for s in samples) for k in keys}


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else os.path.join(SOURCE, "build")
    runs = int(sys.argv[2]) if len(sys.argv) > 2 else 3
    curve_runs = int(sys.argv[3]) if len(sys.argv) > 3 else 1
    exe = os.path.join(build, "fourier-ssi")
    rows, curves = [], []
    with tempfile.TemporaryDirectory() as work:
        for n_max in (2, 4, 8):
            for stiffness in ("tangent", "elastic"):
                load = os.getloadavg()[0]
                samples = [run_case(exe, n_max, work, stiffness)
                           for _ in range(runs)]
                ok = [s for s in samples if s is not None]
                if not ok:
                    print("n <= %d, %s: failed" % (n_max, stiffness))
                    continue
                med = medians(ok, ("iterations", "time", "wall", "Np"))
                steps = ok[0]["steps"]
                rows.append({"n_max": n_max, "stiffness": stiffness,
                             "theta_samples": 4 * (n_max + 1),
                             "runs": len(ok), "steps": steps,
                             "iterations_per_step": med["iterations"] / steps,
                             "time_per_step_s": med["time"] / steps,
                             "wall_s": med["wall"], "Np_at_0.02d": med["Np"],
                             "load_average_1min": load})
                print(rows[-1], flush=True)
        for scene, column, scale, limit in CURVES:
            load = os.getloadavg()[0]
            samples = [run_case(exe, 0, work, "tangent", scene, False)
                       for _ in range(curve_runs)]
            ok = [s for s in samples if s is not None]
            if not ok:
                print(scene, "failed")
                continue
            med = medians(ok, ("iterations", "time", "wall"))
            last = ok[0]["rows"][-1]
            curves.append({"scene": scene, "runs": len(ok),
                           "steps": ok[0]["steps"],
                           "iterations": med["iterations"],
                           "coupled_solve_s": med["time"],
                           "wall_s": med["wall"],
                           "limit": abs(float(last[column])) / scale,
                           "published": limit,
                           "load_average_1min": load})
            print(curves[-1], flush=True)
    for name, table in (("results.csv", rows), ("curves.csv", curves)):
        with open(os.path.join(HERE, name), "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(table[0].keys()))
            w.writeheader()
            w.writerows(table)
    by_case = {(r["n_max"], r["stiffness"]): r for r in rows}
    with open(os.path.join(HERE, "results.md"), "w") as f:
        f.write("# Plastic soil: cost of the coupled iteration\n\n"
                "Regenerate: `benchmarks/soil-plasticity/run.py` (medians "
                "of %d runs in one invocation, the curves %d run(s); the "
                "1-minute load average before each case).\n\n"
                % (runs, curve_runs))
        f.write("## Per load step vs harmonics: Newton vs initial "
                "stiffness\n\n`%s`, %d steps to u = %s m.\n\n"
                % (SCENE, STEPS, TARGET))
        f.write("| n_max | theta samples | iteration | iterations / step | "
                "time / step [s] | initial stiffness / Newton (time) | "
                "wall [s] | N_p = H/(s_u d L) at u = 0.02 d | load (1 min) |\n")
        f.write("|---|---|---|---|---|---|---|---|---|\n")
        for r in rows:
            newton = by_case.get((r["n_max"], "tangent"))
            ratio = (r["time_per_step_s"] / newton["time_per_step_s"]
                     if newton else float("nan"))
            f.write("| %d | %d | %s | %.0f | %.2f | %.2f | %.1f | %.4f | "
                    "%.1f |\n"
                    % (r["n_max"], r["theta_samples"],
                       "Newton" if r["stiffness"] == "tangent"
                       else "initial stiffness",
                       r["iterations_per_step"], r["time_per_step_s"],
                       ratio, r["wall_s"], r["Np_at_0.02d"],
                       r["load_average_1min"]))
        f.write("\n## The bundled capacity curves as shipped (Newton)\n\n"
                "| scene | steps | iterations | coupled solve [s] | wall [s] "
                "| limit reached | published | load (1 min) |\n"
                "|---|---|---|---|---|---|---|---|\n")
        for c in curves:
            f.write("| `%s` | %d | %.0f | %.1f | %.1f | %.3f | %s | %.1f |\n"
                    % (c["scene"], c["steps"], c["iterations"],
                       c["coupled_solve_s"], c["wall_s"], c["limit"],
                       c["published"], c["load_average_1min"]))
    print("wrote", os.path.join(HERE, "results.md"))


if __name__ == "__main__":
    main()
