#!/usr/bin/python3
"""Bearing capacity of a SMOOTH rigid circular (or strip) footing on
cohesionless Mohr-Coulomb soil by the method of stress characteristics
(doc/verification/sand-footings.md; the reference of prm/footing-sand.prm).

Compression positive, z downward, r = x the distance from the axis. The
soil is at yield everywhere in the plastic region (c' = 0); the limit load
of such a field is the exact one of the ASSOCIATED material (psi = phi'),
as Martin (2005) argues for the completed fields of the method:

    sigma_x = s (1 + k cos 2 psi), sigma_z = s (1 - k cos 2 psi),
    tau_xz  = s k sin 2 psi,       k = sin(phi),

psi the angle of the major principal stress from the x axis. Axial
symmetry closes the system with the Haar-von Karman hypothesis: the hoop
stress equals the minor principal stress of the meridional plane,
sigma_theta = s (1 - k) (the soil flows outward under the footing, so the
hoop strain is an extension; Cox, Eason & Hopkins 1961, Cox 1962, Bolton &
Lau 1993). Equilibrium:

    d sigma_x/dx + d tau/dz + (sigma_x - sigma_theta)/x = 0
    d tau/dx + d sigma_z/dz + tau/x = gamma

a quasi-linear system A U_x + B U_z = C for U = (s, psi). Its two
characteristic directions are psi -/+ mu, mu = pi/4 - phi/2 (family I:
psi - mu, running from the free surface down toward the axis; family II:
psi + mu, the fan's radials). Along a direction theta with l^T (A sin theta
- B cos theta) = 0 the compatibility relation is
    w . dU = (l . C) dl,   w = A^T l cos theta + B^T l sin theta,
dl the arc length; the script forms l and w numerically at every step
(no hand-derived relation to get a sign wrong).

Construction (smooth footing, Martin's "solution type 1"): the free surface
x in [a, L] with sigma_z = q, tau = 0 (psi = 0) is a Cauchy problem; the
footing edge is a singular point (a fan: along the degenerate family-I line
w_I . dU = 0, integrated in psi from 0 to pi/2); under the footing the base
z = 0, 0 <= x <= a, is smooth (psi = pi/2) and every family-I line ends on
it. L is chosen by bisection so that the last line ends on the axis. The
vertical force is V = int_0^a 2 pi x sigma_z dx (trapezoidal), and

    N_q = V / (q pi a^2)         (gamma = 0)
    N_gamma = V / (0.5 gamma (2a) pi a^2)   (q -> 0: q = 1e-6 gamma a)

Checks (PASS/FAIL):
  1. plane strain (the 1/x terms dropped): N_q equals Prandtl's
     exp(pi tan phi) tan^2(pi/4 + phi/2);
  2. axial symmetry, phi -> 0: N_c = (N_q - 1) cot(phi) (the shifted-stress
     theorem) tends to Shield's (1955) smooth circular 5.69 (this is what
     decides the hoop stress: sigma_theta = sigma_3 gives 5.69);
  3. convergence: the values on nets of n and 2n lines agree to 1e-2 (the
     scheme is second order: the printed value is Richardson's).
Prints N_q and N_gamma of a smooth circular footing for phi = 30, 35 deg.

Usage: /usr/bin/python3 doc/derivations/circular_footing_characteristics.py
"""
import math
import sys

import numpy as np


class Soil:
    def __init__(self, phi_deg, gamma, axisymmetric):
        self.phi = math.radians(phi_deg)
        self.k = math.sin(self.phi)
        self.mu = math.pi / 4 - self.phi / 2
        self.gamma = gamma
        self.axisymmetric = axisymmetric

    def relation(self, x, s, psi, family):
        """(w, l.C, theta) of the compatibility relation along a family:
        A U_x + B U_z = C at the state (s, psi) and radius x, theta the
        family's direction, l^T (A sin theta - B cos theta) = 0 and
        w = A^T l cos theta + B^T l sin theta (2 x 2, in plain floats)."""
        k, c2, s2 = self.k, math.cos(2 * psi), math.sin(2 * psi)
        a00, a01, a10, a11 = 1 + k * c2, -2 * s * k * s2, k * s2, 2 * s * k * c2
        b00, b01, b10, b11 = k * s2, 2 * s * k * c2, 1 - k * c2, 2 * s * k * s2
        c0, c1 = 0.0, self.gamma
        if self.axisymmetric:
            # (sigma_x - sigma_theta)/x with sigma_theta = s (1 - k); tau/x.
            c0 -= s * k * (1 + c2) / x
            c1 -= s * k * s2 / x
        theta = psi - self.mu if family == 1 else psi + self.mu
        st, ct = math.sin(theta), math.cos(theta)
        m00, m01 = a00 * st - b00 * ct, a01 * st - b01 * ct
        m10, m11 = a10 * st - b10 * ct, a11 * st - b11 * ct
        l0, l1 = m10, -m00
        if abs(l0) + abs(l1) < 1e-12 * (1 + abs(m01) + abs(m11)):
            l0, l1 = m11, -m01
        w0 = (a00 * l0 + a10 * l1) * ct + (b00 * l0 + b10 * l1) * st
        w1 = (a01 * l0 + a11 * l1) * ct + (b01 * l0 + b11 * l1) * st
        return (w0, w1), l0 * c0 + l1 * c1, theta


def solve2(a00, a01, a10, a11, r0, r1):
    det = a00 * a11 - a01 * a10
    return (r0 * a11 - a01 * r1) / det, (a00 * r1 - a10 * r0) / det


def new_point(soil, p1, p2):
    """The point where the family-I line through p1 meets the family-II line
    through p2 (points are (x, z, s, psi)); trapezoidal predictor-corrector."""
    x, z, s, psi = 0.5 * (p1[0] + p2[0]), 0.5 * (p1[1] + p2[1]), \
        0.5 * (p1[2] + p2[2]), 0.5 * (p1[3] + p2[3])
    for _ in range(4):
        w1, g1, t1 = soil.relation(0.5 * (x + p1[0]), 0.5 * (s + p1[2]),
                                   0.5 * (psi + p1[3]), 1)
        w2, g2, t2 = soil.relation(0.5 * (x + p2[0]), 0.5 * (s + p2[2]),
                                   0.5 * (psi + p2[3]), 2)
        # sin t (x - x_i) - cos t (z - z_i) = 0 for both lines.
        s1, c1, s2, c2 = math.sin(t1), math.cos(t1), math.sin(t2), math.cos(t2)
        x, z = solve2(s1, -c1, s2, -c2, s1 * p1[0] - c1 * p1[1],
                      s2 * p2[0] - c2 * p2[1])
        dl1 = (x - p1[0]) * c1 + (z - p1[1]) * s1
        dl2 = (x - p2[0]) * c2 + (z - p2[1]) * s2
        s, psi = solve2(w1[0], w1[1], w2[0], w2[1],
                        w1[0] * p1[2] + w1[1] * p1[3] + g1 * dl1,
                        w2[0] * p2[2] + w2[1] * p2[3] + g2 * dl2)
    return (x, z, s, psi)


def base_point(soil, p1):
    """Where the family-I line through p1 meets the smooth base z = 0
    (psi = pi/2 there)."""
    psi = math.pi / 2
    x, s = p1[0], p1[2]
    for _ in range(4):
        w1, g1, t1 = soil.relation(0.5 * (x + p1[0]), 0.5 * (s + p1[2]),
                                   0.5 * (psi + p1[3]), 1)
        # z = 0 on the line through p1 with direction t1.
        dl1 = -p1[1] / math.sin(t1)
        x = p1[0] + dl1 * math.cos(t1)
        s = (w1[0] * p1[2] + w1[1] * p1[3] + g1 * dl1 - w1[1] * psi) / w1[0]
    return (x, 0.0, s, psi)


def fan(soil, a, s0, n_fan):
    """States at the footing edge for psi from 0 to pi/2: w_I . dU = 0
    (RK4 in psi, 20 sub-steps per fan line)."""
    def ds_dpsi(s, psi):
        w, _, _ = soil.relation(a, s, psi, 1)
        return -w[1] / w[0]
    states, s, psi = [(a, 0.0, s0, 0.0)], s0, 0.0
    h = (math.pi / 2) / (n_fan * 20)
    for i in range(n_fan * 20):
        k1 = ds_dpsi(s, psi)
        k2 = ds_dpsi(s + 0.5 * h * k1, psi + 0.5 * h)
        k3 = ds_dpsi(s + 0.5 * h * k2, psi + 0.5 * h)
        k4 = ds_dpsi(s + h * k3, psi + h)
        s, psi = s + h * (k1 + 2 * k2 + 2 * k3 + k4) / 6, psi + h
        if (i + 1) % 20 == 0:
            states.append((a, 0.0, s, psi))
    return states


def base_pressures(soil, a, L, q, n_surface, n_fan):
    """Base points (x, sigma_z) of the net with n_surface surface intervals
    on [a, L] (graded toward the edge) and n_fan fan intervals."""
    t = np.linspace(0.0, 1.0, n_surface + 1)
    xs = a + (L - a) * t ** 1.5
    s_surface = q / (1 - soil.k)
    edge = fan(soil, a, s_surface, n_fan)
    # Family-I line i starts at surface point i and runs toward the axis;
    # 'previous' holds its last point on each family-II line.
    lines_II = [None] * (n_surface + 1)  # last point on family-II line j >= 0
    fan_II = list(edge[1:])               # last point on fan line j < 0
    active = []                            # last points of active-zone lines
    base = [(a, edge[-1][2] * (1 + soil.k))]
    for i in range(n_surface + 1):
        p = (xs[i], 0.0, s_surface, 0.0)
        lines_II[i] = p
        for j in range(i - 1, -1, -1):        # passive zone
            p = new_point(soil, p, lines_II[j])
            lines_II[j] = p
        if i == 0:
            continue
        for j in range(len(fan_II)):           # the fan
            p = new_point(soil, p, fan_II[j])
            fan_II[j] = p
        for j in range(len(active)):           # the active zone
            p = new_point(soil, p, active[j])
            active[j] = p
        b = base_point(soil, p)
        if b[0] <= 0.0 or (active and b[0] >= active[-1][0]):
            return base, False
        active.append(b)
        base.append((b[0], b[2] * (1 + soil.k)))
    return base, True


def footing_force(soil, a, q, n_surface, n_fan):
    """V on the base 0 <= x <= a (per unit length for plane strain): the
    surface length L is bisected until the last line ends on the axis."""
    lo, hi = a * 1.01, a * 40.0
    for _ in range(60):
        L = 0.5 * (lo + hi)
        base, reached_end = base_pressures(soil, a, L, q, n_surface, n_fan)
        if reached_end and base[-1][0] > 1e-4 * a:
            lo = L
        else:
            hi = L
        if hi - lo < 1e-7 * a:
            break
    base, _ = base_pressures(soil, a, lo, q, n_surface, n_fan)
    base.append((0.0, base[-1][1]))  # the last line ends within 1e-4 a
    xs = np.array([b[0] for b in base])
    ps = np.array([b[1] for b in base])
    weight = 2 * math.pi * xs if soil.axisymmetric else np.ones_like(xs)
    f = weight * ps
    return float(np.sum(0.5 * (f[1:] + f[:-1]) * (xs[:-1] - xs[1:])))


def n_q(phi, axisymmetric, n):
    soil = Soil(phi, 0.0, axisymmetric)
    V = footing_force(soil, 1.0, 1.0, n, n)
    return V / (math.pi if axisymmetric else 1.0)


def n_gamma(phi, axisymmetric, n):
    soil = Soil(phi, 1.0, axisymmetric)
    V = footing_force(soil, 1.0, 1e-6, n, n)
    area = math.pi if axisymmetric else 1.0
    return V / (0.5 * 1.0 * 2.0 * area)


def richardson(f, phi, axisymmetric, n):
    """Values on n and 2n lines and their extrapolation (second order)."""
    v1, v2 = f(phi, axisymmetric, n), f(phi, axisymmetric, 2 * n)
    return v1, v2, v2 + (v2 - v1) / 3


def main():
    ok = True

    def check(name, value, reference, tol):
        nonlocal ok
        good = abs(value - reference) <= tol * abs(reference)
        ok = ok and good
        print(f"{'PASS' if good else 'FAIL'} {name}: {value:.5f} vs "
              f"{reference:.5f} (tol {tol:g})")

    n = 20
    for phi in (30.0, 35.0):
        prandtl = math.exp(math.pi * math.tan(math.radians(phi))) * \
            math.tan(math.pi / 4 + math.radians(phi) / 2) ** 2
        check(f"1. plane-strain N_q, phi = {phi:g}",
              richardson(n_q, phi, False, n)[2], prandtl, 1e-4)
    # N_c(phi) is linear in phi near 0: extrapolate from 0.1 and 0.2 deg,
    # each Richardson-extrapolated in the net.
    n_c = []
    for phi_small in (0.1, 0.2):
        nq_small = richardson(n_q, phi_small, True, n)[2]
        n_c.append((nq_small - 1) / math.tan(math.radians(phi_small)))
    check("2. N_c = (N_q - 1) cot phi, phi -> 0 (Shield 1955: 5.69)",
          2 * n_c[0] - n_c[1], 5.69, 2e-3)
    print("smooth circular footing (method of characteristics, associated "
          "flow, sigma_theta = sigma_3):")
    for phi in (30.0, 35.0):
        for name, f in (("N_q", n_q), ("N_gamma", n_gamma)):
            v1, v2, v = richardson(f, phi, True, n)
            check(f"3. {name} nets {n}/{2 * n}, phi = {phi:g}", v1, v2, 1e-2)
            print(f"   {name}(phi = {phi:g}) = {v:.4f}  (n = {n}: {v1:.4f}, "
                  f"n = {2 * n}: {v2:.4f})")
    print("ALL PASS" if ok else "SOME FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
