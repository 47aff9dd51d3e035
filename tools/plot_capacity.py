#!/usr/bin/python3
"""Plot the mesh studies of tools/capacity.py (doc/soil-plasticity.md 8b):
the plateau of each mesh against its relative cell size h = 2^-level, the
printed value with its error bar at h = 0, and the exact or published limit.

    /usr/bin/python3 tools/plot_capacity.py OUT.png CAPACITY.csv:LABEL:EXACT ...

CAPACITY.csv is what capacity.py wrote (its -runs.csv beside it); EXACT is
the reference drawn as a dashed line (a range lo-hi draws both ends).
Needs Debian's python3-matplotlib (under /usr/bin/python3).
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path) as f:
        capacity = next(csv.DictReader(f))
    with open(os.path.splitext(path)[0] + "-runs.csv") as f:
        runs = [r for r in csv.DictReader(f) if r["run"] == "mesh"]
    return capacity, runs


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    items = [a.split(":") for a in sys.argv[2:]]
    fig, axes = plt.subplots(1, len(items), figsize=(3.0 * len(items), 3.2))
    for ax, (path, label, exact) in zip(axes if len(items) > 1 else [axes],
                                        items):
        capacity, runs = read(path)
        h = [2.0 ** -int(r["level"]) for r in runs]
        ax.errorbar(h, [float(r["plateau"]) for r in runs],
                    yerr=[float(r["plateau_error"]) for r in runs],
                    fmt="o-", ms=4, label="plateau per mesh")
        ax.errorbar([0], [float(capacity["value"])],
                    yerr=[float(capacity["error"])], fmt="s", color="C3",
                    capsize=4, label="printed ± bar")
        for value in exact.split("-"):
            ax.axhline(float(value), ls="--", lw=0.8, color="k")
        ax.set_title(label, fontsize=9)
        ax.set_xlabel("h / h_shipped")
        ax.set_ylabel(capacity["quantity"])
        ax.set_xlim(-0.1, max(h) * 1.1)
        ax.grid(True, alpha=0.3)
    axes_list = axes if len(items) > 1 else [axes]
    axes_list[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(sys.argv[1], dpi=110)
    print("wrote", sys.argv[1])


if __name__ == "__main__":
    main()
