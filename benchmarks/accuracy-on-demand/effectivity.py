#!/usr/bin/env python3
"""Effectivity of the error estimate of Discretization/Target accuracy.

Each case runs once, driven only by a target far below reach, so the
program walks its designed family of nested meshes (member 0, 1, 2, ...)
until Adaptivity/Maximum DoFs stops it. From the rows of results.csv (one
cycle per member) this script forms, for every member k >= 1, the estimate
the program prints for a run that stops at k: eq. (1) of
include/fourier_ssi/sequence_error_estimate.h on the values of members
0..k. The reference is the finest member; its own estimate is its
uncertainty, and a member enters the table only where its true error
|Q_k - Q_ref| / |Q_ref| is at least 2x that uncertainty; the effectivity
is given with the range that uncertainty allows.

    effectivity = estimated relative error / true relative error

Reliability asks effectivity >= 0.8 (at most 20 % under-reported), and
sharpness <= 5.

Usage: effectivity.py --exe build/fourier-ssi [--cases a,b] [--out DIR]
       effectivity.py --rescore [--out DIR]
Writes effectivity.csv and effectivity.md in DIR (default: this folder).
--rescore re-forms the estimates of the committed effectivity.csv with the
present ratios, without running anything: eq. (1) is |d_k| times
r / (1 - r), and |d_k| follows from each row's estimate and ratio, so a
changed assumed ratio rescales the rows where it was used (asymptotic
False); the observed-ratio rows are unchanged. It also gives the member
0 -> 1 error ratio rho = e_1 / e_0 = e_1 / (e_1 + |d_1|) of each member-1
row (the errors fall monotonically on every case).
"""
import argparse
import csv
import os
import pathlib
import subprocess
import sys
import time

HERE = pathlib.Path(__file__).resolve().parent
MINIMUM_RATIO, SLOW_RATIO = 0.25, 0.4  # sequence_error_estimate.h (design members)


def tail(r):
    """The factor r / (1 - r) of eq. (1)."""
    return r / (1. - r)


def estimate(values):
    """Eq. (1): geometric tail of the last difference."""
    k = len(values) - 1
    d = values[k] - values[k - 1]
    r, asymptotic = SLOW_RATIO, False
    if k >= 2 and values[k - 1] != values[k - 2]:
        q = d / (values[k - 1] - values[k - 2])
        if 0. < q < 1.:
            r, asymptotic = max(q, MINIMUM_RATIO), True
    return abs(d) * r / (1. - r) / abs(values[k]), r, asymptotic


def footing(interface, nu, alpha):
    return f"""
subsection Discretization
  set Harmonics = 1
end
subsection Mesh
  set R breakpoints    = 0, 1, 20
  set R cells          = 3, 6
  set R growth         = 0.64, 1.69
  set Z breakpoints    = -25, -1, 0
  set Z cells          = 12, 3
  set Z growth         = 0.8, 0.5
  set Material regions = 1: 0, 1, -1, 0
  set Interface lines  = 5: z=-1, r=0..1; 5: r=1, z=-1..0
end
subsection Materials
  set Materials = 0: G=1000, nu={nu}, alpha={alpha}, depth_ref=1; 1: E=1e6, nu=0.2
end
subsection Interfaces
  set Interfaces = 5: {interface}
end
subsection Boundary conditions
  set Dirichlet = 1: u=0, v=0, w=0; 2: u=0, v=0, w=0
end
subsection Rigid foundation
  set Enabled                 = true
  set Tie                     = material
  set Id                      = 1
  set Reference elevation     = 0
  set Stiffness coefficients  = true
  set Reference shear modulus = 1000
  set Reference length        = 1
end
"""


def pile(interface, nu, alpha):
    # prm/pile.prm (L/d = 10, Ep = 1000 Es) on its base mesh: the design
    # adds the global refinements itself.
    text = (HERE.parent.parent / "prm" / "pile.prm").read_text()
    return text + f"""
subsection Discretization
  set Polynomial degree = 4
end
subsection Mesh
  set Global refinements = 0
end
subsection Materials
  set Materials = 0: G=1000, nu={nu}, alpha={alpha}, depth_ref=10; 1: G=1e6, nu=0.25
end
subsection Interfaces
  set Interfaces = 5: {interface}
end
"""


CASES = {
    "footing-a0.5-nu0.25-rough": (footing, "rough", 0.25, 0.5, 6e5),
    "footing-a0-nu0.25-rough": (footing, "rough", 0.25, 0, 6e5),
    "footing-a1-nu0.25-rough": (footing, "rough", 0.25, 1, 6e5),
    "footing-a0.5-nu0.49-rough": (footing, "rough", 0.49, 0.5, 6e5),
    "footing-a0-nu0.25-smooth": (footing, "smooth", 0.25, 0, 6e5),
    "footing-a1-nu0.25-smooth": (footing, "smooth", 0.25, 1, 6e5),
    "footing-a0.5-nu0.25-smooth": (footing, "smooth", 0.25, 0.5, 6e5),
    "pile-a1-nu0.25-rough": (pile, "rough", 0.25, 1, 6e5),
}


def run_case(exe, name, out):
    scene, interface, nu, alpha, max_dofs = CASES[name]
    work = out / "runs" / name
    work.mkdir(parents=True, exist_ok=True)
    prm = scene(interface, nu, alpha) + f"""
subsection Discretization
  set Target accuracy = 1e-9
end
subsection Adaptivity
  set Maximum DoFs = {max_dofs:g}
  set Allow unconverged = true
end
subsection Output
  set Directory = {work / 'out'}
  set Write vtu = false
  set Write stresses = false
  set Write interface tractions = false
end
"""
    (work / "case.prm").write_text(prm)
    start = time.time()
    result = subprocess.run([exe, str(work / "case.prm")], capture_output=True,
                            text=True)
    (work / "log.txt").write_text(result.stdout + result.stderr)
    if result.returncode != 0:
        sys.exit(f"{name}: run failed\n{result.stderr}")
    rows = list(csv.DictReader(open(work / "out" / "results.csv")))
    return rows, time.time() - start


def table(name, rows):
    series = {}
    for r in rows:
        if r["n"] == "1" and r["family"] == "symmetric":
            series.setdefault(r["quantity"], {})[int(r["cycle"])] = float(
                r["value"])
    lines = []
    for q in ("K_H", "K_M", "K_MH"):
        members = [series[q][k] for k in sorted(series[q])]
        dofs = [series["n_dofs"][k] for k in sorted(series[q])]
        ref = members[-1]
        uncertainty = estimate(members)[0]
        for k in range(1, len(members) - 1):
            est, r, asymptotic = estimate(members[:k + 1])
            error = abs(members[k] - ref) / abs(ref)
            if error < 2 * uncertainty:
                continue
            lines.append(dict(case=name, quantity=q, member=k,
                              dofs=int(dofs[k]), value=members[k],
                              reference=ref,
                              reference_uncertainty=uncertainty,
                              true_error=error, estimate=est, ratio=r,
                              asymptotic=asymptotic,
                              effectivity=est / error,
                              effectivity_low=est / (error + uncertainty),
                              effectivity_high=est / (error - uncertainty),
                              member_ratio=(abs(members[1] - ref) /
                                            abs(members[0] - ref)
                                            if k == 1 else "")))
    return lines


def rescore(path):
    """The rows of a committed effectivity.csv with the present ratios."""
    lines = []
    for row in csv.DictReader(open(path)):
        l = {k: (v if k in ("case", "quantity") else
                 v == "True" if k == "asymptotic" else float(v))
             for k, v in row.items()}
        l["member"], l["dofs"] = int(l["member"]), int(l["dofs"])
        if not l["asymptotic"]:
            step = l["estimate"] / tail(l["ratio"])  # |d_k| / |Q_k|
            l["estimate"] = step * tail(SLOW_RATIO)
            l["ratio"] = SLOW_RATIO
            error, u = l["true_error"], l["reference_uncertainty"]
            l["effectivity"] = l["estimate"] / error
            l["effectivity_low"] = l["estimate"] / (error + u)
            l["effectivity_high"] = l["estimate"] / (error - u)
            if l["member"] == 1:
                l["member_ratio"] = error / (error + step)
        lines.append(l)
    return lines


def write(out, lines):
    fields = list(lines[0])
    if "member_ratio" not in fields:
        fields.append("member_ratio")
    with open(out / "effectivity.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        w.writerows(lines)
    with open(out / "effectivity.md", "w") as f:
        f.write("| case | goal | mesh k | DoFs | estimate | true error | "
                "effectivity | ratio r | e_1/e_0 | reference (uncertainty) |\n"
                "|---|---|---|---|---|---|---|---|---|---|\n")
        for l in lines:
            rho = l.get("member_ratio")
            f.write(f"| {l['case']} | {l['quantity']} | {l['member']} | "
                    f"{l['dofs']} | {l['estimate']:.2e} | "
                    f"{l['true_error']:.2e} | {l['effectivity']:.2f} "
                    f"({l['effectivity_low']:.2f}-{l['effectivity_high']:.2f}) | "
                    f"{l['ratio']:.2f}{'' if l['asymptotic'] else ' (assumed)'}"
                    f" | {'' if rho in (None, '') else f'{rho:.2f}'}"
                    f" | {l['reference']:.8g} ({l['reference_uncertainty']:.1e}) |\n")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--exe")
    parser.add_argument("--rescore", action="store_true")
    parser.add_argument("--cases", default=",".join(CASES))
    parser.add_argument("--out", default=str(HERE))
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    if args.rescore:
        write(out, rescore(HERE / "effectivity.csv"))
        return
    if not args.exe:
        sys.exit("effectivity.py: --exe or --rescore is required")
    lines = []
    for name in args.cases.split(","):
        rows, seconds = run_case(os.path.abspath(args.exe), name, out)
        new = table(name, rows)
        lines += new
        for l in new:
            print(f"{name} {l['quantity']} member {l['member']}: estimate "
                  f"{l['estimate']:.2e}, error {l['true_error']:.2e}, "
                  f"effectivity {l['effectivity']:.2f}", flush=True)
        print(f"{name}: {seconds:.1f} s", flush=True)
    write(out, lines)

if __name__ == "__main__":
    main()
