#!/usr/bin/python3
"""Accuracy in the nonlinear regime against its cost: capacities asked to a
target accuracy with this build's members that follow the mechanism
(Adaptivity/Strategy = kelly) and with an older build's uniform members, side
by side in one run.

    python3 benchmarks/nonlinear-accuracy/run.py NEW_EXE OLD_EXE
        [--cases NAME,...] [--repeats R] [--new-commit C] [--old-commit C]
        [--no-write] [--tag TAG]

Each case appends its entries to a bundled scene (a temporary copy, its own
output folder) and runs it with NEW_EXE (Strategy = kelly, Refine fraction
0.6, and the case's own entries for the new build: for the pile slice its
harmonics grown by the solution) and OLD_EXE (the scene as shipped, the
uniform members of Strategy = global), alternating, one run at a time, R
times (median wall time). Per run: wall time and peak
memory (GNU time's maximum resident set size), the capacity and its printed
relative error bar, the true relative error against the case's reference,
the effectivity (bar over true error) and whether the bar contains the
reference. Writes results.md (results-TAG.md with --tag, for a run of some cases)
beside this script unless --no-write, with
the machine's load average at the start and at the end (the times are only
comparable within one table).
"""
import os
import statistics
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.dirname(HERE))
import side_by_side  # noqa: E402

ADAPTIVE = """
subsection Adaptivity
  set Strategy        = kelly
  set Refine fraction = 0.6
end
"""

# The pile slice's lateral load is n = 1; the solution adds the odd
# harmonics its plastic zone calls for (doc/soil-plasticity.md 3e), where
# the shipped scene lists n <= 8 and a target doubles them all.
GROWN_FROM_N1 = """
subsection Discretization
  set Harmonics = 1
end
subsection Load path
  set Maximum harmonic = 8
end
"""

# The footing twisted instead of pushed down (doc/soil-plasticity.md 5b),
# on both builds: the antisymmetric n = 0, the torque controlled by the
# twist.
TORSION = """
subsection Discretization
  set Family = antisymmetric
end
subsection Rigid foundation
  set Vertical force = 0
  set Torque         = 1
  set Capacity normalisation = T/(a^3 s_u) = 10
end
subsection Load path
  set Controlled motion = twist
  set Target            = 0.02
end
"""
# name: (scene, its entries on both builds, target, capacity row,
# normalisation of the row, reference of the normalised capacity, where
# the reference comes from, the new build's own entries)
CASES = {
    "footing-capacity N_c 2e-2": (
        "prm/footing-capacity.prm", "", 2e-2, "capacity_V",
        -1. / 31.4159265, 6.05, "Eason & Shield (1960), rough", ""),
    "footing-capacity N_c 1e-2": (
        "prm/footing-capacity.prm", "", 1e-2, "capacity_V",
        -1. / 31.4159265, 6.05, "Eason & Shield (1960), rough", ""),
    "pile-capacity N_p 1e-2": (
        "prm/pile-capacity.prm", "", 1e-2, "capacity_H", 0.01, 9.20117,
        "exact plane-strain limit, smooth (Geotechnique 2026)",
        GROWN_FROM_N1),
    "footing torsion T/(a^3 s_u) 1e-2": (
        "prm/footing-capacity.prm", TORSION, 1e-2, "capacity_T", 0.1,
        2.0943951, "2 pi / 3: a uniform shear s_u on the base (exact)",
        ""),
    "footing-sand N_q - 1 2e-2": (
        "prm/footing-sand.prm", "", 2e-2, "capacity_V", -1. / 314.159265,
        28.450, "exact, smooth circular footing, phi' = 30 deg "
        "(doc/sand-footings.md)", ""),
}
# What the table does not show yet (written below it).
NOT_YET = """The footing's N_c, its torsion, the sand footing's N_q and the pile
slice's N_p are measured. The other targets of the nonlinear-accuracy
table are not in this table: disc-tresca's finer meshes cut Newton's steps
(doc/soil-plasticity.md 8d); the free-head pile, the caisson and the
CalculiX runs are not built into it. On the pile slice the new side's time
is the coupled tangent of n <= 16 (8 harmonics grown): its cost per
harmonic is what bounds it now; on the footing, three members of 20 steps
each, every one solved from zero."""


def run_case(exe, scene, scene_entries, target, new_entries, work):
    text = open(os.path.join(ROOT, scene)).read() + scene_entries
    text += """
subsection Discretization
  set Target accuracy = %g
end
subsection Output
  set Write vtu = false
end
""" % target
    if new_entries is not None:
        text += ADAPTIVE + new_entries
    run = side_by_side.timed_run(exe, text, work)
    if "rows" in run:
        run["rows"] = {name: values[-1] for name, values in run["rows"].items()}
    return run


def summarise(runs, row, scale, reference):
    ok = [r for r in runs if "failed" not in r]
    if not ok:
        return None
    value = ok[-1]["rows"][row] * scale
    bar = ok[-1]["rows"].get(row + "_error", float("nan"))
    error = abs(value - reference) / abs(reference)
    return {"wall": statistics.median(r["wall"] for r in ok),
            "rss": max(r["rss_gb"] for r in ok), "value": value,
            "bar": bar, "error": error,
            "contains": abs(value - reference) <= bar * abs(value)}


def main():
    args = side_by_side.arguments(CASES)
    load_start = os.getloadavg()[0]
    lines = []
    for name in args.cases.split(","):
        (scene, scene_entries, target, row, scale, reference, source,
         entries) = CASES[name]
        runs = {"new": [], "old": []}
        with tempfile.TemporaryDirectory() as tmp:
            for k in range(args.repeats):
                for side, exe, new_entries in (("new", args.new, entries),
                                               ("old", args.old, None)):
                    runs[side].append(run_case(
                        exe, scene, scene_entries, target, new_entries,
                        os.path.join(tmp, side)))
                    print(name, side, k, runs[side][-1].get(
                        "wall", runs[side][-1].get("failed")), flush=True)
        new = summarise(runs["new"], row, scale, reference)
        old = summarise(runs["old"], row, scale, reference)
        new_label = "kelly%s (new)" % (", harmonics grown" if entries else "")
        for side, s in ((new_label, new), ("uniform (old)", old)):
            if s is None:
                lines.append("| %s | %s | failed | | | | | | |"
                             % (name, side))
                continue
            lines.append(
                "| %s | %s | %.1f | %.2f | %.4f | %.2g | %.2g | %.2f | %s |"
                % (name, side, s["wall"], s["rss"], s["value"], s["bar"],
                   s["error"], s["bar"] / s["error"] if s["error"] else 0,
                   "yes" if s["contains"] else "NO"))
        if new and old:
            lines.append("| %s | time ratio new / old | %.2f | | | | | | |"
                         % (name, new["wall"] / old["wall"]))
        lines.append("| %s | reference | | | %.4f | | | | %s |"
                     % (name, reference, source))
    side_by_side.report(
        HERE, ["case", "members", "wall s (median of %d)", "peak GB",
               "capacity", "bar (rel)", "true error (rel)", "effectivity",
               "bar holds the reference"], lines,
        "Nonlinear accuracy: adaptive against uniform members",
        "new with kelly members (and its cases' own entries), old with the "
        "uniform members of the scenes as shipped.", args, load_start,
        NOT_YET)


if __name__ == "__main__":
    sys.exit(main())
