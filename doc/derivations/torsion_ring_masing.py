#!/usr/bin/python3
"""Closed form of a rigid disc twisted in a ring of multi-surface (iwan)
clay, monotonic and cyclic (doc/cyclic-loading.md, section 4).

The ring a <= r <= b of height h, fixed at r = b, is twisted by a rigid disc
of radius a through the torque T. Torsion is statically determinate: the
only stress is tau_r_theta(r) = T / (2 pi r^2 h) (equilibrium of a ring of
radius r), whatever the law. The shear strain gamma = r d(w/r)/dr, so the
twist of the disc is

    theta(T) = int_a^b gamma(tau(r)) / r dr
             = int_{tau(b)}^{tau(a)} gamma(tau) / (2 tau) dtau      (T1)

with r^2 = T / (2 pi h tau), dr / r = -dtau / (2 tau). In simple shear the
iwan clay's stress is the tangent polygon of the backbone
tau_b = G0 gamma / (1 + gamma / gamma_ref), capped at s_u
(doc/derivations/multi_surface_clay.md, (B3)): gamma(tau) is piecewise
linear, gamma = c0 + c1 tau on each piece, so each piece of (T1) is
c0 / 2 ln(tau2 / tau1) + c1 / 2 (tau2 - tau1), exact.

Masing's rules hold at every point (a parallel set of elastic-perfectly
plastic elements in one shear component), and tau(r) is the same multiple of
T at every point, so the disc follows them too: from a turning point
(theta_a, T_a) the path is

    theta = theta_a - 2 s theta_b(s (T_a - T) / 2),  s = sign(T_a - T),   (T2)

theta_b the virgin curve (T1). The failure twist is theta_b(2 pi a^2 h s_u).
"""
import math


def tangent_polygon(g0, su, gref, n):
    """Kinks (gamma_k, tau_k) of the model's simple-shear curve."""
    if n == 1:
        return [0., su / g0], [0., su]
    uf = su / (g0 * gref - su)
    step = 2. * math.atan(math.sqrt(uf)) / (n - 1)
    t = [math.tan(0.5 * j * step) ** 2 for j in range(n)]
    t[-1] = uf

    def model(gamma):
        u = gamma / gref
        return min([su] + [g0 * gref * (tj / (1 + tj) + (u - tj) / (1 + tj) ** 2)
                           for tj in t])

    kinks = [0.]
    for j in range(n - 1):
        a, b = t[j], t[j + 1]
        kinks.append(gref * (2. * (1 + a) * (1 + b) / (2 + a + b) - 1.))
    kinks.append(gref * uf)
    return kinks, [model(g) for g in kinks]


def table_polygon(g0, su, table):
    """Kinks (gamma_k, tau_k) of a degradation table's curve: from the
    origin through tau = G0 gamma G/G0 at the table's points, past the last
    one with its last slope, up to s_u (doc/derivations/multi_surface_clay.md
    section 7)."""
    gammas, taus = [0.], [0.]
    slope = g0
    for gamma, ratio in table:
        tau = g0 * gamma * ratio
        slope = (tau - taus[-1]) / (gamma - gammas[-1])
        if tau >= su:
            break
        gammas.append(gamma)
        taus.append(tau)
    gammas.append(gammas[-1] + (su - taus[-1]) / slope)
    taus.append(su)
    return gammas, taus


class TorsionRing:
    def __init__(self, g0, su, gref, n, a, b, h, table=None):
        """The model's polygon: the tangents of the hyperbola (gref, n), or
        a degradation table's polygon [(gamma, G/G0), ...]."""
        self.gamma_k, self.tau_k = table_polygon(g0, su, table) if table \
            else tangent_polygon(g0, su, gref, n)
        self.a, self.b, self.h = a, b, h
        self.failure_torque = 2. * math.pi * a * a * h * su

    def gamma(self, tau):
        """Inverse of the polygon (linear between kinks)."""
        g, t = self.gamma_k, self.tau_k
        for k in range(len(t) - 1):
            if tau <= t[k + 1]:
                return g[k] + (g[k + 1] - g[k]) * (tau - t[k]) / (t[k + 1] - t[k])
        raise ValueError("tau beyond s_u")

    def virgin_twist(self, torque):
        """(T1), exact piece by piece."""
        if torque == 0.:
            return 0.
        c = torque / (2. * math.pi * self.h)
        lo, hi = c / self.b ** 2, c / self.a ** 2
        points = sorted({lo, hi} | {t for t in self.tau_k if lo < t < hi})
        total = 0.
        for t1, t2 in zip(points[:-1], points[1:]):
            g1, g2 = self.gamma(t1), self.gamma(t2)
            c1 = (g2 - g1) / (t2 - t1)
            c0 = g1 - c1 * t1
            total += 0.5 * c0 * math.log(t2 / t1) + 0.5 * c1 * (t2 - t1)
        return total

    def twist_from(self, turning, torque):
        """(T2) from the turning point (theta_a, T_a); (0, 0): virgin."""
        theta_a, torque_a = turning
        if theta_a == 0. and torque_a == 0.:
            return math.copysign(self.virgin_twist(abs(torque)), torque)
        s = 1. if torque_a > torque else -1.
        return theta_a - 2. * s * self.virgin_twist(s * (torque_a - torque) / 2.)

    def torque_at(self, turning, theta):
        """T on the branch from `turning` at the twist theta (bisection)."""
        lo, hi = -self.failure_torque * (1 - 1e-12), self.failure_torque * (1 - 1e-12)
        if turning != (0., 0.):
            t_a = turning[1]
            # The branch spans T_a -/+ 2 T_f.
            lo, hi = max(lo, t_a - 2 * self.failure_torque), min(hi, t_a + 2 * self.failure_torque)
        f = lambda T: self.twist_from(turning, T) - theta
        flo, fhi = f(lo), f(hi)
        assert flo * fhi <= 0., "twist beyond the branch"
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            fm = f(mid)
            if (fm < 0) == (flo < 0):
                lo, flo = mid, fm
            else:
                hi = mid
            if hi - lo < 1e-15 * self.failure_torque:
                break
        return 0.5 * (lo + hi)


if __name__ == "__main__":
    ring = TorsionRing(3000., 10., 0.01, 20, 0.5, 5., 1.)
    print("failure torque", ring.failure_torque, "kNm at twist",
          ring.virgin_twist(ring.failure_torque * (1 - 1e-12)), "rad")
    for theta in [0.0004, 0.0008, 0.0012, 0.0016]:
        print(theta, ring.torque_at((0., 0.), theta))
