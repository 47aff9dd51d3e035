#!/usr/bin/python3
"""What the harmonics cost with plastic soil: the pile slice of
prm/pile-capacity.prm (a lateral capacity, Tresca soil) with its harmonics
listed (n = 0 .. N, as the scene ships them for N = 8) or grown by the
solution from n = 1 up to Load path/Maximum harmonic = M
(doc/soil-plasticity.md 3e), run by two builds side by side.

    python3 benchmarks/harmonic-scaling/run.py NEW_EXE OLD_EXE
        [--cases NAME,...] [--repeats R] [--new-commit C] [--old-commit C]
        [--no-write] [--tag TAG]

One run at a time, the two builds alternating, R times (median wall
time). Per run: wall time and peak memory (GNU time), the harmonics the
last step solved, the capacity H (kN) and N_p = H / (s_u d L) = H / 100 kN.
Writes results.md (results-TAG.md with --tag, for a run of some cases)
beside this script unless --no-write, with the load
average at the start and at the end.
"""
import os
import statistics
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.dirname(HERE))
import side_by_side  # noqa: E402
SCENE = os.path.join(ROOT, "prm", "pile-capacity.prm")


def listed(n_max):
    return """
subsection Discretization
  set Harmonics = %s
end
""" % ", ".join(str(n) for n in range(n_max + 1))


def grown(maximum):
    return """
subsection Discretization
  set Harmonics = 1
end
subsection Load path
  set Maximum harmonic = %d
end
""" % maximum


CASES = {
    "listed n <= 16": listed(16),
    "listed n <= 32": listed(32),
    "grown to M = 16": grown(16),
    "grown to M = 32": grown(32),
    "grown to M = 64": grown(64),
}


# Written below the table.
READING = """Listed harmonics couple every pair of n = 0 .. N in the coupled tangent;
grown ones are the odd n a lateral load's plastic zone calls for (the even
ones are zero by symmetry), added where the soil's stress spectrum passes
Harmonic tolerance = 1e-3. Growth to M = 32 stops at n = 29 (15 harmonics)
and gives the listed n <= 32's N_p to 3e-6; M = 64 adds nothing above n = 29
either, and costs more only through its theta samples (4 (M + 1)). The
profile of the grown M = 32 run (perf, before the return mapping shared its
eigenvalues): the B^T S B products of the softening 25 %, the return
mapping with its Jacobi eigenvalues 25 %, the theta transforms of the
softening 8 %, UMFPACK's refactorization about 20 % (a third of it the
kernel zeroing fresh pages for its workspace)."""


def run_case(exe, entries, work):
    run = side_by_side.timed_run(exe, open(SCENE).read() + entries, work)
    if "failed" in run:
        return run
    rows = run.pop("rows")
    run["capacity"] = rows["capacity_H"][-1]
    # Grown: the last step's harmonics; listed: every harmonic of the scene.
    run["harmonics"] = (int(rows["step_harmonics"][-1])
                        if "step_harmonics" in rows
                        else entries.count(",") + 1)
    return run


def main():
    args = side_by_side.arguments(CASES)
    load_start = os.getloadavg()[0]
    lines = []
    for name in args.cases.split(","):
        runs = {"new": [], "old": []}
        with tempfile.TemporaryDirectory() as tmp:
            for k in range(args.repeats):
                for side, exe in (("new", args.new), ("old", args.old)):
                    runs[side].append(run_case(exe, CASES[name],
                                               os.path.join(tmp, side)))
                    print(name, side, k, runs[side][-1], flush=True)
        walls = {}
        for side in ("new", "old"):
            ok = [r for r in runs[side] if "failed" not in r]
            if not ok:
                lines.append("| %s | %s | failed | | | | |" % (name, side))
                continue
            walls[side] = statistics.median(r["wall"] for r in ok)
            last = ok[-1]
            lines.append("| %s | %s | %.1f | %.2f | %d | %.3f | %.5f |"
                         % (name, side, walls[side],
                            max(r["rss_gb"] for r in ok), last["harmonics"],
                            last["capacity"], last["capacity"] / 100.))
        if len(walls) == 2:
            lines.append("| %s | time ratio new / old | %.2f | | | | |"
                         % (name, walls["new"] / walls["old"]))
    side_by_side.report(
        HERE, ["harmonics", "build", "wall s (median of %d)", "peak GB",
               "harmonics solved", "H [kN]", "N_p"], lines,
        "Harmonics with plastic soil: listed against grown",
        "the pile slice of prm/pile-capacity.prm (26 cells, 6 steps to "
        "0.03 m); the exact plane-strain N_p is 9.20117, the difference is "
        "this mesh's.", args, load_start, READING)


if __name__ == "__main__":
    sys.exit(main())
