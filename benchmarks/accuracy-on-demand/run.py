#!/usr/bin/env python3
"""Accuracy on demand against the hand-tuned recipes, in one run.

The embedded footing (e/a = 1, alpha = 0.5, nu = 0.25) on the coarse base
mesh of the hand-tuned recipes, driven only by Discretization/Target
accuracy (no grading of its own), and the hand-tuned recipes prm/embedded-footing-graded.prm (1e-4)
and -precise.prm (1e-6), each run --repeat times in one invocation;
medians. Per run: the process wall time, the computation (the wall time
of the answer's mesh, its 'cycle k summary' line, plus the solves made for
its estimate, row time_error_estimate: without start-up), the time of the solves made only for the error estimate (row
time_error_estimate: the coarsened mesh of a one-mesh run, the members
before the answer's of a Target accuracy run) as a fraction of the
computation, the peak resident memory of the process, the DoFs of the
answer, its estimated and its true error (references: doc/accuracy-vs-time.md,
"The converged references", good to a few 1e-7 for rough; the smooth reference is the
finest member of benchmarks/accuracy-on-demand/effectivity.csv).

Usage: run.py --exe build/fourier-ssi [--repeat 3] [--before OLD_EXE]
With --before, every run of a case is made with OLD_EXE first and then
with --exe, alternately in one invocation, and the table has a
"(before)" row above each case: before/after under the same load.
Writes benchmark.csv and benchmark.md next to this script.
"""
import argparse
import csv
import math
import os
import pathlib
import re
import statistics
import subprocess
import sys
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import effectivity  # noqa: E402

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent.parent
ROUGH = {"K_H": 10.7991035, "K_M": 18.9791563, "K_MH": -8.76923033}


def smooth_reference():
    path = HERE / "effectivity.csv"
    ref = {}
    if path.exists():
        for r in csv.DictReader(open(path)):
            if r["case"] == "footing-a0.5-nu0.25-smooth":
                ref[r["quantity"]] = float(r["reference"])
    return ref


def designed(interface, target):
    # The recipes' scene and base mesh (effectivity.footing), no grading of
    # its own: the program designs the rest.
    return effectivity.footing(interface, 0.25, 0.5) + f"""
subsection Discretization
  set Target accuracy = {target}
end
"""


def recipe(name):
    return (ROOT / "prm" / name).read_text()


# (name, prm text, reference, runs: None = --repeat)
CASES = [
    ("rough 1e-4, Target accuracy", lambda: designed("rough", "1e-4"), ROUGH,
     None),
    ("rough 1e-4, embedded-footing-graded.prm",
     lambda: recipe("embedded-footing-graded.prm"), ROUGH, None),
    ("rough 1e-6, Target accuracy", lambda: designed("rough", "1e-6"), ROUGH,
     None),
    ("rough 1e-6, embedded-footing-precise.prm",
     lambda: recipe("embedded-footing-precise.prm"), ROUGH, None),
    ("smooth 1e-3, Target accuracy", lambda: designed("smooth", "1e-3"),
     None, None),
]


def run(exe, text, work):
    work.mkdir(parents=True, exist_ok=True)
    prm = text + f"""
subsection Output
  set Directory = {work / 'out'}
  set Write vtu = false
  set Write stresses = false
  set Write interface tractions = false
end
"""
    (work / "case.prm").write_text(prm)
    start = time.time()
    with open(work / "stdout.txt", "w") as out, \
            open(work / "stderr.txt", "w") as err:
        child = subprocess.Popen([exe, str(work / "case.prm")], stdout=out,
                                 stderr=err)
        # os.wait4: this run's own resource usage (peak resident memory).
        _, status, usage = os.wait4(child.pid, 0)
    wall = time.time() - start
    peak_mib = usage.ru_maxrss / 1024.
    p = subprocess.CompletedProcess(
        child.args, os.waitstatus_to_exitcode(status),
        (work / "stdout.txt").read_text(), (work / "stderr.txt").read_text())
    (work / "log.txt").write_text(p.stdout + p.stderr)
    if p.returncode != 0:
        raise SystemExit(f"run failed: {p.stderr}")
    walls = re.findall(r"summary: .* wall ([0-9.e+-]+) s", p.stdout)
    rows = list(csv.DictReader(open(work / "out" / "results.csv")))
    last = max(int(r["cycle"]) for r in rows)
    value = {r["quantity"]: float(r["value"]) for r in rows
             if int(r["cycle"]) == last}
    # The answer's mesh plus the solves made for its estimate: one mesh's
    # coarsened copy (no summary line of its own), or the members before
    # the answer's, whose wall time the program measures as a whole (meshes
    # 0 and 1 may run side by side: their summary walls overlap).
    compute = float(walls[-1]) + value.get("time_error_estimate", 0.)
    # The estimate's share of the work (not of the wall time): the summed
    # walls of the meshes before the answer's over all meshes solved.
    value["work_share"] = (sum(float(w) for w in walls[:-1]) /
                           sum(float(w) for w in walls)
                           if len(walls) > 1 else float("nan"))
    value["peak_mib"] = peak_mib
    return wall, compute, value


def summarize(name, walls, computes, peaks, value, ref):
    estimate_time = value.get("time_error_estimate", float("nan"))
    row = dict(case=name, runs=len(walls), dofs=int(value["n_dofs"]),
               process_s=statistics.median(walls),
               peak_mib=statistics.median(peaks),
               compute_s=statistics.median(computes),
               estimate_share=estimate_time / computes[-1],
               work_share=value["work_share"])
    if math.isnan(row["work_share"]):
        # One mesh: its coarsened copy ran alone, before it.
        row["work_share"] = row["estimate_share"]
    for q in ("K_H", "K_M", "K_MH"):
        row[q + "_estimate"] = value.get(q + "_error", float("nan"))
        row[q + "_error"] = (abs(value[q] - ref[q]) / abs(ref[q])
                             if q in ref else float("nan"))
    return row


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--exe", required=True)
    parser.add_argument("--before", help="the previous build, run "
                        "alternately with --exe")
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    exes = [("", str(pathlib.Path(args.exe).resolve()))]
    if args.before:
        exes.insert(0, (" (before)",
                        str(pathlib.Path(args.before).resolve())))
    lines = []
    for name, text, ref, runs in CASES:
        ref = ref or smooth_reference()
        walls = {tag: [] for tag, _ in exes}
        computes = {tag: [] for tag, _ in exes}
        peaks = {tag: [] for tag, _ in exes}
        value = {}
        for k in range(runs or args.repeat):
            for tag, exe in exes:
                w, c, value[tag] = run(exe, text(), HERE / "runs" /
                                       re.sub(r"[^a-z0-9]+", "-",
                                              name.lower()))
                walls[tag].append(w)
                computes[tag].append(c)
                peaks[tag].append(value[tag]["peak_mib"])
        for tag, _ in exes:
            row = summarize(name + tag, walls[tag], computes[tag],
                            peaks[tag], value[tag], ref)
            lines.append(row)
            print(row, flush=True)
    with open(HERE / "benchmark.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(lines[0]))
        w.writeheader()
        w.writerows(lines)
    with open(HERE / "benchmark.md", "w") as f:
        f.write("Medians of the runs of each case, one invocation, 2 cores "
                "shared with other jobs.\n\n"
                "| case | runs | DoFs | process [s] | computation [s] | peak "
                "memory [MiB] | estimate "
                "share (wall) | estimate share (work) | K_H est / true | "
                "K_M est / true | K_MH est / true |\n"
                "|---|---|---|---|---|---|---|---|---|---|---|\n")
        for r in lines:
            f.write(f"| {r['case']} | {r['runs']} | {r['dofs']} | {r['process_s']:.2f} | "
                    f"{r['compute_s']:.2f} | {r['peak_mib']:.0f} | "
                    f"{r['estimate_share']:.0%} | "
                    f"{r['work_share']:.0%} | " +
                    " | ".join(f"{r[q + '_estimate']:.1e} / {r[q + '_error']:.1e}"
                               for q in ("K_H", "K_M", "K_MH")) + " |\n")


if __name__ == "__main__":
    main()
