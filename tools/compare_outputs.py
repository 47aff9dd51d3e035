#!/usr/bin/python3
"""Runs every bundled scene (prm/*.prm) with two builds of fourier-ssi and
compares their results.csv and load-displacement.csv as text, except the
wall times (rows or columns whose name contains "time"), which differ from
run to run. A refactoring that changes no answer passes it.

Usage:
  tools/compare_outputs.py OLD_BINARY NEW_BINARY [--limit SECONDS] [SCENE...]

Each run writes to its own temporary folder (a copy of the scene with an
Output/Directory appended). A scene whose old run takes longer than
--limit seconds (default 120) is skipped and listed. Prints one line per
scene with both wall times and their ratio; exits 1 if any compared file
differs or a run fails.
"""

import argparse
import csv
import os
import subprocess
import sys
import tempfile
import time

COMPARED_FILES = ["results.csv", "load-displacement.csv"]


def run_scene(binary, prm, folder, limit):
    """Runs `prm` with its output in `folder`; returns (wall time, exit
    code), or (None, None) if it ran past `limit` seconds."""
    os.makedirs(folder, exist_ok=True)
    copy = os.path.join(folder, "scene.prm")
    with open(prm) as source, open(copy, "w") as target:
        target.write(source.read())
        target.write("\nsubsection Output\n  set Directory = %s\nend\n" %
                     os.path.join(folder, "output"))
    start = time.monotonic()
    try:
        process = subprocess.run([binary, copy],
                                 cwd=folder,
                                 stdout=subprocess.DEVNULL,
                                 stderr=subprocess.PIPE,
                                 timeout=limit)
    except subprocess.TimeoutExpired:
        return None, None
    return time.monotonic() - start, process.returncode


def without_times(path):
    """The CSV's rows as text, without the columns and rows that hold
    wall times."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        return rows
    header = rows[0]
    kept = [i for i, name in enumerate(header) if "time" not in name.lower()]
    # A row of results.csv names its quantity in its first cell.
    return [[row[i] for i in kept if i < len(row)] for row in rows
            if not (row is not header and row and "time" in row[0].lower())]


def compare_folder(old, new):
    """The names of the compared files that differ (or exist in one run
    only)."""
    differing = []
    for name in COMPARED_FILES:
        a, b = os.path.join(old, name), os.path.join(new, name)
        if not os.path.exists(a) and not os.path.exists(b):
            continue
        if not (os.path.exists(a) and os.path.exists(b)):
            differing.append(name + " (in one run only)")
        elif without_times(a) != without_times(b):
            differing.append(name)
    return differing


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("old")
    parser.add_argument("new")
    parser.add_argument("scenes", nargs="*")
    parser.add_argument("--limit", type=float, default=120.)
    args = parser.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    scenes = args.scenes or sorted(
        os.path.join(root, "prm", name)
        for name in os.listdir(os.path.join(root, "prm"))
        if name.endswith(".prm"))
    old_binary, new_binary = (os.path.abspath(b) for b in (args.old, args.new))
    failed, skipped, compared = [], [], []
    with tempfile.TemporaryDirectory(prefix="compare-outputs-") as work:
        for prm in scenes:
            scene = os.path.splitext(os.path.basename(prm))[0]
            old_dir = os.path.join(work, scene, "old")
            new_dir = os.path.join(work, scene, "new")
            old_time, old_code = run_scene(old_binary, prm, old_dir, args.limit)
            if old_time is None:
                skipped.append(scene)
                print("%-32s skipped (old run > %g s)" % (scene, args.limit),
                      flush=True)
                continue
            new_time, new_code = run_scene(new_binary, prm, new_dir,
                                           4. * args.limit)
            if new_time is None or old_code != new_code:
                failed.append(scene)
                print("%-32s FAILED: exit codes %s and %s" %
                      (scene, old_code, new_code), flush=True)
                continue
            differing = compare_folder(os.path.join(old_dir, "output"),
                                       os.path.join(new_dir, "output"))
            compared.append(scene)
            if differing:
                failed.append(scene)
            print("%-32s %s  old %7.2f s  new %7.2f s  ratio %.3f" %
                  (scene, "DIFFERS: " + ", ".join(differing) if differing
                   else "identical", old_time, new_time, new_time / old_time),
                  flush=True)
    print("%d scenes compared, %d differ or fail, %d skipped%s" %
          (len(compared), len(failed), len(skipped),
           (": " + ", ".join(skipped)) if skipped else ""))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
