#!/usr/bin/python3
"""Which component's depth (or L/D) model carries the 1D model's error: for
each fitted pile, the 1D model is rerun with one component at a time
replaced by the pile's own per-curve conics (model.OwnCurvesModel), the
others kept from the calibrated model.

Usage: /usr/bin/python3 tools/pisa/which_component.py SITE.txt DIR
(DIR: a calibrate.py --out with its runs and model.json).  Prints, per pile
and replacement, H_1D/H_FE - 1 at the first FE step, at the end and its
largest |.| over the steps."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pipeline  # noqa: E402
import runs  # noqa: E402
from fit import prepare, fit_curve  # noqa: E402
from model import Model, OwnCurvesModel  # noqa: E402
from space import read_spec, SpecError  # noqa: E402


class Mixed(Model):
    """The calibrated model with the components in `own_components` taken
    from one pile's own conics."""

    def __init__(self, model, own_model, own_components):
        super().__init__(model.params, model.profile, model.soil_kind)
        self.own_model = own_model
        self.own_components = own_components

    def at(self, component, s, L_over_D=None):
        if component in self.own_components:
            return self.own_model.at(component, s, L_over_D)
        return Model.at(self, component, s, L_over_D)


def fitted_curves(curves, kind):
    """The pile's curves with each one's conic fit ('fit', None below 3
    points), as calibrate.py fits them."""
    for c in ("py", "mt", "Hb", "Mb"):
        for cv in curves[c]:
            _, x, y = prepare(cv["x"], cv["y"], pipeline.RESISTING_ONLY[kind])
            cv["fit"] = fit_curve(x, y) if x.size >= 3 else None
    return curves


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: which_component.py SITE.txt DIR")
    try:
        spec = read_spec(sys.argv[1])
    except SpecError as e:
        sys.exit(f"which_component.py: {e}")
    out = sys.argv[2]
    if not os.path.isfile(os.path.join(out, "model.json")):
        sys.exit(f"which_component.py: no model.json in {out} (run calibrate.py first)")
    model = Model.from_json(os.path.join(out, "model.json"))
    print("H_1D/H_FE - 1 with the components named taken from the pile's own conics:")
    for p in spec["piles"]:
        if not p["fitted"]:
            continue
        d = runs.read_pile(os.path.join(out, "runs", p["name"]))
        if d is None:
            print(f"  {p['name']}: no curves")
            continue
        d["initial"] = runs.read_pile(os.path.join(out, "runs", p["name"] + "-initial"))
        conics = pipeline.own_conics(fitted_curves(pipeline.pile_curves(p, d, model.soil_kind), model.soil_kind),
                                     lambda c: model.at(c, p["L_over_D"], p["L_over_D"]))
        own = OwnCurvesModel(conics, model.profile, p["D"], model.soil_kind)
        fe = pipeline.head_fe(d)
        for use in ((), ("py",), ("mt",), ("Hb", "Mb"), ("py", "mt", "Hb", "Mb")):
            name = "+".join(use) if use else "none (the model)"
            try:
                dH = pipeline.compare(fe, pipeline.run_1d(Mixed(model, own, use), spec, p))[0]
            except RuntimeError as e:
                print(f"  {p['name']:10s} own {name:18s}: FAILED, {e}")
                continue
            print(f"  {p['name']:10s} own {name:18s}: first step {dH[0]:+.3f}, end {dH[-1]:+.3f}, "
                  f"max |.| {np.abs(dH).max():.3f}")


if __name__ == "__main__":
    main()
