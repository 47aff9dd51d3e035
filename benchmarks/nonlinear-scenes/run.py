#!/usr/bin/python3
"""Every bundled nonlinear scene, this build against the main before the
nonlinear-engine work (commit b759ea2), side by side in one run: the
acceptance item "every bundled nonlinear scene as fast as today or faster,
with the same answers within their tolerances" of the requirement "one
nonlinear engine".

    /usr/bin/python3 benchmarks/nonlinear-scenes/run.py [NEW_EXE] [OLD_EXE] [RUNS]
                     [SCENE,SCENE,...] [TAG]

NEW_EXE defaults to build/fourier-ssi of this tree, OLD_EXE to
/work/wt-oldmain/build/fourier-ssi (b759ea2 built in Release), RUNS to 3.
A list of scenes runs only those; TAG writes results-TAG.csv/.md instead
(a supplementary run that leaves the main table alone).

The scenes: every prm/*.prm that runs a nonlinear load path (a `Load path`
subsection, soil plasticity laws, or coulomb/contact interfaces), run exactly
as shipped. The old binary knows the subsection as `Nonlinear interfaces`:
the copy it reads has that name; an entry it does not declare (added after
b759ea2: Capacity normalisation, Soil reaction depths, ...) is dropped from
its copy, one at a time as it names them, and listed in the table. A run
that the old binary refuses or that fails is recorded with its exit code and
one-line message: that is a finding, not a skipped case.

Each run reads a copy of the prm in its own temporary directory, so the
scene's relative Output/Directory lands there. Old and new alternate (old,
new, old, new, ...) so both see the same machine load. A scene whose first
old and new runs both finish in under SHORT s is run RUNS times per binary
(medians); a longer one, or one that fails, once. Every run has a wall-clock
limit of TIMEOUT s.

Per run: exit code, wall time, the program's own time of the coupled load
steps (`coupled solve: ... s`), accepted load steps, iterations (summed over
the steps the program prints), step cuts, and the scene's goal values from
its results.csv. The goal values and their tolerances are the scene's own
checks (tests/scenes/<stem>.*.checks without `# append:`; a scene with only
appended checks uses those whose quantities its shipped run writes, the
load at the end of the path end_load_X as the last step's load):
new and old agree on a check line when |new - old| is within that line's
tolerance (relative: tol |ref|; absolute: tol; within: the new run's error
bar + model tol |ref|). The same lines are also evaluated against their
references for both binaries ("checks passed").

Writes results.csv (one row per run) and results.md next to this file. The
machine is shared (2 cores): single times carry the noise of other jobs;
the ratios are from runs made side by side.
"""
import csv
import glob
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.normpath(os.path.join(HERE, "..", ".."))
# The old build: b759ea2 (the main before the engine work) unless the
# environment names another commit of this tree that OLD_EXE was built
# from (FSSI_OLD_COMMIT); such a build reads the prms as shipped.
OLD_COMMIT = os.environ.get("FSSI_OLD_COMMIT", "b759ea2")
BEFORE_ENGINE = OLD_COMMIT == "b759ea2"
TIMEOUT = 600.
SHORT = 20.
MOST_DROPPED_ENTRIES = 10
RESULTS = "results"
FIELDS = ["scene", "binary", "run", "exit", "wall_s", "solve_s", "steps",
          "iterations", "cuts", "goal_quantity", "goal_value", "goal_error",
          "dropped_entries", "message"]


# ---------------------------------------------------------------- scenes

def uncommented(text):
    return "\n".join(line.split("#", 1)[0] for line in text.splitlines())


def is_nonlinear(text):
    """A load path, plastic soil, or coulomb/contact interfaces."""
    body = uncommented(text)
    return bool(re.search(r"^\s*subsection\s+Load path\s*$", body, re.M) or
                re.search(r"^\s*set\s+Laws\s*=\s*\S", body, re.M) or
                re.search(r"^\s*set\s+Interfaces\s*=.*\b(coulomb|contact)\b",
                          body, re.M))


def nonlinear_scenes():
    scenes = []
    for prm in sorted(glob.glob(os.path.join(SOURCE, "prm", "*.prm"))):
        if is_nonlinear(open(prm).read()):
            scenes.append(os.path.splitext(os.path.basename(prm))[0])
    return scenes


def linear_scenes():
    return [os.path.splitext(os.path.basename(p))[0]
            for p in sorted(glob.glob(os.path.join(SOURCE, "prm", "*.prm")))
            if not is_nonlinear(open(p).read())]


def output_directory(text):
    found = re.findall(r"^\s*set\s+Directory\s*=\s*(\S+)", uncommented(text),
                       re.M)
    return found[-1] if found else "output"


def for_old_binary(text, dropped):
    """The prm as b759ea2 reads it: the subsection's old name, and without
    the entries it refused so far (name, subsection-free match)."""
    if BEFORE_ENGINE:
        text = re.sub(r"^(\s*)subsection\s+Load path\s*$",
                      r"\1subsection Nonlinear interfaces", text, flags=re.M)
    for entry in dropped:
        text = re.sub(r"^\s*set\s+%s\s*=.*$" % re.escape(entry), "", text,
                      flags=re.M)
    return text


# ---------------------------------------------------------------- checks

def read_checks(stem):
    """[(kind, words)] of the scene's checks: the files without `# append:`
    first; only appended ones if the scene has no other."""
    plain, appended = [], []
    for path in sorted(glob.glob(os.path.join(SOURCE, "tests", "scenes",
                                              stem + ".*.checks"))):
        text = open(path).read()
        lines = [l.split() for l in text.splitlines()
                 if l.strip() and not l.lstrip().startswith("#")]
        target = appended if re.search(r"^#\s*append:", text, re.M) else plain
        target += [(l[0], l[1:], os.path.basename(path)) for l in lines]
    return plain if plain else appended


def read_results(path):
    """(quantity, n, family) -> {cycle: value}."""
    series = {}
    if not os.path.exists(path):
        return series
    with open(path) as f:
        for row in csv.DictReader(f):
            key = (row["quantity"], row["n"], row["family"])
            series.setdefault(key, {})[int(row["cycle"])] = float(row["value"])
    return series


# A scene checked only through a Target-accuracy variant names the load at
# the end of its path end_load_X; the shipped run writes it as its last step.
END_LOAD_AS_STEP = {"end_load_H": "step_horizontal_force",
                    "end_load_V": "step_vertical_force",
                    "end_load_M": "step_moment", "end_load_T": "step_torque"}


def lookup(series, quantity, n, family, cycle):
    name, _, factor = quantity.partition("*")
    if (name, n, family) not in series and name in END_LOAD_AS_STEP:
        name, cycle = END_LOAD_AS_STEP[name], "last"
    s = series.get((name, n, family))
    if not s:
        return None
    c = max(s) if cycle == "last" else int(cycle)
    return s[c] * (float(factor) if factor else 1.) if c in s else None


def with_normalised_capacity(series, text):
    """The old binary predates Rigid foundation/Capacity normalisation: its
    capacity_normalised is formed here as the new one is (|capacity| / REF,
    the bar the plateau's error / REF) from its capacity_X rows."""
    m = re.search(r"^\s*set\s+Capacity normalisation\s*=.*=\s*([-0-9.eE+]+)"
                  r"\s*$", uncommented(text), re.M)
    key = ("capacity_normalised", "0", "symmetric")
    if not m or key in series:
        return series
    reference = float(m.group(1))
    for x in ("H", "V", "M", "T"):
        s = series.get(("capacity_" + x, "0", "symmetric"))
        if s:
            series[key] = {c: abs(v) / reference for c, v in s.items()}
            bar = series.get(("capacity_%s_plateau_error" % x, "0",
                              "symmetric"), {})
            series[("capacity_normalised_error", "0", "symmetric")] = {
                c: abs(v) / reference for c, v in bar.items()}
            break
    return series


def error_bar(series, quantity, n, family, cycle):
    return lookup(series, quantity.partition("*")[0] + "_error", n, family,
                  cycle)


def passes(kind, w, series):
    """The check line against its reference; None if a row is missing."""
    if kind in ("relative", "absolute", "range"):
        v = lookup(series, w[0], w[1], w[2], w[3])
        if v is None:
            return None
        a, b = float(w[4]), float(w[5])
        if kind == "relative":
            return abs(v - a) <= b * abs(a)
        if kind == "absolute":
            return abs(v - a) <= b
        return a <= v <= b
    if kind == "within":
        v = lookup(series, w[0], w[1], w[2], w[3])
        bar = error_bar(series, w[0], w[1], w[2], w[3])
        if v is None or bar is None:
            return None
        a, b = float(w[4]), float(w[5])
        return abs(v - a) <= abs(bar) + b * abs(a)
    if kind == "equal":
        a = lookup(series, w[0], w[2], w[3], w[4])
        b = lookup(series, w[1], w[2], w[3], w[4])
        if a is None or b is None:
            return None
        return abs(a - b) <= float(w[5]) * max(abs(a), abs(b))
    return None  # effectivity, richardson, harmonics: not per-value


def agreement_tolerance(kind, w, new):
    """How far new and old may differ on this line: its own tolerance."""
    if kind == "relative":
        return float(w[5]) * abs(float(w[4]))
    if kind == "absolute":
        return float(w[5])
    if kind == "within":
        bar = error_bar(new, w[0], w[1], w[2], w[3])
        return None if bar is None else \
            abs(bar) + float(w[5]) * abs(float(w[4]))
    return None


def goal_line(checks, *runs):
    """The scene's goal: the first valued check whose quantity every given
    run wrote, preferring one with an error bar."""
    valued = [(k, w) for k, w, _ in checks
              if k in ("relative", "absolute", "within") and
              not w[0].partition("*")[0].endswith("_error") and
              all(lookup(r, *w[:4]) is not None for r in runs)]
    with_bar = [(k, w) for k, w in valued
                if all(error_bar(r, *w[:4]) is not None for r in runs)]
    return (with_bar or valued or [None])[0]


# ---------------------------------------------------------------- runs

def parse_log(log):
    steps = re.findall(r"^\s*step \d+(?: \(held loads\))?:.*?; (\d+) "
                       r"iterations", log, re.M)
    # The program's own time of the coupled load steps (every coupled solve
    # of the run, e.g. per mesh of a target), without start-up and output.
    solves = re.findall(r"^coupled solve: \d+ steps in ([-0-9.e+]+) s", log,
                        re.M)
    return {"steps": len(steps), "iterations": sum(int(s) for s in steps),
            "cuts": len(re.findall(r"^\s*step cut to", log, re.M)),
            "solve": sum(float(t) for t in solves) if solves else None}


def one_line_message(log):
    lines = [l.strip() for l in log.splitlines() if l.strip()]
    for l in lines:
        if re.search(r"\berror\b|refused|not converge|Exception|"
                     r"exception", l, re.I) and not l.startswith("---"):
            return l[:200]
    return lines[-1][:200] if lines else ""


def undeclared_entry(log):
    """The entry name in deal.II's 'not declared' message, if that failed."""
    m = re.search(r"No entry with name <([^>]+)> was declared", log)
    return m.group(1).strip() if m else None


def run_once(exe, text, old):
    """One run in its own temporary directory; for the old binary, retried
    without each entry it does not declare."""
    dropped = []
    while True:
        work = tempfile.mkdtemp(prefix="scene-bench-")
        try:
            prm = os.path.join(work, "scene.prm")
            with open(prm, "w") as f:
                f.write(for_old_binary(text, dropped) if old else text)
            start = time.time()
            try:
                p = subprocess.run([exe, prm], cwd=work, capture_output=True,
                                   text=True, timeout=TIMEOUT)
                code, log = p.returncode, p.stdout + p.stderr
            except subprocess.TimeoutExpired as e:
                code = "timeout"
                log = "timed out after %.0f s" % TIMEOUT
            wall = time.time() - start
            entry = undeclared_entry(log) if old and code != 0 else None
            if entry and entry not in dropped and \
                    len(dropped) < MOST_DROPPED_ENTRIES:
                dropped.append(entry)
                continue
            results = read_results(os.path.join(
                work, output_directory(text), "results.csv"))
            if old:
                results = with_normalised_capacity(results, text)
            r = {"exit": code, "wall": wall, "results": results,
                 "dropped": dropped,
                 "message": "" if code == 0 else
                 one_line_message(log.replace(work + "/", ""))}
            r.update(parse_log(log))
            return r
        finally:
            shutil.rmtree(work, ignore_errors=True)


def bench_scene(stem, exes, runs, writer):
    text = open(os.path.join(SOURCE, "prm", stem + ".prm")).read()
    checks = read_checks(stem)
    done = {"old": [], "new": []}
    for i in range(runs):
        for binary in ("old", "new"):
            first = done[binary][0] if done[binary] else None
            if first and (first["exit"] != 0 or first["wall"] > SHORT or
                          any(d[0]["wall"] > SHORT for d in done.values()
                              if d)):
                continue
            r = run_once(exes[binary], text, binary == "old")
            done[binary].append(r)
            goal = goal_line(checks, r["results"])
            row = {"scene": stem, "binary": binary, "run": i + 1,
                   "exit": r["exit"], "wall_s": "%.2f" % r["wall"],
                   "solve_s": "" if r["solve"] is None else
                   "%.3f" % r["solve"],
                   "steps": r["steps"], "iterations": r["iterations"],
                   "cuts": r["cuts"],
                   "dropped_entries": "; ".join(r["dropped"]),
                   "message": r["message"]}
            if goal:
                w = goal[1]
                row["goal_quantity"] = w[0]
                row["goal_value"] = "%.10g" % lookup(r["results"], *w[:4])
                bar = error_bar(r["results"], *w[:4])
                row["goal_error"] = "" if bar is None else "%.4g" % bar
            writer(row)
            print(row, flush=True)
    return {"stem": stem, "checks": checks, "old": done["old"],
            "new": done["new"]}


# ---------------------------------------------------------------- table

def median_wall(rs):
    ok = [r["wall"] for r in rs if r["exit"] == 0]
    return statistics.median(ok) if ok and len(ok) == len(rs) else None


def median_solve(rs):
    ok = [r["solve"] for r in rs if r["exit"] == 0 and r["solve"] is not None]
    return statistics.median(ok) if ok and len(ok) == len(rs) else None


def cell_run(rs):
    r = rs[0]
    if r["exit"] == 0:
        return "0 / %.2f s%s" % (median_wall(rs),
                                 " (x%d)" % len(rs) if len(rs) > 1 else "")
    return "%s / %.1f s: %s" % (r["exit"], r["wall"],
                                r["message"].replace("|", "/")[:140])


def value_cell(r, goal):
    if goal is None or r["exit"] != 0:
        return "-"
    w = goal[1]
    v = lookup(r["results"], *w[:4])
    if v is None:
        return "no row"
    bar = error_bar(r["results"], *w[:4])
    return "%.7g" % v + ("" if bar is None else " ± %.2g" % abs(bar))


def compare(s):
    """(lines agreeing, lines compared, worst line's text) new vs old."""
    old, new = s["old"][0], s["new"][0]
    if old["exit"] != 0 or new["exit"] != 0:
        return None
    agree, compared, off = 0, 0, []
    for kind, w, _ in s["checks"]:
        if kind not in ("relative", "absolute", "within"):
            continue
        a = lookup(old["results"], *w[:4])
        b = lookup(new["results"], *w[:4])
        tol = agreement_tolerance(kind, w, new["results"])
        if a is None or b is None or tol is None:
            continue
        compared += 1
        if abs(b - a) <= tol:
            agree += 1
        else:
            off.append("%s %s: old %.6g, new %.6g, |diff| %.3g > tol %.3g" % (
                w[0], w[3], a, b, abs(b - a), tol))
    return agree, compared, off


def checks_passed(s, binary):
    r = s[binary][0]
    if r["exit"] != 0:
        return "-"
    verdicts = [passes(k, w, r["results"]) for k, w, _ in s["checks"]]
    valued = [v for v in verdicts if v is not None]
    return "%d/%d" % (sum(valued), len(valued))


def commit_of(path):
    return subprocess.run(["git", "-C", path, "rev-parse", "--short",
                           "HEAD"], capture_output=True,
                          text=True).stdout.strip() or "?"


def write_table(summaries, runs, uptimes, new_exe, old_exe):
    new_commit = commit_of(SOURCE)
    before = ("the main before the engine work" if BEFORE_ENGINE else
              "an earlier build of this tree")
    out = ["# Bundled nonlinear scenes: this build against %s" % before, "",
           "Generated by `benchmarks/nonlinear-scenes/run.py` in one "
           "invocation. new: `%s` (commit %s of this tree); old: `%s` "
           "(commit %s, %s, Release). Every "
           "prm/*.prm with a nonlinear load path, run as shipped; old and "
           "new alternate (old, new, old, new, ...). Scenes whose first old "
           "and new runs both took under %.0f s: %d runs per binary, "
           "medians; otherwise one run. Wall-clock limit %.0f s per run. "
           "Times are whole-process wall times (start-up, mesh, "
           "factorizations, all load steps, output). The machine is shared: "
           "2 cores, other engineers building and testing at the same time; "
           "single times carry that noise, the ratios come from runs made "
           "side by side." % (new_exe, new_commit, old_exe, OLD_COMMIT,
                              before, SHORT, runs, TIMEOUT), "",
           "Not run (linear elastic, no load path): %s." % ", ".join(
               linear_scenes()), "",
           "Load at the start: `%s`" % uptimes[0], "",
           "Load at the end: `%s`" % uptimes[1], "",
           ("The old binary reads the subsection as `Nonlinear interfaces`; "
            "entries it does not declare are dropped from its copy "
            "(column \"dropped for old\"); its capacity_normalised (it has "
            "no Capacity normalisation) is formed from its capacity row as "
            "the new one is, |capacity| / reference. " if BEFORE_ENGINE else
            "Both binaries read the prms as shipped. ") +
           "Goal value: the scene's "
           "first valued check (tests/scenes/<stem>.*.checks) that both "
           "runs wrote, one with an error bar first, with the run's own "
           "error bar (a scene checked only through a Target-accuracy "
           "variant: its end_load_X is the shipped run's last step load). Agree: check lines (relative, "
           "absolute, within) on which |new - old| is within the line's own "
           "tolerance, of those both runs wrote. Checks passed: the same "
           "files' lines against their references (rows missing in a run "
           "are not counted). Steps / iterations: accepted load steps and "
           "the iterations summed over them, as printed (old / new). Solve: "
           "the program's own `coupled solve: ... s` (the load steps alone, "
           "medians).", "",
           "| scene | old exit / time | new exit / time | new/old time | "
           "solve old / new [s] | new/old solve | steps old / new | iterations old / new | goal quantity | "
           "goal value old | goal value new | agree within tolerance? | "
           "checks passed old / new | dropped for old |",
           "|" + "---|" * 14]
    slower, changed = [], []
    for s in summaries:
        old, new = s["old"][0], s["new"][0]
        goal = goal_line(s["checks"], new["results"], old["results"]) or \
            goal_line(s["checks"], new["results"]) or \
            goal_line(s["checks"], old["results"])
        mo, mn = median_wall(s["old"]), median_wall(s["new"])
        ratio = "%.2f" % (mn / mo) if mo and mn else "-"
        if mo and mn and mn > mo:
            slower.append("%s: wall %.2f s new vs %.2f s old (x%.2f, "
                          "+%.0f %%)" % (s["stem"], mn, mo, mn / mo,
                                         100. * (mn / mo - 1.)))
        so, sn = median_solve(s["old"]), median_solve(s["new"])
        solve = "%s / %s" % ("-" if so is None else "%.3f" % so,
                             "-" if sn is None else "%.3f" % sn)
        solve_ratio = "%.2f" % (sn / so) if so and sn else "-"
        c = compare(s)
        if c is None:
            agree = "- (a run failed)"
        elif c[1] == 0:
            agree = "- (no common check row)"
        else:
            agree = ("yes" if c[0] == c[1] else "**no**") + \
                " (%d/%d)" % (c[0], c[1])
            if c[2]:
                changed.append("%s: %s" % (s["stem"], "; ".join(c[2])))
        steps = "%s / %s" % (old["steps"] if old["exit"] == 0 else "-",
                             new["steps"] if new["exit"] == 0 else "-")
        its = "%s / %s" % (old["iterations"] if old["exit"] == 0 else "-",
                           new["iterations"] if new["exit"] == 0 else "-")
        out.append("| " + " | ".join([
            s["stem"], cell_run(s["old"]), cell_run(s["new"]), ratio, solve,
            solve_ratio, steps,
            its, goal[1][0] if goal else "-", value_cell(old, goal),
            value_cell(new, goal), agree,
            "%s / %s" % (checks_passed(s, "old"), checks_passed(s, "new")),
            ", ".join(old["dropped"]) or "-"]) + " |")
    out += ["", "## Scenes slower in the new build", ""]
    out += ["- " + l for l in slower] or ["None."]
    out += ["", "## Answers that moved beyond a check's tolerance", ""]
    out += ["- " + l for l in changed] or ["None."]
    with open(os.path.join(HERE, RESULTS + ".md"), "w") as f:
        f.write("\n".join(out) + "\n")


def uptime():
    """The load averages of `uptime` (the machine's load is what a wall
    time needs beside it; the clock time of the run is left out)."""
    text = subprocess.run(["uptime"], capture_output=True,
                          text=True).stdout.strip()
    return text[text.find("load average"):] if "load average" in text \
        else text


def main():
    new_exe = sys.argv[1] if len(sys.argv) > 1 else \
        os.path.join(SOURCE, "build", "fourier-ssi")
    old_exe = sys.argv[2] if len(sys.argv) > 2 else \
        "/work/wt-oldmain/build/fourier-ssi"
    runs = int(sys.argv[3]) if len(sys.argv) > 3 else 3
    only = sys.argv[4].split(",") if len(sys.argv) > 4 and sys.argv[4] \
        else None
    global RESULTS
    if len(sys.argv) > 5:
        RESULTS = "results-" + sys.argv[5]
    new_exe, old_exe = os.path.abspath(new_exe), os.path.abspath(old_exe)
    exes = {"new": new_exe, "old": old_exe}
    uptimes = [uptime()]
    rows, summaries = [], []

    def writer(row):
        # results.csv after every run: a benchmark cut short keeps its rows.
        rows.append(row)
        with open(os.path.join(HERE, RESULTS + ".csv"), "w",
                  newline="") as f:
            w = csv.DictWriter(f, fieldnames=FIELDS)
            w.writeheader()
            w.writerows(rows)

    for stem in nonlinear_scenes():
        if only and stem not in only:
            continue
        summaries.append(bench_scene(stem, exes, runs, writer))
        # results.md after every scene too (the "end" load is then now).
        write_table(summaries, runs, uptimes + [uptime()], new_exe, old_exe)


if __name__ == "__main__":
    main()
