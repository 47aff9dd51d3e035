"""From the FE runs of a calibration space to the calibrated model: the
curves of every pile, the fits per curve and per family, the 1D model
against the FE's pile head, and the files (calibrate.py's second half)."""
import csv
import json
import os
import sys
import time

import numpy as np

from beam import Beam, Pile
from conic import conic
from fit import prepare, fit_curve, fit_linear_family
from model import Model, OwnCurvesModel, COMPONENTS, SOIL_KINDS
import export

# component: (x column, y column) of soil-reaction-curves.csv
COLUMNS = {
    "py": ("v G/(s D) [-]", "p/(s D) [-]"),
    "mt": ("psi G/s [-]", "m/(s D^2) or m/(|p| D) [-]"),
    "Hb": ("v_base G/(s D) [-]", "H_B/(s D^2) [-]"),
    "Mb": ("psi G/s_base [-]", "M_B/(s D^3) [-]"),
}
# the normalisations of Byrne et al. 2020 (clay) and Burd et al. 2020 (sand)
LABELS = {
    "clay": {"py": "p/(s_u D) vs v G0/(s_u D)", "mt": "m/(s_u D^2) vs psi G0/s_u",
             "Hb": "H_B/(s_u D^2) vs v G0/(s_u D)", "Mb": "M_B/(s_u D^3) vs psi G0/s_u"},
    "sand": {"py": "p/(sigma'_v D) vs v G0/(sigma'_v D)", "mt": "m/(|p| D) vs psi G0/sigma'_v",
             "Hb": "H_B/(sigma'_v D^2) vs v G0/(sigma'_v D)", "Mb": "M_B/(sigma'_v D^3) vs psi G0/sigma'_v"},
}
# y_u of p-v and m-psi varies with this depth variable unless the site says
# otherwise (y_u with depth): clay z/D as Byrne et al. 2020, sand z/L as
# Burd et al. 2020
YU_DEPTH_VARIABLE = {"clay": "z/D", "sand": "z/L"}
# A distributed curve at a depth whose largest lateral displacement |v| [m]
# is below this fraction of its pile's largest (the depths next to the
# rotation point) stays out of the depth fit and of the pile's own conics:
# it carries almost no information on y_u and x_u, and a sand's m/(|p| D)
# is ill-conditioned there (p -> 0).
NEAR_ROTATION_POINT = 0.1


class InputError(Exception):
    pass


def soil_kind(piles, data):
    """'clay' or 'sand', from the normaliser of the runs' curves (every
    pile's the same)."""
    kinds = {}
    for name, d in data.items():
        by = {r.get("normalised by") for r in d["curves"]}
        if len(by) != 1 or next(iter(by)) not in SOIL_KINDS:
            raise InputError(f"pile {name}: the curves are normalised by {', '.join(map(str, sorted(by, key=str)))}; "
                             f"a calibration needs one of {', '.join(SOIL_KINDS)} (a Tresca or iwan clay, "
                             "a Mohr-Coulomb sand)")
        kinds[name] = SOIL_KINDS[next(iter(by))]
    if len(set(kinds.values())) > 1:
        raise InputError("the piles' curves mix clay and sand normalisations: "
                         + ", ".join(f"{n} {k}" for n, k in sorted(kinds.items())))
    return next(iter(kinds.values()))


# A sand's m/(|p| D) point is kept where |p| is at least this fraction of
# the curve's largest |p| and of its sign: where p is about to change sign
# (the rotation point moves down during the push) the ratio spikes and says
# nothing about m.
SMALL_LATERAL_REACTION = 0.1


# Whether a curve's points whose reaction does not resist the motion are
# left out of its fits (fit.prepare).  Sand: yes; without it the 4-depth
# end-to-end space's p-v model collapsed (y_u 20 -> 0.05 over the pile, the
# 1D head 41 % low); on the benchmark it changes the largest head errors by
# at most 0.03.  Clay: no; there it dropped 1-3 early points of the curves
# just above the rotation point and made the largest head errors
# 0.004-0.017 worse (x_u 76 -> 25).
RESISTING_ONLY = {"clay": False, "sand": True}


def scaled_by_lateral_reaction(rows):
    """The rows of one depth's m-psi curve in sand that keep a defined
    m/(|p| D): p of the sign of its largest |p| and at least
    SMALL_LATERAL_REACTION of it, and m of the sign of its largest |m| (at
    the toe m changes sign during the push)."""
    if not rows:
        return rows
    peak = max((r["p [kN/m]"] for r in rows), key=abs)
    moment_peak = max((r["m [kN m/m]"] for r in rows), key=abs)
    return [r for r in rows if r["p [kN/m]"] * peak >= SMALL_LATERAL_REACTION * peak * peak
            and r["m [kN m/m]"] * moment_peak >= 0.0]


def points(rows, xc, yc):
    """x, y of a curve's rows, without the rows whose normalised value is
    empty (a normaliser of zero: p = 0 for a sand's m/(|p| D))."""
    use = [r for r in rows if isinstance(r[xc], float) and isinstance(r[yc], float)]
    return np.array([r[xc] for r in use]), np.array([r[yc] for r in use])


def pile_curves(pile, d, kind):
    """{component: [dict(depth, zD, x, y)]} of one pile whose soil is kind
    (clay or sand), the initial run's point first when there is one."""
    rows = d["curves"]
    init = d["initial"]["curves"] if d.get("initial") else []
    L = pile["L_over_D"] * pile["D"]
    out = {c: [] for c in COMPONENTS}
    depths = sorted({r["depth [m]"] for r in rows})
    for depth in depths:
        if not 0 < depth <= L + 1e-9:
            raise InputError(f"pile {pile['name']}: a curve at depth {depth:g} m lies outside the pile (0, {L:g}] m")
        sel = sorted([r for r in init if abs(r["depth [m]"] - depth) < 1e-9] +
                     [r for r in rows if abs(r["depth [m]"] - depth) < 1e-9],
                     key=lambda r: abs(r["v [m]"]))
        v_max = max(abs(r["v [m]"]) for r in sel)
        for c in ("py", "mt"):
            use = scaled_by_lateral_reaction(sel) if c == "mt" and kind == "sand" else sel
            x, y = points(use, *COLUMNS[c])
            out[c].append(dict(depth=depth, zD=depth / pile["D"], x=x, y=y, v_max=v_max))
    first = depths[0]
    sel = [r for r in init if abs(r["depth [m]"] - first) < 1e-9] + \
          [r for r in rows if abs(r["depth [m]"] - first) < 1e-9]
    for c in ("Hb", "Mb"):
        x, y = points(sel, *COLUMNS[c])
        out[c].append(dict(depth=L, zD=L / pile["D"], x=x, y=y))
    return out


def near_rotation_point(pile_curves_of_one):
    """The depths [m] of one pile whose largest lateral displacement |v| [m]
    is below NEAR_ROTATION_POINT of the pile's largest.  The dimensional v,
    not the normalised x: in sand G0/sigma'_v grows towards the mudline, and
    the normalised x left out every curve below z/D = 2 of the benchmark's
    piles (so the sand's depth model saw only the top 2 D)."""
    v_max = {cv["depth"]: cv["v_max"] for cv in pile_curves_of_one["py"]}
    top = max(v_max.values())
    return {depth for depth, v in v_max.items() if v < NEAR_ROTATION_POINT * top}


def own_conics(pile_curves_of_one, base_fallback):
    """The pile's own per-curve conics for model.OwnCurvesModel, from the
    curves' 'fit' entries: (z/D, (k, n, x_u, y_u)) per depth of p-v and m-psi
    away from the rotation point (interpolated across it), and the base's
    (k, n, x_u, y_u), base_fallback(component) where the base has no fit."""
    skip = near_rotation_point(pile_curves_of_one)
    own = {c: [(cv["zD"], tuple(cv["fit"][q] for q in ("k", "n", "xu", "yu")))
               for cv in pile_curves_of_one[c] if cv.get("fit") and cv["depth"] not in skip]
           for c in ("py", "mt")}
    for c in ("Hb", "Mb"):
        f0 = pile_curves_of_one[c][0].get("fit")
        own[c] = tuple(f0[q] for q in ("k", "n", "xu", "yu")) if f0 else base_fallback(c)
    return own


def soil_profile(data, piles):
    """(depth, s, G0) points from every run's CSV: at the curves' depths,
    and at each pile's tip (s_base, with G0 from the base's normalised
    displacement where the base has moved)."""
    pts = {}
    for name, d in data.items():
        for r in d["curves"]:
            pts[round(r["depth [m]"], 9)] = (r["s [kPa]"], r["G [kPa]"])
        D, L = piles[name]["D"], piles[name]["L_over_D"] * piles[name]["D"]
        moved = [r for r in d["curves"] if isinstance(r["v_base G/(s D) [-]"], float) and r["v_base [m]"] != 0.0]
        if moved:
            r = moved[-1]
            pts.setdefault(round(L, 9), (r["s_base [kPa]"], r["v_base G/(s D) [-]"] * r["s_base [kPa]"] * D /
                                         r["v_base [m]"]))
    depth = sorted(pts)
    return dict(depth=depth, s=[pts[z][0] for z in depth], G=[pts[z][1] for z in depth])


def head_fe(d):
    rows = d["head"]
    v = np.array([0.0] + [r["horizontal_m"] for r in rows])
    th = np.array([0.0] + [r["rotation_rad"] for r in rows])
    H = np.array([0.0] + [r["H_kN"] for r in rows])
    M = np.array([0.0] + [r["M_kNm"] for r in rows])
    return v, th, H, M


def run_1d(model, spec, pile, steps=40, elements=80):
    D = pile["D"]
    L = pile["L_over_D"] * D
    t = spec["t_over_D"] * D
    tube = Pile(D, t, L)
    p, m, HB, MB = model.springs(D, L)
    beam = Beam(tube.EI, tube.kGA, L, elements, p=p, m=m, HB=HB, MB=MB)
    return beam.push(spec["target_over_D"] * D, spec["h_over_D"] * D, steps)


def compare(fe, one_d):
    """Relative differences at the FE's steps: H at the FE's v, and theta
    at the FE's v (the 1D curve interpolated)."""
    v, th, H, M = fe
    v1, th1, H1, M1 = one_d
    H1i = np.interp(v[1:], v1, H1)
    th1i = np.interp(v[1:], v1, th1)
    dH = (H1i - H[1:]) / H[1:]
    dth = (th1i - th[1:]) / th[1:]
    return dH, dth, H1i, th1i


# The family fits see each FE curve at this many points evenly spaced in
# log x (linear between the FE's points): the FE's equal steps put one or
# two points below x = 3, and the model then missed the head's load at
# 0.01 D by up to 25 % (16 points: 18 %).  0: the FE's points as they are.
RESAMPLE = 16


def resample(x, y):
    """The curve at RESAMPLE points evenly spaced in log x between its
    first and last point (linear between the FE's points), or as it is."""
    if not RESAMPLE:
        return x, y
    order = np.argsort(x)
    xs = np.geomspace(x[order][0], x[order][-1], RESAMPLE)
    return xs, np.interp(xs, x[order], y[order])


def regression_start(fam, s0, s1, yu_over="z/D"):
    """A start for the family fit: each parameter of the per-curve fits
    regressed linearly on s (y_u on z/L where it varies with z/L), weighted
    by the curve's largest reaction (the curves whose k is 100 times the
    median, or n = 1, left out)."""
    fits = [f for f in fam if f.get("fit")]
    if len(fits) < 2:
        return None
    kmed = np.median([f["fit"]["k"] for f in fits])
    use = [f for f in fits if f["fit"]["k"] < 100 * kmed and f["fit"]["n"] < 0.999]
    if len({f["s"] for f in use}) < 2:
        return None
    s = np.array([f["s"] for f in use])
    w = np.array([np.abs(f["y"]).max() for f in use])
    start = {}
    for q in ("k", "n", "xu", "yu"):
        v = np.array([f["fit"][q] for f in use])
        over_L = q == "yu" and yu_over == "z/L"
        var, ends = (np.array([f["t"] for f in use]), (0.0, 1.0)) if over_L else (s, (s0, s1))
        b, a = np.polyfit(var, v, 1, w=w)
        lo = 0.0 if q == "n" else 0.05 * np.median(v)
        hi = 1.0 if q == "n" else np.inf
        start[q] = tuple(float(np.clip(a + b * x, lo, hi)) for x in ends)
    return start


def yu_variable(spec, kind):
    """The depth variable of the distributed components' y_u: z/D, or z/L
    (the toe's flow raises p at the same z/L of every pile; PISA's sand
    form, Burd et al. 2020)."""
    chosen = spec.get("yu_depth_variable", "auto")
    return YU_DEPTH_VARIABLE[kind] if chosen == "auto" else chosen


def best_family(fam, s0, s1, component, kind, yu_over):
    """The family fit from the default starts and from the regression of
    the per-curve fits.  x_u is one value for clay's p-v and m-psi (PISA's
    clay form, Byrne et al. 2020): a linear x_u was tried and lowers the
    curves' cost a little by running to x_u -> 0 at depth with k in the
    thousands, which makes the pile head 15-50 % stiffer than the FE.  A
    sand's m/(|p| D) is near its plateau from the first step (m and p grow
    together), so its x_u is left linear in z/D."""
    start = regression_start(fam, s0, s1, yu_over)
    shared = component == "py" or (component == "mt" and kind == "clay")
    yu_range = (0.0, 1.0) if yu_over == "z/L" else None
    return fit_linear_family(fam, s0, s1, start=start, shared_xu=shared, yu_range=yu_range)


def calibrate_and_compare(spec, data, out, plot=True):
    start = time.time()
    piles = {p["name"]: p for p in spec["piles"] if p["name"] in data}
    try:
        kind = soil_kind(piles, data)
        curves = {name: pile_curves(p, data[name], kind) for name, p in piles.items()}
    except InputError as e:
        sys.exit(f"calibrate.py: {e}")
    LABEL = LABELS[kind]
    fitted = [n for n, p in piles.items() if p["fitted"]]
    # 1. one conic per curve
    rows = []
    for name in fitted:
        for c in COMPONENTS:
            for cv in curves[name][c]:
                sgn, x, y = prepare(cv["x"], cv["y"], RESISTING_ONLY[kind])
                cv.update(sgn=sgn, xp=x, yp=y)
                if x.size < 3:
                    cv["fit"] = None
                    continue
                f = fit_curve(x, y)
                cv["fit"] = f
                rows.append(dict(pile=name, component=c, depth_m=cv["depth"], z_over_D=cv["zD"],
                                 L_over_D=piles[name]["L_over_D"], x_max=x.max(), **f))
    # 2. families: linear in z/D (distributed) and in L/D (base)
    params, family_err = {}, {}
    LDs = [piles[n]["L_over_D"] for n in fitted]
    for c in COMPONENTS:
        fam = []
        for name in fitted:
            cvs = [cv for cv in curves[name][c] if cv["xp"].size >= 3]
            if not cvs:
                continue
            skip = near_rotation_point(curves[name])
            for cv in cvs:
                if c in ("py", "mt") and cv["depth"] in skip:
                    cv["in_family"] = False
                    continue
                cv["in_family"] = True
                s = cv["zD"] if c in ("py", "mt") else piles[name]["L_over_D"]
                xr, yr = resample(cv["xp"], cv["yp"])
                fam.append(dict(s=s, t=cv["depth"] / (piles[name]["L_over_D"] * piles[name]["D"]),
                                x=xr, y=yr, x_fe=cv["xp"], y_fe=cv["yp"], pile=name, depth=cv["depth"],
                                k0=cv["fit"]["k"] if cv["fit"] else None, fit=cv["fit"]))
        yu_over = yu_variable(spec, kind) if c in ("py", "mt") else "L/D"
        if c in ("py", "mt"):
            edges = list(spec["layers"]) if spec["layers"] else [0.0, max(LDs)]
            edges[-1] = max(edges[-1], max(LDs))
            if yu_over == "z/L" and len(edges) > 2:
                sys.exit("calibrate.py: y_u linear in z/L takes one model layer ('model layers z/D = auto'); "
                         "set 'y_u with depth = z/D' for layers")
        else:
            edges = [min(LDs), max(LDs)]
        for f in fam:
            if f["k0"] is None:
                f["k0"] = f["y"][0] / f["x"][0]
        # each curve weighted by its pile's largest reaction: the curves
        # that carry the head's load count most
        for f in fam:
            f["scale"] = max(np.abs(g["y"]).max() for g in fam if g["pile"] == f["pile"])
        layers = []
        family_err[c] = []
        for i, (s0, s1) in enumerate(zip(edges[:-1], edges[1:])):
            last = i == len(edges) - 2
            sub = [f for f in fam if s0 <= f["s"] and (f["s"] < s1 or (last and f["s"] <= s1 + 1e-9))]
            if len(sub) < 2 or len({round(f["s"], 9) for f in sub}) < 2:
                sys.exit(f"calibrate.py: component {c}, {'z/D' if c in ('py', 'mt') else 'L/D'} "
                         f"{s0:g}..{s1:g}: {len(sub)} usable curve(s) at fewer than 2 depths or lengths; "
                         "a linear fit needs 2 (more piles, more depths or fewer model layers)")
            r = best_family(sub, s0, s1, c, kind, yu_over)
            layer = dict(top=r["top"], bottom=r["bottom"], s0=s0, s1=s1, yu_over=yu_over)
            # the error over the FE's own points
            rms = []
            for f in sub:
                k, n, xu, yu = Model({c: dict(layers=[layer])}, {}, kind).at(c, f["s"], piles[f["pile"]]["L_over_D"])
                rms.append(float(np.sqrt(np.mean((conic(f["x_fe"], k, n, xu, yu) - f["y_fe"]) ** 2)) / yu))
            layer.update(rms_all=float(np.sqrt(np.mean(np.square(rms)))), rms_max=max(rms))
            layers.append(layer)
            family_err[c] += [(f["pile"], f["depth"], e) for f, e in zip(sub, rms)]
            xmax_all = max(f["x"].max() for f in sub)
            for which, s in (("top", s0), ("bottom", s1)):
                if r[which]["xu"] > xmax_all:
                    print(f"note: {c} x_u at {'z/D' if c in ('py', 'mt') else 'L/D'} = {s:g} is "
                          f"{r[which]['xu']:.4g}, beyond the largest x of its curves ({xmax_all:.4g}): "
                          "its y_u is an extrapolation of curves that never reach x_u")
        errs = np.array([e for _, _, e in family_err[c]])
        params[c] = dict(layers=layers, variable="z/D" if c in ("py", "mt") else "L/D",
                         rms_all=float(np.sqrt(np.mean(errs ** 2))), rms_max=float(errs.max()))
    model = Model(params, soil_profile(data, piles), kind)
    model.to_json(os.path.join(out, "model.json"),
                  extra=dict(normalisation={c: LABEL[c] for c in COMPONENTS},
                             t_over_D=spec["t_over_D"], h_over_D=spec["h_over_D"]))
    # fits.csv: every per-curve fit and every family parameter with its error
    with open(os.path.join(out, "fits.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["kind", "pile", "component", "depth [m]", "z/D or L/D [-]", "k [-]", "n [-]",
                    "x_u [-]", "y_u [-]", "rms (y_fit - y_FE)/y_u [-]", "x_u within data", "largest x [-]"])
        for r in rows:
            s = r["z_over_D"] if r["component"] in ("py", "mt") else r["L_over_D"]
            w.writerow(["curve", r["pile"], r["component"], f"{r['depth_m']:.6g}", f"{s:.6g}",
                        f"{r['k']:.6g}", f"{r['n']:.6g}", f"{r['xu']:.6g}", f"{r['yu']:.6g}",
                        f"{r['rms']:.3g}", int(r["reached"]), f"{r['x_max']:.6g}"])
        for c in COMPONENTS:
            for i, ly in enumerate(params[c]["layers"]):
                for which, s in (("top", ly["s0"]), ("bottom", ly["s1"])):
                    q = ly[which]
                    # y_u over z/L: its top and bottom are at z/L = 0 and 1
                    w.writerow([f"model layer {i + 1} {which}" + (" (y_u at z/L = 0, 1)" if ly["yu_over"] == "z/L"
                                                                  else ""),
                                "all fitted", c, "", f"{s:.6g}", f"{q['k']:.6g}",
                                f"{q['n']:.6g}", f"{q['xu']:.6g}", f"{q['yu']:.6g}",
                                f"{ly['rms_all']:.3g}", "", ""])
    print("conic fits, one per curve (fitted piles), error = RMS of (y_fit - y_FE)/y_u over the curve:")
    for c in COMPONENTS:
        e = [r["rms"] for r in rows if r["component"] == c]
        print(f"  {c:2s} ({LABEL[c]}): {len(e)} curves, error median {np.median(e):.3g}, max {max(e):.3g}")
    print("the model (each parameter linear in z/D for py, mt, y_u where marked in z/L; in L/D for Hb, Mb), "
          "error over its curves:")
    for c in COMPONENTS:
        P = params[c]
        for ly in P["layers"]:
            t, b = ly["top"], ly["bottom"]
            yu_span = "z/L = 0 -> 1: " if ly["yu_over"] == "z/L" else ""
            print(f"  {c:2s} {P['variable']} = {ly['s0']:g} -> {ly['s1']:g}: k {t['k']:.4g} -> {b['k']:.4g}, "
                  f"n {t['n']:.3f} -> {b['n']:.3f}, x_u {t['xu']:.4g} -> {b['xu']:.4g}, "
                  f"y_u {yu_span}{t['yu']:.4g} -> {b['yu']:.4g}; error RMS {ly['rms_all']:.3g}, "
                  f"max {ly['rms_max']:.3g}")
    # 3. the 1D model against the FE's pile head
    head_rows, summary = [], {}
    print("1D model against the FE at the pile head (mudline), at the FE's displacements:")
    for name, p in piles.items():
        fe = head_fe(data[name])
        try:
            one = run_1d(model, spec, p)
        except RuntimeError as e:
            print(f"  {name}: the 1D model failed: {e}")
            continue
        dH, dth, H1i, th1i = compare(fe, one)
        summary[name] = dict(fitted=p["fitted"], D=p["D"], L_over_D=p["L_over_D"],
                             max_dH=float(np.max(np.abs(dH))), end_dH=float(dH[-1]),
                             max_dtheta=float(np.max(np.abs(dth))), end_dtheta=float(dth[-1]),
                             H_FE_end=float(fe[2][-1]), H_1D_end=float(H1i[-1]))
        if p["fitted"]:
            own = own_conics(curves[name], lambda c: model.at(c, p["L_over_D"], p["L_over_D"]))
            try:
                own_1d = run_1d(OwnCurvesModel(own, model.profile, p["D"], kind), spec, p)
                dH_own = compare(fe, own_1d)[0]
                summary[name]["own_max_dH"] = float(np.max(np.abs(dH_own)))
                summary[name]["own_end_dH"] = float(dH_own[-1])
                summary[name]["curve_1d_own"] = [a.tolist() for a in own_1d]
            except RuntimeError as e:
                print(f"  {name}: the 1D model on its own curves failed: {e}")
        tag = "fitted" if p["fitted"] else "LEFT OUT"
        print(f"  {name} ({tag}): H_1D/H_FE - 1 at v/D = {fe[0][1] / p['D']:.3g}..{fe[0][-1] / p['D']:.3g}: "
              f"max |.| {summary[name]['max_dH']:.3f}, at the end {dH[-1]:+.3f} "
              f"(H_FE = {fe[2][-1]:.6g} kN); theta_1D/theta_FE - 1: max |.| {summary[name]['max_dtheta']:.3f}")
        if "own_max_dH" in summary[name]:
            print(f"    the same beam on the pile's own per-curve conics: H_1D/H_FE - 1 max |.| "
                  f"{summary[name]['own_max_dH']:.3f}, at the end {summary[name]['own_end_dH']:+.3f}")
        for i in range(1, fe[0].size):
            head_rows.append([name, int(p["fitted"]), f"{fe[0][i]:.6g}", f"{fe[1][i]:.6g}", f"{fe[2][i]:.6g}",
                              f"{fe[3][i]:.6g}", f"{H1i[i - 1]:.6g}", f"{th1i[i - 1]:.6g}"])
        summary[name]["curve_1d"] = [a.tolist() for a in one]
        summary[name]["curve_fe"] = [a.tolist() for a in fe]
    with open(os.path.join(out, "head-curves.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["pile", "fitted", "v FE [m]", "theta FE [rad]", "H FE [kN]", "M FE [kN m]",
                    "H 1D at v FE [kN]", "theta 1D at v FE [rad]"])
        w.writerows(head_rows)
    with open(os.path.join(out, "summary.json"), "w") as f:
        json.dump(summary, f, indent=1)
    # 4. OpenPile export, one file per pile
    for name, p in piles.items():
        export.write_openpile(model, p, spec["t_over_D"], os.path.join(out, f"openpile-{name}.json"))
    print(f"written: fits.csv, model.json, head-curves.csv, summary.json, openpile-<pile>.json in {out} "
          f"({time.time() - start:.1f} s of fits and 1D runs)")
    if plot:
        import plot_sheet
        plot_sheet.sheet(curves, model, summary, piles, LABEL, os.path.join(out, "sheet.png"))
        print(f"plot sheet: {os.path.join(out, 'sheet.png')}")
