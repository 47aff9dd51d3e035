#!/usr/bin/python3
"""The limit load of a plastic-soil scene with its error bar
(doc/soil-plasticity.md section 8b).

    /usr/bin/python3 tools/capacity.py SCENE.prm [--levels 3] [--first -1]
        [--refine r,z] [--harmonics 4,8] [--set "Mesh/R cells=2, 48"]...
        [--exe build/fourier-ssi] [--work DIR] [--csv FILE]
    /usr/bin/python3 tools/capacity.py --curve load-displacement.csv

Runs the scene (displacement control to its Target) on nested meshes and,
when --harmonics is given, with its harmonic set truncated at each listed
n_max, and prints one line per capacity:

    N_c = 6.046 ± 0.056 (mesh 0.054, harmonics 0, plateau 0.0025); V / (pi a^2 s_u), a = 1 m

How each number is made (the reasons and the measurements are in the doc):
- plateau: the load of the last step of each curve. Its bar is the rise to
  the hyperbolic asymptote of the last three steps (u/P = a + b u fitted,
  P_inf = 1/b), which bounded the remaining rise of every shipped curve.
- meshes: level k has the scene's cell counts times 2^k and each growth
  ratio raised to 2^-k in the refined directions (nested: two fine cells
  with ratio g fill one coarse cell with ratio g^2). Level --first is the
  coarsest (-1: the scene's counts halved). Three or more meshes give the
  observed order p = log2((P0 - P1) / (P1 - P2)) of the last three and
  Richardson's extrapolation P2 - (P1 - P2) / (2^p - 1) with p capped at 1,
  the order measured at shear bands and bonded corners (a higher observed
  order came from meshes not yet asymptotic); two meshes, or an observed
  order below 0.5 or of mixed signs, use p = 1. The mesh bar is the size of
  the extrapolation, |P_extrapolated - P_finest|.
- harmonics: the mesh study runs with the scene's harmonics 0..N; with
  --harmonics, the listed n_max values (doubling, e.g. 2,4 for N = 8) and
  N run on the coarsest mesh. The change from N to the largest n_max is
  added to the value, and the tail beyond the largest is geometric: ratio
  r = d_last / d_previous of the last two changes (when in (0, 0.8]), else
  r = 0.5 (the slowest ratio measured), tail = d_last r / (1 - r). The
  harmonics bar is the tail's size; the tail is added to the value.
- the value printed is the extrapolated one; the bar is the sum of the
  mesh and harmonics bars and the plateau bars carried through the same
  linear combination (each part bounds an error of one sign, summing is
  conservative).
"""
import argparse
import csv
import math
import os
import re
import shutil
import subprocess
import sys
import time

# The column of load-displacement.csv that the controlled motion drives,
# and the column of that motion.
LOAD_OF_MOTION = {"vertical": ("V_kN", "vertical_m", "kN"),
                  "horizontal": ("H_kN", "horizontal_m", "kN"),
                  "rotation": ("M_kNm", "rotation_rad", "kNm"),
                  "twist": ("T_kNm", "twist_rad", "kNm")}


def fail(message):
    sys.exit("capacity.py: " + message)


# ---------------------------------------------------------------- the scene
def read_prm(text):
    """Entries of a deal.II parameter file as {"Sub/Sub/Entry": value};
    the last `set` of an entry wins, as in the program."""
    entries, path = {}, []
    for raw in text.splitlines():
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        if line.startswith("subsection "):
            path.append(line[len("subsection "):].strip())
        elif line == "end":
            path.pop()
        elif line.startswith("set ") and "=" in line:
            key, value = line[4:].split("=", 1)
            entries["/".join(path + [key.strip()])] = value.strip()
    return entries


def prm_block(entries):
    """Parameter-file text that sets `entries` ({"Sub/Entry": value})."""
    text = ""
    for key, value in entries.items():
        *subsections, name = key.split("/")
        text += "".join("subsection %s\n" % s for s in subsections)
        text += "  set %s = %s\n" % (name, value)
        text += "end\n" * len(subsections)
    return text


def numbers(value):
    return [float(v) for v in value.split(",") if v.strip()]


def scene_mesh(entries, direction):
    """Cell counts and growth ratios per segment of the R or Z direction."""
    cells = [int(v) for v in numbers(entries.get("Mesh/%s cells" % direction, "1"))]
    growth = numbers(entries.get("Mesh/%s growth" % direction, "")) or [1.0]
    if len(growth) == 1 and len(cells) > 1:
        growth = growth * len(cells)
    return cells, growth


def mesh_entries(entries, level, refine):
    """The Mesh entries of refinement `level` (0: the scene's mesh)."""
    out = {}
    for direction in refine:
        cells, growth = scene_mesh(entries, direction)
        scaled = []
        for c in cells:
            if level < 0 and c % 2 ** -level:
                fail("Mesh/%s cells = %s cannot be halved %d times (use a "
                     "larger --first)" % (direction, entries.get(
                         "Mesh/%s cells" % direction), -level))
            scaled.append(int(c * 2.0 ** level))
        out["Mesh/%s cells" % direction] = ", ".join(str(c) for c in scaled)
        out["Mesh/%s growth" % direction] = ", ".join(
            "%.12g" % g ** (2.0 ** -level) for g in growth)
    return out


def harmonic_list(entries, n_max):
    """The scene's harmonics truncated (or continued) at n_max; only for a
    scene whose harmonics are 0, 1, ..., N."""
    scene = [int(v) for v in numbers(entries.get("Discretization/Harmonics", "0"))]
    if scene != list(range(len(scene))):
        fail("Discretization/Harmonics = %s: --harmonics needs 0, 1, ..., N"
             % entries.get("Discretization/Harmonics"))
    return ", ".join(str(n) for n in range(n_max + 1))


def normalisation(entries, motion):
    """(name, divisor, formula) of the dimensionless capacity, or the load
    itself when the scene is not one of the recognised families."""
    laws = re.findall(r"su\s*=\s*([0-9.eE+-]+)",
                      entries.get("Soil plasticity/Laws", ""))
    su = float(laws[0]) if laws and len(set(laws)) == 1 else None
    patch = float(entries.get("Mesh/Surface patch radius", "0"))
    tie = entries.get("Rigid foundation/Tie", "")
    if su and tie == "boundary" and patch > 0:
        a = patch
        if motion == "vertical":
            return "N_c", math.pi * a * a * su, "V / (pi a^2 s_u), a = %g m" % a
        if motion == "twist":
            return "T/(a^3 s_u)", a ** 3 * su, "a = %g m" % a
    if su and tie == "material" and motion == "horizontal":
        material = entries.get("Rigid foundation/Id", "1").strip()
        for region in entries.get("Mesh/Material regions", "").split(";"):
            if ":" in region and region.split(":")[0].strip() == material:
                r0, r1, z0, z1 = numbers(region.split(":")[1])
                if r0 == 0:
                    d, length = 2 * r1, z1 - z0
                    return ("N_p", su * d * length,
                            "H / (s_u d L), d = %g m, L = %g m" % (d, length))
    return None


# ---------------------------------------------------------------- the runs
def run_scene(exe, text, overrides, work, name):
    """Run the scene with `overrides` appended; returns (u, P) of its
    load-displacement curve (|motion|, |load|) and the wall time."""
    directory = os.path.join(work, name)
    shutil.rmtree(directory, ignore_errors=True)
    os.makedirs(directory)
    prm = os.path.join(directory, "scene.prm")
    overrides = dict(overrides)
    overrides["Output/Directory"] = os.path.join(directory, "output")
    overrides["Output/Write vtu"] = "false"
    with open(prm, "w") as f:
        f.write(text + "\n" + prm_block(overrides))
    start = time.time()
    with open(os.path.join(directory, "log.txt"), "w") as log:
        p = subprocess.run([exe, prm], cwd=directory, stdout=log,
                           stderr=subprocess.PIPE, text=True)
    wall = time.time() - start
    if p.returncode != 0:
        message = p.stderr.strip().splitlines()
        fail("run %s failed (%s); its log: %s" % (
            name, message[-1] if message else "exit %d" % p.returncode,
            os.path.join(directory, "log.txt")))
    return read_curve(os.path.join(directory, "output", "load-displacement.csv")), wall


def read_curve(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        fail(path + ": no load step")
    return rows


# ---------------------------------------------------------------- the numbers
def plateau(u, load):
    """(last step load, its bar): the bar is the rise to the asymptote of
    the hyperbola u / P = a + b u through the last three steps (least
    squares); infinite when the last steps do not bend over."""
    last = load[-1]
    if len(u) < 3:
        return last, math.inf
    us, qs = u[-3:], [x / p for x, p in zip(u[-3:], load[-3:])]
    mu, mq = sum(us) / 3, sum(qs) / 3
    b = sum((x - mu) * (q - mq) for x, q in zip(us, qs)) / sum(
        (x - mu) ** 2 for x in us)
    return last, abs(1.0 / b - last) if b > 0 else math.inf


def richardson(values):
    """(extrapolated value, order used, observed order or None, weights of
    the values in the extrapolation) from the plateaus of meshes refined
    2x each, coarsest first."""
    if len(values) < 2:
        return values[-1], None, None, [0.0] * (len(values) - 1) + [1.0]
    observed = None
    p = 1.0
    if len(values) >= 3:
        p0, p1, p2 = values[-3:]
        if (p0 - p1) * (p1 - p2) > 0:
            observed = math.log2((p0 - p1) / (p1 - p2))
            # At most 1, the order of a limit load set by a shear band or
            # a singular corner; a higher observed order came from meshes
            # not yet asymptotic (doc/verification/soil-plasticity.md 8b).
            if observed >= 0.5:
                p = min(observed, 1.0)
    fine, coarse = values[-1], values[-2]
    weights = [0.0] * (len(values) - 2) + [-1 / (2 ** p - 1),
                                           2 ** p / (2 ** p - 1)]
    return fine + (fine - coarse) / (2 ** p - 1), p, observed, weights


def harmonic_tail(values, start):
    """(change from values[start] to n -> infinity, tail beyond the last,
    ratio used, weights of the values in the change) from the plateaus at
    n_max doubling, on one mesh."""
    weights = [0.0] * len(values)
    if len(values) < 2:
        return 0.0, 0.0, None, weights
    steps = [b - a for a, b in zip(values, values[1:])]
    r = 0.5
    if len(steps) >= 2 and steps[-2] != 0 and 0 < steps[-1] / steps[-2] <= 0.8:
        r = steps[-1] / steps[-2]
    tail = steps[-1] * r / (1 - r)
    weights[-1] += 1 + r / (1 - r)
    weights[-2] -= r / (1 - r)
    weights[start] -= 1
    return values[-1] - values[start] + tail, tail, r, weights


def combine(mesh, harmonics, start, runs):
    """The value and its bar from the mesh study and the harmonic study
    ((plateau, bar, run index) each) and all runs."""
    extrapolated, p_used, p_observed, w_mesh = richardson([m[0] for m in mesh])
    change, tail, ratio, w_harm = harmonic_tail([h[0] for h in harmonics], start)
    mesh_bar = abs(extrapolated - mesh[-1][0]) if len(mesh) > 1 else math.nan
    # The plateau bars carried through the linear combination that makes
    # the value (the coarsest mesh run may sit in both studies).
    weight = [0.0] * len(runs)
    for (_, _, i), w in list(zip(mesh, w_mesh)) + list(zip(harmonics, w_harm)):
        weight[i] += w
    plateau_bar = sum(abs(w) * run[4] for w, run in zip(weight, runs))
    return {"value": extrapolated + change,
            "error": (0 if math.isnan(mesh_bar) else mesh_bar) + abs(tail)
            + plateau_bar,
            "mesh": mesh_bar, "harmonics": abs(tail), "plateau": plateau_bar,
            "finest": mesh[-1][0], "order_used": p_used,
            "order_observed": p_observed, "ratio": ratio}


def report(r, name, normalisation_text, study):
    """The capacity's line and the line saying how it was made."""
    print("%s = %.4g ± %.2g (mesh %s, harmonics %.2g, plateau %.2g); %s" % (
        name, r["value"], r["error"],
        "not estimated (one mesh)" if math.isnan(r["mesh"]) else "%.2g" % r["mesh"],
        r["harmonics"], r["plateau"], normalisation_text))
    studied = "not studied"
    if study:
        studied = "n_max %s on the coarsest mesh, tail ratio %.2f used" % (
            ",".join(map(str, study)), r["ratio"])
    print("  finest mesh %.5g; mesh order %s%s; harmonics %s" % (
        r["finest"],
        "n/a" if r["order_used"] is None else "%.2f used" % r["order_used"],
        "" if r["order_observed"] is None
        else " (observed %.2f)" % r["order_observed"], studied))


def write_csv(out, r, name, normalisation_text, runs):
    """OUT: the capacity and its bar; OUT-runs.csv: every run."""
    def optional(v):
        return "" if v is None else "%.4g" % v
    with open(out, "w") as f:
        f.write("quantity,normalisation,value,error,error_mesh,error_harmonics,"
                "error_plateau,finest_mesh_value,order_used,order_observed,"
                "tail_ratio\n")
        f.write("%s,%s,%.8g,%.4g,%.4g,%.4g,%.4g,%.8g,%s,%s,%s\n" % (
            name, normalisation_text.replace(",", ";"), r["value"], r["error"],
            r["mesh"], r["harmonics"], r["plateau"], r["finest"],
            optional(r["order_used"]), optional(r["order_observed"]),
            optional(r["ratio"])))
    runs_csv = os.path.splitext(out)[0] + "-runs.csv"
    with open(runs_csv, "w") as f:
        f.write("run,level,n_max,plateau,plateau_error,steps,wall_s\n")
        for kind, level, n_max, v, b, wall, steps in runs:
            f.write("%s,%d,%s,%.8g,%.4g,%d,%.1f\n" % (
                kind, level, "" if n_max is None else n_max, v, b, steps, wall))
    print("wrote", out, "and", runs_csv)


def show_plateaus(path):
    """The plateau bar after every step of an existing curve against the
    rise still to come to its last step: how the bar was measured."""
    if not os.path.isfile(path):
        fail(path + ": no such file")
    rows = read_curve(path)
    for motion, (load_column, motion_column, unit) in LOAD_OF_MOTION.items():
        load = [abs(float(r.get(load_column, 0) or 0)) for r in rows]
        if max(load) > 0:
            break
    u = [abs(float(r[motion_column])) for r in rows]
    print("%s, %s: step, %s, plateau bar, rise to the last step [%s]"
          % (path, load_column, motion_column, unit))
    for k in range(3, len(rows) + 1):
        value, bar = plateau(u[:k], load[:k])
        print("  %3d  %.5g  %.4g  %.4g" % (k, u[k - 1], bar, load[-1] - value))


# ---------------------------------------------------------------- main
def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("prm")
    parser.add_argument("--levels", type=int, default=3,
                        help="number of nested meshes (>= 2 for a mesh bar)")
    parser.add_argument("--first", type=int, default=-1,
                        help="level of the coarsest mesh (0: the scene's, "
                             "-1: its cell counts halved)")
    parser.add_argument("--refine", default="r,z",
                        help="directions refined: r,z or r (a field exact "
                             "in z, e.g. the plane-strain pile)")
    parser.add_argument("--harmonics", default="",
                        help="n_max values, e.g. 4,8: the truncation study")
    parser.add_argument("--set", action="append", default=[],
                        help='"Subsection/Entry=value" applied to the scene')
    parser.add_argument("--exe", default=os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "build", "fourier-ssi"))
    parser.add_argument("--work", default="capacity-runs")
    parser.add_argument("--csv", default="", help="default WORK/capacity.csv")
    parser.add_argument("--curve", action="store_true",
                        help="PRM is a load-displacement.csv: print the "
                             "plateau and its bar after every step, and the "
                             "rise to the last step (runs nothing)")
    return parser.parse_args()


def read_scene(args):
    """The scene's text with the --set entries appended, its entries, the
    refined directions, the n_max list and the controlled motion; one
    line and exit 1 for anything the study cannot use."""
    if not os.path.isfile(args.prm):
        fail(args.prm + ": no such file")
    if not os.access(args.exe, os.X_OK):
        fail(args.exe + ": not an executable (--exe)")
    if args.levels < 1:
        fail("--levels %d: at least 1" % args.levels)
    refine = [{"r": "R", "z": "Z"}.get(d.strip()) for d in args.refine.split(",")]
    if None in refine or not refine:
        fail("--refine %s: r, z or r,z" % args.refine)
    try:
        n_maxes = sorted(int(v) for v in args.harmonics.split(",") if v.strip())
    except ValueError:
        fail("--harmonics %s: comma-separated integers" % args.harmonics)

    text = open(args.prm).read()
    user = {}
    for item in args.set:
        if "=" not in item or "/" not in item.split("=")[0]:
            fail('--set %s: "Subsection/Entry=value"' % item)
        key, value = item.split("=", 1)
        user[key.strip()] = value.strip()
    text += "\n" + prm_block(user)
    entries = read_prm(text)
    if entries.get("Mesh/Type", "rectangle") != "rectangle":
        fail(args.prm + ": Mesh/Type must be rectangle (the levels scale its "
             "cell counts)")
    if entries.get("Load path/Control") != "displacement":
        fail(args.prm + ": Load path/Control must be displacement "
             "(a load-controlled curve has no plateau to read)")
    motion = entries.get("Load path/Controlled motion", "")
    if motion not in LOAD_OF_MOTION:
        fail(args.prm + ": Controlled motion = %s is not one of %s" % (
            motion, ", ".join(LOAD_OF_MOTION)))
    return text, entries, refine, n_maxes, motion


def main():
    args = parse_arguments()
    if args.curve:
        return show_plateaus(args.prm)
    text, entries, refine, n_maxes, motion = read_scene(args)
    load_column, motion_column, unit = LOAD_OF_MOTION[motion]
    norm = normalisation(entries, motion)
    name, divisor = (norm[0], norm[1]) if norm else (load_column, 1.0)
    work = os.path.abspath(args.work)
    os.makedirs(work, exist_ok=True)

    runs = []  # (kind, level, n_max, plateau, bar, wall, steps)

    def run(kind, level, n_max):
        overrides = mesh_entries(entries, level, refine)
        if n_max is not None:
            overrides["Discretization/Harmonics"] = harmonic_list(entries, n_max)
        label = "%s-level%d%s" % (kind, level,
                                  "" if n_max is None else "-n%d" % n_max)
        rows, wall = run_scene(args.exe, text, overrides, work, label)
        u = [abs(float(r[motion_column])) for r in rows]
        load = [abs(float(r[load_column])) / divisor for r in rows]
        value, bar = plateau(u, load)
        runs.append((kind, level, n_max, value, bar, wall, len(rows)))
        print("  %-22s %s = %.5f (plateau bar %.2g), %d steps, %.1f s wall"
              % (label, name, value, bar, len(rows), wall), flush=True)
        return value, bar, len(runs) - 1

    levels = list(range(args.first, args.first + args.levels))
    n_scene = max(int(v) for v in numbers(
        entries.get("Discretization/Harmonics", "0")))
    n_mesh = n_scene if n_maxes else None
    mesh = [run("mesh", level, n_mesh) for level in levels]
    # The harmonic study on the coarsest mesh: the listed n_max and the
    # scene's own (whose run is the mesh study's first).
    study = sorted(set(n_maxes) | {n_scene}) if n_maxes else []
    harmonics = [mesh[0] if n == n_scene else run("harmonics", levels[0], n)
                 for n in study]
    start = study.index(n_scene) if study else 0

    result = combine(mesh, harmonics, start, runs)
    report(result, name, norm[2] if norm else unit, study)
    out = args.csv or os.path.join(work, "capacity.csv")
    write_csv(out, result, name, norm[2] if norm else unit, runs)


if __name__ == "__main__":
    main()
