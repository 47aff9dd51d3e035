"""The calibrated model in the terms of OpenPile's `Custom_pisa_clay` or
`Custom_pisa_sand` lateral models (openpile.soilmodels): for one pile, one
layer per model layer between the mudline and the tip, with the top and
bottom values of X (x_u), n, k and Y (y_u) of py, mt, Hb and Mb and of G0
[kPa], and Su [kPa] for clay.  OpenPile finds a sand's sigma'_v itself,
from the layers' unit weight and the water line: a sand layer carries
`weight` = gamma' + 10 kN/m^3 (OpenPile's unit weight of water) for a water
line at the mudline, and its sigma'_v [kPa] top and bottom as a check.

The base components depend on L/D, so they are the pile's own (the same at
top and bottom).  OpenPile requires n < 1: n is written as at most
N_MAX_OPENPILE.  `read_openpile` is the small reader of those field names
(the test reads an export back with it)."""
import json

import numpy as np

FIELDS = [f"{c}_{q}" for c in ("py", "mt", "Hb", "Mb") for q in ("X", "n", "k", "Y")]
# OpenPile's lateral model and the soil fields of its arguments, per soil kind
OPENPILE_MODEL = {"clay": "Custom_pisa_clay", "sand": "Custom_pisa_sand"}
SOIL_FIELDS = {"clay": ["Su", "G0"], "sand": ["G0"]}
# OpenPile's unit weight of water [kN/m^3] (core/_model_build.py)
WATER_UNIT_WEIGHT = 10.0
N_MAX_OPENPILE = 0.999
OURS = {"X": "xu", "n": "n", "k": "k", "Y": "yu"}


def openpile_layers(model, D, L):
    """The Custom_pisa_clay or Custom_pisa_sand arguments of one pile: a
    list of (top depth, bottom depth [m], {field: [top, bottom]}, soil
    strength s [kPa] at top and bottom), one per model layer of the
    distributed components that the pile reaches."""
    edges = sorted({0.0, L} | {ly[k] * D for ly in model.params["py"]["layers"] + model.params["mt"]["layers"]
                               for k in ("s0", "s1") if 0 < ly[k] * D < L})
    out = []
    for a, b in zip(edges[:-1], edges[1:]):
        args = {}
        strength, G = model.soil(np.array([a, b]))
        if model.soil_kind == "clay":
            args["Su"] = [float(strength[0]), float(strength[1])]
        args["G0"] = [float(G[0]), float(G[1])]
        # the values just inside the layer at both ends (a layer edge of
        # the model is a jump)
        eps = 1e-9 * D
        for c in ("py", "mt"):
            top = model.at(c, (a + eps) / D, L / D)
            bottom = model.at(c, (b - eps) / D, L / D)
            for q, ours in OURS.items():
                j = ("k", "n", "xu", "yu").index(ours)
                args[f"{c}_{q}"] = [float(top[j]), float(bottom[j])]
        for c in ("Hb", "Mb"):
            val = model.at(c, L / D)
            for q, ours in OURS.items():
                j = ("k", "n", "xu", "yu").index(ours)
                args[f"{c}_{q}"] = [float(val[j])] * 2
        for c in ("py", "mt", "Hb", "Mb"):
            args[f"{c}_n"] = [min(v, N_MAX_OPENPILE) for v in args[f"{c}_n"]]
        out.append((a, b, args, [float(strength[0]), float(strength[1])]))
    return out


def write_openpile(model, pile, t_over_D, path):
    D = pile["D"]
    L = pile["L_over_D"] * D
    kind = model.soil_kind
    layers = []
    for i, (a, b, args, strength) in enumerate(openpile_layers(model, D, L)):
        layer = dict(name=f"calibrated {kind} {i + 1}", top=-a, bottom=-b)
        layer[OPENPILE_MODEL[kind]] = args
        if kind == "sand":
            unit_weight = (strength[1] - strength[0]) / (b - a)
            layer.update(weight=unit_weight + WATER_UNIT_WEIGHT, sigma_v=strength)
        layers.append(layer)
    units = {"clay": "kPa for Su and G0; the conic parameters in the PISA clay normalisation "
                     "(p/(Su D), m/(Su D^2), Hb/(Su D^2), Mb/(Su D^3) against y G0/(Su D) or psi G0/Su)",
             "sand": "kPa for G0 and sigma_v, kN/m^3 for weight (water line at the mudline: gamma' = weight - 10); "
                     "the conic parameters in the PISA sand normalisation (p/(sigma'_v D), m/(|p| D), "
                     "Hb/(sigma'_v D^2), Mb/(sigma'_v D^3) against y G0/(sigma'_v D) or psi G0/sigma'_v)"}
    doc = dict(pile=dict(name=pile["name"], diameter=D, wt=t_over_D * D, top_elevation=0.0, bottom_elevation=-L),
               soil_kind=kind, layers=layers, units=units[kind])
    with open(path, "w") as f:
        json.dump(doc, f, indent=1)


def read_openpile(path):
    """Reads an export back: returns (pile dict, list of layer dicts, each
    with name, top, bottom [m elevation] and Custom_pisa_clay or
    Custom_pisa_sand {field: [top, bottom]}, a sand's with its weight);
    raises ValueError naming the first missing or invalid field."""
    with open(path) as f:
        doc = json.load(f)
    kind = doc.get("soil_kind", "clay")
    if kind not in OPENPILE_MODEL:
        raise ValueError(f"{path}: soil_kind '{kind}' is not one of {', '.join(OPENPILE_MODEL)}")
    layers = doc.get("layers")
    if not isinstance(layers, list) or not layers:
        raise ValueError(f"{path}: no layers")
    for layer in layers:
        check_layer(path, layer, kind)
    return doc["pile"], layers


def check_layer(path, layer, kind):
    model_name = OPENPILE_MODEL[kind]
    args = layer.get(model_name)
    if not isinstance(args, dict):
        raise ValueError(f"{path}: layer {layer.get('name')} has no {model_name} object")
    if kind == "sand" and not (isinstance(layer.get("weight"), (int, float)) and layer["weight"] > WATER_UNIT_WEIGHT):
        raise ValueError(f"{path}: layer {layer.get('name')}: weight must be a number above "
                         f"{WATER_UNIT_WEIGHT:g} kN/m^3 (OpenPile's Layer)")
    for name in SOIL_FIELDS[kind] + FIELDS:
        v = args.get(name)
        if not (isinstance(v, list) and len(v) == 2 and all(isinstance(x, (int, float)) for x in v)):
            raise ValueError(f"{path}: field {name} is not [top, bottom]")
        if name.endswith("_n"):
            if not all(0 <= x < 1 for x in v):
                raise ValueError(f"{path}: {name} = {v} outside OpenPile's 0 <= n < 1")
        elif not all(x > 0 for x in v):
            raise ValueError(f"{path}: {name} = {v} must be positive")
