#!/usr/bin/python3
"""Checks of the closed-form return mappings of include/fourier_ssi/coupled/soil_law.h
(doc/soil-plasticity.md section 2). Prints one PASS/FAIL line per check and
exits non-zero on failure. Run with Debian's /usr/bin/python3 (sympy).

Principal stresses s1 >= s2 >= s3, tension positive. Elastic law in principal
space: s = D e, D = (K - 2G/3) 1 1^T + 2G I. A plane of the yield surface is
f = n.s - k with the plastic potential gradient m; the return onto a set of
planes is s = s_tr - sum_a dgamma_a D m_a with f_b(s) = 0.
"""
import sys
import sympy as sp

failures = 0


def report(name, ok):
    global failures
    print(("PASS " if ok else "FAIL ") + name)
    if not ok:
        failures += 1


G, K, k = sp.symbols("G K k", positive=True)
s1, s2, s3 = sp.symbols("s1 s2 s3", real=True)
sf, spsi = sp.symbols("sin_phi sin_psi", nonnegative=True)
D = (K - 2 * G / 3) * sp.ones(3, 3) + 2 * G * sp.eye(3)
trial = sp.Matrix([s1, s2, s3])


def plane(i, j, sine):
    v = [0, 0, 0]
    v[i] = 1 + sine
    v[j] = -(1 - sine)
    return sp.Matrix(v)


def return_to(planes):
    g = sp.symbols("g0:%d" % len(planes))
    s = trial - sum((g[a] * D * planes[a][1] for a in range(len(planes))),
                    sp.zeros(3, 1))
    sol = sp.solve([(planes[b][0].T * s)[0] - planes[b][2]
                    for b in range(len(planes))], g, dict=True)[0]
    return s.subs(sol), [sol[x] for x in g]


# 1. Mohr-Coulomb main plane: de Souza Neto et al. (2008) eq. (8.41):
#    dgamma = f_tr / (4G(1 + sin phi sin psi / 3) + 4K sin phi sin psi)
main = (plane(0, 2, sf), plane(0, 2, spsi), k)
s, g = return_to([main])
f_tr = (s1 - s3) + (s1 + s3) * sf - k
report("MC main plane: dgamma closed form",
       sp.simplify(g[0] - f_tr / (4 * G * (1 + sf * spsi / 3)
                                 + 4 * K * sf * spsi)) == 0)
report("MC main plane: f(s) = 0",
       sp.simplify((main[0].T * s)[0] - k) == 0)
a1 = 2 * G * (1 + spsi / 3) + 2 * K * spsi
a2 = (4 * G / 3 - 2 * K) * spsi
a3 = 2 * G * (1 - spsi / 3) - 2 * K * spsi
report("MC main plane: s1, s2, s3 updates (eq. 8.42)",
       sp.simplify(s - sp.Matrix([s1 - a1 * g[0], s2 + a2 * g[0],
                                  s3 + a3 * g[0]])) == sp.zeros(3, 1))

# 2. Tresca (sin phi = sin psi = 0, k = 2 s_u): the return keeps the mean
#    stress and moves s1, s3 by -/+ (s1 - s3 - 2 s_u)/2.
su = sp.symbols("s_u", positive=True)
tmain = (plane(0, 2, 0), plane(0, 2, 0), 2 * su)
s, g = return_to([tmain])
report("Tresca plane: s1 = s1_tr - f/2, s3 = s3_tr + f/2, s2 kept",
       sp.simplify(s - sp.Matrix([s1 - (s1 - s3 - 2 * su) / 2, s2,
                                  s3 + (s1 - s3 - 2 * su) / 2]))
       == sp.zeros(3, 1))
# Right edge s1 = s2: closed form s1 = s2 = p + 2 s_u / 3, s3 = p - 4 s_u / 3
p = (s1 + s2 + s3) / 3
s, g = return_to([tmain, (plane(1, 2, 0), plane(1, 2, 0), 2 * su)])
report("Tresca right edge: s1 = s2 = p + 2su/3, s3 = p - 4su/3",
       sp.simplify(s - sp.Matrix([p + 2 * su / 3, p + 2 * su / 3,
                                  p - 4 * su / 3])) == sp.zeros(3, 1))
s, g = return_to([tmain, (plane(0, 1, 0), plane(0, 1, 0), 2 * su)])
report("Tresca left edge: s2 = s3 = p - 2su/3, s1 = p + 4su/3",
       sp.simplify(s - sp.Matrix([p + 4 * su / 3, p - 2 * su / 3,
                                  p - 2 * su / 3])) == sp.zeros(3, 1))

# 3. Edge selection: after a main-plane return that breaks the order,
#    s2' > s1' means the right edge (s1 = s2), s2' < s3' the left edge. On
#    the right edge of Tresca the multipliers are both >= 0 exactly when the
#    trial is beyond both planes with s2 closer to s1 than the main-plane
#    return allows: dgamma_2 = (2 f_b - f_a) / (6 G) with f_a, f_b the trial
#    values of the two planes.
s, g = return_to([tmain, (plane(1, 2, 0), plane(1, 2, 0), 2 * su)])
fa = s1 - s3 - 2 * su
fb = s2 - s3 - 2 * su
report("Tresca right edge multipliers: (2 f_a - f_b)/(6G), (2 f_b - f_a)/(6G)",
       sp.simplify(g[0] - (2 * fa - fb) / (6 * G)) == 0
       and sp.simplify(g[1] - (2 * fb - fa) / (6 * G)) == 0)
s_main, g_main = return_to([tmain])
report("Tresca: s2' > s1' after the plane return iff dgamma_2 > 0 on the edge",
       sp.simplify((s_main[1] - s_main[0]) - (2 * fb - fa) / 2) == 0)

# 4. Rough circular footing, Tresca: the published limits used by the tests.
report("Randolph & Houlsby 1984 rough disc: 4 sqrt(2) + 2 pi = 11.94",
       abs(float(4 * sp.sqrt(2) + 2 * sp.pi) - 11.94) < 5e-3)
report("Randolph & Houlsby 1984 smooth disc: 6 + pi = 9.14",
       abs(float(6 + sp.pi) - 9.14) < 5e-3)

sys.exit(1 if failures else 0)
