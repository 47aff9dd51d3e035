#!/usr/bin/python3
"""Checks of the formulas of the multi-surface sand
(include/fourier_ssi/coupled/multi_surface_sand.h; derivation in
doc/derivations/multi_surface_sand.md), independent of the C++ code:
  - the Mohr-Coulomb strengths of simple shear, triaxial compression and
    extension (section 2), in sympy from the principal stresses;
  - the homogeneity f(w sigma; w c) = w f(sigma; c) (section 2);
  - the sum of stresses in w_i C lies in C, and on its face when the
    elements share one face and the principal directions (section 2), by
    sampling random stresses in numpy;
  - the hyperbola (S3): G / G0 = 1/2 at x = 1/R_f, q_f reached at
    x = 1/(1 - R_f), and u_f = R_f / (1 - R_f) in the clay's units.
Prints one PASS/FAIL line per check and exits non-zero on failure.
"""
import sys

import numpy as np
import sympy as sp

failures = 0


def report(name, ok):
    global failures
    print(("PASS " if ok else "FAIL ") + name)
    if not ok:
        failures += 1


phi, p, c, q, tau, w, x, rf = sp.symbols("phi p c q tau w x R_f",
                                         positive=True)


def yield_principal(s1, s3, cohesion):
    """Mohr-Coulomb, tension positive, s1 >= s3."""
    return (s1 - s3) + (s1 + s3) * sp.sin(phi) - 2 * cohesion * sp.cos(phi)


# Section 2: the strengths of the three paths from an isotropic -p.
shear = sp.solve(yield_principal(-p + tau, -p - tau, c), tau)[0]
report("simple shear: tau_f = p sin phi + c cos phi",
       sp.simplify(shear - (p * sp.sin(phi) + c * sp.cos(phi))) == 0)
compression = sp.solve(yield_principal(-p + q / 3, -p - 2 * q / 3, c), q)[0]
report("triaxial compression: q_f = 6 tau_f / (3 - sin phi)",
       sp.simplify(compression - 6 * shear / (3 - sp.sin(phi))) == 0)
extension = sp.solve(yield_principal(-p + 2 * q / 3, -p - q / 3, c), q)[0]
report("triaxial extension: q_f = 6 tau_f / (3 + sin phi)",
       sp.simplify(extension - 6 * shear / (3 + sp.sin(phi))) == 0)
s1, s3 = sp.symbols("s1 s3")
report("homogeneity: f(w sigma; w c) = w f(sigma; c)",
       sp.simplify(yield_principal(w * s1, w * s3, w * c) -
                   w * yield_principal(s1, s3, c)) == 0)
# Drained compression at constant s1 = sigma_r: the axial stress at failure.
sa = sp.symbols("sigma_a", positive=True)
axial = sp.solve(yield_principal(-p, -sa, c), sa)[0]
n_phi = (1 + sp.sin(phi)) / (1 - sp.sin(phi))
report("drained compression: sigma'_a = sigma'_r N_phi + 2 c sqrt(N_phi)",
       abs(float((axial - (p * n_phi + 2 * c * sp.sqrt(n_phi))).subs(
           {phi: 0.61, p: 37.0, c: 3.0}))) < 1e-12)

# Section 2 by sampling: stresses in w_i C sum into C.
rng = np.random.default_rng(3)
f_phi, f_c = np.radians(35.0), 2.0


def f_num(stress, cohesion):
    s = np.linalg.eigvalsh(stress)
    return (s[-1] - s[0]) + (s[-1] + s[0]) * np.sin(f_phi) - \
        2 * cohesion * np.cos(f_phi)


def surface_sample(cohesion):
    """A random stress ON the surface of C(cohesion): the apex c cot phi 1
    plus y with principal values y1 >= y2 >= y3 on the cone f(y; 0) = 0,
    y3 = y1 (1 + sin phi) / (1 - sin phi), in random principal axes."""
    y1 = -rng.uniform(1.0, 200.0)
    y3 = y1 * (1 + np.sin(f_phi)) / (1 - np.sin(f_phi))
    y2 = rng.uniform(y3, y1)
    axes, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    apex = cohesion / np.tan(f_phi)
    return apex * np.eye(3) + axes @ np.diag([y1, y2, y3]) @ axes.T


weights = rng.dirichlet(np.ones(6))
worst, worst_own = -np.inf, 0.0
for trial in range(300):
    parts = [surface_sample(wi * f_c) for wi in weights]
    worst_own = max(worst_own,
                    max(abs(f_num(s_i, wi * f_c))
                        for s_i, wi in zip(parts, weights)))
    worst = max(worst, f_num(sum(parts), f_c))
report("the samples lie on their surfaces w_i C (largest |f| %.2g)" %
       worst_own, worst_own < 1e-10)
report("sum of sigma_i on the surfaces of w_i C is in C (300 samples, "
       "largest f %.3g)" % worst, worst <= 1e-9)
# Coaxial, on one face: s_i = w_i (a point on the face of C).
on_face = np.diag([-50.0, -80.0, 0.0])
top = on_face[0, 0]
on_face[2, 2] = (2 * f_c * np.cos(f_phi) - top * (1 + np.sin(f_phi))) / \
    (np.sin(f_phi) - 1)
report("the face point has f = 0", abs(f_num(on_face, f_c)) < 1e-12)
total = sum(wi * on_face for wi in weights)
report("coaxial elements on one face sum onto the face",
       abs(f_num(total, f_c)) < 1e-12)

# (S3): the hyperbola.
h = x / (1 + rf * x)
report("(S3): G/G0 = h/x = 1/2 at x = 1/R_f",
       sp.simplify((h / x).subs(x, 1 / rf) - sp.Rational(1, 2)) == 0)
report("(S3): h = 1 at x = 1/(1 - R_f)",
       sp.simplify(h.subs(x, 1 / (1 - rf)) - 1) == 0)
report("(S3): u_f = x_f / x_ref = R_f / (1 - R_f)",
       sp.simplify((1 / (1 - rf)) / (1 / rf) - rf / (1 - rf)) == 0)
# (B1) of the clay with G0 = s_u = 1 and gamma_ref = 1/R_f is (S3).
report("(B1) with G0 = s_u = 1, gamma_ref = 1/R_f is (S3)",
       sp.simplify(x / (1 + x / (1 / rf)) - h) == 0)

sys.exit(1 if failures else 0)
