#!/usr/bin/python3
"""Thick cylinder of Mohr-Coulomb soil under internal pressure, plane strain
(prm/cylinder-mohr-coulomb.prm, doc/soil-plasticity.md section 7b).

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
"""
import math

A_IN, B_OUT, NU = 1.0, 2.0, 0.3


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


def check(name, value, reference, tol):
    ok = abs(value - reference) <= tol * max(1.0, abs(reference))
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
    print("ALL PASS" if ok else "SOME FAIL")


if __name__ == "__main__":
    main()
