#!/usr/bin/python3
"""Plot normalised capacity curves of plastic-soil runs against a published
limit (doc/soil-plasticity.md).

    /usr/bin/python3 tools/plot_soil_capacity.py OUT.png TITLE X_COLUMN Y_COLUMN \
        X_SCALE Y_SCALE REFERENCE CSV:LABEL [CSV:LABEL ...]

Each curve is (X / X_SCALE, |Y| / Y_SCALE) from a load-displacement.csv; the
reference values (comma separated, e.g. 6.05,5.69) are drawn as dashed lines.
e.g. footing: X = vertical_m (a = 1 m), Y = V_kN, Y_SCALE = pi a^2 s_u.
Needs Debian's python3-matplotlib (under /usr/bin/python3).
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) < 9:
        sys.exit(__doc__)
    out, title, x_name, y_name = sys.argv[1:5]
    x_scale, y_scale = float(sys.argv[5]), float(sys.argv[6])
    references = [float(v) for v in sys.argv[7].split(",") if v]
    fig, ax = plt.subplots(figsize=(5.2, 3.6))
    for item in sys.argv[8:]:
        path, label = item.split(":", 1)
        with open(path) as f:
            rows = list(csv.DictReader(f))
        x = [0.0] + [abs(float(r[x_name])) / x_scale for r in rows]
        y = [0.0] + [abs(float(r[y_name])) / y_scale for r in rows]
        ax.plot(x, y, "o-", ms=3, label=label)
    for value in references:
        ax.axhline(value, ls="--", lw=0.8, color="k")
        ax.text(ax.get_xlim()[1], value, " %.2f" % value, va="center",
                fontsize=8)
    ax.set_title(title, fontsize=9)
    ax.set_xlabel(x_name + " / " + sys.argv[5])
    ax.set_ylabel("|" + y_name + "| / " + sys.argv[6])
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print("wrote", out)


if __name__ == "__main__":
    main()
