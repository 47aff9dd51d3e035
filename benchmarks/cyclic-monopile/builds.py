#!/usr/bin/python3
"""The monopile in iwan clay on two builds, side by side in one run: the
cost of the multi-surface return map (doc/soil-plasticity.md section 10).

    /usr/bin/python3 benchmarks/cyclic-monopile/builds.py NEW_EXE OLD_EXE [RUNS]

Cases (prm/monopile-clay-iwan.prm, 20 surfaces; the cyclic one as run.sh
builds it, 4 steps a segment):
  monotonic   pushed to 0.1 D in 10 steps, RUNS times per build (default 3);
  cycles      10 cycles at 0.001 D (0.009 m), once per build.
The builds alternate run by run. Each case's answer (H at the end, the last
cycle's damping ratio) must agree between the builds to 1e-8 relative (the
same formulas, summed in another order). Writes results-builds.md next to
this file: median wall times, their ratio new / old, peak memory.
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


def scene(kind, out):
    text = open(os.path.join(SOURCE, "prm", "monopile-clay-iwan.prm")).read()
    text = text.replace("output/monopile-clay-iwan", out)
    if kind == "cycles":
        text = text.replace("  set Target             = 0.9",
                            "  set Targets            = 0.009, -0.009\n"
                            "  set Cycles             = 10")
        text = text.replace("set Load steps         = 10",
                            "set Load steps         = 4")
        text = "\n".join(line for line in text.splitlines()
                         if "Soil reaction" not in line and
                         "Capacity normalisation" not in line) + "\n"
    return text


def run(exe, kind, work):
    out = os.path.join(work, "out")
    prm = os.path.join(work, kind + ".prm")
    open(prm, "w").write(scene(kind, out))
    start = time.time()
    with open(os.path.join(work, "log"), "w") as log:
        p = subprocess.Popen([exe, prm], stdout=log, stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(p.pid, 0)
    wall = time.time() - start
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit("%s %s failed: see %s" % (exe, kind, work))
    if kind == "cycles":
        rows = list(csv.DictReader(open(os.path.join(out, "load-cycles.csv"))))
        answer = float(rows[-1]["damping_ratio"])
    else:
        rows = list(csv.DictReader(open(os.path.join(out,
                                                     "load-displacement.csv"))))
        answer = float(rows[-1]["H_kN"])
    return wall, usage.ru_maxrss / 1e6, answer  # ru_maxrss in kB: GB


def commit_of(exe):
    """The HEAD of the source tree a build/fourier-ssi was built from."""
    tree = os.path.dirname(os.path.dirname(os.path.abspath(exe)))
    return subprocess.run(["git", "-C", tree, "rev-parse", "--short", "HEAD"],
                          capture_output=True, text=True).stdout.strip()


def main():
    new, old = sys.argv[1], sys.argv[2]
    runs = int(sys.argv[3]) if len(sys.argv) > 3 else 3
    load = [os.getloadavg()[0]]
    table = {}
    with tempfile.TemporaryDirectory() as work:
        for kind, n in (("monotonic", runs), ("cycles", 1)):
            for _ in range(n):
                for name, exe in (("new", new), ("old", old)):
                    table.setdefault((kind, name), []).append(
                        run(exe, kind, work))
                    print(kind, name, table[(kind, name)][-1], flush=True)
    load.append(os.getloadavg()[0])
    lines = ["# The iwan monopile on two builds, side by side", "",
             "Written by `builds.py` (%s): new %s, old %s; the builds "
             "alternating run by run. Load average (1 min) %.1f at the "
             "start, %.1f at the end, on 2 cores." % (
                 time.strftime("%Y-%m-%d"), commit_of(new), commit_of(old),
                 load[0], load[1]), "",
             "| case | runs | new wall s (median) | old wall s (median) | "
             "new / old | peak GB new / old | answer new | answer old | "
             "relative difference |",
             "|---|---|---|---|---|---|---|---|---|"]
    for kind, what in (("monotonic", "H at 0.1 D [kN]"),
                       ("cycles", "damping ratio, cycle 10 [-]")):
        a, b = table[(kind, "new")], table[(kind, "old")]
        ta = statistics.median(r[0] for r in a)
        tb = statistics.median(r[0] for r in b)
        diff = abs(a[0][2] - b[0][2]) / abs(b[0][2])
        lines.append("| %s: %s | %d | %.1f | %.1f | %.2f | %.2f / %.2f | "
                     "%.10g | %.10g | %.1e%s |" % (
                         kind, what, len(a), ta, tb, ta / tb,
                         max(r[1] for r in a), max(r[1] for r in b),
                         a[0][2], b[0][2], diff,
                         "" if diff <= 1e-8 else " (beyond 1e-8)"))
    open(os.path.join(HERE, "results-builds.md"), "w").write(
        "\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
