#!/usr/bin/python3
"""Accuracy vs wall time of the stiffness coefficients K_H, K_M, K_MH
(uniform, Kelly and goal-oriented refinement;
doc/verification/accuracy-vs-time.md §9).

Cases: embedded rigid footing e/a = 1 (prm/embedded-footing.prm geometry),
alpha = 0, 0.5, 1, nu = 0.25, rough and smooth interface; alpha = 0.5,
nu = 0.49, rough; laterally loaded
pile L/d = 10, alpha = 1, rough (prm/pile.prm).

Runs per case:
  u2  FE_Q(2), uniform (Strategy = global) refinement of the scene's mesh
  u4  FE_Q(4), uniform refinement of the mesh with half the cells per
      direction (footing: cell counts halved, growth ratios squared), so u2
      and u4 have equal DoFs; pile: both degrees on the scene's base mesh
      (Global refinements 0), u4 with 3 levels only (4x the DoFs of u2)
  k2  FE_Q(2), Kelly (Strategy = kelly, Refine fraction 0.3)
  k4  FE_Q(4), Kelly on the u4 base mesh
  g   goal-oriented (Strategy = goal, Goal = all, Refine fraction 0.8,
      9 cycles) on the u4 base mesh: every cycle solves FE_Q(2) and, for the
      error estimate, FE_Q(4) on the same mesh. One run gives two curves:
      g2 = the FE_Q(2) values (DoFs of FE_Q(2)) with their estimated error,
      g4 = the FE_Q(4) values of the estimator (DoFs of FE_Q(4)); both cost
      the whole run up to that cycle.

Reference per case and quantity: Richardson extrapolation from the three
finest u4 meshes with the observed order p = log2(d1/d2); its uncertainty is
estimated as |R(levels 0,1,2) - R(levels 1,2,3)|.

Timing: the executable prints one line per cycle after the stiffness
coefficients (unit-H and unit-M solves) are done; run.py time-stamps these
lines. t_cum(k) = process wall time from launch to the end of cycle k
(includes MPI/Trilinos start-up, the coefficient solves, Kelly indicators and
mesh refinement): the honest cost of an adaptive result at cycle k. For a
uniform level k the cost of a direct run on that mesh is estimated as
t_start + (t_cum(k) - t_cum(k-1)), t_start = time to the executable's first
output line. results.csv phases (time_setup + time_assembly + time_solve) are
kept as t_phases: setup + assembly + interface assembly + solve (scene and
unit-load solves) + estimate (since the goal-oriented version; rows of
cases not re-run keep the older sum, which left out the coefficient solves).

Usage: benchmarks/accuracy-vs-time/run.py [--exe /tmp/build/fourier-ssi]
        [--cases a,b] [--from-csv]
With --cases, the rows of the other cases are kept from the existing CSV.
Writes accuracy-vs-time.csv, references.csv, summary.md and one PNG per case
next to this script. One process at a time (timings: see summary.md).
"""
import argparse
import csv
import math
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
QUANTITIES = ["K_H", "K_M", "K_MH"]

CASES = {}
for _iface in ("rough", "smooth"):
    for _alpha in (0.0, 0.5, 1.0):
        CASES[f"footing-a{_alpha:g}-nu0.25-{_iface}"] = dict(
            scene="footing", alpha=_alpha, nu=0.25, interface=_iface)
CASES["footing-a0.5-nu0.49-rough"] = dict(scene="footing", alpha=0.5, nu=0.49,
                                           interface="rough")
CASES["pile-Ld10-a1-nu0.25-rough"] = dict(scene="pile", alpha=1.0, nu=0.25,
                                           interface="rough")

# label: (degree, strategy, cycles)
RUNS = {"u2": (2, "global", 4), "u4": (4, "global", 4),
        "k2": (2, "kelly", 12), "k4": (4, "kelly", 12),
        "g": (2, "goal", 9)}
# curves: a run label, or the two curves of the goal run
CURVES = ["u2", "u4", "k2", "k4", "g2", "g4"]
STYLE = {"u2": ("tab:blue", "o", "--", "FE_Q(2) uniform"),
         "u4": ("tab:orange", "s", "--", "FE_Q(4) uniform"),
         "k2": ("tab:green", "^", "-", "FE_Q(2) Kelly"),
         "k4": ("tab:red", "D", "-", "FE_Q(4) Kelly"),
         "g2": ("tab:purple", "v", "-", "FE_Q(2) goal (DWR)"),
         "g4": ("black", "*", "-", "FE_Q(4) of the goal estimator")}
PHASES = ("time_setup", "time_assembly", "time_interface_assembly", "time_solve",
          "time_estimate")


def prm_text(case, degree, strategy, cycles, directory):
    scene = case["scene"]
    template = os.path.join(ROOT, "prm", "embedded-footing.prm" if scene == "footing"
                            else "pile.prm")
    with open(template) as f:
        text = f.read()
    if scene == "footing":
        if degree == 2 and strategy != "goal":
            mesh = ["  set R cells = 6, 12", "  set R growth = 0.8, 1.3",
                    "  set Z cells = 12, 6", "  set Z growth = 0.8, 1"]
        else:
            mesh = ["  set R cells = 3, 6", "  set R growth = 0.64, 1.69",
                    "  set Z cells = 6, 3", "  set Z growth = 0.64, 1"]
        mesh.append("  set Global refinements = 0")
        materials = (f"0: G=1000, nu={case['nu']:g}, alpha={case['alpha']:g}, "
                     "depth_ref=1; 1: E=1e6, nu=0.2")
    else:
        # the scene's base mesh (Global refinements 0) for both degrees: at
        # the shipped Global refinements = 1, four uniform levels reach 830k
        # DoFs (minutes per run)
        mesh = ["  set Global refinements = 0"]
        materials = (f"0: G=1000, nu={case['nu']:g}, alpha={case['alpha']:g}, "
                     "depth_ref=10; 1: G=1e6, nu=0.25")
    lines = ["", "# ---- overrides written by benchmarks/accuracy-vs-time/run.py ----",
             "subsection Discretization", f"  set Polynomial degree = {degree}",
             f"  set Refinement cycles = {cycles}", "end",
             "subsection Adaptivity", f"  set Strategy = {strategy}",
             f"  set Refine fraction = {0.8 if strategy == 'goal' else 0.3}",
             "  set Goal = all", "end",
             "subsection Mesh", *mesh, "end",
             "subsection Materials", f"  set Materials = {materials}", "end",
             "subsection Interfaces", f"  set Interfaces = 5: {case['interface']}", "end",
             "subsection Output", f"  set Directory = {directory}",
             "  set Results file = results.csv", "  set Write vtu = false", "end"]
    return text.rstrip("\n") + "\n" + "\n".join(lines) + "\n"


def run_one(exe, case, label, work):
    degree, strategy, cycles = RUNS[label]
    if case["scene"] == "pile" and label == "u4":
        cycles = 3  # FE_Q(4) on the same base mesh: 4x the DoFs of u2
    out = os.path.join(work, label)
    prm = out + ".prm"
    with open(prm, "w") as f:
        f.write(prm_text(case, degree, strategy, cycles, out))
    t0 = time.monotonic()
    p = subprocess.Popen([exe, prm], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         text=True, bufsize=1)
    t_start, stamps = None, {}
    for line in p.stdout:
        now = time.monotonic() - t0
        if t_start is None:
            t_start = now
        if line.startswith("cycle "):
            stamps[int(line.split()[1].rstrip(","))] = now
    err = p.stderr.read()
    if p.wait() != 0:
        sys.exit(f"{label}: failed: {err.strip()} (prm kept in {prm})")
    t_total = time.monotonic() - t0
    vals = {}
    with open(os.path.join(out, "results.csv")) as f:
        for r in csv.DictReader(f):
            vals[(r["quantity"], int(r["cycle"]))] = float(r["value"])
    rows = []
    for c in sorted(stamps):
        # the cycle line arrives when the cycle is done, including the
        # coefficient solves
        dt = stamps[c] - (stamps[c - 1] if c > 0 else t_start)
        phases = sum(vals.get((q, c), 0.0) for q in PHASES)
        cost = stamps[c] if strategy != "global" else t_start + dt
        common = dict(degree=degree, strategy=strategy, cycle=c, t_phases=phases,
                      t_cycle=dt, t_cum=stamps[c], t_start=t_start, cost=cost,
                      t_process=t_total)
        if strategy != "goal":
            rows.append(dict(run=label, n_dofs=int(vals[("n_dofs", c)]),
                             K_H=vals[("K_H", c)], K_M=vals[("K_M", c)],
                             K_MH=vals[("K_MH", c)], **common))
            continue
        est = {f"est_{q}": vals[(f"goal_error_{q}", c)] for q in QUANTITIES}
        rows.append(dict(run="g2", n_dofs=int(vals[("n_dofs", c)]),
                         K_H=vals[("K_H", c)], K_M=vals[("K_M", c)],
                         K_MH=vals[("K_MH", c)], **est, **common))
        common["degree"] = 4
        rows.append(dict(run="g4", n_dofs=int(vals[("enriched_n_dofs", c)]),
                         K_H=vals[("K_H_enriched", c)], K_M=vals[("K_M_enriched", c)],
                         K_MH=vals[("K_MH_enriched", c)], **est, **common))
    return rows


def richardson(v):
    k0, k1, k2 = v[-3:]
    d1, d2 = k1 - k0, k2 - k1
    if d1 == 0 or d2 == 0 or d1 / d2 <= 1.0:
        return k2, float("nan")
    p = math.log2(d1 / d2)
    return k2 + d2 / (2.0 ** p - 1.0), p


def references(rows):
    u4 = sorted((r for r in rows if r["run"] == "u4"), key=lambda r: int(r["cycle"]))
    ref = {}
    for q in QUANTITIES:
        v = [float(r[q]) for r in u4]
        ext, p = richardson(v)
        ext_prev, p_prev = richardson(v[:-1]) if len(v) >= 4 else (float("nan"),) * 2
        ref[q] = dict(value=ext, order=p, order_prev=p_prev,
                      uncertainty=abs(ext - ext_prev) / abs(ext),
                      finest_u4=v[-1])
    return ref


def plot_case(name, rows, ref, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(3, 2, figsize=(11, 11), sharex="col")
    for i, q in enumerate(QUANTITIES):
        for label in CURVES:
            rr = sorted((r for r in rows if r["run"] == label), key=lambda r: int(r["cycle"]))
            if not rr:
                continue
            color, marker, ls, text = STYLE[label]
            err = [max(abs(float(r[q]) / ref[q]["value"] - 1.0), 1e-12) for r in rr]
            dofs = [int(r["n_dofs"]) for r in rr]
            cost = [float(r["cost"]) for r in rr]
            for j, x in enumerate((dofs, cost)):
                axes[i, j].loglog(x, err, color=color, marker=marker, ls=ls, ms=4,
                                  label=text if (i == 0 and j == 0) else None)
                if label == "g2":
                    # the estimated error of the FE_Q(2) values
                    est = [float(r[f"est_{q}"]) for r in rr]
                    axes[i, j].loglog(x, est, color=color, ls=":", lw=1.2,
                                      label="its DWR estimate" if (i == 0 and j == 0)
                                      else None)
        u = ref[q]["uncertainty"] if math.isfinite(ref[q]["uncertainty"]) else 0.0
        for j in range(2):
            ax = axes[i, j]
            ax.axhline(1e-4, color="grey", lw=0.8, ls=":")
            ax.axhline(1e-3, color="grey", lw=0.8, ls=":")
            if u > 0:
                ax.axhspan(1e-12, u, color="grey", alpha=0.15)
            ax.set_ylim(bottom=max(min(u if u > 0 else 1e-5, 1e-5) / 3, 1e-7))
            ax.grid(True, which="both", alpha=0.3)
        axes[i, 0].set_ylabel(f"|{q} / ref - 1|")
        axes[i, 1].set_title(f"{q}: ref {ref[q]['value']:.6g} (p = {ref[q]['order']:.2f})",
                             fontsize=9)
    axes[2, 0].set_xlabel("DoFs")
    axes[2, 1].set_xlabel("wall time [s]: uniform = one run on that mesh,\n"
                          "adaptive = cumulative cycles 0..k, both incl. process start-up")
    axes[0, 0].legend(fontsize=8)
    fig.suptitle(f"{name}: relative error vs DoFs and vs wall time\n"
                 "(ref = Richardson from the 3 finest uniform FE_Q(4) meshes; "
                 "shaded: its estimated uncertainty)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def cost_to_reach(rows, label, q, refval, tol):
    """Smallest cost of a point of run 'label' with error <= tol from which
    on every later point stays <= tol (for uniform: the level's own cost)."""
    rr = sorted((r for r in rows if r["run"] == label), key=lambda r: int(r["cycle"]))
    ok = None
    for r in reversed(rr):
        if abs(float(r[q]) / refval - 1.0) <= tol:
            ok = r
        else:
            break
    return (float(ok["cost"]), int(ok["n_dofs"])) if ok else None


FIELDS = ["case", "run", "degree", "strategy", "cycle", "n_dofs", "K_H", "K_M", "K_MH",
          "err_K_H", "err_K_M", "err_K_MH", "est_K_H", "est_K_M", "est_K_MH", "t_phases", "t_cycle", "t_cum", "t_start",
          "cost", "t_process"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--exe", default="/tmp/build/fourier-ssi")
    ap.add_argument("--cases", default=",".join(CASES))
    ap.add_argument("--out", default=HERE)
    ap.add_argument("--from-csv", action="store_true", help="only re-plot and re-summarise")
    args = ap.parse_args()
    names = args.cases.split(",")
    os.makedirs(args.out, exist_ok=True)
    csv_path = os.path.join(args.out, "accuracy-vs-time.csv")
    allrows = {}
    if args.from_csv:
        with open(csv_path) as f:
            for r in csv.DictReader(f):
                allrows.setdefault(r["case"], []).append(r)
        names = [n for n in names if n in allrows]
    else:
        kept = {}
        if os.path.exists(csv_path):
            with open(csv_path) as f:
                for r in csv.DictReader(f):
                    if r["case"] not in names:
                        kept.setdefault(r["case"], []).append(r)
        work = tempfile.mkdtemp(prefix="avt-")
        t_all = time.monotonic()
        for name in names:
            rows = []
            for label in RUNS:
                cw = os.path.join(work, name)
                os.makedirs(cw, exist_ok=True)
                rows += run_one(args.exe, CASES[name], label, cw)
                last = rows[-1]
                print(f"{name} {label}: {len(rows)} rows, {last['n_dofs']} dofs, "
                      f"K_H {last['K_H']:.7g}, process {last['t_process']:.1f} s", flush=True)
            for r in rows:
                r["case"] = name
            allrows[name] = rows
        print(f"all runs: {time.monotonic() - t_all:.0f} s")
        # cases not re-run keep their rows (and are re-plotted)
        for name in CASES:
            if name in kept:
                allrows[name] = kept[name]
        names = [n for n in CASES if n in allrows]
    refs = {}
    for name in names:
        rows = allrows[name]
        refs[name] = references(rows)
        for r in rows:
            for q in QUANTITIES:
                r[f"err_{q}"] = abs(float(r[q]) / refs[name][q]["value"] - 1.0)
        plot_case(name, rows, refs[name], os.path.join(args.out, f"{name}.png"))
    if not args.from_csv:
        with open(csv_path, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=FIELDS)
            w.writeheader()
            for name in names:
                for r in allrows[name]:
                    out = dict(r)
                    for k in ("K_H", "K_M", "K_MH"):
                        out[k] = f"{float(r[k]):.10g}"
                    for k in FIELDS:
                        if k.startswith("est_") and r.get(k, "") in ("", None):
                            out[k] = ""
                        elif k.startswith("err_") or k.startswith("est_"):
                            out[k] = f"{float(r[k]):.3e}"
                        elif k.startswith("t_") or k == "cost":
                            out[k] = f"{float(r[k]):.3f}"
                    w.writerow({k: out[k] for k in FIELDS})
    with open(os.path.join(args.out, "references.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case", "quantity", "reference", "order_p", "order_p_levels012",
                    "rel_uncertainty", "finest_u4_rel_err", "finest_k4", "finest_k4_rel_err",
                    "finest_k4_dofs", "finest_k4_cum_s", "agree"])
        for name in names:
            k4 = sorted((r for r in allrows[name] if r["run"] == "k4"),
                        key=lambda r: int(r["cycle"]))[-1]
            for q in QUANTITIES:
                R = refs[name][q]
                ek = abs(float(k4[q]) / R["value"] - 1.0)
                eu = abs(R["finest_u4"] / R["value"] - 1.0)
                # agreement: the Kelly value lies within the reference's
                # uncertainty (or within its own last-step change)
                agree = ek <= max(3 * R["uncertainty"], 1e-6)
                w.writerow([name, q, f"{R['value']:.8g}", f"{R['order']:.3f}",
                            f"{R['order_prev']:.3f}", f"{R['uncertainty']:.2e}",
                            f"{eu:.2e}", f"{float(k4[q]):.8g}", f"{ek:.2e}",
                            int(k4["n_dofs"]), f"{float(k4['cost']):.2f}",
                            "n/a (3 levels, no uncertainty)" if not math.isfinite(R["uncertainty"])
                            else ("yes" if agree else "NO")])
    write_summary(names, allrows, refs, os.path.join(args.out, "summary.md"))
    return 0


def write_summary(names, allrows, refs, path):
    out = ["# Accuracy vs time: summary (generated by run.py)", "",
           "Cost to reach a relative error (and stay below it on later cycles), in "
           "seconds of wall time [DoFs]; uniform: one run on that mesh, adaptive: "
           "cumulative cycles 0..k incl. process start-up. '-' = not reached. "
           "FE_Q(4) of the goal estimator: DoFs of the FE_Q(4) solve, cost of "
           "the whole goal run (FE_Q(2) + FE_Q(4) per cycle). Below the "
           "reference's uncertainty (see the last table) a 'reached' is not "
           "certified.", ""]
    for q in QUANTITIES:
        out += [f"## {q}", "", "| case | tol | " + " | ".join(STYLE[l][3] for l in CURVES) + " |",
                "|---|---|" + "---|" * len(CURVES)]
        for name in names:
            for tol in (1e-2, 1e-3, 1e-4, 1e-5, 1e-6):
                cells = []
                for label in CURVES:
                    c = cost_to_reach(allrows[name], label, q, refs[name][q]["value"], tol)
                    cells.append(f"{c[0]:.2f} s [{c[1]}]" if c else "-")
                out.append(f"| {name} | {tol:g} | " + " | ".join(cells) + " |")
        out.append("")
    out += ["## Goal-oriented estimate: effectivity index (estimated / true error of "
            "the FE_Q(2) value)", "",
            "Only cycles whose true error exceeds 10x the reference's uncertainty "
            "(below that the 'true' error is not known well enough).", "",
            "| case | quantity | cycle | DoFs | true error | estimate | effectivity | "
            "FE_Q(4) error / estimate |", "|---|---|---|---|---|---|---|---|"]
    for name in names:
        g2 = sorted((r for r in allrows[name] if r["run"] == "g2"), key=lambda r: int(r["cycle"]))
        g4 = {int(r["cycle"]): r for r in allrows[name] if r["run"] == "g4"}
        for q in QUANTITIES:
            R = refs[name][q]
            u = R["uncertainty"] if math.isfinite(R["uncertainty"]) else 0.0
            for r in g2:
                err = abs(float(r[q]) / R["value"] - 1.0)
                est = float(r[f"est_{q}"])
                if err <= 10 * u:
                    continue
                e4 = abs(float(g4[int(r["cycle"])][q]) / R["value"] - 1.0)
                out.append(f"| {name} | {q} | {r['cycle']} | {r['n_dofs']} | {err:.2e} | "
                           f"{est:.2e} | {est / err:.2f} | {e4 / est:.2f} |")
    out.append("")
    out += ["## References (Richardson, 3 finest uniform FE_Q(4))", "",
            "| case | quantity | reference | p (levels 1-3) | p (levels 0-2) | uncertainty |",
            "|---|---|---|---|---|---|"]
    for name in names:
        for q in QUANTITIES:
            R = refs[name][q]
            out.append(f"| {name} | {q} | {R['value']:.7g} | {R['order']:.2f} | "
                       f"{R['order_prev']:.2f} | {R['uncertainty']:.1e} |")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    sys.exit(main())
