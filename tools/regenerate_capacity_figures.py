#!/usr/bin/python3
"""Regenerate the committed curves and figures of the plastic-soil and
coulomb-interface scenes (doc/soil-plasticity.md sections 5, 6, 7, 8b;
doc/nonlinear-interfaces.md section 9) from the scenes, as the docs say
they were made.

    /usr/bin/python3 tools/regenerate_capacity_figures.py \
        [--exe build/fourier-ssi] [--work output/regenerate-figures] \
        [--only FAMILY]...

Families (each a function below; --only may be repeated):
  footing          footing-capacity-{rough,smooth}.csv, footing-capacity.png
  pile             pile-capacity-{n4,n8,n8-36cells}.csv, pile-capacity.png
  rough-disc-mesh  pile-capacity-rough-n8{,-36cells,-48cells}.csv,
                   disc-tresca-rough-mesh.png
  disc-tresca      disc-tresca-{rough,smooth}.csv, disc-tresca.png
  capacity         capacity-{footing,torsion,pile,disc}{,-runs}.csv,
                   capacity-error-bars.png (tools/capacity.py)
  adhesion         capacity-adhesion-<alpha>{,-runs}.csv, pile-adhesion.png,
                   pile-adhesion-interface-state.png (tools/capacity.py
                   per adhesion factor)
  pile-lateral-slip  pile-lateral-slip.csv, .png, -interface-state.png
  disc-gap         disc-gap.csv, disc-gap.png
  reaction-curves  soil-reaction-curves-pile-{free-head,sand}.{csv,png}
                   (doc/soil-reaction-curves.md sections 4 and 5)

Every run is the shipped scene with the listed entries appended (the
program takes the last `set` of an entry), its output in WORK/<run>; the
wall time of each run is printed. A family's files in doc/figures are
replaced only after all its runs succeeded, each through a temporary file
and a rename, so a failed or interrupted run never leaves a partial file.
A run that fails stops the script with one line and a non-zero exit.
Not here: capacity-envelope.* (tools/capacity_envelope.py), the thesis families (tools/thesis_figures.py).
Needs Debian's python3-matplotlib (under /usr/bin/python3).
"""
import argparse
import os
import shutil
import subprocess
import sys
import time

from capacity import prm_block  # tools/capacity.py: the same .prm text

SOURCE = os.path.normpath(os.path.join(os.path.dirname(
    os.path.abspath(__file__)), ".."))
FIGURES = os.path.join(SOURCE, "doc", "figures")
TOOLS = os.path.join(SOURCE, "tools")
PYTHON = sys.executable

# Normalisations of the plotted loads: pi a^2 s_u (footing, a = 1 m,
# s_u = 10 kPa), s_u d L (pile slice, d = 1 m, L = 10 m), s_u D (disc
# slice of 1 m, D = 1 m).
FOOTING_SCALE = "31.4159265"
PILE_SCALE = "100"
DISC_SCALE = "10"


def fail(message):
    sys.exit("regenerate_capacity_figures.py: " + message)


# ------------------------------------------------------------------ helpers
def run_scene(context, name, prm, entries=None, appended_file=None):
    """Run prm (relative to the source) with `appended_file` (a committed
    prm fragment) and then `entries` appended; returns its output folder."""
    directory = os.path.join(context.work, name)
    shutil.rmtree(directory, ignore_errors=True)
    os.makedirs(directory)
    # Relative to the run's folder, as in the shipped scenes (and in the
    # title that tools/plot_interface_state.py takes from the path).
    relative_output = os.path.join("output", name)
    with open(os.path.join(SOURCE, prm)) as f:
        text = f.read()
    if appended_file:
        with open(os.path.join(SOURCE, appended_file)) as f:
            text += "\n" + f.read()
    overrides = dict(entries or {})
    overrides["Output/Directory"] = relative_output
    scene = os.path.join(directory, "scene.prm")
    with open(scene, "w") as f:
        f.write(text + "\n" + prm_block(overrides))
    start = time.monotonic()
    with open(os.path.join(directory, "log.txt"), "w") as log:
        p = subprocess.run([context.exe, scene], cwd=directory, stdout=log,
                           stderr=subprocess.STDOUT)
    wall = time.monotonic() - start
    if p.returncode != 0:
        fail("run %s (%s) failed with exit %d after %.1f s; log: %s"
             % (name, prm, p.returncode, wall,
                os.path.join(directory, "log.txt")))
    print("  %-28s %7.1f s wall" % (name, wall), flush=True)
    return os.path.join(directory, relative_output)


def run_tool(context, name, arguments):
    """Run a tools/ script (a capacity study) in WORK/name, its output
    shown; stop on failure."""
    start = time.monotonic()
    p = subprocess.run([PYTHON, os.path.join(TOOLS, arguments[0])]
                       + arguments[1:], cwd=SOURCE)
    wall = time.monotonic() - start
    if p.returncode != 0:
        fail("%s (tools/%s) failed with exit %d after %.1f s"
             % (name, arguments[0], p.returncode, wall))
    print("  %-28s %7.1f s wall (all its runs)" % (name, wall), flush=True)


def plot(context, tool, arguments, png, cwd=None):
    """Draw `png` (a doc/figures name) with tools/`tool` into the work
    folder, run in `cwd`; returns the drawn file. `arguments` may contain
    the placeholder OUT for the output file."""
    out = os.path.join(context.work, "figures", png)
    os.makedirs(os.path.dirname(out), exist_ok=True)
    arguments = [out if a == "OUT" else a for a in arguments]
    p = subprocess.run([PYTHON, os.path.join(TOOLS, tool)] + arguments,
                       stdout=subprocess.DEVNULL, cwd=cwd)
    if p.returncode != 0:
        fail("plotting %s with tools/%s failed (exit %d)"
             % (png, tool, p.returncode))
    return out


def install(files):
    """Copy {doc/figures name: produced file} into doc/figures, each
    through a temporary file and a rename (never a partial file there)."""
    for name, produced in files.items():
        target = os.path.join(FIGURES, name)
        partial = target + ".part"
        shutil.copyfile(produced, partial)
        os.replace(partial, target)
        print("  wrote doc/figures/%s" % name)


def curve(output):
    return os.path.join(output, "load-displacement.csv")


def figure(name):
    return os.path.join(FIGURES, name)


def plot_soil_capacity(context, png, title, x, y, x_scale, y_scale,
                       references, curves):
    """tools/plot_soil_capacity.py of [(csv name in doc/figures, label)]."""
    return plot(context, "plot_soil_capacity.py",
                ["OUT", title, x, y, x_scale, y_scale, references]
                + ["%s:%s" % (figure(c), label) for c, label in curves], png)


def curve_family(context, prm, runs, png, title, x, y, y_scale, references):
    """Run prm once per (csv name in doc/figures, run name, entries, label)
    of `runs`, install the curves, then plot them into png with
    tools/plot_soil_capacity.py."""
    outputs = {csv_name: curve(run_scene(context, name, prm, entries))
               for csv_name, name, entries, _ in runs}
    install(outputs)
    install({png: plot_soil_capacity(
        context, png, title, x, y, "1", y_scale, references,
        [(csv_name, label) for csv_name, _, _, label in runs])})


# ------------------------------------------------------------------ families
def footing_capacity(context):
    """doc/soil-plasticity.md section 5: prm/footing-capacity.prm as shipped
    (rough, to w = 0.1 a in 20 steps) and smooth (Tied components =
    normal) to w = 0.04 a in 8 steps."""
    curve_family(
        context, "prm/footing-capacity.prm",
        [("footing-capacity-rough.csv", "footing-rough", None, "rough"),
         ("footing-capacity-smooth.csv", "footing-smooth",
          {"Rigid foundation/Tied components": "normal",
           "Load path/Target": "-0.04",
           "Load path/Load steps": "8"}, "smooth")],
        "footing-capacity.png",
        "rigid circular footing on Tresca soil, n = 0 (a = 1 m, s_u = 10 kPa)",
        "vertical_m", "V_kN", FOOTING_SCALE, "6.05,5.69")


def pile_capacity(context):
    """doc/soil-plasticity.md section 7: prm/pile-capacity.prm (smooth
    shaft, to u = 0.03 d in 6 steps) with n <= 4, as shipped (n <= 8), and
    with 36 radial cells (growth 1.075)."""
    curve_family(
        context, "prm/pile-capacity.prm",
        [("pile-capacity-n4.csv", "pile-n4",
          {"Discretization/Harmonics": "0, 1, 2, 3, 4"}, "n<=4, 24 cells"),
         ("pile-capacity-n8.csv", "pile-n8", None,
          "n<=8, 24 cells (shipped)"),
         ("pile-capacity-n8-36cells.csv", "pile-n8-36cells",
          {"Mesh/R cells": "2, 36", "Mesh/R growth": "1, 1.075"},
          "n<=8, 36 cells")],
        "pile-capacity.png",
        "rigid pile d = 1 m, L = 10 m, Tresca layer, smooth (plane-strain limit)",
        "horizontal_m", "H_kN", PILE_SCALE, "9.14,9.20")


def rough_disc_mesh(context):
    """doc/verification/soil-plasticity.md section 6, "Mesh refinement at
    the rough disc": prm/pile-capacity.prm with a rough shaft (the rough
    disc times L), n <= 8, to u = 0.03 d in 6 steps, on 24 (shipped), 36
    (growth 1.075) and 48 (growth 1.06) radial cells."""
    rough = {"Interfaces/Interfaces": "5: rough"}
    curve_family(
        context, "prm/pile-capacity.prm",
        [("pile-capacity-rough-n8.csv", "pile-rough-n8", rough,
          "24 cells, h=0.038 m"),
         ("pile-capacity-rough-n8-36cells.csv", "pile-rough-n8-36cells",
          dict(rough, **{"Mesh/R cells": "2, 36",
                         "Mesh/R growth": "1, 1.075"}), "36 cells, h=0.027 m"),
         ("pile-capacity-rough-n8-48cells.csv", "pile-rough-n8-48cells",
          dict(rough, **{"Mesh/R cells": "2, 48",
                         "Mesh/R growth": "1, 1.06"}), "48 cells, h=0.018 m")],
        "disc-tresca-rough-mesh.png",
        "rough disc (pile scene / L), n<=8: radial mesh refinement",
        "horizontal_m", "H_kN", PILE_SCALE, "11.94")


def disc_tresca(context):
    """doc/soil-plasticity.md section 6: prm/disc-tresca.prm as shipped
    (rough, n <= 16, to 0.05 D in 10 steps) and smooth to 0.03 D in 6
    steps."""
    curve_family(
        context, "prm/disc-tresca.prm",
        [("disc-tresca-rough.csv", "disc-tresca-rough", None, "rough"),
         ("disc-tresca-smooth.csv", "disc-tresca-smooth",
          {"Interfaces/Interfaces": "5: smooth",
           "Load path/Target": "0.03",
           "Load path/Load steps": "6"}, "smooth")],
        "disc-tresca.png",
        "rigid disc in a Tresca ring, harmonics 0..16 (D = 1 m, s_u = 10 kPa)",
        "horizontal_m", "H_kN", DISC_SCALE, "11.94,9.14")


def capacity_error_bars(context):
    """doc/soil-plasticity.md section 8b: the four tools/capacity.py
    studies (footing pushed down and twisted, smooth pile, rough disc at
    n <= 8) and tools/plot_capacity.py of their CSVs."""
    studies = {
        "footing": ["prm/footing-capacity.prm"],
        "torsion": ["prm/footing-capacity.prm",
                    "--set", "Discretization/Family=antisymmetric",
                    "--set", "Rigid foundation/Vertical force=0",
                    "--set", "Rigid foundation/Torque=1",
                    "--set", "Load path/Controlled motion=twist",
                    "--set", "Load path/Target=0.02",
                    "--set", "Load path/Load steps=10"],
        "pile": ["prm/pile-capacity.prm", "--refine", "r",
                 "--harmonics", "2,4"],
        "disc": ["prm/disc-tresca.prm", "--refine", "r",
                 "--set", "Discretization/Harmonics=0, 1, 2, 3, 4, 5, 6, 7, 8",
                 "--harmonics", "2,4"]}
    produced = {}
    for name, arguments in studies.items():
        work = os.path.join(context.work, "capacity-" + name)
        out = os.path.join(work, "capacity.csv")
        run_tool(context, "capacity-" + name,
                 ["capacity.py"] + arguments
                 + ["--exe", context.exe, "--work", work, "--csv", out])
        produced["capacity-%s.csv" % name] = out
        produced["capacity-%s-runs.csv" % name] = os.path.join(
            work, "capacity-runs.csv")
    install(produced)
    install({"capacity-error-bars.png": plot(
        context, "plot_capacity.py",
        ["OUT",
         figure("capacity-footing.csv") + ":footing, vertical (dashed 6.05):6.05",
         figure("capacity-torsion.csv")
         + ":footing, twisted (dashed 2π/3):2.0943951",
         figure("capacity-pile.csv")
         + ":smooth pile, n ≤ 8 (dashed 9.14, 9.20):9.14-9.20",
         figure("capacity-disc.csv") + ":rough disc, n ≤ 8 (dashed 11.94):11.94"],
        "capacity-error-bars.png")})


ADHESION_FACTORS = ["0", "0.25", "0.5", "0.75", "1"]


def adhesion(context):
    """doc/soil-plasticity.md section 6b: prm/pile-adhesion.prm (plastic
    soil and a coulomb shaft of adhesion c = alpha s_u) through
    tools/capacity.py (two radial refinements, n_max 2, 4, 8) for each
    alpha; the capacities against alpha; the interface state of the
    shipped scene (alpha = 0.5)."""
    produced, plotted = {}, []
    for alpha in ADHESION_FACTORS:
        name = "capacity-adhesion-" + alpha
        work = os.path.join(context.work, name)
        out = os.path.join(work, "capacity.csv")
        law = ("5: coulomb, kn=1e6, ks=1e6, c=%g, phi=0, sigma_t=none"
               % (10.0 * float(alpha)))
        run_tool(context, name,
                 ["capacity.py", "prm/pile-adhesion.prm", "--refine", "r",
                  "--harmonics", "2,4", "--set", "Interfaces/Interfaces=" + law,
                  "--exe", context.exe, "--work", work, "--csv", out])
        produced[name + ".csv"] = out
        produced[name + "-runs.csv"] = os.path.join(work, "capacity-runs.csv")
        plotted.append("%s:%s" % (alpha, figure(name + ".csv")))
    install(produced)
    output = run_scene(context, "pile-adhesion", "prm/pile-adhesion.prm")
    install({
        "pile-adhesion.png": plot(context, "plot_adhesion.py",
                                  ["OUT"] + plotted, "pile-adhesion.png"),
        "pile-adhesion-interface-state.png": plot(
            context, "plot_interface_state.py",
            ["output/pile-adhesion/interface-state.csv", "OUT"],
            "pile-adhesion-interface-state.png",
            cwd=os.path.dirname(os.path.dirname(output)))})


def pile_lateral_slip(context):
    """doc/nonlinear-interfaces.md section 9: prm/pile-lateral-slip.prm as
    shipped; the curve and the interface state of the last step."""
    output = run_scene(context, "pile-lateral-slip", "prm/pile-lateral-slip.prm")
    install({"pile-lateral-slip.csv": curve(output)})
    install({
        "pile-lateral-slip.png": plot(
            context, "plot_load_displacement.py",
            [figure("pile-lateral-slip.csv"), "horizontal_m", "H_kN", "OUT",
             "pile, Coulomb phi = 25 deg"], "pile-lateral-slip.png"),
        "pile-lateral-slip-interface-state.png": plot(
            context, "plot_interface_state.py",
            ["output/pile-lateral-slip/interface-state.csv", "OUT"],
            "pile-lateral-slip-interface-state.png",
            cwd=os.path.dirname(os.path.dirname(output)))})


def disc_gap(context):
    """doc/nonlinear-interfaces.md section 9: prm/disc-gap.prm as shipped."""
    output = run_scene(context, "disc-gap", "prm/disc-gap.prm")
    install({"disc-gap.csv": curve(output)})
    install({"disc-gap.png": plot(
        context, "plot_load_displacement.py",
        [figure("disc-gap.csv"), "horizontal_m", "H_kN", "OUT",
         "disc in ring, tensionless frictionless"], "disc-gap.png")})


def reaction_curves(context):
    """doc/soil-reaction-curves.md sections 4 and 5: prm/pile-free-head.prm
    (Tresca clay) and prm/pile-sand.prm (Mohr-Coulomb sand) as shipped; the
    PISA-normalised curves of every step and depth."""
    for scene, title in (("pile-free-head", "free-head rigid pile, Tresca clay"),
                         ("pile-sand", "rigid pile in sand, phi' = 30 deg")):
        output = run_scene(context, scene, "prm/%s.prm" % scene)
        data = os.path.join(output, "soil-reaction-curves.csv")
        name = "soil-reaction-curves-%s" % scene
        install({name + ".csv": data})
        install({name + ".png": plot(
            context, "plot_soil_reaction_curves.py",
            [data, "OUT", "--title", title], name + ".png")})


FAMILIES = {"footing": footing_capacity,
            "pile": pile_capacity,
            "rough-disc-mesh": rough_disc_mesh,
            "disc-tresca": disc_tresca,
            "capacity": capacity_error_bars,
            "adhesion": adhesion,
            "pile-lateral-slip": pile_lateral_slip,
            "disc-gap": disc_gap,
            "reaction-curves": reaction_curves}


def main():
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--exe", default=os.path.join(
        SOURCE, "build", "fourier-ssi"))
    parser.add_argument("--work", default=os.path.join(
        SOURCE, "output", "regenerate-figures"))
    parser.add_argument("--only", action="append", choices=list(FAMILIES),
                        help="run only this family (may be repeated)")
    context = parser.parse_args()
    context.exe = os.path.abspath(context.exe)
    context.work = os.path.abspath(context.work)
    if not os.access(context.exe, os.X_OK):
        fail("no executable program at %s (build it, or give --exe)"
             % context.exe)
    for name in context.only or list(FAMILIES):
        print("%s:" % name, flush=True)
        start = time.monotonic()
        FAMILIES[name](context)
        print("%s: %.1f s wall" % (name, time.monotonic() - start), flush=True)


if __name__ == "__main__":
    main()
