#!/usr/bin/python3
"""What the coupled Newton tangent costs on MPI ranks: the pile slice of
prm/pile-capacity.prm (Tresca soil, a lateral capacity, Newton) with its
harmonics listed n = 0 .. N, run one build four ways, one run at a time:

  umfpack 1   one rank, UMFPACK on the whole tangent (the default);
  umfpack 2   two ranks, each the block rows of its harmonics, summed, one
              rank factorizes with UMFPACK and broadcasts (the default
              under mpirun);
  mumps 1     one rank, Linear solver/Distributed = always: MUMPS;
  mumps 2     two ranks, Distributed = always: the tangent one matrix over
              both, each rank its harmonics' rows, MUMPS.

    python3 benchmarks/coupled-tangent-ranks/run.py EXE [--n-max N,...]
        [--repeats R] [--commit C] [--no-write]

Per run: wall time, the peak memory of each rank (GNU time around every
rank), H (kN) and its difference from the umfpack-1 run. Writes
results.md beside this script unless --no-write.
"""
import argparse
import csv
import datetime
import os
import shutil
import statistics
import subprocess
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
SCENE = os.path.join(ROOT, "prm", "pile-capacity.prm")
WAYS = [("umfpack", 1), ("umfpack", 2), ("mumps", 1), ("mumps", 2)]
# What to read in the table (written below it).
READING = """Every way gives the same H to the 9 digits shown (the MUMPS runs
are within 2e-14 of UMFPACK's, test mpi_soil_mumps_ranks). On 2 shared
cores no way is faster than one rank's UMFPACK, which also threads its
point loops over both cores: the ranks pay for the sums and broadcasts of
every Newton update, and MUMPS for its own overhead. What the distributed
tangent buys is memory per rank: its factors are shared by the ranks, so
the largest rank needs less than the one-rank run (at n <= 16 the peak
falls by about a fifth); the harmonic set itself (every rank sets up every
harmonic, and holds its own harmonics' factorizations) is not shared."""


def scene(n_max, solver):
    text = open(SCENE).read() + """
subsection Discretization
  set Harmonics = %s
end
subsection Output
  set Directory = out
end
""" % ", ".join(str(n) for n in range(n_max + 1))
    if solver == "mumps":
        text += "subsection Linear solver\n  set Distributed = always\nend\n"
    return text


def run(exe, text, ranks, work):
    """Wall [s], the peak memory of every rank [GB] and H [kN]."""
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    open(os.path.join(work, "case.prm"), "w").write(text)
    timed = ["/usr/bin/time", "-f", "rank-peak %M", exe, "case.prm"]
    launcher = ([] if ranks == 1 else
                ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np",
                 str(ranks)])
    start = datetime.datetime.now()
    result = subprocess.run(launcher + timed, cwd=work, capture_output=True,
                            text=True)
    wall = (datetime.datetime.now() - start).total_seconds()
    if result.returncode != 0:
        raise SystemExit("failed: " + result.stdout[-400:] +
                         result.stderr[-400:])
    peaks = [float(line.split()[1]) / 1024. ** 2
             for line in result.stderr.splitlines()
             if line.startswith("rank-peak")]
    with open(os.path.join(work, "out", "results.csv")) as f:
        H = [float(r["value"]) for r in csv.DictReader(f)
             if r["quantity"] == "capacity_H"]
    return wall, peaks, H[-1]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("exe")
    parser.add_argument("--n-max", default="8,16")
    parser.add_argument("--repeats", type=int, default=1)
    parser.add_argument("--commit", default="unknown")
    parser.add_argument("--no-write", action="store_true")
    args = parser.parse_args()
    args.exe = os.path.abspath(args.exe)
    load_start = os.getloadavg()[0]
    lines = []
    work = tempfile.mkdtemp(prefix="coupled-tangent-ranks-")
    for n_max in [int(n) for n in args.n_max.split(",")]:
        walls, peaks, H = {}, {}, {}
        for repeat in range(args.repeats):
            for way in WAYS:
                wall, rank_peaks, h = run(args.exe, scene(n_max, way[0]),
                                          way[1], os.path.join(work, "case"))
                walls.setdefault(way, []).append(wall)
                peaks[way], H[way] = rank_peaks, h
        reference = H[WAYS[0]]
        for way in WAYS:
            lines.append("| n <= %d | %s | %d | %.1f | %s | %.9g | %.1e |"
                         % (n_max, way[0], way[1],
                            statistics.median(walls[way]),
                            " / ".join("%.2f" % p for p in peaks[way]),
                            H[way], abs(H[way] - reference) / abs(reference)))
    shutil.rmtree(work, ignore_errors=True)
    table = ("| harmonics | factorization | ranks | wall s (median of %d) | "
             "peak GB per rank | H kN | vs umfpack 1 (rel) |\n"
             "|---|---|---|---|---|---|---|\n" % args.repeats +
             "\n".join(lines))
    print(table)
    if args.no_write:
        return
    with open(os.path.join(HERE, "results.md"), "w") as f:
        f.write("# The coupled Newton tangent on MPI ranks\n\nWritten by "
                "`run.py` (%s), build %s: prm/pile-capacity.prm with its "
                "harmonics listed, one run at a time. Load average (1 min) "
                "%.1f at the start, %.1f at the end, on 2 cores.\n\n%s\n\n%s\n"
                % (datetime.date.today(), args.commit, load_start,
                   os.getloadavg()[0], table, READING))


if __name__ == "__main__":
    main()
