"""Constrained fits of the PISA conic (conic.py) to normalised reaction
curves: one curve at a time (`fit_curve`), and a family of curves whose
parameters vary linearly in a variable s (z/D for the distributed
components, L/D for the base ones, `fit_linear_family`).

Constraints as PISA: 0 <= n <= 1, y_u > 0, x_u > 0, k >= y_u/x_u.  The error
of a fit is the RMS over the curve's points of (y_fit - y_FE) / y_u."""
import numpy as np
from scipy.optimize import least_squares

from conic import conic


def prepare(x, y, resisting_only=False):
    """The curve's monotonic branch in the direction of its largest |x|:
    returns (sign, x >= 0, y) without the points that move against it, and
    with resisting_only without those whose reaction does not resist the
    motion (y < 0: above a rotation point that moves down during the push,
    the soil can push the pile along at the first steps)."""
    x = np.asarray(x, float)
    y = np.asarray(y, float)
    if x.size == 0 or not np.any(x != 0):
        return 0.0, x[:0], y[:0]
    sgn = np.sign(x[np.argmax(np.abs(x))])
    xs, ys = sgn * x, sgn * y
    keep = (xs > 0) & ((ys >= 0) | (not resisting_only))
    return sgn, xs[keep], ys[keep]


def fit_curve(x, y, xu_max_factor=10.0):
    """Fits (k, n, x_u, y_u) to one curve x, y (x > 0, increasing branch).
    x_u is bounded by xu_max_factor times the largest x of the data; when it
    lands beyond the data, `reached` is False (the plateau is extrapolated).
    Returns dict k, n, xu, yu, rms, reached."""
    x = np.asarray(x, float)
    y = np.asarray(y, float)
    xmax = x.max()
    ymax = max(np.abs(y).max(), 1e-12)
    # parameters: ln y_u, ln x_u, n, ln K with K = k x_u / y_u >= 1
    lo = [np.log(ymax) - 5, np.log(xmax) - 8, 0.0, 0.0]
    hi = [np.log(ymax) + 5, np.log(xmax * xu_max_factor), 1.0, np.log(1e6)]

    def unpack(q):
        yu, xu, n, K = np.exp(q[0]), np.exp(q[1]), q[2], np.exp(q[3])
        return K * yu / xu, n, xu, yu

    def resid(q):
        k, n, xu, yu = unpack(q)
        return (conic(x, k, n, xu, yu) - y) / ymax

    i0 = np.argmin(x)
    k0 = max(y[i0] / x[i0], 1e-9)
    best = None
    for n0 in (0.05, 0.5, 0.95):
        for xu0 in (0.5 * xmax, 2 * xmax):
            yu0 = ymax * (1.0 if xu0 == xmax else 1.2)
            K0 = max(k0 * xu0 / yu0, 1.0 + 1e-6)
            q0 = np.clip([np.log(yu0), np.log(xu0), n0, np.log(K0)], lo, hi)
            r = least_squares(resid, q0, bounds=(lo, hi), x_scale="jac",
                              xtol=1e-12, ftol=1e-12, gtol=1e-12, max_nfev=300)
            if best is None or r.cost < best.cost:
                best = r
    k, n, xu, yu = unpack(best.x)
    rms = float(np.sqrt(np.mean((conic(x, k, n, xu, yu) - y) ** 2)) / yu)
    return dict(k=float(k), n=float(n), xu=float(xu), yu=float(yu), rms=rms,
                reached=bool(xu <= xmax * (1 + 1e-9)))


def linear(top, bottom, s, s0, s1):
    """The value at s of the linear function through (s0, top), (s1, bottom)."""
    w = 0.0 if s1 == s0 else (np.asarray(s, float) - s0) / (s1 - s0)
    return top + (bottom - top) * w


def fit_linear_family(curves, s0, s1, start=None, xu_max_factor=10.0, shared_xu=False, yu_range=None):
    """One fit of all `curves` (list of dicts with s, x, y; x > 0) with each
    parameter linear in s between its values at s0 and s1.  Returns dict
    with 'top' and 'bottom' (k, n, xu, yu at s0 and s1), 'rms' per curve
    and 'rms_all'.  The constraints are imposed at s0 and s1 (n, x_u,
    y_u: linear, so everywhere between) and k x_u >= y_u on the curves'
    s by a penalty.  A curve's residuals are divided by its 'scale' (default
    its own largest |y|).  shared_xu: one x_u for all s (as PISA's clay
    p-v and m-psi, Byrne et al. 2020), when the curves do not resolve its
    variation.  yu_range = (t0, t1): y_u linear in each curve's 't'
    instead of s (z/L, as PISA's sand p-v and m-psi, Burd et al. 2020), its
    'top' and 'bottom' values then at t0 and t1."""
    xmax = max(c["x"].max() for c in curves)
    ymax = max(np.abs(c["y"]).max() for c in curves)
    scale = [c.get("scale") or max(np.abs(c["y"]).max(), 1e-12) for c in curves]
    # q = ln k0, ln k1, n0, n1, ln xu0, ln xu1, ln yu0, ln yu1
    lo = [np.log(ymax / xmax) - 6] * 2 + [0.0, 0.0] + [np.log(xmax) - 8] * 2 + [np.log(ymax) - 6] * 2
    hi = [np.log(ymax / xmax) + 12] * 2 + [1.0, 1.0] + [np.log(xmax * xu_max_factor)] * 2 + [np.log(ymax) + 3] * 2

    def params(q, s, t=None):
        if shared_xu:
            q = np.concatenate([q[:5], q[4:5], q[5:]])
        k = linear(np.exp(q[0]), np.exp(q[1]), s, s0, s1)
        n = linear(q[2], q[3], s, s0, s1)
        xu = linear(np.exp(q[4]), np.exp(q[5]), s, s0, s1)
        if yu_range is None:
            yu = linear(np.exp(q[6]), np.exp(q[7]), s, s0, s1)
        else:
            yu = linear(np.exp(q[6]), np.exp(q[7]), t, *yu_range)
        return k, n, xu, yu

    def at_curve(q, c):
        return params(q, c["s"], c.get("t"))

    def resid(q):
        out = []
        for c, sc in zip(curves, scale):
            k, n, xu, yu = at_curve(q, c)
            out.append((conic(c["x"], k, n, xu, yu) - c["y"]) / sc)
            out.append([10.0 * max(0.0, 1.0 - k * xu / yu)])
        return np.concatenate(out)

    starts = []
    if start is not None:
        starts.append(start)
    ks = [c.get("k0", ymax / xmax) for c in curves]
    for n0 in (0.2, 0.8):
        starts.append(dict(k=(np.median(ks),) * 2, n=(n0, n0), xu=(xmax,) * 2, yu=(ymax,) * 2))
    best = None
    for st in starts:
        q0 = np.array([np.log(st["k"][0]), np.log(st["k"][1]), st["n"][0], st["n"][1],
                       np.log(st["xu"][0]), np.log(st["xu"][1]),
                       np.log(st["yu"][0]), np.log(st["yu"][1])])
        lo_, hi_ = np.array(lo), np.array(hi)
        if shared_xu:
            q0, lo_, hi_ = (np.delete(a, 5) for a in (q0, lo_, hi_))
        q0 = np.clip(q0, lo_ + 1e-9, hi_ - 1e-9)
        r = least_squares(resid, q0, bounds=(lo_, hi_), x_scale="jac", max_nfev=3000)
        if best is None or r.cost < best.cost:
            best = r
    q = best.x
    rms = []
    for c in curves:
        k, n, xu, yu = at_curve(q, c)
        rms.append(float(np.sqrt(np.mean((conic(c["x"], k, n, xu, yu) - c["y"]) ** 2)) / yu))
    names = ("k", "n", "xu", "yu")
    ends = (None, None) if yu_range is None else yu_range
    top = dict(zip(names, [float(v) for v in params(q, s0, ends[0])]))
    bottom = dict(zip(names, [float(v) for v in params(q, s1, ends[1])]))
    # the penalty holds k x_u >= y_u to about 1e-3; make it exact at the ends
    for end in (top, bottom):
        end["k"] = max(end["k"], end["yu"] / end["xu"])
    return dict(top=top, bottom=bottom, s0=float(s0), s1=float(s1), rms=rms, cost=float(best.cost),
                rms_all=float(np.sqrt(np.mean(np.square(rms)))))
