#!/usr/bin/python3
"""Table 7.1 of Hernoune (2007), section 7.7, regenerated with error bars:
the displacements of the nodes of one interface element around the rigid
disc displaced in an elastic ring (prm/disc-rough.prm, prm/disc-smooth.prm;
doc/disc.md), for the 10-node interface (FE_Q(4) soil) and the 6-node one
(FE_Q(2) soil).

Usage: tools/table_7_1.py [--exe build/fourier-ssi] [--out doc/figures]
                          [--target ROUGH,SMOOTH]

Cases, all in one 'fourier-ssi --batch' process:
  10-node: the scene driven by Discretization/Target accuracy (default 1e-4
           rough, 1e-3 smooth; the design is FE_Q(4), whose interface
           faces carry 5 + 5 nodes);
  6-node:  the scene as shipped (FE_Q(2), 3 + 3 nodes per face) with
           Refinement cycles = 4 (the design is FE_Q(4) only): the
           program's estimate from the nested cycles.
The disc side (nodes 1..p+1, the thesis's numbering) is rigid: its
amplitudes are u = U_h, w = -U_h (u = U_h cos t, w = -U_h sin t, thesis
eq. 5.1), with the estimated error of U_h. The soil side (nodes p+2..2p+2)
adds the relative displacement of the interface CSV (soil - disc, normal
+r; doc/interfaces-usage.md); its error bar adds the geometric tail of that
jump over the nested meshes (the program's rule, doc/accuracy-vs-time.md
eq. (1), ratio assumed 0.5 with two meshes, 0.65 for cycles of one halving)
to the error of U_h. Every node of the longest face is listed; the solution does
not depend on z (plane strain by a one-element slice, doc/disc.md), so any
face of the line gives the same values.

Reference: the closed form of doc/disc.md for a perfectly bonded rough disc
and a frictionless smooth one, with the shipped H = P(ubar = 1e-3 m): the
soil at r = a moves U = 1e-3 m, W = -1e-3 m (rough), W = -0.7477972e-3 m
(smooth). The interface compliance (kn = ks = 1e10) lets the disc move
|t|/k = 4.5e-9 m further: 4.5e-6 relative.

Writes OUT/table-7-1.csv and OUT/table-7-1.md. Prints the wall time.
"""
import argparse
import csv
import glob
import os
import shutil
import subprocess
import sys
import tempfile

from batch_runs import read_last_cycle, run_batch
import time

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
UBAR = 1e-3  # m, the imposed amplitude the shipped H corresponds to
EXACT_W = {"rough": -1e-3, "smooth": -0.7477972e-3}  # m, soil at r = a
THESIS = {  # Tableau 7.1, rough: u [m] by node number
    6: [1.000000000261800e-3, 1.000000000291604e-3, 1.000000000248340e-3,
        1.232230152903422e-3, 1.164555480097815e-3, 9.690321913891948e-4],
    10: [1.000000000548005e-3, 1.000000001082410e-3, 1.000000000804579e-3,
         1.000000000243567e-3, 9.99999999888026e-4, 1.17276054613e-3,
         9.958745786550623e-4, 9.893323652443262e-4, 9.846397454226858e-4,
         9.78202314148117e-4],
}


def tail(values, assumed):
    """Estimated error of the last value (doc/accuracy-vs-time.md, eq. 1)."""
    if len(values) < 2:
        return float("nan")
    d = [b - a for a, b in zip(values, values[1:])]
    r = assumed
    if len(d) >= 2 and d[-2] != 0 and 0 < d[-1] / d[-2] < 1:
        r = max(0.25, d[-1] / d[-2])
    return abs(d[-1]) * r / (1 - r)


def case_prm(interface, nodes, target, out):
    with open(os.path.join(ROOT, f"prm/disc-{interface}.prm")) as f:
        text = f.read()
    if nodes == 10:
        disc = f"  set Target accuracy = {target:g}"
    else:
        disc = "  set Refinement cycles = 4"
    return (text.rstrip("\n") + "\n\n# ---- overrides written by tools/table_7_1.py ----\n"
            f"subsection Discretization\n{disc}\nend\n"
            "subsection Output\n"
            f"  set Directory = {out}\n  set Write vtu = false\n"
            "  set Write interface tractions = true\nend\n")


def read_case(out, assumed):
    res = read_last_cycle(os.path.join(out, "results.csv"))
    res["meshes"] = res["members"]
    last = res["members"] - 1
    faces = []  # the longest face of every cycle: [(z, d_n, d_theta)], top first
    for c in range(last + 1):
        path = glob.glob(os.path.join(out, f"interface-5-n1-symmetric-cycle{c}.csv"))[0]
        by_face = {}
        with open(path) as f:
            for r in csv.DictReader(f):
                by_face.setdefault(r["face"], []).append(
                    (float(r["z"]), float(r["relative_n"]), float(r["relative_theta"])))
        # the longest face (the design grades toward the slice's top and
        # bottom, where its faces are tiny), the upper one of equals
        longest = max(by_face.values(), key=lambda nodes: (
            round(max(q[0] for q in nodes) - min(q[0] for q in nodes), 9),
            max(q[0] for q in nodes)))
        faces.append(sorted(longest, key=lambda q: -q[0]))
    return res, faces


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--exe", default=os.path.join(ROOT, "build/fourier-ssi"))
    ap.add_argument("--out", default=os.path.join(ROOT, "doc/figures"))
    ap.add_argument("--target", default="1e-4,1e-3", metavar="ROUGH,SMOOTH")
    args = ap.parse_args()
    try:
        rough, smooth = (float(x) for x in args.target.split(","))
    except ValueError:
        sys.exit(f"--target: '{args.target}' is not ROUGH,SMOOTH (e.g. 1e-4,1e-3)")
    targets = {"rough": rough, "smooth": smooth}
    work = tempfile.mkdtemp(prefix="table71-")
    cases = [(i, n) for i in ("rough", "smooth") for n in (10, 6)]
    for interface, nodes in cases:
        out = os.path.join(work, f"{interface}-{nodes}")
        with open(out + ".prm", "w") as f:
            f.write(case_prm(interface, nodes, targets[interface], out))
    wall = run_batch(args.exe, work,
                     [os.path.join(work, f"{i}-{n}.prm") for i, n in cases])

    records, summary = [], []
    for interface, nodes in cases:
        assumed = 0.5 if nodes == 10 else 0.65
        res, faces = read_case(os.path.join(work, f"{interface}-{nodes}"), assumed)
        u_h = res["foundation_horizontal_displacement"]
        e_u = res["foundation_horizontal_displacement_error"] * abs(u_h)
        last = faces[-1]
        summary.append((interface, nodes, res, e_u))
        for side in ("disc", "soil"):
            for k, (z, d_n, d_t) in enumerate(last):
                number = k + 1 + (len(last) if side == "soil" else 0)
                if side == "disc":
                    u, w, eu, ew = u_h, -u_h, e_u, e_u
                else:
                    # the jump at the nearest node of each earlier mesh
                    hist = [min(face, key=lambda q: abs(q[0] - z)) for face in faces]
                    u = u_h + d_n
                    w = -u_h + d_t
                    eu = e_u + tail([q[1] for q in hist], assumed)
                    ew = e_u + tail([q[2] for q in hist], assumed)
                thesis = THESIS[nodes][number - 1] if interface == "rough" else None
                records.append(dict(
                    interface=interface, element=f"{nodes}-node", node=number, side=side,
                    z=f"{z:g}", u=f"{u:.10e}", u_error=f"{eu:.1e}", w=f"{w:.10e}",
                    w_error=f"{ew:.1e}",
                    exact_soil_u=f"{UBAR:.7e}", exact_soil_w=f"{EXACT_W[interface]:.7e}",
                    thesis_u=f"{thesis:.10e}" if thesis else "",
                    dofs=int(res["n_dofs"]), meshes=res["meshes"],
                    converged=int(res.get("target_accuracy_reached", 1))))
    with open(os.path.join(args.out, "table-7-1.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(records[0]))
        w.writeheader()
        w.writerows(records)
    write_markdown(records, summary, targets, wall, os.path.join(args.out, "table-7-1.md"))
    shutil.rmtree(work, ignore_errors=True)
    for interface, nodes, res, e_u in summary:
        print(f"{interface} {nodes}-node: U_h = {res['foundation_horizontal_displacement']:.10e} m "
              f"+- {e_u:.1e} m, {int(res['n_dofs'])} DoFs, {res['meshes']} meshes, "
              f"{res['seconds']:.2f} s")
    print(f"table 7.1: {len(cases)} cases in {wall:.1f} s wall (one --batch process) -> "
          f"{os.path.join(args.out, 'table-7-1')}.csv, .md")
    return 0


def write_markdown(records, summary, targets, wall, path):
    out = ["# Table 7.1 with error bars (disc displaced in an elastic ring)", "",
           "Generated by `tools/table_7_1.py` (tools/thesis_figures.py). Amplitudes of "
           "the nodal displacements of one interface element, u = U cos t and "
           "w = W sin t [m], disc side (nodes 1..p+1) and soil side (p+2..2p+2), "
           "each with its estimated absolute error. 10-node: FE_Q(4) designed by "
           f"Discretization/Target accuracy ({targets['rough']:g} rough, "
           f"{targets['smooth']:g} smooth); 6-node: FE_Q(2) as shipped, 4 nested "
           "cycles. Exact (perfect bond / frictionless, doc/disc.md): soil at r = a "
           "U = 1e-3 m, W = -1e-3 m (rough), -0.7477972e-3 m (smooth); the disc "
           f"moves |t|/k = 4.5e-9 m further. {len(summary)} cases in {wall:.1f} s "
           "wall, one process.", ""]
    for interface in ("rough", "smooth"):
        for nodes in (10, 6):
            rows = [r for r in records if r["interface"] == interface
                    and r["element"] == f"{nodes}-node"]
            res = next(s[2] for s in summary if s[0] == interface and s[1] == nodes)
            out += [f"## {interface}, {nodes}-node interface ({int(res['n_dofs'])} DoFs, "
                    f"{res['meshes']} meshes)", "",
                    "| node | side | z [m] | u [m] | ± | w [m] | ± | thesis u [m] |",
                    "|---|---|---|---|---|---|---|---|"]
            for r in rows:
                out.append(f"| {r['node']} | {r['side']} | {r['z']} | {float(r['u']):.10e} "
                           f"| {r['u_error']} | {float(r['w']):.10e} | {r['w_error']} "
                           f"| {float(r['thesis_u']):.10e} |" if r["thesis_u"] else
                           f"| {r['node']} | {r['side']} | {r['z']} | {float(r['u']):.10e} "
                           f"| {r['u_error']} | {float(r['w']):.10e} | {r['w_error']} | – |")
            out.append("")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    sys.exit(main())
