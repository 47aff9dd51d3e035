#!/usr/bin/python3
"""Plot stiffness sweeps written by tools/sweep.py (thesis Hernoune 2007
Figs 4.6-4.11 for the embedded footing, Figs 6.2-6.7 for the pile).

Usage: tools/plot_sweeps.py CSV... [--out doc/figures]

For every CSV and every interface in it: one PNG <csv-stem>-<interface>.png
with rows K_H, K_M, -K_MH and one column per nu; x = alpha, one curve per
e/a (footing) or L/d (pile; one figure per Ep/Es if several). Plus one PNG
<csv-stem>-smooth-over-rough.png with the ratio smooth/rough of K_H and K_M
when both interfaces are present.

Where the CSV has error columns (K_H_error, ...: estimated relative errors,
tools/sweep.py with 'target accuracy'), every point carries its error bar
(value x relative error; at 1e-4 smaller than the marker) and each panel's
title names the largest relative error of its points; a case that did not
reach its target (converged = 0) is drawn with an open marker.

A rigid pile CSV (Ep_over_Es = rigid) is plotted like a flexible one.

K_MH is plotted as -K_MH: ours is the off-diagonal of the true inverse of
the influence matrix with H along +x and M about +y (u_x = Theta z), which
is negative for an embedded footing or a pile; the thesis plots a positive
(normalised) coupling (doc/scenes.md).
"""
import argparse
import csv
import os
from collections import defaultdict

import sys

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

QUANT = [("K_H", "$K_H$", 1.0), ("K_M", "$K_M$", 1.0), ("K_MH", "$-K_{MH}$", -1.0)]


def load(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise SystemExit(f"{path}: no rows")
    geo = "e_over_a" if "e_over_a" in rows[0] else "L_over_d"
    for r in rows:
        for k, v in r.items():
            if k == "interface" or (k == "Ep_over_Es" and v == "rigid"):
                continue
            r[k] = float(v) if v not in ("", None) else float("nan")
    return rows, geo


def plot_family(rows, geo, title, png):
    nus = sorted({r["nu"] for r in rows})
    geos = sorted({r[geo] for r in rows})
    glabel = "e/a" if geo == "e_over_a" else "L/d"
    fig, axes = plt.subplots(len(QUANT), len(nus), figsize=(4.6 * len(nus), 3.3 * len(QUANT)),
                             squeeze=False)
    markers = "osD^v<>p"
    for j, nu in enumerate(nus):
        for i, (q, qlabel, sign) in enumerate(QUANT):
            ax = axes[i][j]
            worst = 0.
            for m, g in enumerate(geos):
                sub = sorted((r for r in rows if r["nu"] == nu and r[geo] == g),
                             key=lambda r: r["alpha"])
                if not sub:
                    continue
                x = [r["alpha"] for r in sub]
                y = [sign * r[q] for r in sub]
                rel = [r.get(q + "_error", float("nan")) for r in sub]
                err = [abs(v) * e if e == e else 0. for v, e in zip(y, rel)]
                worst = max([worst] + [e for e in rel if e == e])
                line = ax.errorbar(x, y, yerr=err, marker=markers[m % len(markers)], ms=4,
                                   capsize=2, label=f"{glabel} = {g:g}")
                unmet = [(a, b) for a, b, r in zip(x, y, sub) if r.get("converged") == 0.]
                if unmet:
                    ax.plot(*zip(*unmet), ls="none", marker=markers[m % len(markers)], ms=7,
                            mfc="white", color=line[0].get_color(), zorder=3)
            ax.set_xlabel(r"$\alpha$")
            ax.set_ylabel(qlabel)
            bar = f", largest error {worst:.0e}" if worst > 0. else ""
            ax.set_title(f"{qlabel}, $\\nu_s$ = {nu:g}{bar}", fontsize=10)
            ax.grid(alpha=0.3)
            if geo == "L_over_d" or q == "K_M":
                ax.set_yscale("log")
            if i == 0 and j == 0:
                ax.legend(fontsize=8)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)
    print("wrote", png)


def plot_ratio(rows, geo, title, png):
    nus = sorted({r["nu"] for r in rows})
    geos = sorted({r[geo] for r in rows})
    glabel = "e/a" if geo == "e_over_a" else "L/d"
    key = lambda r: (r["nu"], r[geo], r["alpha"])  # noqa: E731
    rough = {key(r): r for r in rows if r["interface"] == "rough"}
    smooth = {key(r): r for r in rows if r["interface"] == "smooth"}
    fig, axes = plt.subplots(2, len(nus), figsize=(4.6 * len(nus), 6.4), squeeze=False)
    for j, nu in enumerate(nus):
        for i, q in enumerate(["K_H", "K_M"]):
            ax = axes[i][j]
            for g in geos:
                pts = sorted((k[2], smooth[k][q] / rough[k][q]) for k in rough
                             if k in smooth and k[0] == nu and k[1] == g)
                if pts:
                    ax.plot(*zip(*pts), marker="o", ms=4, label=f"{glabel} = {g:g}")
            ax.axhline(1.0, color="k", lw=0.6)
            ax.set_xlabel(r"$\alpha$")
            ax.set_ylabel(f"{q} smooth / rough")
            ax.set_title(f"{q} smooth/rough, $\\nu_s$ = {nu:g}", fontsize=10)
            ax.grid(alpha=0.3)
            if i == 0 and j == 0:
                ax.legend(fontsize=8)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)
    print("wrote", png)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("csv", nargs="+")
    ap.add_argument("--out", default="doc/figures")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    for path in args.csv:
        rows, geo = load(path)
        stem = os.path.splitext(os.path.basename(path))[0]
        scene = "embedded footing" if geo == "e_over_a" else "pile"
        groups = defaultdict(list)
        for r in rows:
            groups[(r["interface"], r.get("Ep_over_Es"))].append(r)
        several_ep = len({k[1] for k in groups}) > 1
        for (itf, ep), sub in sorted(groups.items(), key=lambda kv: str(kv[0])):
            ep_name = ep if isinstance(ep, str) else (f"{ep:g}" if ep is not None else None)
            tag = f"{stem}-{itf}" + (f"-Ep{ep_name}" if several_ep else "")
            extra = f", $E_p/E_s$ = {ep_name}" if ep is not None else ""
            plot_family(sub, geo, f"{scene}, {itf} interface{extra}",
                        os.path.join(args.out, tag + ".png"))
        if {"rough", "smooth"} <= {r["interface"] for r in rows}:
            for ep in sorted({k[1] for k in groups}, key=str):
                sub = [r for r in rows if r.get("Ep_over_Es") == ep]
                tag = f"{stem}-smooth-over-rough" + (f"-Ep{ep}" if several_ep else "")
                plot_ratio(sub, geo, f"{scene}: smooth / rough",
                           os.path.join(args.out, tag + ".png"))


if __name__ == "__main__":
    main()
