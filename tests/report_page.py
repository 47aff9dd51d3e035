#!/usr/bin/python3
"""The run report page (tools/report.py, doc/report.md) on four bundled
scenes of four kinds:

  stiffness  prm/default.prm (linear, rigid footing, error estimates of the
             motions from 2 nested meshes);
  interface  prm/disc-gap.prm with Discretization/Target accuracy = 1e-2
             (coulomb interface on elastic soil: curve, interface state,
             the end load with its error bar);
  plastic    prm/triaxial-mohr-coulomb.prm with Write vtu (plastic soil:
             curve to a plateau, capacity with its plateau's error,
             yielding, the plastic zone);
  boundary load  prm/cylinder-mohr-coulomb.prm (plastic soil under a
             pressure on a boundary, no rigid foundation, no target: its
             curve has no foundation load or motion and there is no goal
             value, so both panels are left out and named).

For each it checks:
(1) the PNG is written, a PNG of one A4 page (827 x 1169 px at 100 dpi);
(2) the panels drawn are the ones the run's files allow (geometry with
    --prm; curve iff load-displacement.csv; interface state iff
    interface-state.csv; yielding iff plastic-sample rows; the plastic
    zone iff plastic-field-theta0-step*.vtu; goal table iff goal rows) and
    every panel left out is named with a reason;
(3) the goal rows on the page are exactly: every quantity Q with a row
    Q_error in results.csv, every foundation stiffness (whose bar is its
    motion's: K = F/u at a given F), every capacity without a total bar
    (whose bar is its plateau's error);
(4) each value is results.csv's to the last bit (the full value printed
    next to the page's text), the page's text (6 significant digits) is
    within half a unit of its last digit of it: 5e-6 relative, and the
    page's bar (2 significant digits) is within 5 % of the bar computed
    here from the *_error row (relative x |value|) or the plateau row;
(5) the interface-state panel shows the last step of load-displacement.csv;
(6) without --prm the geometry is left out and named; on a folder without
    results.csv the tool prints one line naming the file, exits non-zero
    and leaves no PNG;
(7) a bar that is the plateau's error alone is one-sided (the rise still
    to come): its goal-table entry reads "+bar", every other "bar"; on
    the plastic page the curve panel, drawn again here as report.py draws
    it, has the capacity's error bar from the capacity upward (its lower
    part 0, its upper part the bar), labelled one-sided, and its title
    says "+ bar (one-sided...".
Usage: report_page.py FOURIER_SSI_EXE SOURCE_DIR WORK_DIR
"""
import csv
import math
import os
import shutil
import struct
import subprocess
import sys

exe, source_dir, work = sys.argv[1:4]
report = os.path.join(source_dir, "tools/report.py")
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
failed = 0

SCENES = {
    "stiffness": ("prm/default.prm", "",
                  ["geometry", "goals"]),
    "interface": ("prm/disc-gap.prm",
                  "subsection Discretization\n"
                  "  set Target accuracy = 1e-2\nend\n",
                  ["geometry", "load-displacement", "interface-state",
                   "goals"]),
    "plastic": ("prm/triaxial-mohr-coulomb.prm",
                "subsection Output\n  set Write vtu = true\nend\n",
                ["geometry", "load-displacement", "yielding", "plastic-zone",
                 "goals"]),
    "boundary load": ("prm/cylinder-mohr-coulomb.prm", "",
                      ["geometry", "yielding"]),
}
# Half a unit in the 6th significant digit is at most 5e-6 of the value;
# half a unit in the 2nd is at most 5 % of the bar.
VALUE_TOLERANCE, BAR_TOLERANCE = 5e-6 * (1 + 1e-9), 0.05 * (1 + 1e-9)


def check(what, ok):
    global failed
    print(("  ok   " if ok else "  FAIL ") + what)
    failed += 0 if ok else 1


def run_scene(name, prm, appended):
    """The scene with its output in WORK/name/out."""
    folder = os.path.join(work, name.replace(" ", "-"))
    os.makedirs(folder)
    text = open(os.path.join(source_dir, prm)).read() + appended
    text += "\nsubsection Output\n  set Directory = out\nend\n"
    scene = os.path.join(folder, "scene.prm")
    open(scene, "w").write(text)
    subprocess.run([exe, "scene.prm"], cwd=folder, check=True,
                   stdout=subprocess.DEVNULL)
    return scene, os.path.join(folder, "out")


def run_report(out, png, prm=None):
    command = ["/usr/bin/python3", report, out, "-o", png]
    command += ["--prm", prm] if prm else []
    return subprocess.run(command, capture_output=True, text=True)


def parse_report(stdout):
    """panels, reasons left out, interface step, goal lines."""
    panels, missing, step, goals = [], [], None, []
    for line in stdout.splitlines():
        if line.startswith("panels: "):
            panels = line[len("panels: "):].split(", ")
        elif line.startswith("not shown: "):
            missing.append(line[len("not shown: "):])
        elif line.startswith("interface-state: step "):
            step = int(line.split()[2].rstrip(";"))
        elif line.startswith("goal: "):
            key, *rest = line[len("goal: "):].split(" | ")
            fields = dict(f.split("=", 1) for f in rest)
            goals.append((tuple(key.split(",")), fields))
    return panels, missing, step, goals


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    if head[:8] != b"\x89PNG\r\n\x1a\n":
        return None
    return struct.unpack(">II", head[16:24])


def results_of(out):
    with open(os.path.join(out, "results.csv")) as f:
        rows = list(csv.DictReader(f))
    return {(r["quantity"], r["n"], r["family"], r["cycle"]): r for r in rows}


def expected_goals(rows):
    """(quantity, n, family, cycle) -> absolute bar, by the rules of (3)."""
    expected = {}
    for (q, n, family, cycle), r in rows.items():
        value = (q[:-len("_error")], n, family, cycle)
        if q.endswith("_error") and value in rows:
            expected[value] = float(r["value"]) * abs(
                float(rows[value]["value"]))
    motion_of = {"vertical": "foundation_vertical_displacement",
                 "rocking": "foundation_rotation",
                 "horizontal": "foundation_horizontal_displacement",
                 "torsional": "foundation_twist"}
    for (q, n, family, cycle), r in rows.items():
        parts = q.split("_")
        if q.startswith("foundation_") and "stiffness" in parts:
            motion = (motion_of[parts[1]] + "_error", n, family, cycle)
            expected[(q, n, family, cycle)] = float(
                rows[motion]["value"]) * abs(float(r["value"]))
        if q in ("capacity_V", "capacity_H", "capacity_M", "capacity_T") \
                and (q + "_error", n, family, cycle) not in rows:
            plateau = rows[(q + "_plateau_error", n, family, cycle)]
            expected[(q, n, family, cycle)] = float(plateau["value"])
    return expected


def check_goals(name, out, goals):
    rows = results_of(out)
    expected = expected_goals(rows)
    shown = {key: fields for key, fields in goals}
    check("%s: goal rows on the page %s = expected %s"
          % (name, sorted(k[0] for k in shown),
             sorted(k[0] for k in expected)),
          set(shown) == set(expected))
    for key, fields in shown.items():
        if key not in rows:
            continue
        value = float(rows[key]["value"])
        page = float(fields["page_value"])
        bar = expected.get(key, math.nan)
        check("%s: %s = %s (results.csv %s), on the page %s %s ± %s"
              % (name, key[0], fields["value"], rows[key]["value"],
                 fields["page_value"], fields["unit"], fields["page_bar"]),
              float(fields["value"]) == value and
              abs(page - value) <= VALUE_TOLERANCE * abs(value) and
              fields["unit"] == rows[key]["unit"] and
              abs(float(fields["page_bar"]) - bar) <= BAR_TOLERANCE * bar)


def check_scene(name, prm, appended, panels_expected):
    scene, out = run_scene(name, prm, appended)
    png = os.path.join(work, name.replace(" ", "-") + ".png")
    result = run_report(out, png, scene)
    check("%s: report.py exits 0 (%s)" % (name, result.stderr.strip()[-200:]),
          result.returncode == 0)
    check("%s: PNG of one A4 page, %s px" % (name, png_size(png)),
          png_size(png) == (827, 1169))
    panels, missing, step, goals = parse_report(result.stdout)
    check("%s: panels %s = %s" % (name, panels, panels_expected),
          panels == panels_expected)
    optional = ["geometry", "load-displacement", "interface-state",
                "plastic-zone", "goals"]
    check("%s: each panel left out is named with its reason (%d lines)"
          % (name, len(missing)),
          all((p in panels) != any(m.startswith(p + ": ") for m in missing)
              for p in optional))
    check_goals(name, out, goals)
    for key, fields in goals:
        one_sided = fields["bar_from"].endswith("_plateau_error")
        check("%s: %s's bar %s on the page %s"
              % (name, key[0], fields["page_bar"],
                 "one-sided (+)" if one_sided else "without a +"),
              fields["page_bar"].startswith("+") == one_sided)
    if "interface-state" in panels:
        with open(os.path.join(out, "load-displacement.csv")) as f:
            last = int(list(csv.DictReader(f))[-1]["step"])
        check("%s: interface state of step %s = last step %d"
              % (name, step, last), step == last)
    return out


outputs = {name: check_scene(name, *spec) for name, spec in SCENES.items()}


def check_one_sided_bar(out, scene):
    """(7) on the plastic page's curve panel, drawn as draw_page does."""
    sys.path.insert(0, os.path.join(source_dir, "tools"))
    import report
    rows = report.read_results(out)
    goals = report.goal_values(rows)
    curve = report.read_csv(os.path.join(out, "load-displacement.csv"))
    motion = report.controlled_motion(report.read_prm(scene), rows) or \
        report.largest_motion(curve)
    fig = report.plt.figure()
    ax = fig.add_subplot()
    report.draw_curve(ax, curve, motion, goals, rows)
    goal = [g for g in goals if g.row["quantity"].startswith("capacity_")]
    bars = [c for c in ax.containers
            if c.get_label().startswith("error bar")]
    if len(goal) != 1 or len(bars) != 1:
        check("plastic: one capacity (%d) with one error bar drawn (%d)"
              % (len(goal), len(bars)), False)
        return
    goal, bar = goal[0], bars[0]
    (x0, low), (x1, high) = bar.lines[2][0].get_segments()[0]
    value = abs(goal.value)  # the panel draws the load as it rises
    # The drawn ends are value and value + bar, rounded: a few ulps of the
    # value (the bar of a flat plateau can be 1e-13 of it).
    rounding = 4 * math.ulp(value)
    check("plastic: capacity %.9g drawn with its bar from the capacity + "
          "%.2g to the capacity + %.2g (the bar %.2g), labelled '%s'"
          % (value, low - value, high - value, goal.bar, bar.get_label()),
          goal.bar > 0. and low == value and
          abs((high - low) - goal.bar) <= rounding and
          "one-sided" in bar.get_label())
    check("plastic: the panel's title says one-sided: %s" % ax.get_title(),
          ("+ %s (one-sided" % (report.BAR_FORMAT % goal.bar))
          in ax.get_title())
    report.plt.close(fig)


check_one_sided_bar(outputs["plastic"],
                    os.path.join(work, "plastic", "scene.prm"))

png = os.path.join(work, "no-prm.png")
result = run_report(outputs["interface"], png)
panels, missing, _, _ = parse_report(result.stdout)
check("without --prm: panels %s, geometry named as left out" % panels,
      result.returncode == 0 and "geometry" not in panels and
      any(m.startswith("geometry: no --prm") for m in missing))

empty = os.path.join(work, "empty")
os.makedirs(empty)
png = os.path.join(work, "empty.png")
result = run_report(empty, png)
lines = result.stderr.strip().splitlines()
check("no results.csv: one line naming it (%s), exit %d, no PNG"
      % (lines, result.returncode),
      len(lines) == 1 and "results.csv" in lines[0] and
      result.returncode != 0 and not os.path.exists(png))
print("%d failed" % failed)
sys.exit(1 if failed else 0)
