"""A calibration space for the PISA fits (a site and its piles): the spec file, its checks, and the .prm
overrides of one pile of the calibration space.

The spec is a list of `key = value` lines (`#` starts a comment):

    base scene    = prm/monopile-clay-lateral.prm  # the soil profile and laws
    diameters     = 9                # D [m]
    L/D           = 3, 4.5, 6        # embedded length / D, fitted
    left out      = 4@9, 5@4.5       # L/D@D piles run but not fitted (may be empty)
    wall t/D      = 0.0122           # steel wall thickness / D
    stick-up h/D  = 2                # height of H above the mudline / D (M = H h)
    target v/D    = 0.1              # mudline displacement pushed to / D
    initial v/D   = 0.002            # a second run per pile, one step to this
                                     # (the curves' initial slope; 0: none)
    load steps    = 10
    depths        = 20               # reaction curves at the middles of N parts
    cells along pile = 10
    model layers z/D = auto          # edges of the layers in z/D within which the
                                     # p-v and m-psi parameters are linear (OpenPile
                                     # layers); auto: one, 0 to the largest L/D
    y_u with depth = auto            # z/D, z/L, or auto: z/D for clay (Byrne et
                                     # al. 2020), z/L for sand (Burd et al. 2020)

The base scene must be a monopile scene in the form of
prm/monopile-clay-lateral.prm: a steel wall (material 1), a tied ring on its
head (material 2), plastic soil around; the overrides below replace its mesh
geometry, loads, load path and output.  deal.II's ParameterHandler keeps the
last `set` of an entry, so the overrides are appended to the scene's text.
"""
import os

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))

DEFAULTS = {
    "base scene": "prm/monopile-clay-lateral.prm",
    "diameters": "9",
    "L/D": "3, 4.5, 6",
    "left out": "4@9, 5@4.5",
    "wall t/D": "0.0122",
    "stick-up h/D": "2",
    "target v/D": "0.1",
    "initial v/D": "0.002",
    "load steps": "10",
    "depths": "20",
    "cells along pile": "10",
    "model layers z/D": "auto",
    "y_u with depth": "auto",
}


class SpecError(Exception):
    """Bad input: its message is the one line printed."""


def _numbers(text, key, path):
    try:
        values = [float(x) for x in text.replace(",", " ").split()]
    except ValueError:
        raise SpecError(f"{path}: '{key} = {text}' is not a list of numbers")
    if any(v <= 0 for v in values):
        raise SpecError(f"{path}: '{key} = {text}' must be positive")
    return values


def spec_steps(entries, path):
    try:
        return max(int(entries["load steps"]), 1)
    except ValueError:
        raise SpecError(f"{path}: 'load steps = {entries['load steps']}' is not an integer")


def read_spec(path):
    """The site as a dict: base scene (absolute path), piles (list of dicts
    name, D, L_over_D, fitted), t_over_D, h_over_D, target_over_D, steps,
    depths, cells."""
    if not os.path.isfile(path):
        raise SpecError(f"{path}: no such site file")
    entries = dict(DEFAULTS)
    with open(path) as f:
        for number, line in enumerate(f, 1):
            line = line.split("#", 1)[0].strip()
            if not line:
                continue
            if "=" not in line:
                raise SpecError(f"{path}:{number}: expected 'key = value', got '{line}'")
            key, value = (s.strip() for s in line.split("=", 1))
            if key not in DEFAULTS:
                raise SpecError(f"{path}:{number}: unknown key '{key}' (known: {', '.join(DEFAULTS)})")
            entries[key] = value
    base = entries["base scene"]
    if not os.path.isabs(base):
        here = os.path.join(os.path.dirname(os.path.abspath(path)), base)
        base = here if os.path.isfile(here) else os.path.join(ROOT, base)
    if not os.path.isfile(base):
        raise SpecError(f"{path}: base scene '{entries['base scene']}' not found")
    diameters = _numbers(entries["diameters"], "diameters", path)
    ratios = _numbers(entries["L/D"], "L/D", path)
    piles = [dict(D=D, L_over_D=r, fitted=True) for D in diameters for r in ratios]
    for item in entries["left out"].replace(",", " ").split():
        try:
            r, D = (float(x) for x in item.split("@"))
        except ValueError:
            raise SpecError(f"{path}: 'left out' item '{item}' is not L/D@D")
        if r <= 0 or D <= 0:
            raise SpecError(f"{path}: 'left out' item '{item}' must be positive")
        piles.append(dict(D=D, L_over_D=r, fitted=False))
    for p in piles:
        p["name"] = f"D{p['D']:g}-LD{p['L_over_D']:g}" + ("" if p["fitted"] else "-left-out")
    # The depth variation is linear (2 parameters) in z/D, the base's in L/D:
    # two fitted piles of different L/D at least.
    if len({p["L_over_D"] for p in piles if p["fitted"]}) < 2:
        raise SpecError(f"{path}: the base components are fitted linearly in L/D: "
                        "the space needs fitted piles of at least 2 different L/D")
    spec = dict(base=base, piles=piles, path=path)
    for key, name in [("wall t/D", "t_over_D"), ("target v/D", "target_over_D")]:
        (spec[name],) = _numbers(entries[key], key, path)[:1] or [None]
    try:
        spec["initial_over_D"] = float(entries["initial v/D"])
    except ValueError:
        raise SpecError(f"{path}: 'initial v/D = {entries['initial v/D']}' is not a number")
    if not 0 <= spec["initial_over_D"] < spec["target_over_D"] / spec_steps(entries, path):
        raise SpecError(f"{path}: 'initial v/D' must lie in [0, target v/D / load steps)")
    h = entries["stick-up h/D"].strip()
    try:
        spec["h_over_D"] = float(h)
    except ValueError:
        raise SpecError(f"{path}: 'stick-up h/D = {h}' is not a number")
    if spec["h_over_D"] < 0:
        raise SpecError(f"{path}: 'stick-up h/D = {h}' must be >= 0")
    for key, name in [("load steps", "steps"), ("depths", "depths"), ("cells along pile", "cells")]:
        try:
            spec[name] = int(entries[key])
        except ValueError:
            raise SpecError(f"{path}: '{key} = {entries[key]}' is not an integer")
        if spec[name] < 2:
            raise SpecError(f"{path}: '{key} = {entries[key]}' must be at least 2")
    ml = entries["model layers z/D"].strip()
    if ml == "auto":
        spec["layers"] = None
    else:
        try:
            edges = [float(x) for x in ml.replace(",", " ").split()]
        except ValueError:
            raise SpecError(f"{path}: 'model layers z/D = {ml}' is not 'auto' or a list of numbers")
        if len(edges) < 2 or edges[0] != 0 or any(b <= a for a, b in zip(edges, edges[1:])):
            raise SpecError(f"{path}: 'model layers z/D = {ml}' must start at 0 and increase")
        spec["layers"] = edges
    spec["yu_depth_variable"] = entries["y_u with depth"].strip()
    if spec["yu_depth_variable"] not in ("auto", "z/D", "z/L"):
        raise SpecError(f"{path}: 'y_u with depth = {spec['yu_depth_variable']}' is not auto, z/D or z/L")
    if spec["t_over_D"] >= 0.5:
        raise SpecError(f"{path}: 'wall t/D' must be below 0.5")
    return spec


def pile_overrides(spec, pile, out_dir, initial=False):
    """The entries appended to the base scene for one pile: the tube's
    geometry (the domain scaled with D and L as the base scene's 50 m radius
    and 23 m below the tip of the 9 m x 42 m monopile), the load's
    eccentricity, the push and the curves' depths."""
    D, L = pile["D"], pile["L_over_D"] * pile["D"]
    R = D / 2
    t = spec["t_over_D"] * D
    ri = R - t
    far = max(50. / 4.5 * R, 3. * L)
    below = max(23. / 42. * L, 2.5 * D)
    h = spec["h_over_D"] * D
    target = (spec["initial_over_D"] if initial else spec["target_over_D"]) * D
    steps = 1 if initial else spec["steps"]
    return f"""
# ---- appended by tools/pisa/calibrate.py: pile {pile['name']} ----
subsection Mesh
  set R breakpoints    = 0, {ri:.6g}, {R:.6g}, {far:.6g}
  set Z breakpoints    = {-(L + below):.6g}, {-L:.6g}, 0, {t:.6g}
  set Z cells          = 3, {spec['cells']}, 1
  set Material regions = 1: {ri:.6g}, {R:.6g}, {-L:.6g}, 0; 2: {ri:.6g}, {R:.6g}, 0, {t:.6g}
  set Removed regions  = 0, {ri:.6g}, 0, {t:.6g}; {R:.6g}, {far:.6g}, 0, {t:.6g}
end
subsection Rigid foundation
  set Reference elevation = 0
  set Horizontal force    = 1
  set Moment              = {h:.6g}
  set Capacity normalisation =
end
subsection Load path
  set Control           = displacement
  set Controlled motion = horizontal
  set Target            = {target:.6g}
  set Load steps        = {steps}
end
subsection Output
  set Directory            = {out_dir}
  set Write vtu            = false
  set Soil reaction pile   = 1
  set Soil reaction depths = auto {spec['depths']}
end
"""
