#!/usr/bin/python3
"""Runs OpenPile (github.com/TchilDill/openpile, its source; pydantic >= 2)
on an export of calibrate.py and compares its mudline deflection with the
1D model of tools/pisa/beam.py at the same loads.

Usage: PYTHONPATH=<pydantic 2>:<openpile>/src /usr/bin/python3 \\
           tools/pisa/openpile_check.py DIR PILE
DIR: calibrate.py's --out; PILE: a pile name (openpile-PILE.json there).
The pile stands h = stick-up above the mudline (its top loaded by H: M = H h
at the mudline) and the soil is one Custom_pisa_clay or Custom_pisa_sand
Layer per exported layer from the mudline to the tip, under water (the
water line above the mudline): a sand layer's weight is the export's
(gamma' + 10 kN/m^3, so that OpenPile's sigma'_v is the FE's); a clay's is
18 kN/m^3, which Custom_pisa_clay does not use.  Prints, at 20-90 % of the 1D model's H at the end of its push,
OpenPile's and the 1D model's mudline deflection [m] and their ratio."""
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import export  # noqa: E402


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: openpile_check.py DIR PILE")
    out, name = sys.argv[1:3]
    try:
        from openpile.construct import Pile, SoilProfile, Layer, Model
        import openpile.soilmodels as soilmodels
    except ImportError as e:
        sys.exit(f"openpile_check.py: OpenPile cannot be imported ({e}); see doc/pisa-design-model.md")
    try:
        pile, layers = export.read_openpile(os.path.join(out, f"openpile-{name}.json"))
    except (OSError, ValueError) as e:
        sys.exit(f"openpile_check.py: {e}")
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)[name]
    with open(os.path.join(out, "model.json")) as f:
        h = json.load(f)["h_over_D"] * pile["diameter"]
    v1, th1, H1, M1 = (np.array(a) for a in s["curve_1d"])
    top = max(h, 1e-3)
    p = Pile.create_tubular(name=name, top_elevation=top, bottom_elevation=pile["bottom_elevation"],
                            diameter=pile["diameter"], wt=pile["wt"])
    with open(os.path.join(out, f"openpile-{name}.json")) as f:
        kind = json.load(f).get("soil_kind", "clay")
    lateral = getattr(soilmodels, export.OPENPILE_MODEL[kind])
    sp = SoilProfile(name="calibrated", top_elevation=0.0, water_line=10.0,
                     layers=[Layer(name=ly["name"], top=ly["top"], bottom=ly["bottom"], weight=ly.get("weight", 18.0),
                                   lateral_model=lateral(**ly[export.OPENPILE_MODEL[kind]])) for ly in layers])
    print(f"{'H [kN]':>10} {'v OpenPile [m]':>15} {'v 1D [m]':>10} {'ratio':>7}")
    for frac in (0.2, 0.4, 0.6, 0.8, 0.9):
        H = frac * H1[-1]
        m = Model.create(name=name, pile=p, soil=sp, x2mesh=[])  # x2mesh: its default is a pydantic Field object
        m.set_pointload(elevation=top, Py=H)
        m.set_support(elevation=pile["bottom_elevation"], Tz=True)
        r = m.solve()
        d = r.deflection
        z = d["Elevation [m]"].to_numpy()
        y = d["Deflection [m]"].to_numpy()
        order = np.argsort(z)
        v_op = float(np.interp(0.0, z[order], y[order]))
        v_1d = float(np.interp(H, H1, v1))
        print(f"{H:10.5g} {v_op:15.5g} {v_1d:10.5g} {v_op / v_1d:7.3f}")


if __name__ == "__main__":
    main()
