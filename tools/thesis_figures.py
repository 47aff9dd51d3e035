#!/usr/bin/python3
"""Regenerate the thesis figure families with error bars.

Usage: tools/thesis_figures.py [--exe build/fourier-ssi] [--mpi 2]
                               [--only footing,pile,table-4-1,table-7-1,disc]
                               [--out doc/figures]

Runs the stiffness sweeps of prm/sweeps/ (footing: Figs 4.6-4.11, 80 cases;
pile: Figs 6.2-6.7, 48 flexible and 48 rigid cases), each case driven by the
sweep file's 'target accuracy' (1e-4 rough, 1e-3 smooth) through one
'fourier-ssi --batch' job (tools/sweep.py), copies the CSVs to --out and
plots them with tools/plot_sweeps.py (every point with its error bar, the
largest error in each panel's title). The tables, each in one --batch
process (--mpi does not apply there): Table 4.1 (30 cases,
benchmarks/table-4-1/run.py --target 1e-4,1e-3 -> table-4-1.csv, .md) and
Table 7.1 (tools/table_7_1.py -> table-7-1.csv, .md), and the disc
stresses of Figs 5.6-5.24 (10 cases, tools/plot_disc.py --converged ->
disc-stresses-converged.csv, .png, disc-stresses-poisson.png). Prints the
wall time of each step and of the whole set.
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
FAMILIES = {
    "footing": ("prm/sweeps/footing.sweep", ["footing-stiffness"]),
    "pile": ("prm/sweeps/pile.sweep", ["pile-stiffness", "pile-stiffness-rigid"]),
}
# The tables and the disc stresses: the command that writes them into OUT
# (one --batch process each).
SCRIPTS = {
    "table-4-1": lambda exe, out: [
        os.path.join(ROOT, "benchmarks/table-4-1/run.py"), "--exe", exe, "--target",
        "1e-4,1e-3", "--out", out, "--tag", "table-4-1"],
    "table-7-1": lambda exe, out: [
        os.path.join(ROOT, "tools/table_7_1.py"), "--exe", exe, "--target", "1e-4,1e-3",
        "--out", out],
    "disc": lambda exe, out: [
        os.path.join(ROOT, "tools/plot_disc.py"), "--converged", "--exe", exe, "--out", out],
}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--exe", default=os.path.join(ROOT, "build/fourier-ssi"))
    ap.add_argument("--mpi", type=int, default=2, metavar="N",
                    help="MPI ranks of the --batch job (0: one process, no mpirun)")
    ap.add_argument("--mpirun", default="mpirun")
    ap.add_argument("--only", default=",".join([*FAMILIES, *SCRIPTS]))
    ap.add_argument("--out", default=os.path.join(ROOT, "doc/figures"))
    args = ap.parse_args()
    work = tempfile.mkdtemp(prefix="thesis-figures-")
    t_all = time.time()
    for name in args.only.split(","):
        if name in SCRIPTS:
            t0 = time.time()
            if subprocess.run([sys.executable, *SCRIPTS[name](args.exe, args.out)]).returncode:
                sys.exit(f"{name}: the table failed")
            print(f"{name}: {time.time() - t0:.1f} s wall, one process", flush=True)
            continue
        if name not in FAMILIES:
            sys.exit(f"--only: '{name}' is not one of {', '.join([*FAMILIES, *SCRIPTS])}")
        sweep, stems = FAMILIES[name]
        t0 = time.time()
        cmd = [sys.executable, os.path.join(ROOT, "tools/sweep.py"), os.path.join(ROOT, sweep),
               "--exe", args.exe, "--out", work, "--mpi", str(args.mpi),
               "--mpirun", args.mpirun]
        if subprocess.run(cmd).returncode != 0:
            sys.exit(f"{sweep}: the sweep failed")
        csvs = []
        for stem in stems:
            shutil.copy(os.path.join(work, stem + ".csv"), args.out)
            csvs.append(os.path.join(args.out, stem + ".csv"))
        t1 = time.time()
        subprocess.run(["/usr/bin/python3", os.path.join(ROOT, "tools/plot_sweeps.py"), *csvs,
                        "--out", args.out], check=True)
        print(f"{name}: sweep {t1 - t0:.1f} s, plots {time.time() - t1:.1f} s wall", flush=True)
    shutil.rmtree(work, ignore_errors=True)
    print(f"figure set ({args.only}): {time.time() - t_all:.1f} s wall, "
          f"{args.mpi if args.mpi > 0 else 1} process(es)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
