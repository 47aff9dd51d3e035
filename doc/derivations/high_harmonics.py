#!/usr/bin/python3
"""
Manufactured solutions for high harmonics n = 8 and n = 16 (symmetric family)
for tests/harmonic/robust_high_harmonics.cc (hard-case stability suite, doc/robustness.md).

Run:   /usr/bin/python3 doc/derivations/high_harmonics.py
Writes tests/support/mms_high_harmonics.h (or the path given as first argument) and
prints PASS/FAIL lines; exits non-zero on failure.

Reuses manufactured_solutions.py unchanged: the same amplitudes (U - W =
r^(n-1) P, U + W = r^(n+1) Q, V = r^n S with the symmetric P, Q, S), the same
amplitude equilibrium equations from operator.py, the same muparser printer
and header writer (renamed namespace mms_high and include guard). Checks:
every string is a polynomial in r times smooth factors (no division by r),
the axis conditions U = V = W = 0 at r = 0 hold (n >= 2), and the strings
agree with the sympy expressions; the 3D Cartesian div(sigma) check of
manufactured_solutions.py is run on a few points (Chebyshev reconstruction).
"""
import importlib.util
import math
import os
import random
import sys

import sympy as sp

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, '..', '..'))
_spec = importlib.util.spec_from_file_location(
    'fssi_mms', os.path.join(HERE, 'manufactured_solutions.py'))
ms = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(ms)
op, r, z, x, y = ms.op, ms.r, ms.z, ms.x, ms.y
lam, mu, SYM = ms.lam, ms.mu, ms.SYM

HARMONICS = (8, 16)


def main():
    out_path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        ROOT, 'tests', 'mms_high_harmonics.h')
    rng = random.Random(5)
    Ev, nuv = 2.5, 0.3
    entries = []
    for nn in HARMONICS:
        fam = SYM
        tag = f'n={nn} {fam}'
        (U, V, W), fields, strings, ok_reg = ms.harmonic_fields(nn, fam)
        ms.check(ok_reg, f'{tag}: only r^k, k >= 0 (no division by r)')
        U0, V0, W0 = [sp.limit(q, r, 0) for q in (U, V, W)]
        ms.check(U0 == 0 and V0 == 0 and W0 == 0, f'{tag}: axis conditions')
        # 3D Cartesian div(sigma) + f = 0 at a few points
        pts = [(rng.uniform(0.2, 1), rng.uniform(0, 2 * math.pi), rng.uniform(0, 1))
               for _ in range(5)]
        err = ms.cartesian_equilibrium_residual(nn, fam, (U, V, W), strings, pts, Ev, nuv)
        ms.check(err < 1e-9, f'{tag}: Cartesian div(sigma) + f = 0 (max rel. {err:.1e})')
        # strings equal sympy
        ok = ms.strings_match_sympy(fields, strings,
                                    [(0.0, 0.3), (0.37, 0.81), (1.0, 1.0), (0.9, 0.0)],
                                    Ev, nuv, 1e-11)
        ms.check(ok, f'{tag}: muparser strings match sympy')
        entries.append((nn, fam, strings, (U, V, W)))
    tmp = out_path + '.tmp'
    ms.write_header(tmp, entries)
    with open(tmp) as fh:
        text = fh.read()
    os.remove(tmp)
    text = text.replace('manufactured_solutions.py', 'high_harmonics.py (reusing manufactured_solutions.py)', 1)
    text = text.replace('fourier_ssi_tests_mms_solutions_h', 'fourier_ssi_tests_mms_high_harmonics_h')
    text = text.replace('namespace mms\n', 'namespace mms_high\n').replace('} // namespace mms\n', '} // namespace mms_high\n')
    with open(out_path, 'w') as fh:
        fh.write(text)
    print(f'wrote {os.path.relpath(out_path, ROOT)}')
    if ms._failures:
        print(f'SUMMARY: {len(ms._failures)} FAIL')
        sys.exit(1)
    print('SUMMARY: all checks PASS')


if __name__ == '__main__':
    main()
