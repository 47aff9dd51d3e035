#!/usr/bin/env python3
"""Effectivity of the error estimate of Discretization/Target accuracy.

Each case runs once, driven only by a target far below reach, so the
program walks its designed family of nested meshes (member 0, 1, 2, ...)
until Adaptivity/Maximum DoFs stops it. From the rows of results.csv (one
cycle per member) this script forms, for every member k >= 1, the estimate
the program prints for a run that stops at k: eq. (1) of
include/fourier_ssi/estimation/sequence_error_estimate.h on the values of members
0..k. The reference is the finest member; its own estimate is its
uncertainty, and a member enters the table only where its true error
|Q_k - Q_ref| / |Q_ref| is at least 2x that uncertainty; the effectivity
is given with the range that uncertainty allows.

    effectivity = estimated relative error / true relative error

Reliability asks effectivity >= 0.8 (at most 20 % under-reported), and
sharpness <= 5.

The assumed ratio of a two-value estimate is design_member_ratio(nu,
slip_wedges) of sequence_error_estimate.h (0.4 below nu = 0.45 without a
smooth interface, 0.6 from nu = 0.45 or with one; mirrored in
design_ratio() here). The cases are the eight of the accuracy study, the
smooth pile (added with the deeper slip-wedge grading), and six
of the thesis figure families ('sweep-*', written by tools/sweep.py) whose
members converge more slowly; every member value of a case run is kept in
members.csv, from which the member-ratio table (rho = e_1/e_0 per case and
goal, and the member-1 effectivity with r = 0.4 and with the rule) is
formed.

Usage: effectivity.py --exe build/fourier-ssi [--cases a,b] [--out DIR]
       effectivity.py --rescore [--out DIR]
Writes effectivity.csv, effectivity.md and members.csv in DIR (default:
this folder); the rows of the cases not in --cases are kept from the
committed effectivity.csv (re-formed as --rescore does).
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
MINIMUM_RATIO = 0.25  # sequence_error_estimate.h
LOCKING_POISSON_RATIO = 0.45  # input_checks.h


def design_ratio(nu, interface):
    """design_member_ratio(nu, slip_wedges) of
    source/estimation/sequence_error_estimate.cc: every case with a smooth interface
    has slip wedges (the ends of its interface lines)."""
    return 0.6 if nu >= LOCKING_POISSON_RATIO or interface == "smooth" \
        else 0.4


def case_ratio(name):
    """The assumed member ratio of a case of CASES."""
    _, interface, nu, _, _ = CASES[name]
    return design_ratio(nu, interface)


def tail(r):
    """The factor r / (1 - r) of eq. (1)."""
    return r / (1. - r)


def estimate(values, assumed):
    """Eq. (1): geometric tail of the last difference."""
    k = len(values) - 1
    d = values[k] - values[k - 1]
    r, asymptotic = assumed, False
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


def sweep_scene(template, scene, **case):
    """A case of the thesis figure families (prm/sweeps/*.sweep), written
    by tools/sweep.py's own prm_text with the designed base mesh."""
    sys.path.insert(0, str(HERE.parent.parent / "tools"))
    import sweep
    text = (HERE.parent.parent / "prm" / template).read_text()

    def build(interface, nu, alpha):
        return sweep.prm_text(text, scene, dict(case, interface=interface,
                                                nu=nu, alpha=alpha),
                              0, "unused", target=1e-9)
    return build


def sweep_footing(e_over_a):
    return sweep_scene("embedded-footing.prm", "footing", **{"e/a": e_over_a})


def sweep_pile(l_over_d, ep_over_es):
    return sweep_scene("pile.prm", "pile",
                       **{"L/d": l_over_d, "Ep/Es": ep_over_es})


CASES = {
    "footing-a0.5-nu0.25-rough": (footing, "rough", 0.25, 0.5, 6e5),
    "footing-a0-nu0.25-rough": (footing, "rough", 0.25, 0, 6e5),
    "footing-a1-nu0.25-rough": (footing, "rough", 0.25, 1, 6e5),
    "footing-a0.5-nu0.49-rough": (footing, "rough", 0.49, 0.5, 6e5),
    "footing-a0-nu0.25-smooth": (footing, "smooth", 0.25, 0, 6e5),
    "footing-a1-nu0.25-smooth": (footing, "smooth", 0.25, 1, 6e5),
    "footing-a0.5-nu0.25-smooth": (footing, "smooth", 0.25, 0.5, 6e5),
    "pile-a1-nu0.25-rough": (pile, "rough", 0.25, 1, 6e5),
    # The smooth pile: its slip wedges (shaft ends, tip) graded deeper
    # (discretization_design.h, slip_wedge_extra_levels).
    "pile-a1-nu0.25-smooth": (pile, "smooth", 0.25, 1, 6e5),
    # The classes of the figure families (doc/scenes.md) that converge
    # more slowly per member than the eight above. The footing runs to its
    # member 3 (459k DoFs), the piles to member 2 (about 410k; member 3
    # would be 1.5M).
    "sweep-footing-e0.5-a0.75-nu0.49-rough": (sweep_footing(0.5), "rough",
                                              0.49, 0.75, 6e5),
    "sweep-footing-e0.5-a0.5-nu0.49-rough": (sweep_footing(0.5), "rough",
                                             0.49, 0.5, 6e5),
    "sweep-pile-rigid-L15-a0-nu0.49-smooth": (sweep_pile(15, "rigid"),
                                              "smooth", 0.49, 0, 6e5),
    "sweep-pile-rigid-L15-a0-nu0.49-rough": (sweep_pile(15, "rigid"),
                                             "rough", 0.49, 0, 6e5),
    "sweep-pile-L15-a0-nu0.49-rough": (sweep_pile(15, 1000.), "rough",
                                       0.49, 0, 6e5),
    "sweep-pile-rigid-L15-a1-nu0.25-rough": (sweep_pile(15, "rigid"),
                                             "rough", 0.25, 1, 6e5),
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


def member_values(name, rows):
    """The goal values of every member: rows of members.csv."""
    series = {}
    for r in rows:
        if r["n"] == "1" and r["family"] == "symmetric":
            series.setdefault(r["quantity"], {})[int(r["cycle"])] = float(
                r["value"])
    return [dict(case=name, quantity=q, member=k,
                 dofs=int(series["n_dofs"][k]), value=series[q][k])
            for q in ("K_H", "K_M", "K_MH") for k in sorted(series[q])]


def read_members(path):
    """members.csv as {case: {quantity: ([values], [dofs])}}."""
    cases = {}
    if path.exists():
        for r in csv.DictReader(open(path)):
            v, d = cases.setdefault(r["case"], {}).setdefault(
                r["quantity"], ([], []))
            v.append(float(r["value"]))
            d.append(int(r["dofs"]))
    return cases


def table(name, series):
    """Effectivity rows of one case, from its member values."""
    assumed = case_ratio(name)
    lines = []
    for q in ("K_H", "K_M", "K_MH"):
        members, dofs = series[q]
        ref = members[-1]
        uncertainty = estimate(members, assumed)[0]
        for k in range(1, len(members) - 1):
            est, r, asymptotic = estimate(members[:k + 1], assumed)
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
        l = {k: (v if k in ("case", "quantity") or v == "" else
                 v == "True" if k == "asymptotic" else float(v))
             for k, v in row.items()}
        l["member"], l["dofs"] = int(l["member"]), int(l["dofs"])
        if not l["asymptotic"]:
            step = l["estimate"] / tail(l["ratio"])  # |d_k| / |Q_k|
            l["ratio"] = case_ratio(l["case"])
            l["estimate"] = step * tail(l["ratio"])
            error, u = l["true_error"], l["reference_uncertainty"]
            l["effectivity"] = l["estimate"] / error
            l["effectivity_low"] = l["estimate"] / (error + u)
            l["effectivity_high"] = l["estimate"] / (error - u)
            if l["member"] == 1 and l.get("member_ratio") in ("", None):
                l["member_ratio"] = error / (error + step)  # monotone
        lines.append(l)
    return lines


def study_ratios(lines, members):
    """The member ratios of the effectivity rows (member 1, e_1/e_0
    against the finest member) of the cases without members.csv."""
    out = []
    for l in lines:
        if l["member"] != 1 or l["member_ratio"] in ("", None) or \
           l["case"] in members:
            continue
        nu = CASES[l["case"]][2]
        step = l["estimate"] / tail(l["ratio"])
        out.append(dict(case=l["case"], nu=nu, quantity=l["quantity"],
                        dofs=f"member 1: {l['dofs'] // 1000}k",
                        rho=l["member_ratio"],
                        measured_as="e_1/e_0 against the finest member",
                        effectivity_0_4=step * tail(0.4) / l["true_error"],
                        ratio=case_ratio(l["case"]),
                        effectivity=step * tail(case_ratio(l["case"])) /
                        l["true_error"]))
    return out


def member_ratios(members):
    """The member 0 -> 1 error ratio rho of every case and goal with three
    members or more, and the effectivity of its member-1 estimate (two
    values, assumed ratio) with r = 0.4 and with case_ratio(name). Where
    the finest member's own estimate is below half of e_1 (as for the
    effectivity rows), rho = e_1/e_0 against it and the effectivity is
    measured: |d_1| (r/(1-r)) / e_1. Else (three members) rho = d_2/d_1,
    the ratio of a geometric sequence, and the effectivity is (2),
    (r/(1-r)) / (rho/(1-rho)): inferred, no independent reference."""
    lines = []
    for name, goals in members.items():
        nu = CASES[name][2]
        for q in ("K_H", "K_M", "K_MH"):
            values, dofs = goals[q]
            if len(values) < 3:
                continue
            ref = values[-1]
            uncertainty = estimate(values, case_ratio(name))[0] * abs(ref)
            e0, e1 = abs(values[0] - ref), abs(values[1] - ref)
            d1 = abs(values[1] - values[0])
            if len(values) >= 4:
                rho = e1 / e0
                how = f"e_1/e_0 against member {len(values) - 1}"
                if (values[0] - ref) * (values[1] - ref) < 0 or rho >= 1:
                    how += " (errors not monotone)"
                bound = e1 < 2 * uncertainty
                if bound:
                    # e_1 within twice the reference's uncertainty u: the
                    # effectivity is at least the one against e_1 + u.
                    how += ", e_1 within 2x its uncertainty: effectivity >="

                def effectivity(r):
                    return d1 * tail(r) / (e1 + uncertainty if bound else e1)
            else:
                rho = abs(values[2] - values[1]) / d1
                how = "d_2/d_1 (geometric; inferred)"

                def effectivity(r):
                    return tail(r) / tail(rho)
            lines.append(dict(case=name, nu=nu, quantity=q,
                              dofs="/".join(f"{d // 1000}k" for d in dofs),
                              rho=rho, measured_as=how,
                              effectivity_0_4=effectivity(0.4),
                              ratio=case_ratio(name),
                              effectivity=effectivity(case_ratio(name))))
    return lines


def write_members(out, members):
    with open(out / "members.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["case", "quantity", "member", "dofs", "value"])
        for name, goals in members.items():
            for q, (values, dofs) in goals.items():
                for k, (v, d) in enumerate(zip(values, dofs)):
                    w.writerow([name, q, k, d, repr(v)])


def write(out, lines, ratios):
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
        f.write("\nMember ratios rho = e_1/e_0 (members 0 -> 1) of every case, "
                "and the effectivity of the member-1 estimate (two values, "
                "assumed ratio) with r = 0.4 and with the rule's "
                "design_member_ratio(nu, slip_wedges) (0.4 below nu = "
                "0.45 without a smooth interface, 0.6 from nu = 0.45 or "
                "with one). 'd_2/d_1': three members only, rho of a geometric "
                "sequence and effectivity (r/(1-r))/(rho/(1-rho)), "
                "inferred (no reference finer than member 2).\n\n"
                "| case | nu | goal | member DoFs | rho | measured as | "
                "effectivity, r = 0.4 | rule's r | effectivity, rule's r |\n"
                "|---|---|---|---|---|---|---|---|---|\n")
        for l in ratios:
            f.write(f"| {l['case']} | {l['nu']:g} | {l['quantity']} | "
                    f"{l['dofs']} | {l['rho']:.2f} | {l['measured_as']} | "
                    f"{l['effectivity_0_4']:.2f} | {l['ratio']:.1f} | "
                    f"{l['effectivity']:.2f} |\n")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--exe")
    parser.add_argument("--rescore", action="store_true")
    parser.add_argument("--cases", default=",".join(CASES))
    parser.add_argument("--out", default=str(HERE))
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    members = read_members(HERE / "members.csv")
    if args.rescore:
        lines = rescore(HERE / "effectivity.csv")
        write(out, lines, study_ratios(lines, members) +
              member_ratios(members))
        return
    if not args.exe:
        sys.exit("effectivity.py: --exe or --rescore is required")
    names = args.cases.split(",")
    for name in names:
        if name not in CASES:
            sys.exit(f"effectivity.py: --cases: no case '{name}'")
    # The rows of the cases not run now are kept from the committed csv.
    lines = [l for l in rescore(HERE / "effectivity.csv")
             if l["case"] not in names]
    for name in names:
        rows, seconds = run_case(os.path.abspath(args.exe), name, out)
        members[name] = {}
        for m in member_values(name, rows):
            v, d = members[name].setdefault(m["quantity"], ([], []))
            v.append(m["value"])
            d.append(m["dofs"])
        new = table(name, members[name])
        lines += new
        for l in new:
            print(f"{name} {l['quantity']} member {l['member']}: estimate "
                  f"{l['estimate']:.2e}, error {l['true_error']:.2e}, "
                  f"effectivity {l['effectivity']:.2f}", flush=True)
        print(f"{name}: {seconds:.1f} s", flush=True)
    order = list(CASES)
    lines.sort(key=lambda l: order.index(l["case"]))
    write(out, lines, study_ratios(lines, members) + member_ratios(members))
    write_members(out, members)

if __name__ == "__main__":
    main()
