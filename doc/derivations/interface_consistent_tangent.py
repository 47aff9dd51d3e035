#!/usr/bin/python3
"""The consistent tangent D_t = dt/dd of the Mohr-Coulomb interface return
mapping with a tension cut-off (include/fourier_ssi/interfaces/interface_law.h,
doc/nonlinear-interfaces.md section 2), derived with sympy and checked here
against central differences of the return mapping itself.
Prints PASS/FAIL per check, exits non-zero on a failure.

Return mapping (tension positive t_n, D = diag(ks, kn, ks)):
  t_tr = t0 + D (d - d_p,old),  tau_tr = |(t_s,tr, t_theta,tr)|,
  f = tau + t_n tan(phi) - c,   H = ks + kn tan(phi) tan(psi),
  open  (t_n,tr > sigma_t): t = 0                       ->  D_t = 0
  stick (f(t_tr) <= 0):     t = t_tr                    ->  D_t = D
  slip  (f(t_tr) > 0):      dl = f(t_tr) / H,
                            t_a = (tau_tr - ks dl) m_a  (a = s, theta;
                                   m = shear direction of the trial),
                            t_n = t_n,tr - kn tan(psi) dl.
Closed form of the slip tangent (the result checked below), with
rho = (tau_tr - ks dl) / tau_tr (the radial-return shrink factor):
  dt_a/dd_b = ks rho (delta_ab - m_a m_b) + ks kn tan(phi) tan(psi)/H m_a m_b
  dt_a/dd_n = -ks kn tan(phi) / H m_a
  dt_n/dd_b = -ks kn tan(psi) / H m_b
  dt_n/dd_n = ks kn / H
(non-symmetric unless psi = phi: non-associated flow).

The corner where the slip cone meets the cut-off: in this return mapping the
slip return only lowers t_n (psi >= 0), so no returned point lies above
sigma_t and the corner is the boundary t_n,tr = sigma_t of the slip region
with the open region; there t jumps from the slip return to 0 unless the cone
apex is at sigma_t (c = sigma_t tan(phi), e.g. cohesionless, tensionless),
and the tangent jumps from the slip tangent to 0 on both counts. Each side
has its own one-sided tangent; the checks sample both sides a few difference
steps away from the boundary, and the C++ test does the same.
"""
import random
import sys

import sympy as sp

failures = 0


def report(name, ok):
    global failures
    print(("PASS " if ok else "FAIL ") + name)
    failures += 0 if ok else 1


kn, ks, c, tp, tq = sp.symbols("k_n k_s c tan_phi tan_psi", positive=True)
d = sp.Matrix(sp.symbols("d_s d_n d_theta", real=True))
t0 = sp.Matrix(sp.symbols("t0_s t0_n t0_theta", real=True))
dp = sp.Matrix(sp.symbols("dp_s dp_n dp_theta", real=True))
D = sp.diag(ks, kn, ks)

# 1. The slip return as a function of d, differentiated symbolically.
trial = t0 + D * (d - dp)
tau_tr = sp.sqrt(trial[0]**2 + trial[2]**2)
H = ks + kn * tp * tq
dl = (tau_tr + trial[1] * tp - c) / H
rho = (tau_tr - ks * dl) / tau_tr
t_slip = sp.Matrix([rho * trial[0], trial[1] - kn * tq * dl, rho * trial[2]])
J = t_slip.jacobian(d)

m = sp.Matrix([trial[0] / tau_tr, 0, trial[2] / tau_tr])
closed = sp.zeros(3, 3)
for a in (0, 2):
    for b in (0, 2):
        closed[a, b] = (ks * rho * ((1 if a == b else 0) - m[a] * m[b]) +
                        ks * kn * tp * tq / H * m[a] * m[b])
    closed[a, 1] = -ks * kn * tp / H * m[a]
    closed[1, a] = -ks * kn * tq / H * m[a]
closed[1, 1] = ks * kn / H
difference = (J - closed).applyfunc(sp.simplify)
report("slip: sympy Jacobian of the return mapping = closed form",
       difference == sp.zeros(3, 3))
report("stick: Jacobian of t_tr = D", trial.jacobian(d) == D)
report("slip tangent symmetric iff psi = phi",
       sp.simplify((closed - closed.T).subs(tq, tp)) == sp.zeros(3, 3) and
       sp.simplify(closed[0, 1] - closed[1, 0]) != 0)
# Along the trial shear direction at psi = phi = 0 the slip tangent has no
# shear stiffness (perfect plasticity), across it rho ks (radial return).
report("slip at phi = psi = 0: m^T D_t m = 0",
       sp.simplify((m.T * closed * m)[0].subs({tp: 0, tq: 0})) == 0)


# 2. The return mapping in floating point (all three cases) against the
#    closed form by central differences at random states of every regime.
def return_map(law, d, t0, dp):
    kn_, ks_, c_, tp_, tq_, st = law
    k = (ks_, kn_, ks_)
    t = [t0[i] + k[i] * (d[i] - dp[i]) for i in range(3)]
    if t[1] > st:
        return [0., 0., 0.], "open"
    tau = (t[0]**2 + t[2]**2) ** 0.5
    f = tau + t[1] * tp_ - c_
    if f <= 0.:
        return t, "stick"
    dl_ = f / (ks_ + kn_ * tp_ * tq_)
    r = (tau - ks_ * dl_) / tau
    return [r * t[0], t[1] - kn_ * tq_ * dl_, r * t[2]], "slip"


closed_f = sp.lambdify((kn, ks, c, tp, tq, d, t0, dp), closed)


def tangent(law, d, t0, dp):
    kn_, ks_, c_, tp_, tq_, st = law
    t, state = return_map(law, d, t0, dp)
    if state == "open":
        return [[0.] * 3 for _ in range(3)]
    if state == "stick":
        return [[(ks_, kn_, ks_)[a] if a == b else 0. for b in range(3)]
                for a in range(3)]
    return closed_f(kn_, ks_, c_, tp_, tq_, d, t0, dp).tolist()


random.seed(3)
worst = {"stick": 0., "slip": 0., "open": 0.}
count = {"stick": 0, "slip": 0, "open": 0}
for _ in range(3000):
    phi = random.uniform(1., 45.)
    law = (random.uniform(1e3, 1e6), random.uniform(1e3, 1e6),
           random.uniform(0., 20.), sp.tan(sp.rad(phi)).evalf(),
           sp.tan(sp.rad(random.uniform(0., phi))).evalf(), 0.)
    law = tuple(float(x) for x in law)
    law = law[:5] + (random.uniform(0., 1.) * law[2] / law[3],)
    t0_ = [random.uniform(-10., 10.), random.uniform(-200., 0.), 0.]
    d_ = [random.uniform(-1., 1.) * 100. / law[1] for _ in range(3)]
    dp_ = [random.uniform(-1., 1.) * 20. / law[1], 0.,
           random.uniform(-1., 1.) * 20. / law[1]]
    t, state = return_map(law, d_, t0_, dp_)
    h = 1e-7 * 100. / max(law[0], law[1])  # 1e-7 of the traction scale
    # a few steps away from a regime boundary (one-sided tangents there)
    if any(return_map(law, [d_[i] + s * h * (i == b) for i in range(3)],
                      t0_, dp_)[1] != state
           for b in range(3) for s in (-4, 4)):
        continue
    Dt = tangent(law, d_, t0_, dp_)
    scale = max(law[0], law[1])
    for b in range(3):
        plus = return_map(law, [d_[i] + h * (i == b) for i in range(3)],
                          t0_, dp_)[0]
        minus = return_map(law, [d_[i] - h * (i == b) for i in range(3)],
                           t0_, dp_)[0]
        for a in range(3):
            fd = (plus[a] - minus[a]) / (2 * h)
            worst[state] = max(worst[state], abs(fd - Dt[a][b]) / scale)
    count[state] += 1
print("   states sampled: %s" % count)
print("   worst |D_t - central difference| / max(kn, ks): %s" % worst)
# Central differences: truncation h^2 |t'''| / 6 and round-off
# eps |t| / h; with h = 1e-7 of the traction scale both are below 1e-7 of
# the stiffness.
report("closed form = central differences in every regime (1e-6 of k)",
       all(count[s] > 100 for s in count) and
       all(w < 1e-6 for w in worst.values()))

sys.exit(1 if failures else 0)
