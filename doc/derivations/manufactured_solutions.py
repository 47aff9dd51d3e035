#!/usr/bin/python3
"""
Manufactured solutions for the Fourier (semi-analytical) elasticity solver.

Run:   /usr/bin/python3 doc/derivations/manufactured_solutions.py
Writes tests/support/mms_solutions.h (path relative to the repository root; pass
another path as the first argument) and prints PASS/FAIL lines; exits
non-zero on failure.

For n in {0, 1, 2, 3} and both families the amplitudes (U, V, W)(r, z) on
r in [0, 1], z in [0, 1] are the Fourier amplitudes of a SMOOTH Cartesian
field.  With P, Q, S smooth functions of (r^2, z):
  symmetric,     n >= 1:  U - W = r^(n-1) P,  U + W = r^(n+1) Q,  V = r^n S
  antisymmetric, n >= 1:  U + W = r^(n-1) P,  U - W = r^(n+1) Q,  V = r^n S
  n = 0 symmetric:        U = r P, V = S, W = 0
  n = 0 antisymmetric:    W = r P, U = V = 0
(doc/theory.md, section "Axis conditions": r^m g(r^2) cos(m t) = Re(x+iy)^m
g(x^2+y^2) is smooth).  The body force f = -div(sigma) is obtained from the
amplitude equilibrium equations derived in 3D by operator.py (section e) for
a homogeneous isotropic material (Lame constants from E, nu), and checked
here numerically against div(sigma) computed in Cartesian coordinates from
the reconstructed 3D field, at random points including r = 1e-8.
"""
import importlib.util
import math
import os
import random
import sys

import sympy as sp
from sympy.printing.str import StrPrinter

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, '..', '..'))

_spec = importlib.util.spec_from_file_location('fssi_operator', os.path.join(HERE, 'operator.py'))
op = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(op)

r, z, th, x, y = op.r, op.z, op.th, op.x, op.y
lam, mu, E, nu = op.lam, op.mu, op.E, op.nu
SYM, ANTI = op.SYM, op.ANTI

LAM_STR = '(E*nu/((1+nu)*(1-2*nu)))'
MU_STR = '(E/(2*(1+nu)))'

_failures = []


def check(ok, what):
    ok = bool(ok)
    print(('PASS ' if ok else 'FAIL ') + what)
    if not ok:
        _failures.append(what)
    return ok


# ----------------------------------------------------------------------------
# the manufactured amplitudes
# ----------------------------------------------------------------------------
def amplitudes(nn, family):
    if family == SYM:
        P = sp.exp(-r ** 2) * sp.cos(z)
        Q = sp.sin(r ** 2 + z)
        S = sp.cos(r ** 2) * sp.exp(z / 2)
    else:
        P = sp.cos(r ** 2) * sp.sin(z + 1)
        Q = sp.exp(-r ** 2 / 2) * sp.cos(2 * z)
        S = sp.exp(-r ** 2) * sp.sin(z + sp.Rational(1, 2))
    if nn == 0:
        if family == SYM:
            return r * P, S, sp.Integer(0)
        return sp.Integer(0), sp.Integer(0), r * P
    lo = r ** (nn - 1) * P
    hi = r ** (nn + 1) * Q
    V = r ** nn * S
    if family == SYM:
        U, W = (lo + hi) / 2, (hi - lo) / 2
    else:
        U, W = (lo + hi) / 2, (lo - hi) / 2
    return sp.expand(U), sp.expand(V), sp.expand(W)


def regular_form(expr):
    """Expand; every term must carry a non-negative integer power of r."""
    e = sp.expand(sp.powsimp(sp.expand(expr)))
    bad = []
    for term in sp.Add.make_args(e):
        powr = sp.sympify(term.as_powers_dict().get(r, 0))
        if not (powr.is_integer and powr >= 0):
            bad.append(term)
    return e, bad


# ----------------------------------------------------------------------------
# muparser printing: no '^' (unary minus / power precedence differs between
# muparser versions), integer powers written as products
# ----------------------------------------------------------------------------
class MuParserPrinter(StrPrinter):
    def _print_Pow(self, expr, rational=False):
        b, e = expr.as_base_exp()
        bs = self.parenthesize(b, 100)  # always parenthesise compound bases
        if not (b.is_Symbol or b.is_Number):
            bs = '(' + self._print(b) + ')'
        if e.is_Integer and e > 0:
            return '(' + '*'.join([bs] * int(e)) + ')'
        if e.is_Integer and e < 0:
            return '(1/(' + '*'.join([bs] * int(-e)) + '))'
        if e == sp.Rational(1, 2):
            return 'sqrt(' + self._print(b) + ')'
        raise ValueError(f'power {expr} not printable for muparser')

    def _print_Rational(self, expr):
        return f'({expr.p}/{expr.q})'

    def _print_Exp1(self, expr):
        raise ValueError('Euler number e not allowed')

    def _print_Pi(self, expr):
        raise ValueError('pi not expected')


def mup(expr):
    return MuParserPrinter().doprint(expr)


_env = {'sin': math.sin, 'cos': math.cos, 'exp': math.exp, 'sqrt': math.sqrt}


def eval_string(s, rv, zv, Ev, nuv):
    assert '^' not in s and '**' not in s
    return eval(s, {'__builtins__': {}}, dict(_env, r=rv, z=zv, E=Ev, nu=nuv))


# ----------------------------------------------------------------------------
# 3D Cartesian reconstruction without square roots
# ----------------------------------------------------------------------------
def cartesian_field(nn, family, U, V, W):
    R = sp.sqrt(x ** 2 + y ** 2)
    c = x / R
    s = y / R
    cn = sp.chebyshevt(nn, c)
    sn = s * sp.chebyshevu(nn - 1, c) if nn >= 1 else sp.Integer(0)
    tu, tw = (cn, sn) if family == SYM else (sn, cn)
    sub = lambda e: e.subs(r, R)
    u, v, w = sub(U) * tu, sub(V) * tu, sub(W) * tw
    comps = (u * c - w * s, u * s + w * c, v)
    out = []
    for cpt in comps:
        e = sp.cancel(sp.together(sp.expand(cpt)))
        num, den = sp.fraction(e)
        out.append((e, den))
    return out


def harmonic_fields(nn, fam):
    """The amplitudes of harmonic (nn, fam), their 15 fields (U, V, W, their
    first derivatives, the body-force amplitudes) as sympy expressions and as
    muparser strings; ok is False if a field divides by r."""
    U, V, W = amplitudes(nn, fam)
    A = op.equilibrium_amplitudes(nn, fam, U, V, W, lam, mu)
    fields = {'U': U, 'V': V, 'W': W,
              'dU_dr': sp.diff(U, r), 'dU_dz': sp.diff(U, z),
              'dV_dr': sp.diff(V, r), 'dV_dz': sp.diff(V, z),
              'dW_dr': sp.diff(W, r), 'dW_dz': sp.diff(W, z)}
    strings = {}
    ok = True
    for k, e in fields.items():
        e, bad = regular_form(e)
        ok &= not bad
        fields[k] = e
        strings[k] = mup(e)
    for k, a in zip(('f_r', 'f_z', 'f_theta'), A):
        f, bad = regular_form(-a)
        ok &= not bad
        if bad:
            print('   singular terms:', bad)
        # f = lam * fl + mu * fm exactly: the strings carry E and nu.
        fl = sp.expand(f.coeff(lam))
        fm = sp.expand(f.coeff(mu))
        ok &= sp.expand(f - lam * fl - mu * fm) == 0
        fields[k] = f
        parts = []
        if fl != 0:
            parts.append(f'{LAM_STR}*({mup(fl)})')
        if fm != 0:
            parts.append(f'{MU_STR}*({mup(fm)})')
        strings[k] = ' + '.join(parts) if parts else '0'
    return (U, V, W), fields, strings, ok


def cartesian_equilibrium_residual(nn, fam, UVW, strings, points, Ev, nuv):
    """Largest relative |div(sigma) + f| of the reconstructed 3D Cartesian
    field at the points (r, theta, z), f taken from the muparser strings."""
    lamv = Ev * nuv / ((1 + nuv) * (1 - 2 * nuv))
    muv = Ev / (2 * (1 + nuv))
    cart = cartesian_field(nn, fam, *UVW)
    X3 = (x, y, z)
    uc = sp.Matrix([e for e, _ in cart])
    grad = uc.jacobian(X3)
    eps = (grad + grad.T) / 2
    sig = lamv * eps.trace() * sp.eye(3) + 2 * muv * eps
    div = [sum(sp.diff(sig[i, j], X3[j]) for j in range(3)) for i in range(3)]
    divf = sp.lambdify(X3, div, 'math')
    err = 0.
    for rv, tv, zv in points:
        d = divf(rv * math.cos(tv), rv * math.sin(tv), zv)
        fr, fz, ft = [eval_string(strings[k], rv, zv, Ev, nuv)
                      for k in ('f_r', 'f_z', 'f_theta')]
        cn, sn = math.cos(nn * tv), math.sin(nn * tv)
        Tu, Tw = (cn, sn) if fam == SYM else (sn, cn)
        fx = fr * Tu * math.cos(tv) - ft * Tw * math.sin(tv)
        fy = fr * Tu * math.sin(tv) + ft * Tw * math.cos(tv)
        scale = 1 + max(abs(q) for q in d)
        err = max(err, abs(d[0] + fx) / scale, abs(d[1] + fy) / scale,
                  abs(d[2] + fz * Tu) / scale)
    return err


def strings_match_sympy(fields, strings, points, Ev, nuv, rtol):
    """Every string is finite at the points (r, z) and equals its sympy
    expression to rtol where r > 0."""
    lamv = Ev * nuv / ((1 + nuv) * (1 - 2 * nuv))
    muv = Ev / (2 * (1 + nuv))
    ok = True
    for k, e in fields.items():
        fnum = sp.lambdify((r, z), e.subs({lam: lamv, mu: muv}), 'mpmath')
        for rv, zv in points:
            sv = eval_string(strings[k], rv, zv, Ev, nuv)
            ok &= math.isfinite(sv)
            if rv > 0:
                ok &= abs(sv - float(fnum(rv, zv))) <= rtol * (1 + abs(sv))
    return ok


def main():
    out_path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, 'tests', 'mms_solutions.h')
    rng = random.Random(20070101)
    Ev, nuv = 2.5, 0.3
    entries = []
    for nn in range(4):
        for fam in (SYM, ANTI):
            tag = f'n={nn} {fam}'
            (U, V, W), fields, strings, ok_reg = harmonic_fields(nn, fam)
            check(ok_reg, f'{tag}: U,V,W, derivatives and f contain only r^k, k >= 0 '
                          f'(no division by r)')
            # axis conditions and parity on the amplitudes
            U0, V0, W0 = [sp.limit(q, r, 0) for q in (U, V, W)]
            if nn == 0:
                ok = (U0 == 0) if fam == SYM else (W0 == 0)
            elif nn == 1:
                ok = V0 == 0 and sp.simplify(U0 + (1 if fam == SYM else -1) * W0) == 0
            else:
                ok = U0 == 0 and V0 == 0 and W0 == 0
            check(ok, f'{tag}: axis conditions hold at r = 0')
            # the 3D field is smooth: Cartesian components are sqrt-free
            # expressions with denominators free of x, y
            cart = cartesian_field(nn, fam, U, V, W)
            ok = all(not e.has(sp.sqrt(x ** 2 + y ** 2)) and
                     not any(p.exp.is_Rational and not p.exp.is_Integer for p in e.atoms(sp.Pow))
                     and all(isinstance(fac, sp.exp) or not (fac.has(x) or fac.has(y))
                             for fac in sp.Mul.make_args(den)) for e, den in cart)
            check(ok, f'{tag}: reconstructed Cartesian field is smooth (no sqrt(x^2+y^2), '
                      f'no 1/(x^2+y^2))')
            # 3D Cartesian div(sigma) at random points vs the f strings
            pts = [(rng.uniform(0, 1), rng.uniform(0, 2 * math.pi), rng.uniform(0, 1))
                   for _ in range(8)]
            pts += [(1e-8, rng.uniform(0, 2 * math.pi), rng.uniform(0, 1)) for _ in range(3)]
            pts += [(1.0, 0.7, 1.0), (0.5, 2.0, 0.0)]
            err = cartesian_equilibrium_residual(nn, fam, (U, V, W), strings, pts, Ev, nuv)
            check(err < 1e-10, f'{tag}: Cartesian 3D div(sigma) + f = 0 at {len(pts)} random '
                               f'points incl. r = 1e-8 (max rel. residual {err:.1e})')
            # strings equal the sympy expressions; finite at r = 0 and continuous
            ok = strings_match_sympy(fields, strings,
                                     [(0.0, 0.3), (1e-8, 0.3), (0.37, 0.81), (1.0, 1.0), (0.9, 0.0)],
                                     Ev, nuv, 1e-12)
            for k in fields:
                near = eval_string(strings[k], 1e-8, 0.3, Ev, nuv)
                at0 = eval_string(strings[k], 0.0, 0.3, Ev, nuv)
                ok &= abs(near - at0) <= 1e-6 * (1 + abs(at0))
            check(ok, f'{tag}: the 15 muparser strings match sympy, are finite at r = 0 '
                      f'and continuous there')
            entries.append((nn, fam, strings, (U, V, W)))
    write_header(out_path, entries)
    print()
    if _failures:
        print(f'SUMMARY: {len(_failures)} FAIL')
        for f in _failures:
            print('  FAIL', f)
        sys.exit(1)
    print('SUMMARY: all checks PASS')


def write_header(path, entries):
    L = []
    L.append('// Generated by doc/derivations/manufactured_solutions.py -- do not edit by hand.')
    L.append('//')
    L.append('// Manufactured solutions of the harmonic (n, family) elasticity problem on')
    L.append('// r in [0, 1], z in [0, 1] (doc/theory.md, "Manufactured solutions").')
    L.append('// Symmetric family:     u = U cos(n t), v = V cos(n t), w = W sin(n t),')
    L.append('// antisymmetric family: u = U sin(n t), v = V sin(n t), w = W cos(n t);')
    L.append('// the body-force amplitudes (f_r, f_z, f_theta) carry the trig factors of')
    L.append('// (u, v, w).  (U, V, W) are the amplitudes of a smooth 3D Cartesian field, so')
    L.append('// they satisfy the axis conditions at r = 0, and solve div(sigma) + f = 0 for')
    L.append('// a homogeneous isotropic material with Young modulus E and Poisson ratio nu.')
    L.append('// Expressions: deal.II FunctionParser (muparser) syntax, variables "r,z",')
    L.append('// constants E and nu (pass them in the constants map); only + - * / ( ),')
    L.append('// sin, cos, exp; no "^"; every expression is finite at r = 0.')
    L.append('// dX_dr, dX_dz: first derivatives of the amplitudes (for H1 errors).')
    L.append('#ifndef fourier_ssi_tests_mms_solutions_h')
    L.append('#define fourier_ssi_tests_mms_solutions_h')
    L.append('')
    L.append('namespace mms')
    L.append('{')
    L.append('  struct ManufacturedSolution')
    L.append('  {')
    L.append('    unsigned int n;')
    L.append('    bool         symmetric;')
    L.append('    const char  *U, *V, *W;')
    L.append('    const char  *f_r, *f_z, *f_theta;')
    L.append('    const char  *dU_dr, *dU_dz, *dV_dr, *dV_dz, *dW_dr, *dW_dz;')
    L.append('  };')
    L.append('')
    L.append('  /** Variable names for dealii::FunctionParser::initialize(). */')
    L.append('  constexpr const char *variables = "r,z";')
    L.append('')
    L.append('  // Amplitudes chosen (P, Q, S as in manufactured_solutions.py):')
    for nn, fam, strings, (U, V, W) in entries:
        L.append(f'  //   n={nn} {fam}: U = {sp.factor(U)}, V = {sp.factor(V)}, W = {sp.factor(W)}')
    L.append('  constexpr ManufacturedSolution solutions[] = {')
    keys = ('U', 'V', 'W', 'f_r', 'f_z', 'f_theta',
            'dU_dr', 'dU_dz', 'dV_dr', 'dV_dz', 'dW_dr', 'dW_dz')
    for nn, fam, strings, _ in entries:
        L.append(f'    // n = {nn}, {fam}')
        L.append(f'    {{{nn},')
        L.append(f'     {"true" if fam == SYM else "false"},')
        for i, k in enumerate(keys):
            sep = ',' if i + 1 < len(keys) else '},'
            L.append(f'     /* {k} */ "{strings[k]}"{sep}')
    L.append('  };')
    L.append('')
    L.append('  constexpr unsigned int n_solutions =')
    L.append('    sizeof(solutions) / sizeof(solutions[0]);')
    L.append('} // namespace mms')
    L.append('')
    L.append('#endif')
    with open(path, 'w') as fh:
        fh.write('\n'.join(L) + '\n')
    print(f'wrote {os.path.relpath(path, ROOT)} ({len(entries)} solutions)')


if __name__ == '__main__':
    main()
