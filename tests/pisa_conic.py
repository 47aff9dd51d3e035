#!/usr/bin/python3
"""The PISA conic of tools/pisa/conic.py: its slope at the origin is k, it
reaches y_u at x_u and stays there, n = 0 is the bilinear min(k x, y_u),
n = 1 the straight line y_u x/x_u, every point is a root of the conic's
equation with y <= y_u, and conic_slope is its derivative.
Usage: pisa_conic.py EXE SOURCE_DIR WORK_DIR (EXE and WORK_DIR unused)."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(sys.argv[2] if len(sys.argv) > 2 else ".", "tools", "pisa"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from relative_checks import check, failed  # noqa: E402
from conic import conic, conic_slope  # noqa: E402



k, xu, yu = 40.0, 12.0, 9.0
for n in (0.0, 0.2, 0.5, 0.75, 0.95):
    h = 1e-9 * xu
    # the secant y(h)/h = k + O(h): extrapolated from h and 2 h
    sec = 2 * conic(h, k, n, xu, yu) / h - conic(2 * h, k, n, xu, yu) / (2 * h)
    check(f"n={n}: slope at the origin (secants at 1e-9, 2e-9 x_u, extrapolated) equals k", sec, k, 1e-6)
    check(f"n={n}: y(x_u) = y_u", conic(xu, k, n, xu, yu), yu, 1e-12)
    check(f"n={n}: y(3 x_u) = y_u", conic(3 * xu, k, n, xu, yu), yu, 1e-15)
    check(f"n={n}: odd, y(-x) = -y(x)", -conic(-0.3 * xu, k, n, xu, yu), conic(0.3 * xu, k, n, xu, yu), 1e-15)
    x = np.linspace(0, xu, 401)
    y = conic(x, k, n, xu, yu)
    X, Y, K = x / xu, y / yu, k * xu / yu
    F = -n * (Y - X) ** 2 + (1 - n) * (Y - K * X) * (Y - 1)
    check(f"n={n}: max |conic equation| on [0, x_u]", 1.0 + np.abs(F).max(), 1.0, 1e-13)
    check(f"n={n}: max y / y_u <= 1", max(1.0, Y.max()), 1.0, 1e-14)
    if not np.all(np.diff(y) >= -1e-13):
        failed.append(f"n={n}: monotonic")
    xs = np.linspace(0.05, 0.95, 19) * xu
    fd = (conic(xs + 1e-6, k, n, xu, yu) - conic(xs - 1e-6, k, n, xu, yu)) / 2e-6
    check(f"n={n}: conic_slope against central differences (max rel)",
          1.0 + np.max(np.abs(conic_slope(xs, k, n, xu, yu) - fd) / k), 1.0, 1e-6)
x = np.linspace(0, 2 * xu, 97)
check("n=0: bilinear min(k x, y_u), max deviation / y_u",
      1.0 + np.abs(conic(x, k, 0.0, xu, yu) - np.minimum(k * x, yu)).max() / yu, 1.0, 1e-14)
check("n=1: straight line y_u x/x_u, max deviation / y_u",
      1.0 + np.abs(conic(x, k, 1.0, xu, yu) - yu * np.minimum(x / xu, 1)).max() / yu, 1.0, 1e-14)
print(f"{len(failed)} failed")
sys.exit(1 if failed else 0)
