"""The calibrated model in the terms of OpenPile's `Custom_pisa_clay`
lateral model (openpile.soilmodels): one layer from the mudline to the tip
of one pile, with the top and bottom values of X (x_u), n, k and Y (y_u) of
py, mt, Hb and Mb and of Su and G0 [kPa].

The base components depend on L/D, so they are the pile's own (the same at
top and bottom).  OpenPile requires n < 1: n is written as at most
N_MAX_OPENPILE.  `read_openpile` is the small reader of those field names
(the test reads an export back with it)."""
import json

import numpy as np

FIELDS = [f"{c}_{q}" for c in ("py", "mt", "Hb", "Mb") for q in ("X", "n", "k", "Y")]
N_MAX_OPENPILE = 0.999
OURS = {"X": "xu", "n": "n", "k": "k", "Y": "yu"}


def openpile_layer(model, D, L):
    """The Custom_pisa_clay arguments of one pile: {field: [top, bottom]}."""
    args = {}
    su, G = model.soil(np.array([0.0, L]))
    args["Su"] = [float(su[0]), float(su[1])]
    args["G0"] = [float(G[0]), float(G[1])]
    for c in ("py", "mt"):
        top = model.at(c, 0.0)
        bottom = model.at(c, L / D)
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
    return args


def write_openpile(model, pile, t_over_D, path):
    D = pile["D"]
    L = pile["L_over_D"] * D
    doc = dict(
        pile=dict(name=pile["name"], diameter=D, wt=t_over_D * D, top_elevation=0.0, bottom_elevation=-L),
        layer=dict(name="calibrated clay", top=0.0, bottom=-L),
        Custom_pisa_clay=openpile_layer(model, D, L),
        units="kPa for Su and G0; the conic parameters in the PISA clay normalisation "
              "(p/(Su D), m/(Su D^2), Hb/(Su D^2), Mb/(Su D^3) against y G0/(Su D) or psi G0/Su)",
    )
    with open(path, "w") as f:
        json.dump(doc, f, indent=1)


def read_openpile(path):
    """Reads an export back: returns (pile dict, layer dict, {field: [top,
    bottom]}); raises ValueError naming the first missing or invalid field."""
    with open(path) as f:
        doc = json.load(f)
    args = doc.get("Custom_pisa_clay")
    if not isinstance(args, dict):
        raise ValueError(f"{path}: no Custom_pisa_clay object")
    for name in ["Su", "G0"] + FIELDS:
        v = args.get(name)
        if not (isinstance(v, list) and len(v) == 2 and all(isinstance(x, (int, float)) for x in v)):
            raise ValueError(f"{path}: field {name} is not [top, bottom]")
        if name.endswith("_n"):
            if not all(0 <= x < 1 for x in v):
                raise ValueError(f"{path}: {name} = {v} outside OpenPile's 0 <= n < 1")
        elif not all(x > 0 for x in v):
            raise ValueError(f"{path}: {name} = {v} must be positive")
    return doc["pile"], doc["layer"], args
