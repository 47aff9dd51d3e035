#!/usr/bin/python3
"""tools/pisa/fit.py recovers known parameters: one synthetic conic curve
(points to 2 x_u) and a family whose parameters are linear in s, each
within the tolerances stated below.
Usage: pisa_fit.py EXE SOURCE_DIR WORK_DIR (EXE and WORK_DIR unused)."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(sys.argv[2] if len(sys.argv) > 2 else ".", "tools", "pisa"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from relative_checks import check, failed  # noqa: E402
from conic import conic  # noqa: E402
from fit import fit_curve, fit_linear_family, linear  # noqa: E402



# one curve: PISA-like clay p-v values (k x_u / y_u = 26), 30 points
truth = dict(k=9.0, n=0.6, xu=30.0, yu=10.4)
x = np.geomspace(0.02, 60.0, 30)
y = conic(x, **truth)
f = fit_curve(x, y)
for q in ("k", "n", "xu", "yu"):
    check(f"one curve: {q}", f[q], truth[q], 1e-6)
check("one curve: RMS error / y_u below 1e-9", 1 + f["rms"], 1.0, 1e-9)

# a family: 5 curves at s = 0..4 with k, n, x_u, y_u linear in s
top = dict(k=12.0, n=0.3, xu=20.0, yu=8.0)
bottom = dict(k=6.0, n=0.7, xu=40.0, yu=12.0)
curves = []
for s in np.linspace(0, 4, 5):
    p = {q: linear(top[q], bottom[q], s, 0.0, 4.0) for q in top}
    xs = np.geomspace(0.02, 2.2 * p["xu"], 25)
    curves.append(dict(s=s, x=xs, y=conic(xs, **p)))
r = fit_linear_family(curves, 0.0, 4.0)
for which, ref in (("top", top), ("bottom", bottom)):
    for q in ref:
        check(f"family: {q} at the {which}", r[which][q], ref[q], 1e-6)
print(f"{len(failed)} failed")
sys.exit(1 if failed else 0)
