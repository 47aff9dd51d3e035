#!/usr/bin/python3
"""Checks of the formulas of the multi-surface clay
(include/fourier_ssi/coupled/multi_surface_backbone.h and multi_surface_clay.h;
derivation in doc/derivations/multi_surface_clay.md). Prints one PASS/FAIL
line per check and exits non-zero on failure. Run with Debian's
/usr/bin/python3 (sympy).

Units: strains in gamma_ref (u = gamma / gamma_ref), stresses in
G0 gamma_ref, so the backbone is f(u) = u / (1 + u).
"""
import sys
import sympy as sp

failures = 0


def report(name, ok):
    global failures
    print(("PASS " if ok else "FAIL ") + name)
    if not ok:
        failures += 1


u, p, q, x, w, h = sp.symbols("u p q x w h", positive=True)
f = u / (1 + u)


def tangent_at(t):
    """The tangent line of f at u = t, as a function of u (eq. 2.2)."""
    return f.subs(u, t) + sp.diff(f, u).subs(u, t) * (u - t)


# (2.2) slope and intercept of the tangent at t.
line = sp.expand(tangent_at(p))
report("2.2: tangent slope 1/(1+t)^2",
       sp.simplify(sp.diff(line, u) - 1 / (1 + p) ** 2) == 0)
report("2.2: tangent intercept t^2/(1+t)^2",
       sp.simplify(line.subs(u, 0) - p ** 2 / (1 + p) ** 2) == 0)

# (2.3) two tangents cross where 1 + u is the harmonic mean of 1 + p, 1 + q.
crossing = sp.solve(sp.Eq(tangent_at(p), tangent_at(q)), u)
harmonic = 2 * (1 + p) * (1 + q) / ((1 + p) + (1 + q)) - 1
report("2.3: tangents cross at the harmonic mean of 1 + t",
       len(crossing) == 1 and sp.simplify(crossing[0] - harmonic) == 0)

# (2.5) the cap at u_f: the last tangent passes through (u_f, f(u_f)) = s_u.
uf = sp.symbols("u_f", positive=True)
report("2.5: the tangent at u_f meets the cap at u_f",
       sp.simplify(tangent_at(uf).subs(u, uf) - f.subs(u, uf)) == 0)
su, G0, gr = sp.symbols("s_u G0 gamma_r", positive=True)
report("B2: s_u = G0 gamma_ref u_f / (1 + u_f) at u_f = s_u / (G0 gamma_ref - s_u)",
       sp.simplify(G0 * gr * f.subs(u, su / (G0 * gr - su)) - su) == 0)

# (3.1) the error of two tangents at their crossing, leading order in the
# spacing h, relative to f: h^2 / (4 u (1 + u)^2) with u the midpoint.
a = sp.symbols("a", positive=True)
cross = harmonic.subs({p: a - h / 2, q: a + h / 2})
gap = (tangent_at(a - h / 2).subs(u, cross) - f.subs(u, cross)) / f.subs(u, cross)
leading = sp.series(gap, h, 0, 3).removeO()
report("3.1: relative error at a crossing = h^2 / (4 u (1 + u)^2) + O(h^3)",
       sp.simplify(leading - h ** 2 / (4 * a * (1 + a) ** 2)) == 0)

# (3.2) psi(u) = 2 atan(sqrt(u)) has dpsi/du = 1 / (sqrt(u) (1 + u)): equal
# steps dpsi give h = dpsi sqrt(u) (1 + u), so the error (3.1) is dpsi^2 / 4.
psi = 2 * sp.atan(sp.sqrt(u))
report("3.2: dpsi/du = 1 / (sqrt(u) (1 + u))",
       sp.simplify(sp.diff(psi, u) - 1 / (sp.sqrt(u) * (1 + u))) == 0)
dpsi = sp.symbols("dpsi", positive=True)
report("3.2: the error (3.1) with h = dpsi sqrt(u)(1+u) is dpsi^2 / 4",
       sp.simplify((h ** 2 / (4 * u * (1 + u) ** 2)).subs(
           h, dpsi * sp.sqrt(u) * (1 + u)) - dpsi ** 2 / 4) == 0)
report("3.2: the nodes t = tan^2(psi / 2) invert psi",
       sp.simplify(sp.tan(psi / 2) ** 2 - u) == 0)

# (6.1) the damping of the Masing hyperbola: W_d = 8 (int_0^x f - x f(x)/2),
# W_s = x f(x) / 2, xi = W_d / (4 pi W_s).
area = 8 * (sp.integrate(f, (u, 0, x)) - x * f.subs(u, x) / 2)
xi = sp.simplify(area / (4 * sp.pi * x * f.subs(u, x) / 2))
closed = 4 / sp.pi * (1 + 1 / x) * (1 - sp.log(1 + x) / x) - 2 / sp.pi
report("6.1: xi(x) = (4/pi)(1 + 1/x)(1 - ln(1 + x)/x) - 2/pi",
       sp.simplify(xi - closed) == 0)
report("6.1: xi -> 0 as x -> 0 and -> 2/pi as x -> oo",
       sp.limit(closed, x, 0) == 0 and sp.limit(closed, x, sp.oo) == 2 / sp.pi)

# (6.2) the loop of one elastic-perfectly plastic element (G, tau) between
# +-x: a parallelogram of area 4 tau (x - tau / G) (x >= tau / G).
Ge, te = sp.symbols("G_e tau_e", positive=True)
y = te / Ge
# Unloading from (x, tau): elastic down to (x - 2y, -tau), then plastic.
loop = (te * (x - (-x + 2 * y))  # upper plastic branch on reloading
        + te * (x - 2 * y - (-x)))  # lower plastic branch on unloading
report("6.2: EPP loop area 4 tau (x - tau/G)",
       sp.simplify(loop - 4 * te * (x - y)) == 0)

sys.exit(1 if failures else 0)
