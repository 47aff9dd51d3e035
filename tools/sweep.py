#!/usr/bin/python3
"""Parameter sweeps of the stiffness coefficients K_H, K_M, K_MH (thesis
Hernoune 2007, chapter 4: embedded footing, Figs 4.6-4.11; chapter 6: pile,
Figs 6.2-6.7).

Usage: tools/sweep.py SWEEP_FILE [--exe PATH] [--out DIR] [--refinements N]
                      [--mpi N [--mpirun CMD]] [--dry-run]

A sweep file (prm/sweeps/*.sweep) holds lines 'set key = v1, v2, ...'
('#' starts a comment):

    set template       = prm/embedded-footing.prm   # or prm/pile.prm
    set figure family  = footing-stiffness          # CSV name: DIR/<family>.csv
    set scene          = footing                    # footing | pile (optional:
                                                    # guessed from the keys)
    set alpha          = 0, 0.5, 1                  # G(depth) exponent
    set nu             = 0.25, 0.49                 # soil Poisson ratio
    set interface      = rough, smooth
    set e/a            = 0.5, 1, 2                  # footing only
    set L/d            = 10, 25                     # pile only
    set Ep/Es          = 1000, rigid                # pile only; rigid: the
                                                    # whole pile tied as a rigid
                                                    # body (own CSV family)
    set target accuracy = rough: 1e-4, smooth: 1e-3 # or one number for all

Every combination is run: the template text is copied and override
subsections are appended (a later 'subsection X / set Y = ... / end' wins in
deal.II's ParameterHandler), so mesh, materials, interfaces and output are
replaced while everything else (boundary conditions, rigid foundation, degree)
comes from the template.

Footing (radius a = 1 m, embedment e = (e/a) a): domain radius 20 a, depth
25 e below the ground (thesis 4.2); G(depth) = G_e (depth/e)^alpha with
G_e = 1000 kPa at depth e (depth_ref = e), which is also the normalisation
G_se of K (eq. 4.2). Interface on the footing base z = -e and side r = a.

Pile (diameter d = 1 m, radius r = 0.5 m, length L = (L/d) d): domain radius
20 d, bottom L below the tip (thesis 6.2); G(depth) = G_L (depth/L)^alpha,
G_L = 1000 kPa at the tip depth = normalisation G_sL (eq. 6.1), reference
length r. Pile modulus E_p = (Ep/Es) E_s with E_s = 2 G_L (1 + nu_s) (Young's
modulus of the soil at the tip depth), nu_p = 0.25.

nu = 0.5 is replaced by 0.49 (the operator needs nu < 0.5; the thesis does the
same for its FE runs, section 6.2).

With 'target accuracy' every case is driven by Discretization/Target
accuracy (doc/accuracy-vs-time.md: the program designs its nested meshes from
the coarse base mesh and stops when the estimated relative error of K_H, K_M
and K_MH is below the target; Adaptivity/Allow unconverged = true, so a case
stopped by Adaptivity/Maximum DoFs keeps its best value with converged = 0).
The CSV then has K_H_error, K_M_error, K_MH_error (estimated relative errors)
next to each K, and 'converged'. Without it each case solves the template
coarse mesh refined --refinements times (default 1) once, and the error
columns hold the one-mesh estimate (the mesh against its coarsening by one
level; doc/accuracy-vs-time.md).

A rigid pile (Ep/Es = rigid) ties the whole pile region (material 1) to the
rigid motion (Rigid foundation/Tie = material, as the embedded footing): its
rows go to DIR/<family>-rigid.csv, the flexible ones to DIR/<family>.csv.

All cases run in one process, 'fourier-ssi --batch' (no start-up per case);
--mpi N hands them to 'mpirun -np N fourier-ssi --batch' instead (each rank
takes the next case when it is free, each solved serially: README, "MPI"). The
'seconds' column is the case's computation: the sum over its meshes of the
setup, assembly, solve and postprocess wall times from its results.csv.
One progress line per case; one CSV row per case (DIR default output/sweeps).
"""
import argparse
import csv
import itertools
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

from mesh_grading import growth_for

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
G_REF = 1000.0  # kPa, G at depth e (footing) or L (pile)
RIGID = "rigid"  # Ep/Es of a rigid pile


def parse_sweep(path):
    entries = {}
    with open(path) as f:
        for lineno, raw in enumerate(f, 1):
            line = raw.split("#", 1)[0].strip()
            if not line:
                continue
            if not line.startswith("set ") or "=" not in line:
                sys.exit(f"{path}:{lineno}: expected 'set key = v1, v2, ...'")
            key, value = line[4:].split("=", 1)
            entries[key.strip().lower()] = [v.strip() for v in value.split(",") if v.strip()]
    for key in ("template", "figure family"):
        if key not in entries or len(entries[key]) != 1:
            sys.exit(f"{path}: 'set {key} = ...' (one value) is required")
    return entries


def footing_overrides(case, designed=False):
    a = 1.0
    e = case["e/a"] * a
    depth = 25.0 * e
    if designed:
        # The coarse base mesh of the designed family (that of
        # prm/embedded-footing-graded.prm scaled with e): the program grades
        # and refines it (doc/accuracy-vs-time.md). The side cells shrink
        # toward the surface (G vanishes there for alpha > 0), the top one
        # about 0.14 a as in the recipe.
        n_side = 3 + int(round(math.log2(e / a)))
        mesh = [
            f"  set R breakpoints    = 0, {a:g}, {20 * a:g}",
            "  set R cells          = 3, 6",
            "  set R growth         = 0.64, 1.69",
            f"  set Z breakpoints    = {-depth:g}, {-e:g}, 0",
            f"  set Z cells          = 12, {n_side}",
            f"  set Z growth         = 0.8, {growth_for(n_side, e, 0.143 * a):.10g}",
            f"  set Material regions = 1: 0, {a:g}, {-e:g}, 0",
            f"  set Interface lines  = 5: z={-e:g}, r=0..{a:g}; 5: r={a:g}, z={-e:g}..0",
        ]
        return mesh, *footing_materials(case, a, e)
    # cells on the embedded side: 6 for e <= a, more for deeper footings so
    # that the side cells stay <= ~0.35 a on the coarse mesh
    n_side = max(6, int(math.ceil(e / 0.35)))
    mesh = [
        f"  set R breakpoints    = 0, {a:g}, {20 * a:g}",
        "  set R cells          = 6, 12",
        "  set R growth         = 0.8, 1.3",
        f"  set Z breakpoints    = {-depth:g}, {-e:g}, 0",
        f"  set Z cells          = 12, {n_side}",
        "  set Z growth         = 0.8, 1",
        f"  set Material regions = 1: 0, {a:g}, {-e:g}, 0",
        f"  set Interface lines  = 5: z={-e:g}, r=0..{a:g}; 5: r={a:g}, z={-e:g}..0",
    ]
    return mesh, *footing_materials(case, a, e)


def footing_materials(case, a, e):
    materials = (f"0: G={G_REF:g}, nu={case['nu']:g}, alpha={case['alpha']:g}, "
                 f"depth_ref={e:g}; 1: E=1e6, nu=0.2")
    rigid = ["  set Reference shear modulus = %g" % G_REF, f"  set Reference length = {a:g}"]
    return materials, rigid


def pile_overrides(case, designed=False):
    d = 1.0
    r = 0.5 * d
    L = case["L/d"] * d
    # shaft: cells shrink toward the head, top cell 0.25 d on the coarse mesh
    n_shaft = 16 if L <= 10 else int(round(16 + 6 * math.log2(L / 10.0)))
    g_shaft = growth_for(n_shaft, L, 0.25 * d)
    # below the tip: 10 cells shrinking toward the tip, last one ~0.5 d
    g_tip = growth_for(10, L, 0.5 * d) if L > 5 * d else 1.0
    mesh = [
        f"  set R breakpoints        = 0, {r:g}, {20 * d:g}",
        "  set R cells              = 3, 14",
        "  set R growth             = 0.8, 1.3",
        f"  set Z breakpoints        = {-2 * L:g}, {-L:g}, 0",
        f"  set Z cells              = 10, {n_shaft}",
        f"  set Z growth             = {g_tip:.10g}, {g_shaft:.10g}",
        f"  set Surface patch radius = {r:g}",
        f"  set Material regions     = 1: 0, {r:g}, {-L:g}, 0",
        f"  set Interface lines      = 5: r={r:g}, z={-L:g}..0; 5: z={-L:g}, r=0..{r:g}",
    ]
    E_s = 2.0 * G_REF * (1.0 + case["nu"])
    rigid = ["  set Reference shear modulus = %g" % G_REF, f"  set Reference length = {r:g}"]
    if case["Ep/Es"] == RIGID:
        # The whole pile is one rigid body (as the embedded footing): its
        # material only fills the matrix pattern.
        E_p = 1000.0 * E_s
        rigid += ["  set Tie = material", "  set Id = 1", "  set Reference elevation = 0"]
    else:
        E_p = case["Ep/Es"] * E_s
    materials = (f"0: G={G_REF:g}, nu={case['nu']:g}, alpha={case['alpha']:g}, "
                 f"depth_ref={L:g}; 1: E={E_p:.8g}, nu=0.25")
    return mesh, materials, rigid


def prm_text(template_text, scene, case, refinements, directory, target=None):
    overrides = footing_overrides if scene == "footing" else pile_overrides
    mesh, materials, rigid = overrides(case, designed=target is not None)
    if target is None:
        discretization = ["  set Refinement cycles = 1"]
        mesh += [f"  set Global refinements = {refinements}"]
        adaptivity = []
    else:
        # The design walks its own meshes: one cycle each (the template's
        # Refinement cycles would be refused with a target).
        discretization = ["  set Refinement cycles = 1", f"  set Target accuracy = {target:g}"]
        adaptivity = ["subsection Adaptivity", "  set Allow unconverged = true", "end"]
    lines = [
        "", "# ---- overrides written by tools/sweep.py ----",
        "subsection Discretization", *discretization, "end",
        "subsection Mesh", *mesh, "end", *adaptivity,
        "subsection Materials", f"  set Materials = {materials}", "end",
        "subsection Interfaces", f"  set Interfaces = 5: {case['interface']}", "end",
        "subsection Rigid foundation", "  set Stiffness coefficients = true", *rigid, "end",
        "subsection Output", f"  set Directory = {directory}", "  set Results file = results.csv",
        "  set Write vtu = false", "  set Write interface tractions = false", "end",
    ]
    return template_text.rstrip("\n") + "\n" + "\n".join(lines) + "\n"


def read_results(path):
    """The last cycle's rows, and the computation summed over every cycle."""
    last = {}
    with open(path) as f:
        rows = list(csv.DictReader(f))
    cycle = max(int(r["cycle"]) for r in rows)
    for r in rows:
        if int(r["cycle"]) == cycle:
            last[r["quantity"]] = float(r["value"])
    last["seconds"] = sum(float(r["value"]) for r in rows if r["quantity"] in
                          ("time_setup", "time_assembly", "time_interface_assembly",
                           "time_solve", "time_postprocess"))
    return last


def parse_targets(raw, path):
    """'1e-4' (every interface) or 'rough: 1e-4, smooth: 1e-3'."""
    targets = {}
    for item in raw:
        key, _, value = item.rpartition(":")
        key = key.strip() or "*"
        try:
            targets[key] = float(value)
        except ValueError:
            sys.exit(f"{path}: target accuracy: '{item}' is not 'interface: value' or a number")
        if not 0. < targets[key] < 1.:
            sys.exit(f"{path}: target accuracy: '{item}' is not between 0 and 1")
    return targets


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("sweep")
    ap.add_argument("--exe", default=os.path.join(ROOT, "build/fourier-ssi"))
    ap.add_argument("--out", default=os.path.join(ROOT, "output/sweeps"))
    ap.add_argument("--refinements", type=int, default=1,
                    help="global refinements of each case (without 'target accuracy')")
    ap.add_argument("--mpi", type=int, default=0, metavar="N",
                    help="run all cases in one 'mpirun -np N fourier-ssi --batch' call")
    ap.add_argument("--mpirun", default="mpirun",
                    help="MPI launcher and its options for --mpi (e.g. 'mpirun --oversubscribe')")
    ap.add_argument("--dry-run", action="store_true", help="print the first case's .prm and stop")
    args = ap.parse_args()

    sw = parse_sweep(args.sweep)
    template = sw["template"][0]
    if not os.path.isabs(template) and not os.path.exists(template):
        template = os.path.join(ROOT, template)
    with open(template) as f:
        template_text = f.read()
    family = sw["figure family"][0]
    scene = sw.get("scene", [None])[0] or ("pile" if "l/d" in sw else "footing")
    if scene not in ("footing", "pile"):
        sys.exit(f"{args.sweep}: scene must be footing or pile")
    targets = parse_targets(sw["target accuracy"], args.sweep) if "target accuracy" in sw else None
    geo = ["e/a"] if scene == "footing" else ["L/d", "Ep/Es"]
    keys = ["interface", "nu"] + geo + ["alpha"]
    defaults = {"interface": ["rough"], "nu": ["0.25"], "alpha": ["0"], "e/a": ["1"],
                "L/d": ["10"], "Ep/Es": ["1000"]}
    values = {}
    for k in keys:
        raw = sw.get(k.lower(), defaults[k])
        if k == "interface":
            for v in raw:
                if v not in ("rough", "smooth"):
                    sys.exit(f"{args.sweep}: interface must be rough or smooth, not '{v}'")
            values[k] = raw
        elif k == "Ep/Es":
            try:
                values[k] = [RIGID if v.lower() == RIGID else float(v) for v in raw]
            except ValueError:
                sys.exit(f"{args.sweep}: Ep/Es must be numbers or 'rigid'")
        else:
            vals = [float(v) for v in raw]
            if k == "nu":
                if any(v >= 0.5 for v in vals):
                    print("note: nu = 0.5 replaced by 0.49 (the operator needs nu < 0.5)")
                vals = [0.49 if v >= 0.5 else v for v in vals]
            values[k] = vals
    unknown = (set(sw) - {"template", "figure family", "scene", "target accuracy"}
               - {k.lower() for k in keys})
    if unknown:
        sys.exit(f"{args.sweep}: unknown or not applicable entries for the {scene}: "
                 + ", ".join(sorted(unknown)))
    if targets is not None:
        for interface in values["interface"]:
            if interface not in targets and "*" not in targets:
                sys.exit(f"{args.sweep}: target accuracy: no value for the {interface} interface")

    def target_of(case):
        if targets is None:
            return None
        return targets.get(case["interface"], targets.get("*"))

    cases = [dict(zip(keys, combo)) for combo in itertools.product(*(values[k] for k in keys))]
    col = {"e/a": "e_over_a", "L/d": "L_over_d", "Ep/Es": "Ep_over_Es"}
    fields = ([col.get(k, k) for k in keys] +
              ["K_H", "K_H_error", "K_M", "K_M_error", "K_MH", "K_MH_error", "converged",
               "target", "I_H", "I_M", "I_MH", "I_MH_asym", "dofs", "seconds"])
    os.makedirs(args.out, exist_ok=True)
    work = tempfile.mkdtemp(prefix="sweep-")

    def paths(i):
        out = os.path.join(work, f"case{i}")
        return out, out + ".prm"

    for i, case in enumerate(cases, 1):
        out, prm = paths(i)
        with open(prm, "w") as f:
            f.write(prm_text(template_text, scene, case, args.refinements, out, target_of(case)))
    if args.dry_run:
        print(open(paths(1)[1]).read())
        shutil.rmtree(work)
        return 0

    # Every case in one process (or one MPI job): the executable runs them
    # one after the other, without a start-up per case.
    t_all = time.time()
    cmd = [args.exe, "--batch", "--csv", os.path.join(work, "batch.csv")]
    if args.mpi > 0:
        cmd = args.mpirun.split() + ["-np", str(args.mpi)] + cmd
    with open(os.path.join(work, "cases.txt"), "w") as f:
        f.write("\n".join(paths(i)[1] for i in range(1, len(cases) + 1)) + "\n")
    p = subprocess.run(cmd + [os.path.join(work, "cases.txt")], stdout=subprocess.DEVNULL,
                       stderr=subprocess.PIPE, text=True)
    wall = time.time() - t_all
    batch_failed = p.stderr.strip() if p.returncode != 0 else None

    # Rigid piles in their own family: a rigid pile is another body, not a
    # point of the flexible curves.
    files = {}
    for name in sorted({family + ("-rigid" if case.get("Ep/Es") == RIGID else "")
                        for case in cases}):
        f = open(os.path.join(args.out, name + ".csv"), "w", newline="")
        files[name] = (f, csv.DictWriter(f, fieldnames=fields))
        files[name][1].writeheader()
    worst = 0.
    for i, case in enumerate(cases, 1):
        out, prm = paths(i)
        label = " ".join(f"{k}={case[k]:g}" if k != "Ep/Es" or case[k] != RIGID else f"{k}=rigid"
                         for k in keys[1:]) + f" {case['interface']}"
        if not os.path.exists(os.path.join(out, "results.csv")):
            sys.exit(f"case {i}/{len(cases)}: {label}: failed ({batch_failed}); "
                     f"prm kept in {prm}")
        res = read_results(os.path.join(out, "results.csv"))
        i_mh = 0.5 * (res["I_MH_from_H"] + res["I_MH_from_M"])
        asym = abs(res["I_MH_from_H"] - res["I_MH_from_M"]) / max(abs(i_mh), 1e-300)
        row = {col.get(k, k): case[k] if isinstance(case[k], str) else f"{case[k]:g}"
               for k in keys}
        row.update(K_H=f"{res['K_H']:.8g}", K_M=f"{res['K_M']:.8g}", K_MH=f"{res['K_MH']:.8g}",
                   I_H=f"{res['I_H']:.8g}", I_M=f"{res['I_M']:.8g}", I_MH=f"{i_mh:.8g}",
                   I_MH_asym=f"{asym:.2e}", dofs=int(res["n_dofs"]),
                   seconds=f"{res['seconds']:.2f}")
        for q in ("K_H", "K_M", "K_MH"):
            e = res.get(q + "_error", float("nan"))
            row[q + "_error"] = f"{e:.2e}"
            if e == e:
                worst = max(worst, e)
        target = target_of(case)
        row["target"] = f"{target:g}" if target else ""
        row["converged"] = int(res.get("target_accuracy_reached", 0)) if target else ""
        name = family + ("-rigid" if case.get("Ep/Es") == RIGID else "")
        files[name][1].writerow(row)
        print(f"case {i}/{len(cases)}: {label}: K_H={res['K_H']:.6g} K_M={res['K_M']:.6g} "
              f"K_MH={res['K_MH']:.6g} (largest error {max(res.get(q + '_error', 0.) for q in ('K_H', 'K_M', 'K_MH')):.1e}, "
              f"{res['dofs'] if 'dofs' in res else int(res['n_dofs'])} DoFs, {res['seconds']:.2f} s)",
              flush=True)
    for f, _ in files.values():
        f.close()
    if batch_failed is not None:
        sys.exit(f"fourier-ssi --batch failed: {batch_failed}")
    shutil.rmtree(work, ignore_errors=True)
    print(f"{len(cases)} cases in {wall:.1f} s wall (one --batch process"
          f"{'' if args.mpi <= 0 else f' on {args.mpi} ranks'}); largest estimated error "
          f"{worst:.1e} -> " + ", ".join(os.path.join(args.out, n + ".csv") for n in files))
    return 0


if __name__ == "__main__":
    sys.exit(main())
