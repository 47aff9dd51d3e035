#!/usr/bin/python3
"""Plot load-displacement curves written by a nonlinear-interface run
(<Output/Directory>/load-displacement.csv, doc/nonlinear-interfaces.md).

    /usr/bin/python3 tools/plot_load_displacement.py CSV X_COLUMN Y_COLUMN OUT.png [LABEL]

e.g. tools/plot_load_displacement.py output/pile-lateral-slip/load-displacement.csv \
        horizontal_m H_kN doc/figures/pile-lateral-slip.png
Needs Debian's python3-matplotlib (under /usr/bin/python3).
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) < 5:
        sys.exit(__doc__)
    path, x_name, y_name, out = sys.argv[1:5]
    label = sys.argv[5] if len(sys.argv) > 5 else path
    with open(path) as f:
        rows = [r for r in csv.DictReader(f) if not r["step"].startswith("#")]
    x = [0.0] + [float(r[x_name]) for r in rows]
    y = [0.0] + [float(r[y_name]) for r in rows]
    fig, ax = plt.subplots(figsize=(5, 3.6))
    ax.plot(x, y, "o-", ms=3, label=label)
    ax.set_xlabel(x_name.replace("_", " [") + "]")
    ax.set_ylabel(y_name.replace("_", " [") + "]")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print("wrote", out)


if __name__ == "__main__":
    main()
