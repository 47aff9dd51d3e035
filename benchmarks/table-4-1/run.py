#!/usr/bin/python3
"""Convergence study for Table 4.1 of Hernoune (2007), section 4.2: rotation
of a rigid circular surface footing (a = 1) under a moment M, reported as
theta E_s a^3 / M, for nu in {0, 0.1, 0.2, 0.3, 0.4, 0.49} and five contact
models:
  bonded  -- "sans interface": soil surface nodes r < a tied to the rigid
             motion in u, v, w (Tie = boundary, Id = 4);
  k1e6, k1e8, k1e10 -- rigid block (material 1, 0 <= z <= 0.2) resting on
             a zero-thickness interface at z = 0 with kn = ks = k [kPa/m];
  smooth  -- only the normal component tied (frictionless), exact
             3 (1 - nu^2) / 4 (Poulos & Davis 1974, thesis eq. 4.1).
Soil: G = 1000 kPa (thesis 4.2: "le module de cisaillement est fixe a 1000"),
E_s = 2 G (1 + nu); M = 1 kN.m, so theta E_s a^3 / M = theta E_s.

Mesh: domain radius = depth = L (fixed far boundaries), geometric grading
toward the footing edge (r, z) = (a, 0) with edge cell size h_e on the coarse
mesh; each run solves 'levels' uniformly refined meshes (Refinement cycles).
The value is Richardson-extrapolated from the last three levels with the
observed order.

Usage: benchmarks/table-4-1/run.py [--exe BUILD/fourier-ssi] [--levels 4]
       [--L 100] [--out benchmarks/table-4-1] [--rows bonded,k1e10,...]
       [--nus 0,0.3]
Writes OUT/table-4-1.csv (one row per nu, model, level) and OUT/table-4-1.md.

With --target ROUGH,SMOOTH (e.g. 1e-4,1e-3) the same scenes are driven by
Discretization/Target accuracy instead (ROUGH for the bonded and interface
rows, SMOOTH for the smooth one): the program designs its nested FE_Q(4)
meshes from the coarse mesh above and stops when the estimated relative
error of the foundation's motion is below the target
(doc/accuracy-vs-time.md). Every case runs in one 'fourier-ssi --batch'
process. Writes OUT/TAG.csv and OUT/TAG.md (default tag table-4-1-target):
each value with its estimated error, next to the thesis, the exact smooth
value and the 4-level Richardson study of benchmarks/table-4-1/table-4-1.csv.
"""
import argparse
import csv
import math
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "..", "tools"))
from batch_runs import read_last_cycle, run_batch  # noqa: E402
from mesh_grading import growth_for  # noqa: E402

THESIS = {
    "bonded": [0.66060, 0.67329, 0.67255, 0.65629, 0.62132, 0.56882],
    "k1e6": [0.68860, 0.70063, 0.69912, 0.68193, 0.64596, 0.59293],
    "k1e8": [0.6706, 0.67375, 0.67298, 0.65671, 0.62168, 0.56924],
    "k1e10": [0.66062, 0.67331, 0.67255, 0.65629, 0.62132, 0.56882],
}
NUS = [0.0, 0.1, 0.2, 0.3, 0.4, 0.49]
ROWS = ["bonded", "k1e6", "k1e8", "k1e10", "smooth"]
LABEL = {
    "bonded": "without interface (bonded)",
    "k1e6": "interface k = 1e6",
    "k1e8": "interface k = 1e8",
    "k1e10": "interface k = 1e10",
    "smooth": "smooth, exact 3(1-nu^2)/4",
}


def mesh_entries(L, h_edge=0.05, n_foot=6, n_out=14, n_depth=16):
    """Graded (r, z) rectangle: n_foot cells on 0 < r < a shrinking to h_edge
    at r = a, n_out cells on a < r < L growing from h_edge, n_depth cells on
    -L < z < 0 shrinking to h_edge at z = 0."""
    g_foot = growth_for(n_foot, 1.0, h_edge)
    g_out = 1.0 / growth_for(n_out, L - 1.0, h_edge)  # reversed: grows
    g_depth = growth_for(n_depth, L, h_edge)
    return g_foot, g_out, g_depth


def prm_text(row, nu, L, levels, directory, target=None):
    G = 1000.0
    E = 2 * G * (1 + nu)
    g_foot, g_out, g_depth = mesh_entries(L)
    block = row.startswith("k")
    lines = [
        "subsection Discretization",
        "  set Harmonics = 1",
        f"  set Refinement cycles = {levels}",
        "end",
        "subsection Mesh",
        f"  set R breakpoints = 0, 1, {L:g}",
        "  set R cells = 6, 14",
        f"  set R growth = {g_foot:.12g}, {g_out:.12g}",
    ]
    if block:
        lines += [
            f"  set Z breakpoints = -{L:g}, 0, 0.2",
            "  set Z cells = 16, 1",
            f"  set Z growth = {g_depth:.12g}, 1",
            "  set Material regions = 1: 0, 1, 0, 0.2",
            f"  set Removed regions = 1, {L:g}, 0, 0.2",
            "  set Interface lines = 5: z=0, r=0..1",
        ]
    else:
        lines += [
            f"  set Z breakpoints = -{L:g}, 0",
            "  set Z cells = 16",
            f"  set Z growth = {g_depth:.12g}",
            "  set Surface patch radius = 1",
        ]
    lines += ["end", "subsection Materials"]
    if block:
        lines.append(f"  set Materials = 0: E={E:g}, nu={nu:g}; 1: E=1e6, nu=0.2")
    else:
        lines.append(f"  set Materials = 0: E={E:g}, nu={nu:g}")
    lines.append("end")
    if block:
        k = row[1:]
        lines += ["subsection Interfaces", f"  set Interfaces = 5: kn={k}, ks={k}", "end"]
    lines += [
        "subsection Boundary conditions",
        "  set Dirichlet = 1: u=0, v=0, w=0; 2: u=0, v=0, w=0",
        "end",
        "subsection Rigid foundation",
        "  set Enabled = true",
    ]
    if block:
        lines += ["  set Tie = material", "  set Id = 1"]
    else:
        lines += [
            "  set Tie = boundary",
            "  set Id = 4",
            "  set Tied components = " + ("normal" if row == "smooth" else "all"),
        ]
    lines += [
        "  set Moment = 1",
        "end",
        "subsection Output",
        f"  set Directory = {directory}",
        "  set Write vtu = false",
        "end",
    ]
    if target is not None:
        # The design replaces Refinement cycles; a case the DoF limit stops
        # keeps its value, marked not converged.
        lines += ["subsection Discretization", f"  set Target accuracy = {target:g}", "end",
                  "subsection Adaptivity", "  set Allow unconverged = true", "end"]
    return "\n".join(lines) + "\n", E


def richardson(v):
    """Extrapolate from the last three values (meshes h, h/2, h/4)."""
    k0, k1, k2 = v[-3:]
    d1, d2 = k1 - k0, k2 - k1
    if d1 == 0 or d2 == 0 or d1 / d2 <= 1.0:  # no asymptotic range
        return k2, float("nan")
    p = math.log2(d1 / d2)
    return k2 + d2 / (2.0 ** p - 1.0), p


def exact_smooth(nu):
    return 0.75 * (1 - nu * nu)


def reference(row, i, nu):
    return exact_smooth(nu) if row == "smooth" else THESIS[row][i]


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", default=os.path.join(here, "../../build/fourier-ssi"))
    ap.add_argument("--levels", type=int, default=4)
    ap.add_argument("--L", type=float, default=100.0)
    ap.add_argument("--out", default=here)
    ap.add_argument("--rows", default=",".join(ROWS))
    ap.add_argument("--nus", default=",".join(str(n) for n in NUS))
    ap.add_argument("--tag", default=None,
                    help="output stem (default table-4-1, with --target table-4-1-target)")
    ap.add_argument("--target", default=None, metavar="ROUGH,SMOOTH",
                    help="drive every case by Discretization/Target accuracy (e.g. 1e-4,1e-3)")
    ap.add_argument("--from-csv", action="store_true",
                    help="only rewrite OUT/TAG.md from OUT/TAG.csv")
    args = ap.parse_args()
    rows = args.rows.split(",")
    nus = [float(x) for x in args.nus.split(",")]
    if args.tag is None:
        args.tag = "table-4-1-target" if args.target else "table-4-1"
    if args.target:
        return run_targets(args, rows, nus, here)
    if args.from_csv:
        with open(os.path.join(args.out, args.tag + ".csv")) as f:
            records = list(csv.DictReader(f))
        for r in records:
            r["nu"] = float(r["nu"])
            if r["level"] != "extrapolated":
                r["level"] = int(r["level"])
        rows = [m for m in rows if any(r["model"] == m for r in records)]
        write_markdown(records, rows, nus, args,
                       os.path.join(args.out, args.tag + ".md"))
        return 0

    records = []
    work = tempfile.mkdtemp(prefix="table41-")
    for row in rows:
        for nu in nus:
            i = NUS.index(nu)
            out = os.path.join(work, f"{row}-{nu}")
            text, E = prm_text(row, nu, args.L, args.levels, out)
            prm = out + ".prm"
            with open(prm, "w") as f:
                f.write(text)
            t0 = time.time()
            subprocess.run([args.exe, prm], check=True, stdout=subprocess.DEVNULL)
            dt = time.time() - t0
            theta, dofs = {}, {}
            with open(os.path.join(out, "results.csv")) as f:
                for r in csv.DictReader(f):
                    if r["quantity"] == "foundation_rotation":
                        theta[int(r["cycle"])] = float(r["value"])
                    if r["quantity"] == "n_dofs":
                        dofs[int(r["cycle"])] = int(float(r["value"]))
            values = [theta[c] * E for c in sorted(theta)]
            ext, p = richardson(values)
            ref = reference(row, i, nu)
            for c, v in enumerate(values):
                records.append(dict(model=row, nu=nu, L=args.L, level=c,
                                    dofs=dofs.get(c, ""), value=f"{v:.6f}",
                                    reference=f"{ref:.5f}"))
            records.append(dict(model=row, nu=nu, L=args.L, level="extrapolated",
                                dofs="", value=f"{ext:.6f}",
                                reference=f"{ref:.5f}", order=f"{p:.3f}",
                                diff_percent=f"{100 * (ext / ref - 1):+.3f}"))
            print(f"{row:7s} nu={nu:<5g} " + " ".join(f"{v:.5f}" for v in values)
                  + f" -> {ext:.5f} (p={p:.2f}) ref {ref:.5f} "
                  f"({100 * (ext / ref - 1):+.2f}%) {dt:.1f}s", flush=True)

    fields = ["model", "nu", "L", "level", "dofs", "value", "reference",
              "order", "diff_percent"]
    csv_path = os.path.join(args.out, args.tag + ".csv")
    with open(csv_path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        for r in records:
            w.writerow(r)
    write_markdown(records, rows, nus, args, os.path.join(args.out, args.tag + ".md"))



def study_values(here):
    """The 4-level Richardson study (table-4-1.csv), extrapolated values."""
    path = os.path.join(here, "table-4-1.csv")
    study = {}
    if os.path.exists(path):
        with open(path) as f:
            for r in csv.DictReader(f):
                if r["level"] == "extrapolated":
                    study[(r["model"], float(r["nu"]))] = float(r["value"])
    return study


def run_targets(args, rows, nus, here):
    """Every (row, nu) driven by Target accuracy in one --batch process."""
    try:
        rough, smooth = (float(x) for x in args.target.split(","))
    except ValueError:
        sys.exit(f"--target: '{args.target}' is not ROUGH,SMOOTH (e.g. 1e-4,1e-3)")
    work = tempfile.mkdtemp(prefix="table41-target-")
    cases = []
    for row in rows:
        for nu in nus:
            out = os.path.join(work, f"{row}-{nu}")
            target = smooth if row == "smooth" else rough
            text, E = prm_text(row, nu, args.L, 1, out, target)
            with open(out + ".prm", "w") as f:
                f.write(text)
            cases.append((row, nu, E, target, out))
    wall = run_batch(args.exe, work, [c[4] + ".prm" for c in cases])
    study = study_values(here)
    records = []
    for row, nu, E, target, out in cases:
        res = read_last_cycle(os.path.join(out, "results.csv"))
        value = res["foundation_rotation"] * E  # theta E_s a^3 / M, M = 1, a = 1
        error = res["foundation_rotation_error"]
        ref = reference(row, NUS.index(nu), nu)
        old = study.get((row, nu))
        records.append(dict(
            model=row, nu=f"{nu:g}", L=f"{args.L:g}", value=f"{value:.8f}",
            error=f"{error:.2e}", target=f"{target:g}",
            converged=int(res.get("target_accuracy_reached", 0)),
            reference=f"{ref:.5f}", diff_percent=f"{100 * (value / ref - 1):+.3f}",
            study=f"{old:.6f}" if old else "",
            diff_study=f"{value / old - 1:+.1e}" if old else "",
            dofs=int(res["n_dofs"]), members=res["members"], seconds=f"{res['seconds']:.2f}"))
        print(f"{row:7s} nu={nu:<5g} {value:.6f} +- {error:.1e} (rel, target {target:g}, "
              f"{'reached' if records[-1]['converged'] else 'NOT reached'}) ref {ref:.5f} "
              f"({records[-1]['diff_percent']}%), {int(res['n_dofs'])} DoFs, "
              f"{res['seconds']:.1f} s", flush=True)
    fields = list(records[0])
    with open(os.path.join(args.out, args.tag + ".csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        w.writerows(records)
    write_target_markdown(records, rows, nus, args, wall,
                          os.path.join(args.out, args.tag + ".md"))
    print(f"{len(cases)} cases in {wall:.1f} s wall (one --batch process); largest estimated "
          f"error {max(float(r['error']) for r in records):.1e} -> "
          f"{os.path.join(args.out, args.tag)}.csv, .md")
    return 0


def write_target_markdown(records, rows, nus, args, wall, path):
    get = {(r["model"], float(r["nu"])): r for r in records}
    out = [f"# Table 4.1 at target accuracy {args.target} (L = {args.L:g} a)", "",
           "Generated by `benchmarks/table-4-1/run.py --target "
           f"{args.target}` (tools/thesis_figures.py). theta E_s a^3 / M "
           "± its estimated relative error (Discretization/Target accuracy: "
           "rough/bonded and interface rows at the first target, smooth at the "
           "second); in brackets the thesis value (smooth: exact "
           f"3(1-nu^2)/4, half-space). {len(records)} cases in {wall:.0f} s wall, "
           "one process.", "",
           "| row | " + " | ".join(f"nu = {nu:g}" for nu in nus) + " |",
           "|---" * (len(nus) + 1) + "|"]
    for row in rows:
        cells = []
        for nu in nus:
            r = get[(row, nu)]
            mark = "" if r["converged"] else " (not reached)"
            cells.append(f"{float(r['value']):.5f} ± {float(r['error']):.1e}{mark} "
                         f"({float(r['reference']):.5f})")
        out.append(f"| {LABEL[row]} | " + " | ".join(cells) + " |")
    out += ["", "## Every case", "",
            "| row | nu | value | est. rel. error | target | reached | thesis / exact "
            "| diff % | 4-level Richardson study | rel. diff to study | DoFs | meshes "
            "| computation [s] |",
            "|---" * 13 + "|"]
    for r in records:
        out.append(f"| {r['model']} | {r['nu']} | {r['value']} | {r['error']} | {r['target']} "
                   f"| {'yes' if r['converged'] else 'no'} | {r['reference']} "
                   f"| {r['diff_percent']} | {r['study']} | {r['diff_study']} | {r['dofs']} "
                   f"| {r['members']} | {r['seconds']} |")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def write_markdown(records, rows, nus, args, path):
    get = {}
    for r in records:
        get[(r["model"], r["nu"], r["level"])] = r
    out = [f"# Table 4.1 convergence study (L = {args.L:g} a, "
           f"{args.levels} levels)", "",
           "Generated by `benchmarks/table-4-1/run.py`. theta E_s a^3 / M; "
           "levels 0.. are uniform refinements of the graded coarse mesh; "
           "'extr.' is Richardson from the last three levels with the observed "
           "order p; 'ref' is the thesis value (smooth: exact 3(1-nu^2)/4).",
           "", "## Summary: extrapolated (thesis)", "",
           "| row | " + " | ".join(f"nu = {nu:g}" for nu in nus) + " |",
           "|---" * (len(nus) + 1) + "|"]
    for row in rows:
        cells = []
        for nu in nus:
            e = get[(row, nu, "extrapolated")]
            cells.append(f"{float(e['value']):.5f} ({float(e['reference']):.5f})")
        out.append(f"| {LABEL[row]} | " + " | ".join(cells) + " |")
    out.append("")
    for row in rows:
        out += [f"## {LABEL[row]}", "",
                "| nu | " + " | ".join(f"level {c}" for c in range(args.levels))
                + " | extr. | p | ref | diff % |",
                "|---" * (args.levels + 5) + "|"]
        for nu in nus:
            lv = [get[(row, nu, c)]["value"] for c in range(args.levels)]
            e = get[(row, nu, "extrapolated")]
            out.append(f"| {nu:g} | " + " | ".join(lv) + f" | {e['value']} | "
                       f"{e['order']} | {e['reference']} | {e['diff_percent']} |")
        out.append("")
    dofs = [str(get[(rows[0], nus[0], c)]["dofs"]) for c in range(args.levels)]
    out.append(f"DoFs per level ({rows[0]}): " + ", ".join(dofs))
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    sys.exit(main())
