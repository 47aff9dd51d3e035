"""The PISA conic function (Byrne et al. 2020, Burd et al. 2020,
Geotechnique 70(11)) and its derivative.

With X = x/x_u, Y = y/y_u and K = k x_u / y_u (K >= 1), the curve for
0 <= x < x_u is the root of

    -n (Y - X)^2 + (1 - n) (Y - K X) (Y - 1) = 0,

and y = y_u for x >= x_u.  Expanded in Y this is a Y^2 + b Y + c = 0 with

    a = 1 - 2 n,
    b = 2 n X - (1 - n) (1 + K X),
    c = (1 - n) K X - n X^2.

At X = 0 the roots are Y = 0 and Y = (1 - n)/(1 - 2 n); the curve is the
branch through the origin, written without the cancellation at a = 0
(n = 1/2):

    Y = 2 c / (-b + sqrt(b^2 - 4 a c)).

Checks (tests/pisa_conic.py): near the origin Y = K X + O(X^2), so the slope
dy/dx is k; at X = 1, a + b + c = 0, so Y = 1 is a root, the one this
branch reaches; n = 0 gives (Y - K X)(Y - 1) = 0, the bilinear curve
min(k x, y_u); n = 1 gives (Y - X)^2 = 0, the straight line y = y_u x/x_u
(k then has no effect).  Odd extension: y(-x) = -y(x).
"""
import numpy as np


def conic(x, k, n, xu, yu):
    """y(x) of the conic; x any array, the parameters scalars or arrays that
    broadcast with it."""
    x = np.asarray(x, dtype=float)
    s = np.sign(x)
    X = np.minimum(np.abs(x) / xu, 1.0)
    K = k * xu / yu
    a = 1.0 - 2.0 * n
    b = 2.0 * n * X - (1.0 - n) * (1.0 + K * X)
    c = (1.0 - n) * K * X - n * X * X
    disc = np.maximum(b * b - 4.0 * a * c, 0.0)
    den = -b + np.sqrt(disc)
    # den vanishes only for n = 1 (then b^2 = 4 a c and Y = X); for n near
    # 1 it may be negative with c < 0, and 2 c / den is still the branch.
    tiny = 1e-14 * (1.0 + np.abs(b))
    with np.errstate(invalid="ignore", divide="ignore"):
        Y = np.where(np.abs(den) > tiny, 2.0 * c / np.where(np.abs(den) > tiny, den, 1.0), X)
    return s * yu * np.minimum(Y, 1.0)


def conic_slope(x, k, n, xu, yu):
    """dy/dx by implicit differentiation of F(X, Y) = 0 (F the quadratic
    above): dY/dX = -F_X / F_Y; 0 beyond x_u."""
    x = np.asarray(x, dtype=float)
    X = np.minimum(np.abs(x) / xu, 1.0)
    Y = np.abs(conic(x, k, n, xu, yu)) / yu
    K = k * xu / yu
    FX = 2.0 * n * (Y - X) - (1.0 - n) * K * (Y - 1.0)
    FY = -2.0 * n * (Y - X) + (1.0 - n) * (2.0 * Y - 1.0 - K * X)
    with np.errstate(invalid="ignore", divide="ignore"):
        dYdX = np.where(np.abs(FY) > 1e-12, -FX / np.where(np.abs(FY) > 1e-12, FY, 1.0), 1.0)
    # F_Y = F_X = 0 only on the straight line of n = 1: dY/dX = 1 there.
    dYdX = np.where(np.abs(x) >= xu, 0.0, dYdX)
    return dYdX * yu / xu
