#!/usr/bin/python3
"""Rigid disc (radius a = r0) displaced by ubar inside an elastic ring
a <= r <= R, outer boundary fixed, plane strain: closed form (Michell n = 1
solution, Baguelin, Frank & Said 1977) for a rough (u_r, u_theta continuous)
and a smooth (u_r continuous, tau_rtheta = 0) interface, with all finite-R
terms. Compares with the thesis (Hernoune 2007) eqs 5.6-5.8.

Conventions (as the code, doc/theory.md): u_r = U(r) cos t, u_t = W(r) sin t,
sigma_r = Sr(r) cos t, sigma_t = St(r) cos t, tau_rt = T(r) sin t, tension
positive. The rigid disc moves u = ubar cos t, w = -ubar sin t (x-translation).
P = force per unit length applied to the disc along +x = force the disc
exerts on the soil = -pi r (Sr - T) (any r: equilibrium of the ring part).

Run: /usr/bin/python3 doc/derivations/disc_ring.py  (prints formulas, checks, numbers)
"""
import sympy as sp

r, a, R, ub, E, nu, P = sp.symbols('r a R ubar E nu P', positive=True)
lam = E * nu / ((1 + nu) * (1 - 2 * nu))
mu = E / (2 * (1 + nu))
b1, b2, b3, b4 = sp.symbols('b1:5')

# 1. General n = 1 solution: ansatz r^2, r^-2, 1, ln r in U and W; the
#    Navier equations fix four of the eight coefficients.
A = sp.symbols('A1:5')
Ut = A[0] * r**2 + A[1] / r**2 + A[2] + A[3] * sp.log(r)
Wt = b1 * r**2 + b2 / r**2 + b3 + b4 * sp.log(r)


def fields(U, W):
    er = sp.diff(U, r)
    et = (U + W) / r
    g = -U / r + sp.diff(W, r) - W / r
    Sr = (lam + 2 * mu) * er + lam * et
    St = lam * er + (lam + 2 * mu) * et
    T = mu * g
    return Sr, St, T


Sr, St, T = fields(Ut, Wt)
eq1 = sp.diff(Sr, r) + T / r + (Sr - St) / r   # radial equilibrium / cos t
eq2 = sp.diff(T, r) - St / r + 2 * T / r       # circumferential / sin t
L = sp.Symbol('L')
coeffs = []
for e in (eq1, eq2):
    e = sp.expand(sp.simplify(e * r**5)).subs(sp.log(r), L)
    coeffs += sp.Poly(e, r, L).coeffs()
sol = sp.solve(coeffs, A, dict=True)[0]
U = sp.simplify(Ut.subs(sol))
W = sp.simplify(Wt.subs(sol))
print('General n=1 solution (plane strain):')
print('  U =', U)
print('  W =', W)
Sr, St, T = [sp.simplify(f) for f in fields(U, W)]
for e in (sp.diff(Sr, r) + T / r + (Sr - St) / r,
          sp.diff(T, r) - St / r + 2 * T / r):
    assert sp.simplify(e) == 0
Pr = sp.simplify(-sp.pi * r * (Sr - T))
assert sp.simplify(sp.diff(Pr, r)) == 0, 'P must not depend on r'
print('  P = -pi r (Sr - T) =', sp.factor(Pr), '(independent of r: checked)')

cases = {
    'rough': [U.subs(r, a) - ub, W.subs(r, a) + ub,
              U.subs(r, R), W.subs(r, R)],
    'smooth': [U.subs(r, a) - ub, T.subs(r, a),
               U.subs(r, R), W.subs(r, R)],
}
kappa = 3 - 4 * nu
num = {E: 1e5, nu: sp.Rational(3, 10), a: sp.Rational(1, 2), R: 10}
results = {}
for name, bcs in cases.items():
    c = sp.solve(bcs, [b1, b2, b3, b4], dict=True)[0]
    Uc, Wc, Src, Stc, Tc = [sp.simplify(f.subs(c)) for f in (U, W, Sr, St, T)]
    Pc = sp.simplify(Pr.subs(c))
    k = sp.simplify(Pc / ub)
    results[name] = dict(U=Uc, W=Wc, Sr=Src, St=Stc, T=Tc, k=k)
    print('\n=== %s interface ===' % name)
    # ubar 8 pi E (1-nu) / (P (1+nu)) = bracket
    bracket = sp.simplify(8 * sp.pi * E * (1 - nu) / ((1 + nu) * k))
    print('  ubar = P (1+nu) / (8 pi E (1-nu)) * [',
          sp.simplify(sp.expand_log(bracket, force=True)), ']')
    print('  P/ubar =', float(k.subs(num)), 'kN/m per m (E=1e5, nu=0.3, a=0.5, R=10)')
    # stresses with P as the load: divide by P/ubar
    for lab, f in (('Sr', Src), ('St', Stc), ('T', Tc)):
        g = sp.simplify(f * 4 * sp.pi * a * (1 - nu) / (k * ub))  # bracket of 5.7
        print('  %s * 4 pi a (1-nu) / P =' % lab, sp.simplify(sp.expand(g)))
    # Compact forms (kappa = 3 - 4 nu), checked:
    if name == 'rough':
        B = kappa * sp.log(R**2 / a**2) - 2 / kappa * (R**2 - a**2) / (R**2 + a**2)
    else:
        B = kappa * sp.log(R**2 / a**2) + (R**2 - a**2) * (
            kappa**2 * (R**2 + a**2) + kappa * (R**2 - 3 * a**2) - 4 * R**2) / (
            2 * (kappa * R**4 + a**4))
    assert sp.simplify(sp.expand_log(bracket - B, force=True)) == 0
    print('  compact: ubar = P (1+nu)/(8 pi E (1-nu)) [', B, '] (checked)')
    if name == 'rough':
        pre = ub * k / (4 * sp.pi * a * (1 - nu))
        q = 1 / kappa / (1 + (R / a)**2) * r / a
        c3 = (a / r)**3 / (1 + (a / R)**2)
        forms = dict(Sr=-pre * ((3 - 2 * nu) * a / r - c3 + q),
                     St=pre * ((1 - 2 * nu) * a / r - c3 - 3 * q),
                     T=pre * ((1 - 2 * nu) * a / r + c3 - q))
        for lab, f in forms.items():
            assert sp.simplify(f - results[name][lab]) == 0, lab
        print('  compact (tension +, P along +x; Sr, St ~ cos t, T ~ sin t), checked:')
        print('    Sr = -P/(4 pi a (1-nu)) [(3-2nu) a/r - (a/r)^3/(1+(a/R)^2) + (r/a)/(kappa (1+(R/a)^2))]')
        print('    St = +P/(4 pi a (1-nu)) [(1-2nu) a/r - (a/r)^3/(1+(a/R)^2) - 3 (r/a)/(kappa (1+(R/a)^2))]')
        print('    T  = +P/(4 pi a (1-nu)) [(1-2nu) a/r + (a/r)^3/(1+(a/R)^2) - (r/a)/(kappa (1+(R/a)^2))]')
        # Thesis eq. 5.6 as printed
        u56 = P / (8 * sp.pi * E) * (1 + nu) / (1 - nu) * (
            kappa * sp.log((R / a)**2) - 2 / kappa)
        print('  thesis 5.6 P/ubar =', float((P / u56).subs(num)))
        # thesis 5.7 (as printed; cos t on all three, sign: compression +?)
        pre = P / (4 * sp.pi * a * (1 - nu))
        Sr57 = pre * ((3 - 2 * nu) * a / r - 1 / (1 + (a / R)**2) * (a / r)**3
                      + 1 / kappa / (1 + (R / a)**2) * r / a)
        St57 = pre * ((1 - 2 * nu) * a / r - 1 / (1 + (a / R)**2) * (a / r)**3
                      - 1 / kappa / (1 + (R / a)**2) * r / a)
        T57 = pre * ((1 - 2 * nu) * a / r + 1 / (1 + (a / R)**2) * (a / r)**3
                     - 1 / kappa / (1 + (R / a)**2) * r / a)
        results['thesis'] = dict(Sr=Sr57, St=St57, T=T57)

print('\nNumbers (E=1e5 kPa, nu=0.3, a=0.5, R=10, ubar=1e-3 m):')
for name in ('rough', 'smooth'):
    d = results[name]
    k = float(d['k'].subs(num))
    print('%s: P/ubar = %.6f kN/m/m, P(ubar=1e-3) = %.6f kN/m' % (name, k, k * 1e-3))
    for x in (1, 1.5, 2, 3, 5, 10):
        v = {**num, r: x * num[a], ub: sp.Rational(1, 1000)}
        print('  r/a=%-4s U=%.6e W=%.6e Sr=%.6f St=%.6f T=%.6f' % (
            x, *[float(d[f].subs(v)) for f in ('U', 'W', 'Sr', 'St', 'T')]))
d = results['thesis']
kr = results['rough']['k']
print('thesis 5.7 as printed with P = (P/ubar)_rough * 1e-3 (cos t; sign as printed):')
for x in (1, 1.5, 2, 3, 5, 10):
    v = {**num, r: x * num[a], ub: sp.Rational(1, 1000)}
    v[P] = kr.subs(v) * v[ub]
    print('  r/a=%-4s Sr=%.6f St=%.6f T=%.6f' % (
        x, *[float(d[f].subs(v)) for f in ('Sr', 'St', 'T')]))
