#!/usr/bin/python3
"""The theta integrals behind the soil-reaction curves of a rigid pile
(doc/soil-reaction-curves.md, source/postprocess/soil_reaction_curves.cc).

Derives, with sympy, and checks:

1. the lateral reaction p and the distributed moment m per unit length of a
   shaft of radius R from the n = 1 (symmetric) stress amplitudes of the
   soil at the shaft (tension positive; sigma_rr, sigma_rz ~ cos theta,
   sigma_rtheta ~ sin theta, the code's ThetaFactor):
       force on the pile along x   = int (s_rr cos t - s_rt sin t) R dt
       moment on the pile about y  = int -(R cos t) s_rz R dt
   and p, m the soil's resistance (the negatives of these):
       p = -pi R (S_rr - S_rt),   m = pi R^2 S_rz ;
2. that the nodal forces of the harmonic system give the same numbers
   through the rigid modes: the force on the U, V, W amplitude of a node
   is the work of the traction on u_r = N cos t, u_z = N cos t,
   u_theta = N sin t, so P = f_U - f_W (the work on u_x = 1) and
   Q = -r f_V (the work on u_z = -x) are int N (..) dz of the p and m
   above, with the signs the code uses;
3. that the shaft line's field p_h with M p_h = P (M the mass matrix of the
   line's quadratic Lagrange elements) keeps the resultants:
       int p_h dz = sum P_i,   int p_h z dz = sum P_i z_i,
   exactly, for any P (random rationals on three unequal elements): the
   reason the shaft and base reactions balance H and M to the solver's
   tolerance.

Usage: soil_reaction_integrals.py   (prints the results; exit 1 on a miss)
"""

import random
import sys

import sympy as sp

t, R, z = sp.symbols("theta R z", real=True)
S_rr, S_rt, S_rz = sp.symbols("S_rr S_rt S_rz", real=True)
failures = 0


def check(name, expression, expected):
    global failures
    ok = sp.simplify(expression - expected) == 0
    failures += 0 if ok else 1
    print(f"{'ok  ' if ok else 'MISS'} {name}: {sp.simplify(expression)}"
          f" (expected {expected})")


# 1. The stress at the shaft and the traction on the pile (normal e_r).
s_rr, s_rt, s_rz = S_rr * sp.cos(t), S_rt * sp.sin(t), S_rz * sp.cos(t)
force_x = sp.integrate((s_rr * sp.cos(t) - s_rt * sp.sin(t)) * R,
                       (t, 0, 2 * sp.pi))
moment_y = sp.integrate(-(R * sp.cos(t)) * s_rz * R, (t, 0, 2 * sp.pi))
p, m = -force_x, -moment_y
check("p = -(force on the pile along x)", p, -sp.pi * R * (S_rr - S_rt))
check("m = -(moment on the pile about y)", m, sp.pi * R**2 * S_rz)
# Nothing along y and no moment about x or z from n = 1 symmetric.
check("force along y", sp.integrate(
    (s_rr * sp.sin(t) + s_rt * sp.cos(t)) * R, (t, 0, 2 * sp.pi)), 0)

# 2. The nodal forces (per unit N int dz): the soil's force on the node's
# amplitudes is the work of the traction the node exerts on the soil,
# -(sigma . e_r), on the virtual displacement of that amplitude.
f_U = sp.integrate(-s_rr * sp.cos(t) * R, (t, 0, 2 * sp.pi))
f_W = sp.integrate(-s_rt * sp.sin(t) * R, (t, 0, 2 * sp.pi))
f_V = sp.integrate(-s_rz * sp.cos(t) * R, (t, 0, 2 * sp.pi))
check("P = f_U - f_W", f_U - f_W, p)
check("Q = -R f_V", -R * f_V, m)

# 3. The line's recovered field keeps the resultants (quadratic elements).
xi = sp.symbols("xi")
shape = [2 * (xi - sp.Rational(1, 2)) * (xi - 1), 4 * xi * (1 - xi),
         2 * xi * (xi - sp.Rational(1, 2))]
vertices = [sp.Integer(-10), sp.Rational(-7), sp.Rational(-5, 2), sp.Integer(0)]
n = 2 * (len(vertices) - 1) + 1
M = sp.zeros(n, n)
nodes = []
for e in range(len(vertices) - 1):
    a, b = vertices[e], vertices[e + 1]
    for i in range(3):
        for j in range(3):
            M[2 * e + i, 2 * e + j] += sp.integrate(
                shape[i] * shape[j] * (b - a), (xi, 0, 1))
nodes = [vertices[0]]
for e in range(len(vertices) - 1):
    nodes += [(vertices[e] + vertices[e + 1]) / 2, vertices[e + 1]]
random.seed(1)
P = sp.Matrix([sp.Rational(random.randint(-50, 50), 7) for _ in range(n)])
values = M.LUsolve(P)
integral = integral_z = 0
for e in range(len(vertices) - 1):
    a, b = vertices[e], vertices[e + 1]
    field = sum(values[2 * e + i] * shape[i] for i in range(3))
    integral += sp.integrate(field * (b - a), (xi, 0, 1))
    integral_z += sp.integrate(field * (a + (b - a) * xi) * (b - a),
                               (xi, 0, 1))
check("int p_h dz = sum P", integral, sum(P))
check("int p_h z dz = sum P z", integral_z,
      sum(P[i] * nodes[i] for i in range(n)))

print("all checks passed" if failures == 0 else f"{failures} checks missed")
sys.exit(1 if failures else 0)
