"""The plot sheet of a calibration: per component the FE curves against the
fitted conics (one per depth) and against the model (linear in z/D or L/D),
the parameters against z/D, and the 1D model against the FE at the pile
head."""
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from conic import conic  # noqa: E402


def sheet(curves, model, summary, piles, labels, path):
    fitted = [n for n, p in piles.items() if p["fitted"]]
    fig, axes = plt.subplots(3, 4, figsize=(20, 14))
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for j, c in enumerate(("py", "mt", "Hb", "Mb")):
        ax = axes[0, j]
        for i, name in enumerate(fitted):
            for cv in curves[name][c]:
                if cv.get("fit") is None:
                    continue
                col = colours[i % len(colours)]
                ax.plot(cv["xp"], cv["yp"], "o", ms=3, color=col)
                xs = np.linspace(0, cv["xp"].max(), 100)
                f = cv["fit"]
                ax.plot(xs, conic(xs, f["k"], f["n"], f["xu"], f["yu"]), "-", lw=0.8, color=col)
                s = cv["zD"] if c in ("py", "mt") else piles[name]["L_over_D"]
                ax.plot(xs, conic(xs, *model.at(c, s, piles[name]["L_over_D"])), ":", lw=0.8, color=col)
        ax.set_title(f"{c}: {labels[c]}\nFE (dots), conic per curve (-), model (:)", fontsize=9)
        ax.set_xlabel("x (normalised, see title)")
        ax.set_ylabel("y (normalised)")
        ax.set_xscale("symlog", linthresh=0.1)
    # parameters against z/D (per-curve fits) with the model's lines
    for j, q in enumerate(("k", "n", "xu", "yu")):
        ax = axes[1, j]
        for c, mk in (("py", "o"), ("mt", "s")):
            for i, name in enumerate(fitted):
                zs = [cv["zD"] for cv in curves[name][c] if cv.get("fit")]
                vs = [cv["fit"][q] for cv in curves[name][c] if cv.get("fit")]
                ax.plot(zs, vs, mk, ms=4, color=colours[i % len(colours)],
                        mfc="none" if c == "mt" else None, label=f"{c} {name}")
            P = model.params[c]
            # y_u over z/L: one model line per fitted pile, to its tip
            lines = [piles[name]["L_over_D"] for name in fitted] \
                if q == "yu" and P["layers"][0].get("yu_over") == "z/L" else [P["layers"][-1]["s1"]]
            for j_line, LD in enumerate(lines):
                ss = np.linspace(P["layers"][0]["s0"], min(LD, P["layers"][-1]["s1"]), 200)
                ax.plot(ss, [model.at(c, s, LD)[("k", "n", "xu", "yu").index(q)] for s in ss],
                        "k-" if c == "py" else "k--", lw=1, label=f"{c} model" if j_line == 0 else None)
        ax.set_xlabel("z/D [-]")
        ax.set_ylabel(f"{q} [-]")
        ax.set_yscale("log" if q != "n" else "linear")
        ax.set_title(f"{q} against z/D: py (filled), mt (open), model lines", fontsize=9)
    axes[1, 0].legend(fontsize=6)
    # the pile head
    ax_h, ax_m = axes[2, 0], axes[2, 1]
    for i, (name, s) in enumerate(summary.items()):
        col = colours[i % len(colours)]
        D = s["D"]
        v1, th1, H1, M1 = (np.array(a) for a in s["curve_1d"])
        v, th, H, M = (np.array(a) for a in s["curve_fe"])
        lab = name + ("" if s["fitted"] else " (left out)")
        ax_h.plot(v / D, H, "o", color=col, ms=4, label=f"FE {lab}")
        ax_h.plot(v1 / D, H1, "-", color=col, label=f"1D {lab}")
        ax_m.plot(th, M, "o", color=col, ms=4)
        ax_m.plot(th1, M1, "-", color=col)
    ax_h.set_xlabel("v/D at the mudline [-]")
    ax_h.set_ylabel("H [kN]")
    ax_h.legend(fontsize=7)
    ax_h.set_title("pile head: FE (dots) and 1D PISA model (lines)", fontsize=9)
    ax_m.set_xlabel("theta at the mudline [rad]")
    ax_m.set_ylabel("M at the mudline [kN m]")
    ax_m.set_title("M-theta at the mudline", fontsize=9)
    ax = axes[2, 2]
    for i, (name, s) in enumerate(summary.items()):
        v, th, H, M = (np.array(a) for a in s["curve_fe"])
        v1, th1, H1, M1 = (np.array(a) for a in s["curve_1d"])
        dH = np.interp(v[1:], v1, H1) / H[1:] - 1
        ax.plot(v[1:] / s["D"], 100 * dH, "o-", color=colours[i % len(colours)], ms=3, label=name)
    ax.axhline(5, color="grey", lw=0.5)
    ax.axhline(-5, color="grey", lw=0.5)
    ax.set_xlabel("v/D [-]")
    ax.set_ylabel("H_1D / H_FE - 1 [%]")
    ax.legend(fontsize=7)
    ax.set_title("1D against FE at equal mudline displacement", fontsize=9)
    axes[2, 3].axis("off")
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    plt.close(fig)
