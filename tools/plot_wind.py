#!/usr/bin/python3
"""The half-cosine surface load of prm/wind-pressure.prm in 3D: surface
settlement u_z and radial displacement u_r along the radius at several
angles, from the program's 3D reconstruction (lines-3d.csv), and the load
series truncated at the selected harmonics against max(cos t, 0).

Usage: tools/plot_wind.py [--exe build/fourier-ssi] [--out doc/figures]
Writes OUT/wind-pressure.png and OUT/wind-pressure-lines.csv.
"""
import argparse
import csv
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

# Debian's python3-matplotlib imports under /usr/bin/python3 only; another
# python3 first on PATH may lack it: re-run under Debian's interpreter.
try:
    import matplotlib
except ImportError:
    if sys.executable != "/usr/bin/python3":
        os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
    sys.exit(sys.argv[0] + ": needs matplotlib (Debian: apt-get install "
             "python3-matplotlib python3-numpy)")

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--exe", default=os.path.join(ROOT, "build", "fourier-ssi"))
    parser.add_argument("--out", default=os.path.join(ROOT, "doc", "figures"))
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        prm = open(os.path.join(ROOT, "prm", "wind-pressure.prm")).read()
        prm += "subsection Output\n set Directory = %s\n set Write 3D vtu = false\nend\n" % work
        with open(os.path.join(work, "scene.prm"), "w") as f:
            f.write(prm)
        log = subprocess.run([args.exe, os.path.join(work, "scene.prm")],
                             check=True, capture_output=True, text=True).stdout
        rows = list(csv.DictReader(open(os.path.join(work, "lines-3d.csv"))))
        os.makedirs(args.out, exist_ok=True)
        shutil.copy(os.path.join(work, "lines-3d.csv"),
                    os.path.join(args.out, "wind-pressure-lines.csv"))
    selected = sorted({int(n) for n in re.findall(r"\n    n=(\d+) symmetric", log)})

    fig, axes = plt.subplots(1, 3, figsize=(14, 4.2))
    for theta in sorted({float(r["theta_deg"]) for r in rows}):
        line = [r for r in rows if float(r["theta_deg"]) == theta]
        radius = [float(r["r"]) for r in line]
        axes[0].plot(radius, [1e3 * float(r["u_z"]) for r in line], label="θ = %g°" % theta)
        axes[1].plot(radius, [1e3 * float(r["u_r"]) for r in line], label="θ = %g°" % theta)
    axes[0].set(xlabel="r [m]", ylabel="u_z [mm]", title="surface settlement")
    axes[1].set(xlabel="r [m]", ylabel="u_r [mm]", title="surface radial displacement")
    for ax in axes[:2]:
        ax.axvline(1.0, color="0.7", lw=0.8)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)

    def coefficient(n):
        if n == 0:
            return 1 / math.pi
        if n == 1:
            return 0.5
        return 2 / math.pi * math.cos(n * math.pi / 2) / (1 - n * n)

    t = [2 * math.pi * k / 720 for k in range(721)]
    axes[2].plot([math.degrees(x) for x in t], [max(math.cos(x), 0) for x in t],
                 color="k", lw=2, label="p/p0 = max(cos θ, 0)")
    axes[2].plot([math.degrees(x) for x in t],
                 [sum(coefficient(n) * math.cos(n * x) for n in selected) for x in t],
                 label="harmonics solved: %d (n ≤ %d)" % (len(selected), max(selected)))
    axes[2].set(xlabel="θ [deg]", ylabel="p / p0", title="load and its solved series")
    axes[2].grid(alpha=0.3)
    axes[2].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "wind-pressure.png"), dpi=110)
    print("wrote", os.path.join(args.out, "wind-pressure.png"))


if __name__ == "__main__":
    main()
