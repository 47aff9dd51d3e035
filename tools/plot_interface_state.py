#!/usr/bin/python3
"""Plot the interface state around the circumference written by a
nonlinear-interface run (<Output/Directory>/interface-state.csv,
doc/nonlinear-interfaces.md section 9): for one load step (default the last),
one column of panels per interface line (faces of one orientation of one
interface id), theta [deg] across and the position along the line [m] up:
stick / slip / open on top, the normal traction t_n [kPa] (tension > 0)
below.

    /usr/bin/python3 tools/plot_interface_state.py CSV OUT.png [STEP]

Needs Debian's python3-matplotlib and python3-numpy (under /usr/bin/python3).
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402

STATES = ["stick", "slip", "open"]
COLOURS = ["#4c72b0", "#dd8452", "#c44e52"]


def read_step(path, step):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(path + ": no rows")
    last = max(int(r["step"]) for r in rows)
    step = last if step is None else step
    rows = [r for r in rows if int(r["step"]) == step]
    if not rows:
        sys.exit(path + ": no step " + str(step) + " (last " + str(last) + ")")
    return step, rows


def lines_of(rows):
    """Group rows by (interface id, face orientation): one interface line.
    A vertical face (normal along r) runs along z, a horizontal one along r."""
    groups = {}
    for r in rows:
        vertical = abs(float(r["normal_r"])) > abs(float(r["normal_z"]))
        key = (r["interface_id"], "z" if vertical else "r")
        groups.setdefault(key, []).append(r)
    return groups


def grid(rows, along, column):
    """Values on the (position along the line) x (theta) grid."""
    coords = sorted({float(r[along + "_m"]) for r in rows})
    thetas = sorted({float(r["theta_deg"]) for r in rows})
    ic = {c: i for i, c in enumerate(coords)}
    it = {t: j for j, t in enumerate(thetas)}
    values = np.full((len(coords), len(thetas)), np.nan)
    for r in rows:
        v = STATES.index(r["state"]) if column == "state" else float(r[column])
        values[ic[float(r[along + "_m"])], it[float(r["theta_deg"])]] = v
    # Close the circle: theta = 360 repeats theta = 0.
    thetas = thetas + [360.0]
    values = np.hstack([values, values[:, :1]])
    return np.array(thetas), np.array(coords), values


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    path, out = sys.argv[1:3]
    step, rows = read_step(path, int(sys.argv[3]) if len(sys.argv) > 3 else None)
    groups = lines_of(rows)
    fig, axes = plt.subplots(
        2, len(groups), figsize=(4.2 * len(groups), 6.4), squeeze=False
    )
    for col, ((interface, along), group) in enumerate(sorted(groups.items())):
        thetas, coords, state = grid(group, along, "state")
        _, _, normal = grid(group, along, "t_n_kPa")
        top, bottom = axes[0][col], axes[1][col]
        mesh = top.pcolormesh(
            thetas, coords, state, shading="nearest",
            cmap=ListedColormap(COLOURS), vmin=-0.5, vmax=2.5,
        )
        bar = fig.colorbar(mesh, ax=top, ticks=[0, 1, 2])
        bar.ax.set_yticklabels(STATES)
        top.set_title("interface %s, face along %s" % (interface, along))
        mesh = bottom.pcolormesh(thetas, coords, normal, shading="nearest",
                                 cmap="viridis")
        fig.colorbar(mesh, ax=bottom, label="t_n [kPa] (tension > 0)")
        for ax in (top, bottom):
            ax.set_xlabel("theta [deg]")
            ax.set_ylabel(along + " [m]")
            ax.set_xticks([0, 90, 180, 270, 360])
    fig.suptitle("%s, step %d" % (path, step), fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    print("wrote " + out)


if __name__ == "__main__":
    main()
