#!/usr/bin/python3
"""Plot the lateral capacity of the plane-strain pile slice against the
adhesion factor alpha of its shaft (doc/soil-plasticity.md section 6b):
tools/capacity.py's value and error bar for each alpha, Randolph &
Houlsby's (1984) closed form and the exact end values.

    /usr/bin/python3 tools/plot_adhesion.py OUT.png ALPHA:CAPACITY.csv ...

CAPACITY.csv is what capacity.py wrote for the scene with c = alpha s_u.
Needs Debian's python3-matplotlib (under /usr/bin/python3).
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# Exact plane-strain values at alpha = 0 and 1 (the slip-line solutions:
# smooth 9.20117, rough 4 sqrt(2) + 2 pi = 11.9400).
EXACT_SMOOTH = 9.20117
EXACT_ROUGH = 4.0 * math.sqrt(2.0) + 2.0 * math.pi


def randolph_houlsby(alpha):
    """N_p = pi + 2 D + 2 cos D + 4 (cos D/2 + sin D/2), D = arcsin alpha
    (Randolph & Houlsby 1984; exact at alpha = 1, below the exact value
    by 0.7 % at alpha = 0)."""
    d = math.asin(alpha)
    return (math.pi + 2.0 * d + 2.0 * math.cos(d)
            + 4.0 * (math.cos(d / 2.0) + math.sin(d / 2.0)))


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    alpha, value, error = [], [], []
    for item in sys.argv[2:]:
        a, path = item.split(":", 1)
        with open(path) as f:
            row = next(csv.DictReader(f))
        alpha.append(float(a))
        value.append(float(row["value"]))
        error.append(float(row["error"]))
    fig, ax = plt.subplots(figsize=(5.5, 4.0))
    grid = [k / 100.0 for k in range(101)]
    ax.plot(grid, [randolph_houlsby(a) for a in grid], "k--", lw=1,
            label="Randolph & Houlsby (1984)")
    ax.plot([0, 1], [EXACT_SMOOTH, EXACT_ROUGH], "ks", mfc="none",
            label="exact: 9.201 (smooth), 11.940 (rough)")
    ax.errorbar(alpha, value, yerr=error, fmt="o", color="C0", capsize=3,
                label="fourier-ssi, n ≤ 8, extrapolated ± error bar")
    for a, v, e in zip(alpha, value, error):
        ax.annotate("%.2f ± %.2f" % (v, e), (a, v), textcoords="offset points",
                    xytext=(6, -12), fontsize=7)
    ax.set_xlabel("adhesion factor α = c_interface / s_u")
    ax.set_ylabel("N_p = H_ult / (s_u d L)")
    ax.set_title("rigid pile in Tresca clay, plane strain: rough to smooth",
                 fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="lower right")
    fig.tight_layout()
    fig.savefig(sys.argv[1], dpi=130)


if __name__ == "__main__":
    main()
