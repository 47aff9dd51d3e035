#!/usr/bin/python3
"""Cost of the coupled plastic-soil iteration (doc/soil-plasticity.md
section 8): iterations and wall time per load step vs the number of
harmonics, on the bundled scene prm/pile-capacity.prm (the rigid pile in a
Tresca layer, smooth shaft) shortened to 4 steps to u = 0.02 m = 0.02 d
(past first yield, onto the plateau).

    /usr/bin/python3 benchmarks/soil-plasticity/run.py [BUILD_DIR] [RUNS]

Every case is the bundled scene with a few entries overridden (an appended
subsection: later `set` lines win), run RUNS times (default 3) in this one
invocation; the table gives medians, and the 1-minute load average of the
machine before every case (2 shared cores: times carry the noise of other
jobs). Writes results.csv and results.md next to this file.
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


def run_case(exe, n_max, work):
    with open(os.path.join(SOURCE, SCENE)) as f:
        text = f.read()
    out = os.path.join(work, "out")
    text += (
        "\nsubsection Discretization\n  set Harmonics = %s\nend\n"
        "subsection Nonlinear interfaces\n  set Load steps = %d\n"
        "  set Target = %s\nend\n"
        "subsection Output\n  set Directory = %s\nend\n"
        % (harmonics(n_max), STEPS, TARGET, out)
    )
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
            "time": sum(times), "wall": wall,
            "Np": abs(float(rows[-1]["H_kN"])) / FORCE_SCALE}


def main():
    build = sys.argv[1] if len(sys.argv) > 1 else os.path.join(SOURCE, "build")
    runs = int(sys.argv[2]) if len(sys.argv) > 2 else 3
    exe = os.path.join(build, "fourier-ssi")
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for n_max in (2, 4, 8):
            load = os.getloadavg()[0]
            samples = [run_case(exe, n_max, work) for _ in range(runs)]
            ok = [s for s in samples if s is not None]
            if not ok:
                print("n <= %d: failed" % n_max)
                continue
            med = {k: statistics.median(s[k] for s in ok)
                   for k in ("iterations", "time", "wall", "Np")}
            steps = ok[0]["steps"]
            rows.append({"n_max": n_max, "theta_samples": 4 * (n_max + 1),
                         "runs": len(ok), "steps": steps,
                         "iterations_per_step": med["iterations"] / steps,
                         "time_per_step_s": med["time"] / steps,
                         "wall_s": med["wall"], "Np_at_0.02d": med["Np"],
                         "load_average_1min": load})
            print(rows[-1], flush=True)
    with open(os.path.join(HERE, "results.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    base = rows[0]["time_per_step_s"]
    with open(os.path.join(HERE, "results.md"), "w") as f:
        f.write("# Plastic soil: cost per load step vs harmonics\n\n"
                "`%s`, %d steps to u = %s m (medians of %d runs, "
                "`benchmarks/soil-plasticity/run.py`).\n\n" %
                (SCENE, STEPS, TARGET, runs))
        f.write("| n_max | theta samples | iterations / step | "
                "time / step [s] | ratio to n_max = %d | wall [s] | "
                "N_p = H/(s_u d L) at u = 0.02 d | load (1 min) |\n"
                % rows[0]["n_max"])
        f.write("|---|---|---|---|---|---|---|---|\n")
        for r in rows:
            f.write("| %d | %d | %.0f | %.2f | %.2f | %.1f | %.4f | %.1f |\n"
                    % (r["n_max"], r["theta_samples"],
                       r["iterations_per_step"], r["time_per_step_s"],
                       r["time_per_step_s"] / base, r["wall_s"],
                       r["Np_at_0.02d"], r["load_average_1min"]))
    print("wrote", os.path.join(HERE, "results.md"))


if __name__ == "__main__":
    main()
