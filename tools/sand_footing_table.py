#!/usr/bin/python3
"""The comparison table of doc/verification/sand-footings.md: N_q of the
smooth rigid circular footing on weightless Mohr-Coulomb sand
(prm/footing-sand.prm) and N_gamma on sand with its weight
(prm/footing-sand-gamma.prm) against the method of characteristics
(doc/derivations/circular_footing_characteristics.py), phi' = 30 and 35 deg,
with the run's own error bar and its cost.

    /usr/bin/python3 tools/sand_footing_table.py [--exe build/fourier-ssi]
        [--work sand-footing-runs] [--skip-target]

Runs each scene for phi' = 30 deg, the same with the entries of
tests/prm/footing_sand{,_gamma}_phi35.prm (35 deg), and for 30 deg with a
Discretization/Target accuracy (tests/accuracy/footing_sand{,_gamma}_target_*.prm),
each in its own folder of --work, and prints the Markdown table (value, bar,
reference, difference, CPU and wall time). About 2.5 min of CPU in all,
plus about 2 min for the references.
"""
import argparse
import csv
import functools
import math
import os
import resource
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "doc", "derivations"))
import circular_footing_characteristics as characteristics  # noqa: E402

CASES = [
    # (factor, scene stem, label, phi', files appended to the scene)
    ("N_q - 1", "footing-sand", "shipped mesh (480 cells)", 30.0, []),
    ("N_q - 1", "footing-sand", "shipped mesh (480 cells)", 35.0,
     ["tests/prm/footing_sand_phi35.prm"]),
    ("N_q - 1", "footing-sand", "Target accuracy = 5e-2", 30.0,
     ["tests/accuracy/footing_sand_target_5e-2.prm"]),
    ("N_gamma", "footing-sand-gamma", "shipped mesh (480 cells)", 30.0, []),
    ("N_gamma", "footing-sand-gamma", "shipped mesh (480 cells)", 35.0,
     ["tests/prm/footing_sand_gamma_phi35.prm"]),
    ("N_gamma", "footing-sand-gamma", "Target accuracy = 15e-2", 30.0,
     ["tests/accuracy/footing_sand_gamma_target_15e-2.prm"]),
]


def run(exe, work, name, stem, appended):
    """Run prm/STEM.prm with `appended` files; (results rows, CPU s, wall s)."""
    directory = os.path.join(work, name)
    os.makedirs(directory, exist_ok=True)
    text = open(os.path.join(ROOT, "prm", stem + ".prm")).read()
    for path in appended:
        text += "\n" + open(os.path.join(ROOT, path)).read()
    prm = os.path.join(directory, "scene.prm")
    with open(prm, "w") as f:
        f.write(text)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.time()
    with open(os.path.join(directory, "log.txt"), "w") as log:
        p = subprocess.run([exe, prm], cwd=directory, stdout=log,
                           stderr=subprocess.STDOUT)
    wall = time.time() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    if p.returncode != 0:
        sys.exit("sand_footing_table.py: run %s failed; its log: %s" %
                 (name, os.path.join(directory, "log.txt")))
    rows = {}
    results = os.path.join(directory, "output", stem, "results.csv")
    with open(results) as f:
        for row in csv.DictReader(f):
            rows[row["quantity"]] = float(row["value"])
    return rows, cpu, wall


@functools.lru_cache(maxsize=None)
def reference(factor, phi):
    """N_q - 1 or N_gamma of the smooth circular footing (Richardson over
    nets of 20 and 40 lines)."""
    if factor == "N_q - 1":
        return characteristics.richardson(characteristics.n_q, phi, True,
                                          20)[2] - 1
    return characteristics.richardson(characteristics.n_gamma, phi, True,
                                      20)[2]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--exe", default=os.path.join(ROOT, "build",
                                                      "fourier-ssi"))
    parser.add_argument("--work", default="sand-footing-runs")
    parser.add_argument("--skip-target", action="store_true",
                        help="leave out the Target accuracy runs")
    args = parser.parse_args()
    exe = os.path.abspath(args.exe)
    print("| factor | phi' | run | computed | its bar (what it holds) | "
          "exact (smooth, associated) | difference | error within bar? "
          "| CPU | wall |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for index, (factor, stem, label, phi, appended) in enumerate(CASES):
        if args.skip_target and "Target" in label:
            continue
        rows, cpu, wall = run(exe, args.work, "case-%d" % index, stem,
                              appended)
        value = rows["capacity_normalised"]
        bar = rows["capacity_normalised_error"]
        holds = "mesh + plateau" if "Target" in label else "plateau only"
        exact = reference(factor, phi)
        error = value - exact
        print("| %s | %g° | %s | %.3f | ± %.2f (%s) | %.3f | %+.2f %% | %s | "
              "%.0f s | %.0f s |" % (factor, phi, label, value, bar, holds,
                                     exact, 100 * error / exact,
                                     "yes" if abs(error) <= bar else "no",
                                     cpu, wall), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
