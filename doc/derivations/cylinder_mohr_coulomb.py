#!/usr/bin/python3
"""Thick cylinder of Mohr-Coulomb soil under internal pressure, plane strain
(prm/cylinder-mohr-coulomb.prm, doc/soil-plasticity.md section 7b; the
derivation and the work of the loads: doc/verification/soil-plasticity.md
sections 7b and 8c).

Compression positive here. Equilibrium d(s_r)/dr + (s_r - s_t)/r = 0; in the
plastic zone a < r < rho the yield condition on the (r, theta) plane,
s_r + c cot(phi) = N (s_t + c cot(phi)), N = (1 + sin phi)/(1 - sin phi)
(sigma_z intermediate), gives q = s_r + c cot(phi) ~ r^-(N-1)/N. The elastic
ring rho < r < b (s_r(b) = 0) is Lame's s_r = A (b^2/r^2 - 1),
s_t = -A (b^2/r^2 + 1), at yield at r = rho. Hence p(rho); p(b) = p_lim.
Checks (PASS/FAIL): p(a) equals the pressure of first yield from the elastic
Lame field; p(b) = p_lim; phi -> 0 gives Tresca's 2 c ln(b/a) (Hill 1950);
sigma_z = nu (s_r + s_t) of the elastic ring lies between s_r and s_t.
Prints the pressure of the scene, the plastic radius at every load step and
the Gauss rows (4 per cell, 16 cells) inside it: the expected plastic count.

Bore displacement u(a) (small strain, u outward, G = 1000 kPa). With psi = 0
and sigma_z intermediate the plastic strain is (1, 0, -1) in (r, z, theta):
no volume change and eps_p_z = 0, so eps_z = 0 keeps sigma_z = nu (s_r + s_t)
(zero initial stress) and everywhere the in-plane volumetric strain is elastic,
(1/r) d(r u)/dr = -(1 - 2 nu)/(2 G) (s_r + s_t)   (compression positive).
Ring rho < r < b: u = A/(2G) [(1 - 2 nu) r + b^2/r]. Plastic zone:
r u(r) = rho u(rho) + (1 - 2 nu)/(2G) I(r), I(r) = int_r^rho s (s_r + s_t) ds
= q(rho) rho^2 [1 - (r/rho)^((N+1)/N)] - c cot(phi) (rho^2 - r^2)
(= rho^2 s_r(rho) - r^2 s_r(r): by equilibrium r (s_r + s_t) = d(r^2 s_r)/dr).
Hence u(a) = [2 (1 - nu) A b^2 - (1 - 2 nu) a^2 p] / (2 G a); elastic (rho = a,
A = p a^2/(b^2 - a^2)): u(a) = p a/(2G) [(1 - 2 nu) a^2 + b^2]/(b^2 - a^2).
phi -> 0: 2 G u(a)/(c a) = 2 (1 - nu) rho^2/a^2 - (1 - 2 nu) p/c with
p/c = 1 - rho^2/b^2 + 2 ln(rho/a) (Tresca: Hill's log stresses integrated
the same way, s_r + s_t = 2 p - 2 c - 4 c ln(r/a)). Work of the
pressure on the slice h = 0.25 m: W = 2 pi a h p u(a) [kJ] (load times final
displacement, as the code's load work). Checks (PASS/FAIL): the elastic u(a)
against Lame and against Hooke's hoop strain; I(a) against Simpson; the
equilibrium form of u(a); the Tresca limit; continuity at first yield;
sigma_z intermediate in the plastic zone at every load step.
"""
import math

A_IN, B_OUT, NU = 1.0, 2.0, 0.3
G_MOD, H_SLICE = 1000.0, 0.25


def p_of_rho(rho, c, phi):
    s = math.sin(phi)
    n = (1 + s) / (1 - s)
    cc = c / math.tan(phi)
    x = B_OUT ** 2 / rho ** 2
    amp = cc * (n - 1) / (x - 1 + n * (x + 1))
    q = amp * (x - 1) + cc
    return q * (rho / A_IN) ** ((n - 1) / n) - cc


def first_yield_lame(c, phi):
    # Elastic Lame field at r = a per unit pressure (compression positive):
    k = B_OUT ** 2 / A_IN ** 2 - 1
    sr, st = 1.0, -(B_OUT ** 2 / A_IN ** 2 + 1) / k
    s = math.sin(phi)
    # f = (s1 - s3) - (s1 + s3) sin(phi) - 2 c cos(phi), compression positive
    return 2 * c * math.cos(phi) / ((sr - st) - (sr + st) * s)


def rho_of_p(p, c, phi):
    lo, hi = A_IN, B_OUT
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if p_of_rho(mid, c, phi) < p:
            lo = mid
        else:
            hi = mid
    return lo


def ring_amplitude(rho, c, phi):
    # A of the elastic ring at yield at r = rho (s_r = A (b^2/r^2 - 1)).
    s = math.sin(phi)
    n = (1 + s) / (1 - s)
    cc = c / math.tan(phi)
    x = B_OUT ** 2 / rho ** 2
    return cc * (n - 1) / (x - 1 + n * (x + 1))


def plastic_sum(r, rho, c, phi):
    # s_r + s_t in the plastic zone (compression positive).
    s = math.sin(phi)
    n = (1 + s) / (1 - s)
    cc = c / math.tan(phi)
    q = (ring_amplitude(rho, c, phi) * (B_OUT ** 2 / rho ** 2 - 1) + cc) \
        * (rho / r) ** ((n - 1) / n)
    return q - cc + q / n - cc


def integral_closed(r, rho, c, phi):
    # int_r^rho s (s_r + s_t) ds in the plastic zone, closed form.
    s = math.sin(phi)
    n = (1 + s) / (1 - s)
    cc = c / math.tan(phi)
    q_rho = ring_amplitude(rho, c, phi) * (B_OUT ** 2 / rho ** 2 - 1) + cc
    return (q_rho * rho ** 2 * (1 - (r / rho) ** ((n + 1) / n))
            - cc * (rho ** 2 - r ** 2))


def integral_simpson(r, rho, c, phi, m=2000):
    h = (rho - r) / m
    total = 0.0
    for i in range(m + 1):
        s = r + i * h
        w = 1 if i in (0, m) else (4 if i % 2 else 2)
        total += w * s * plastic_sum(s, rho, c, phi)
    return total * h / 3


def lame_u_bore(p):
    # Plane-strain Lame: u(a) = p a/(2G) [(1 - 2 nu) a^2 + b^2]/(b^2 - a^2).
    return (p * A_IN / (2 * G_MOD) * ((1 - 2 * NU) * A_IN ** 2 + B_OUT ** 2)
            / (B_OUT ** 2 - A_IN ** 2))


def hooke_u_bore(p):
    # u(a) = a eps_t, eps_t = [(1 - nu) t_t - nu t_r]/(2G), tension positive,
    # Lame's t_r(a) = -p, t_t(a) = p (b^2 + a^2)/(b^2 - a^2).
    t_r = -p
    t_t = p * (B_OUT ** 2 + A_IN ** 2) / (B_OUT ** 2 - A_IN ** 2)
    return A_IN * ((1 - NU) * t_t - NU * t_r) / (2 * G_MOD)


def bore_state(p, c, phi):
    # (rho, A): rho = a and the elastic Lame amplitude below first yield.
    if p <= p_of_rho(A_IN, c, phi):
        return A_IN, p * A_IN ** 2 / (B_OUT ** 2 - A_IN ** 2)
    rho = rho_of_p(p, c, phi)
    return rho, ring_amplitude(rho, c, phi)


def u_bore(p, c, phi):
    # r u = rho u(rho) + (1 - 2 nu)/(2G) I(r) at r = a; u outward [m].
    rho, amp = bore_state(p, c, phi)
    u_rho = amp / (2 * G_MOD) * ((1 - 2 * NU) * rho + B_OUT ** 2 / rho)
    inte = integral_closed(A_IN, rho, c, phi) if rho > A_IN else 0.0
    return (rho * u_rho + (1 - 2 * NU) / (2 * G_MOD) * inte) / A_IN


def u_bore_equilibrium(p, c, phi):
    # u(a) = [2 (1 - nu) A b^2 - (1 - 2 nu) a^2 p]/(2 G a).
    amp = bore_state(p, c, phi)[1]
    return ((2 * (1 - NU) * amp * B_OUT ** 2 - (1 - 2 * NU) * A_IN ** 2 * p)
            / (2 * G_MOD * A_IN))


def u_bore_tresca(p, c):
    # Tresca (phi = 0, sigma_z intermediate), Hill's log stresses integrated:
    # 2 G u(a)/(c a) = 2 (1 - nu) rho^2/a^2 - (1 - 2 nu) p/c,
    # p/c = 1 - rho^2/b^2 + 2 ln(rho/a).
    lo, hi = A_IN, B_OUT
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        pm = c * (1 - mid ** 2 / B_OUT ** 2 + 2 * math.log(mid / A_IN))
        if pm < p:
            lo = mid
        else:
            hi = mid
    return c * A_IN / (2 * G_MOD) * (2 * (1 - NU) * lo ** 2 / A_IN ** 2
                                     - (1 - 2 * NU) * p / c)


def check(name, value, reference, tol, rel=False):
    scale = abs(reference) if rel else max(1.0, abs(reference))
    ok = abs(value - reference) <= tol * scale
    print("%s %s: %.12g vs %.12g" % ("PASS" if ok else "FAIL", name, value,
                                     reference))
    return ok


def main():
    c, phi = 10.0, math.radians(20.0)
    s = math.sin(phi)
    n = (1 + s) / (1 - s)
    cc = c / math.tan(phi)
    p_lim = cc * ((B_OUT / A_IN) ** ((n - 1) / n) - 1)
    ok = check("p(b) = p_lim", p_of_rho(B_OUT, c, phi), p_lim, 1e-12)
    ok &= check("p(a) = first yield of the Lame field",
                p_of_rho(A_IN, c, phi), first_yield_lame(c, phi), 1e-12)
    tiny = math.radians(1e-4)
    ok &= check("phi -> 0: Tresca 2 c ln(b/a)",
                p_of_rho(B_OUT, c, tiny), 2 * c * math.log(B_OUT / A_IN),
                1e-5)
    rho = A_IN + 8.5 / 16 * (B_OUT - A_IN)
    p_scene = p_of_rho(rho, c, phi)
    # sigma_z intermediate in the elastic ring at the scene's load.
    x = B_OUT ** 2 / rho ** 2
    amp = cc * (n - 1) / (x - 1 + n * (x + 1))
    inter = True
    for i in range(101):
        r = rho + (B_OUT - rho) * i / 100
        sr = amp * (B_OUT ** 2 / r ** 2 - 1)
        st = -amp * (B_OUT ** 2 / r ** 2 + 1)
        sz = NU * (sr + st)
        inter &= min(sr, st) <= sz <= max(sr, st)
    print("%s sigma_z intermediate in the elastic ring" %
          ("PASS" if inter else "FAIL"))
    ok &= inter
    print("p_lim = %.15g kPa, p(rho = %.5f m) = %.15g kPa" %
          (p_lim, rho, p_scene))
    g1 = (1 - math.sqrt(3 / 7 + 2 / 7 * math.sqrt(6 / 5))) / 2
    g2 = (1 - math.sqrt(3 / 7 - 2 / 7 * math.sqrt(6 / 5))) / 2
    rows = sorted(A_IN + (i + t) / 16 for i in range(16)
                  for t in (g1, g2, 1 - g2, 1 - g1))
    for step in range(1, 9):
        p = step / 8 * p_scene
        if p < p_of_rho(A_IN, c, phi):
            print("step %d: p = %.6g kPa, elastic" % (step, p))
            continue
        r = rho_of_p(p, c, phi)
        inside = sum(1 for q in rows if q < r)
        margin = min(abs(q - r) for q in rows)
        print("step %d: p = %.6g kPa, rho = %.6f m, plastic Gauss points "
              "%d (4 per row), nearest row %.4f m away"
              % (step, p, r, 4 * inside, margin))
    # Bore displacement u(a) and the work of the pressure on the slice.
    p4 = 4 / 8 * p_scene
    ok &= check("elastic u(a) at step 4 = Lame plane strain [m]",
                u_bore(p4, c, phi), lame_u_bore(p4), 1e-12, rel=True)
    ok &= check("Lame u(a) = a eps_theta from Hooke (plane strain) [m]",
                lame_u_bore(p4), hooke_u_bore(p4), 1e-12, rel=True)
    ok &= check("int_a^rho s (s_r + s_t) ds closed form = Simpson",
                integral_closed(A_IN, rho, c, phi),
                integral_simpson(A_IN, rho, c, phi), 1e-10, rel=True)
    ok &= check("I(a) = rho^2 s_r(rho) - a^2 p (equilibrium)",
                integral_closed(A_IN, rho, c, phi),
                rho ** 2 * amp * (x - 1) - A_IN ** 2 * p_scene, 1e-10,
                rel=True)
    ok &= check("u(a) = [2(1-nu) A b^2 - (1-2nu) a^2 p]/(2 G a) [m]",
                u_bore(p_scene, c, phi), u_bore_equilibrium(p_scene, c, phi),
                1e-10, rel=True)
    ok &= check("phi = 1e-6 rad: u(a) = Tresca (log stresses) at p_scene [m]",
                u_bore(p_scene, c, 1e-6), u_bore_tresca(p_scene, c), 1e-6,
                rel=True)
    p1 = p_of_rho(A_IN, c, phi)
    ok &= check("u(a) continuous at first yield p(a) -+ 1e-9 kPa [m]",
                u_bore(p1 + 1e-9, c, phi), u_bore(p1 - 1e-9, c, phi), 1e-9,
                rel=True)
    # sigma_z = nu (s_r + s_t) between s_t and s_r in the plastic zone.
    inter = True
    for step in range(1, 9):
        p = step / 8 * p_scene
        r_p = bore_state(p, c, phi)[0]
        if r_p <= A_IN:
            continue
        for i in range(101):
            r = A_IN + (r_p - A_IN) * i / 100
            q = (ring_amplitude(r_p, c, phi) * (B_OUT ** 2 / r_p ** 2 - 1)
                 + cc) * (r_p / r) ** ((n - 1) / n)
            sr, st = q - cc, q / n - cc
            inter &= st <= NU * (sr + st) <= sr
    print("%s sigma_z intermediate in the plastic zone (every step, the end "
          "pressure included)" % ("PASS" if inter else "FAIL"))
    ok &= inter
    for step in range(1, 9):
        p = step / 8 * p_scene
        r_p = bore_state(p, c, phi)[0]
        u = u_bore(p, c, phi)
        print("step %d: p = %.10g kPa, rho = %s, u(a) = %.10g m, W = %.10g kJ"
              % (step, p, "%.10f m" % r_p if r_p > A_IN else "- (elastic)",
                 u, 2 * math.pi * A_IN * H_SLICE * p * u))
    u_end = u_bore(p_scene, c, phi)
    print("end: p = %.15g kPa, rho = %.10g m, u(a) = %.10g m, "
          "W = 2 pi a h p u(a) = %.10g kJ (h = %g m)"
          % (p_scene, rho, u_end,
             2 * math.pi * A_IN * H_SLICE * p_scene * u_end, H_SLICE))
    print("ALL PASS" if ok else "SOME FAIL")


if __name__ == "__main__":
    main()
