#!/usr/bin/python3
"""Plot the soil-reaction curves of a rigid pile (soil-reaction-curves.csv,
Output/Soil reaction depths; doc/soil-reaction-curves.md): the four PISA
curves p-v, m-psi at every depth and the base H_B-v_base, M_B-psi, one point
per load step, in the PISA normalisation (clay: p/(s_u D) against
v G/(s_u D), ...) or, with --dimensional, in kN, m and rad.

    /usr/bin/python3 tools/plot_soil_reaction_curves.py CSV OUT.png
        [--dimensional] [--title TEXT]

Needs Debian's python3-matplotlib (under /usr/bin/python3).
"""
import argparse
import csv
import math
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# (x column, y column, axis labels) of the four panels, normalised and not;
# S in a label stands for s_u (clay) or sigma'_v (sand).
NORMALISED = [
    ("v G/(s D) [-]", "p/(s D) [-]", "v G / (S D)", "p / (S D)"),
    ("psi G/s [-]", "m/(s D^2) or m/(|p| D) [-]", "psi G / S", None),
    ("v_base G/(s D) [-]", "H_B/(s D^2) [-]", "v_base G / (S D)",
     "H_B / (S D^2)"),
    ("psi G/s_base [-]", "M_B/(s D^3) [-]", "psi G / S", "M_B / (S D^3)"),
]
DIMENSIONAL = [
    ("v [m]", "p [kN/m]", "v [m]", "p [kN/m]"),
    ("psi [rad]", "m [kN m/m]", "psi [rad]", "m [kN m/m]"),
    ("v_base [m]", "H_B [kN]", "v_base [m]", "H_B [kN]"),
    ("psi [rad]", "M_B [kN m]", "psi [rad]", "M_B [kN m]"),
]


def read(path):
    """Rows grouped by depth: {depth: [row, ...]} in step order."""
    by_depth = defaultdict(list)
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            by_depth[float(row["depth [m]"])].append(row)
    return by_depth


def series(rows, x, y):
    """The (0, 0) start of the path, then one point per step."""
    xs, ys = [0.0], [0.0]
    for row in rows:
        a, b = float(row[x]), float(row[y])
        if math.isfinite(a) and math.isfinite(b):
            xs.append(a)
            ys.append(b)
    return xs, ys


def near_rotation_point(by_depth, fraction=0.1):
    """Depths whose |p| at the last step is below `fraction` of the largest:
    there p changes sign, and the sand normalisation m / (|p| D) is
    undefined (it grows without bound as p passes zero)."""
    last = {d: abs(float(rows[-1]["p [kN/m]"])) for d, rows in
            by_depth.items()}
    largest = max(last.values())
    return {d for d, p in last.items() if p < fraction * largest}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv")
    parser.add_argument("png")
    parser.add_argument("--dimensional", action="store_true")
    parser.add_argument("--title", default="")
    args = parser.parse_args()
    by_depth = read(args.csv)
    if not by_depth:
        raise SystemExit(f"{args.csv}: no rows")
    panels = DIMENSIONAL if args.dimensional else NORMALISED
    first = by_depth[min(by_depth)][0]
    # A flexible pile's base turns by its own psi_base (a rigid pile's
    # psi is the same at every depth and has no such column).
    if args.dimensional and "psi_base [rad]" in first:
        panels = panels[:3] + [("psi_base [rad]",) + panels[3][1:2] +
                               ("psi_base [rad]",) + panels[3][3:]]
    clay = first["normalised by"] == "s_u"
    strength = "s_u" if clay else "sigma'_v"
    # m / (|p| D) is left out where p passes zero (sand, normalised).
    skip_m = set() if clay or args.dimensional else \
        near_rotation_point(by_depth)
    fig, axes = plt.subplots(2, 2, figsize=(10, 8))
    for k, (x, y, xlabel, ylabel) in enumerate(panels):
        ax = axes[k // 2][k % 2]
        if k < 2:
            for depth in sorted(by_depth):
                if k == 1 and depth in skip_m:
                    continue
                xs, ys = series(by_depth[depth], x, y)
                ax.plot(xs, ys, marker=".", label=f"{depth:g} m")
            ax.legend(title="depth", fontsize="small")
        else:
            xs, ys = series(by_depth[min(by_depth)], x, y)
            ax.plot(xs, ys, marker=".", color="black")
        if ylabel is None:  # PISA: m / (s_u D^2) in clay, m / (|p| D) in sand
            ylabel = "m / (S D^2)" if clay else "m / (|p| D)"
        if not args.dimensional:
            xlabel = xlabel.replace("S", strength)
            ylabel = ylabel.replace("S", strength)
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
        ax.axhline(0.0, color="grey", linewidth=0.5)
        ax.grid(True, linewidth=0.3)
    axes[0][0].set_title("lateral reaction p - v")
    axes[0][1].set_title("distributed moment m - psi" + (
        "\n(left out where |p| < 0.1 max |p|: %s m)"
        % ", ".join("%g" % d for d in sorted(skip_m)) if skip_m else ""))
    axes[1][0].set_title("base shear H_B - v_base")
    axes[1][1].set_title("base moment M_B - psi")
    if args.title:
        fig.suptitle(args.title)
    fig.tight_layout()
    fig.savefig(args.png, dpi=110)
    print(f"{args.png}: {len(by_depth)} depths, "
          f"{len(by_depth[min(by_depth)])} steps")


if __name__ == "__main__":
    main()
