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
    set Ep/Es          = 1000                       # pile only

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

Each case solves the template coarse mesh refined --refinements times (default
1) once (Refinement cycles = 1). One progress line per case; one CSV row per
case in DIR/<family>.csv (DIR default output/sweeps).

--mpi N writes every case's .prm first and hands them all to one
'mpirun -np N fourier-ssi --batch' call (cases dealt round-robin to the
ranks, each solved serially: README, "MPI"); the CSV is the same, except the
'seconds' column, which then holds the case's setup + assembly + solve wall
time from its results.csv instead of the whole process time.
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

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
G_REF = 1000.0  # kPa, G at depth e (footing) or L (pile)


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


def growth_for(n, length, h_end):
    """Ratio g of n geometric cells summing to 'length' whose LAST cell is
    h_end (g < 1 shrinks toward the segment end)."""
    if abs(n * h_end - length) < 1e-12:
        return 1.0

    def total(g):
        return sum(h_end / g ** (n - 1 - i) for i in range(n))

    lo, hi = (1e-3, 1.0) if n * h_end < length else (1.0, 1e3)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if (total(mid) > length) == (n * h_end < length):
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def footing_overrides(case):
    a = 1.0
    e = case["e/a"] * a
    depth = 25.0 * e
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
    materials = (f"0: G={G_REF:g}, nu={case['nu']:g}, alpha={case['alpha']:g}, "
                 f"depth_ref={e:g}; 1: E=1e6, nu=0.2")
    rigid = ["  set Reference shear modulus = %g" % G_REF, f"  set Reference length = {a:g}"]
    return mesh, materials, rigid


def pile_overrides(case):
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
    E_p = case["Ep/Es"] * E_s
    materials = (f"0: G={G_REF:g}, nu={case['nu']:g}, alpha={case['alpha']:g}, "
                 f"depth_ref={L:g}; 1: E={E_p:.8g}, nu=0.25")
    rigid = ["  set Reference shear modulus = %g" % G_REF, f"  set Reference length = {r:g}"]
    return mesh, materials, rigid


def prm_text(template_text, scene, case, refinements, directory):
    mesh, materials, rigid = (footing_overrides if scene == "footing" else pile_overrides)(case)
    lines = [
        "", "# ---- overrides written by tools/sweep.py ----",
        "subsection Discretization", "  set Refinement cycles = 1", "end",
        "subsection Mesh", *mesh, f"  set Global refinements = {refinements}", "end",
        "subsection Materials", f"  set Materials = {materials}", "end",
        "subsection Interfaces", f"  set Interfaces = 5: {case['interface']}", "end",
        "subsection Rigid foundation", "  set Stiffness coefficients = true", *rigid, "end",
        "subsection Output", f"  set Directory = {directory}", "  set Results file = results.csv",
        "  set Write vtu = false", "end",
    ]
    return template_text.rstrip("\n") + "\n" + "\n".join(lines) + "\n"


def read_results(path):
    last = {}
    with open(path) as f:
        rows = list(csv.DictReader(f))
    cycle = max(int(r["cycle"]) for r in rows)
    for r in rows:
        if int(r["cycle"]) == cycle:
            last[r["quantity"]] = float(r["value"])
    return last


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("sweep")
    ap.add_argument("--exe", default=os.path.join(ROOT, "build/fourier-ssi"))
    ap.add_argument("--out", default=os.path.join(ROOT, "output/sweeps"))
    ap.add_argument("--refinements", type=int, default=1)
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
        else:
            vals = [float(v) for v in raw]
            if k == "nu":
                if any(v >= 0.5 for v in vals):
                    print("note: nu = 0.5 replaced by 0.49 (the operator needs nu < 0.5)")
                vals = [0.49 if v >= 0.5 else v for v in vals]
            values[k] = vals
    unknown = set(sw) - {"template", "figure family", "scene"} - {k.lower() for k in keys}
    if unknown:
        sys.exit(f"{args.sweep}: unknown or not applicable entries for the {scene}: "
                 + ", ".join(sorted(unknown)))

    cases = [dict(zip(keys, combo)) for combo in itertools.product(*(values[k] for k in keys))]
    col = {"e/a": "e_over_a", "L/d": "L_over_d", "Ep/Es": "Ep_over_Es"}
    fields = [col.get(k, k) for k in keys] + ["K_H", "K_M", "K_MH", "I_H", "I_M", "I_MH",
                                             "I_MH_asym", "dofs", "seconds"]
    os.makedirs(args.out, exist_ok=True)
    csv_path = os.path.join(args.out, family + ".csv")
    work = tempfile.mkdtemp(prefix="sweep-")
    if args.dry_run:
        print(prm_text(template_text, scene, cases[0], args.refinements, os.path.join(work, "c")))
        shutil.rmtree(work)
        return 0
    t_all = time.time()

    def label_of(case):
        return " ".join(f"{k}={case[k]:g}" for k in keys[1:]) + f" {case['interface']}"

    def paths(i):
        out = os.path.join(work, f"case{i}")
        return out, out + ".prm"

    batch_failed = None
    if args.mpi > 0:
        # All cases in one MPI job: the executable deals them to the ranks.
        for i, case in enumerate(cases, 1):
            out, prm = paths(i)
            with open(prm, "w") as f:
                f.write(prm_text(template_text, scene, case, args.refinements, out))
        cmd = args.mpirun.split() + ["-np", str(args.mpi), args.exe, "--batch",
                                     "--csv", os.path.join(work, "batch.csv")]
        cmd += [paths(i)[1] for i in range(1, len(cases) + 1)]
        p = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        if p.returncode != 0:
            batch_failed = p.stderr.strip()
    with open(csv_path, "w", newline="") as fcsv:
        w = csv.DictWriter(fcsv, fieldnames=fields)
        w.writeheader()
        for i, case in enumerate(cases, 1):
            out, prm = paths(i)
            label = label_of(case)
            if args.mpi > 0:
                if not os.path.exists(os.path.join(out, "results.csv")):
                    sys.exit(f"case {i}/{len(cases)}: {label}: failed ({batch_failed}); "
                             f"prm kept in {prm}")
                res = read_results(os.path.join(out, "results.csv"))
                dt = sum(res.get(t, 0.0) for t in ("time_setup", "time_assembly", "time_solve"))
            else:
                with open(prm, "w") as f:
                    f.write(prm_text(template_text, scene, case, args.refinements, out))
                t0 = time.time()
                p = subprocess.run([args.exe, prm], stdout=subprocess.DEVNULL,
                                   stderr=subprocess.PIPE, text=True)
                dt = time.time() - t0
                if p.returncode != 0:
                    sys.exit(f"case {i}/{len(cases)}: {label}: failed ({p.stderr.strip()}); prm kept in {prm}")
                res = read_results(os.path.join(out, "results.csv"))
            i_mh = 0.5 * (res["I_MH_from_H"] + res["I_MH_from_M"])
            asym = abs(res["I_MH_from_H"] - res["I_MH_from_M"]) / max(abs(i_mh), 1e-300)
            row = {col.get(k, k): case[k] for k in keys}
            row.update(K_H=f"{res['K_H']:.6g}", K_M=f"{res['K_M']:.6g}", K_MH=f"{res['K_MH']:.6g}",
                       I_H=f"{res['I_H']:.6g}", I_M=f"{res['I_M']:.6g}", I_MH=f"{i_mh:.6g}",
                       I_MH_asym=f"{asym:.2e}", dofs=int(res["n_dofs"]), seconds=f"{dt:.2f}")
            w.writerow(row)
            fcsv.flush()
            print(f"case {i}/{len(cases)}: {label}: K_H={res['K_H']:.4g} K_M={res['K_M']:.4g} "
                  f"K_MH={res['K_MH']:.4g} ({dt:.1f} s)", flush=True)
            shutil.rmtree(out, ignore_errors=True)
            os.remove(prm)
    if batch_failed is not None:
        sys.exit(f"mpirun --batch failed: {batch_failed}")
    shutil.rmtree(work, ignore_errors=True)
    print(f"{len(cases)} cases in {time.time() - t_all:.0f} s -> {csv_path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
