#!/usr/bin/python3
"""Checks of doc/nonlinear-interfaces.md (sympy). Prints PASS/FAIL per check,
exits non-zero on a failure.

 1. Slip return of the Mohr-Coulomb interface (tension positive t_n):
    dl = f_tr / (ks + kn tan(phi) tan(psi)) lands on f = 0, and the plastic
    increment is dl * grad g (g = tau + t_n tan(psi)), i.e. t = t_tr - D dl grad g.
 2. The theta integral of the virtual work, trapezoidal rule with N > 2 n_max,
    equals the exact integral for products of harmonics <= n_max.
 3. The capacities of the rigid pile used by tests/coupled/interface_coulomb_pile.cc.
 4. Gauss with p + 1 points integrates N_i N_j r (degree 2p + 1) exactly.
"""
import sys
import sympy as sp

failures = 0


def report(name, ok):
    global failures
    print(("PASS " if ok else "FAIL ") + name)
    failures += 0 if ok else 1


# 1. slip return
kn, ks, c, tp, tq = sp.symbols("k_n k_s c tan_phi tan_psi", positive=True)
ts, tn, tt = sp.symbols("t_s t_n t_theta", real=True)
tau = sp.sqrt(ts**2 + tt**2)
f_tr = tau + tn * tp - c
dl = f_tr / (ks + kn * tp * tq)
scale = (tau - ks * dl) / tau
t_new = (scale * ts, tn - kn * tq * dl, scale * tt)
f_new = sp.sqrt(t_new[0]**2 + t_new[2]**2) + t_new[1] * tp - c
# on the slip branch tau - ks dl >= 0, so sqrt(...) = tau - ks dl
f_branch = (tau - ks * dl) + t_new[1] * tp - c
report("slip return lands on f = 0", sp.simplify(f_branch) == 0)
grad_g = (ts / tau, tq, tt / tau)
D = (ks, kn, ks)
flow = [sp.simplify((t_new[i] - (ts, tn, tt)[i]) + D[i] * dl * grad_g[i])
        for i in range(3)]
report("t = t_tr - D dl grad g (non-associated flow)", all(e == 0 for e in flow))
num = {kn: 1000, ks: 500, c: 10, tp: sp.tan(sp.pi / 6), tq: 0, ts: 100,
       tn: -100, tt: 50}
report("hand case slip tau = 67.73503",
       abs(float(((tau - ks * dl)).subs(num)) - 67.73502691896257) < 1e-9)

# 2. trapezoidal theta integration
th = sp.symbols("theta")
ok = True
for n_max in (0, 1, 2, 3):
    N = 2 * n_max + 1
    for m in range(n_max + 1):
        for n in range(n_max + 1):
            for fm in (sp.cos, sp.sin):
                for fn in (sp.cos, sp.sin):
                    e = fm(m * th) * fn(n * th)
                    exact = sp.integrate(e, (th, 0, 2 * sp.pi))
                    trap = 2 * sp.pi / N * sum(
                        e.subs(th, 2 * sp.pi * j / N) for j in range(N))
                    ok = ok and abs(float(exact - trap)) < 1e-12
report("trapezoid with N = 2 n_max + 1 exact for products <= n_max", ok)
e = sp.cos(2 * th)**2
trap = 2 * sp.pi / 4 * sum(e.subs(th, 2 * sp.pi * j / 4) for j in range(4))
report("N = 2 n_max aliases: cos^2 2t at N = 4 gives 2 pi, not pi",
       sp.simplify(trap - 2 * sp.pi) == 0)

# 3. capacities (a, L, c, phi, gamma', K0)
a, L, z, r = sp.symbols("a L z r", positive=True)
g, K0 = sp.symbols("gamma K0", positive=True)
shaft_torque = sp.integrate(2 * sp.pi * a * a * (c + K0 * g * z * tp), (z, 0, L))
base_torque = sp.integrate(2 * sp.pi * r * r * (c + g * L * tp), (r, 0, a))
report("torsion shaft 2 pi a^2 (c L + K0 g tan L^2/2)",
       sp.simplify(shaft_torque - 2 * sp.pi * a**2 * (c * L + K0 * g * tp * L**2 / 2)) == 0)
report("torsion base 2 pi a^3 (c + g L tan)/3",
       sp.simplify(base_torque - 2 * sp.pi * a**3 * (c + g * L * tp) / 3) == 0)
vals = {a: sp.Rational(1, 2), L: 5, c: 5, tp: sp.tan(25 * sp.pi / 180), g: 10,
        K0: sp.Rational(1, 2)}
print("   T_u(a=0.5, L=5, c=5, phi=25, g=10, K0=0.5) = %.6f kN m"
      % float((shaft_torque + base_torque).subs(vals)))
pull = sp.integrate(2 * sp.pi * a * (K0 * g * z * tp), (z, 0, L)) + g * L * sp.pi * a**2
vals[c] = 0
print("   V_u pull-out (c=0) shaft + base release = %.6f kN" % float(pull.subs(vals)))

# 4. Gauss p + 1 on N_i N_j r
xi = sp.symbols("xi")
for p in (2, 4):
    nodes = [sp.Rational(k, p) for k in range(p + 1)]
    Nf = [sp.prod([(xi - nodes[m]) / (nodes[k] - nodes[m])
                   for m in range(p + 1) if m != k]) for k in range(p + 1)]
    roots = sp.Poly(sp.legendre(p + 1, xi)).nroots(n=30)
    gx = [(rt + 1) / 2 for rt in roots]
    gw = [1 / ((1 - rt**2) * sp.diff(sp.legendre(p + 1, xi), xi).subs(xi, rt)**2)
          for rt in roots]
    rr = 1 + 3 * xi
    ok = True
    for i in range(p + 1):
        for j in range(p + 1):
            e = Nf[i] * Nf[j] * rr
            exact = sp.integrate(e, (xi, 0, 1))
            quad = sum(w * e.subs(xi, x) for x, w in zip(gx, gw))
            ok = ok and abs(float(exact - quad)) < 1e-14  # 30-digit roots
    report("Gauss %d points exact for N_i N_j r, p = %d" % (p + 1, p), ok)

sys.exit(1 if failures else 0)
