#!/usr/bin/python3
"""The loops of a cyclic run (Load path/Targets; doc/cyclic-loading.md).

    /usr/bin/python3 tools/plot_cycles.py OUTPUT_DIR [-o loops.png]
        [--label TEXT] [OUTPUT_DIR2 ...]

Reads load-displacement.csv (its segment column) and load-cycles.csv of
each OUTPUT_DIR and draws the load against the motion the cycles are
drawn in, the virgin segment dashed, each cycle's secant stiffness and
damping ratio with its error bar in the legend. Several folders (e.g. two
amplitudes) go on one figure. Needs Debian's python3-matplotlib.
"""
import argparse
import csv
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

LOAD_COLUMN = {"H": "H_kN", "M": "M_kNm", "T": "T_kNm", "V": "V_kN"}
MOTION_COLUMN = {"horizontal": "horizontal_m", "rotation": "rotation_rad",
                 "twist": "twist_rad", "vertical": "vertical_m"}


def read_run(folder):
    steps = list(csv.DictReader(open(os.path.join(folder,
                                                  "load-displacement.csv"))))
    cycles_file = os.path.join(folder, "load-cycles.csv")
    if not os.path.exists(cycles_file) or "segment" not in steps[0]:
        sys.exit(folder + ": not a cyclic run (no load-cycles.csv or no "
                 "segment column in load-displacement.csv)")
    reader = csv.DictReader(open(cycles_file))
    cycles = list(reader)
    # end_<load>_<unit>, end_<motion>_<unit>: the pair the loops are in.
    names = [f for f in reader.fieldnames if f.startswith("end_")]
    load = re.match(r"end_([A-Z])_", names[0]).group(1)
    motion = re.match(r"end_([a-z]+)_", names[1]).group(1)
    return steps, cycles, load, motion


def draw(ax, folder, label):
    steps, cycles, load, motion = read_run(folder)
    f_col, u_col = LOAD_COLUMN[load], MOTION_COLUMN[motion]
    u = [0.] + [float(s[u_col]) for s in steps]
    f = [0.] + [float(s[f_col]) for s in steps]
    seg = [1] + [int(s["segment"]) for s in steps]
    virgin = [i for i, s in enumerate(seg) if s <= 1]
    line, = ax.plot([u[i] for i in virgin], [f[i] for i in virgin], "--",
                    lw=1)
    rest = [i for i, s in enumerate(seg) if s >= 1 and i >= virgin[-1]]
    text = []
    for c in cycles:
        text.append("cycle %s: k = %.4g %s/%s, xi = %.4f +- %.4f" % (
            c["cycle"], float(c[[k for k in c if k.startswith("secant")][0]]),
            f_col.split("_")[1], u_col.split("_")[1],
            float(c["damping_ratio"]), float(c["damping_ratio_error"])))
    ax.plot([u[i] for i in rest], [f[i] for i in rest], "-o", ms=2, lw=1,
            color=line.get_color(),
            label=(label or folder) + "\n" + "\n".join(text))
    return f_col, u_col


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("folders", nargs="+")
    parser.add_argument("-o", "--output", default="loops.png")
    parser.add_argument("--label", action="append", default=[])
    args = parser.parse_args()
    fig, ax = plt.subplots(figsize=(7, 5))
    for k, folder in enumerate(args.folders):
        label = args.label[k] if k < len(args.label) else None
        f_col, u_col = draw(ax, folder, label)
    ax.set_xlabel(u_col.replace("_", " [") + "]")
    ax.set_ylabel(f_col.replace("_", " [") + "]")
    ax.axhline(0., color="0.7", lw=0.5)
    ax.axvline(0., color="0.7", lw=0.5)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper left")
    ax.set_title("load cycles (dashed: the virgin segment); xi's bar is "
                 "the steps' error", fontsize=9)
    fig.tight_layout()
    fig.savefig(args.output, dpi=130)
    print("loops written to " + args.output)


if __name__ == "__main__":
    main()
