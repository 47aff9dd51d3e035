#!/usr/bin/python3
"""A direction probe through an exact (contact) interface.

The rigid disc of prm/disc-gap.prm (disc r0 = 0.5 m in an elastic ring,
G = E / (2 (1 + nu)) = 38462 kPa, n = 0..8), its tensionless frictionless
interface the disc's only tie to the ring, driven along the probe
u : L theta = 1 : 1 (L = 1 m) to u = 1e-3 m in 4 steps, three ways:
  contact   `contact, phi=0` (exact non-penetration);
  k5, k6    `coulomb, kn=ks=kappa G / r0, c=0, phi=0, sigma_t=0` at
            kappa = 1e5 and 1e6 (stiff penalties; Newton by default).
The rotation changes the contact arc along the face (16/35 slip/open
samples against 21/30 for the pure H path), so the probe's H is not the
pure path's: the references are the penalty limit and homogeneity.
Checks:
(1) every run exits 0;
(2) the direction holds at every step: L theta = u to 1e-12 m (the
    combination is constrained exactly; the bound is round-off);
(3) positive homogeneity (no strength, no initial stress: the response
    scales with the motion): probe_H / u equal at every step to 1e-8 (the
    steps stop at a residual of 1e-10 of the force scale);
(4) contact's probe_H against the 1/kappa extrapolation of the penalties,
    H_inf = H(1e6) + (H(1e6) - H(1e5)) / 9, to 1e-7 relative (measured
    6.4e-11): the penalty
    error is a / kappa + O(1 / kappa^2) when the open samples are the
    same at 1e5 and 1e6 (asserted), so the extrapolation's own error is
    of order (H(1e6) - H(1e5)) / 10 / kappa, far below 1e-7; the bound is
    set by the runs' convergence (1e-10 of a force scale that reaches
    kappa / 10 times the load at 1e6); a contact kept as a spring of
    the augmentation (1000 G / l) would be off by about 1e-3;
(5) the rotation is resisted, in the sense of the probe: 0 < probe_M <=
    1e3 kN m (the contact pressure's lever is at most 0.5 m);
(6) Newton keeps its few updates with every Load path entry at its
    default: at most 15 per step.
Usage: direction_probe_contact.py FOURIER_SSI_EXE SOURCE_DIR WORK_DIR
"""
import csv
import os
import shutil
import subprocess
import sys

exe, source_dir, work = sys.argv[1:4]
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from relative_checks import finish, that  # noqa: E402

shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
environment = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
G, R0 = 1e5 / 2.6, 0.5
OUTPUT = """
subsection Output
  set Directory = out
end
subsection Rigid foundation
  set Motion direction = u: 1, rotation: 1
  set Direction length = 1
end
"""


def law(kappa):
    if kappa is None:
        return "5: contact, phi=0"
    k = kappa * G / R0
    return "5: coulomb, kn=%.17g, ks=%.17g, c=0, phi=0, sigma_t=0" % (k, k)




def run(name, kappa):
    folder = os.path.join(work, name)
    os.makedirs(folder)
    scene = open(os.path.join(source_dir, "prm/disc-gap.prm")).read()
    extra = "subsection Interfaces\n  set Interfaces = %s\nend\n" % law(kappa)
    open(os.path.join(folder, "scene.prm"), "w").write(scene + OUTPUT + extra)
    done = subprocess.run([exe, "scene.prm"], cwd=folder, env=environment,
                          capture_output=True, text=True)
    print("%s:" % name)
    that(done.returncode == 0,
     "exits 0 (%s)" % done.stderr.strip()[-200:])
    path = os.path.join(folder, "out", "load-displacement.csv")
    return list(csv.DictReader(open(path))) if os.path.isfile(path) else []


steps = {name: run(name, kappa)
         for name, kappa in (("contact", None), ("k5", 1e5), ("k6", 1e6))}
c = steps["contact"]
if len(c) != 4 or any(len(s) != 4 for s in steps.values()):
    that(False,
     "4 steps in every run")
    finish()
H = {name: float(s[-1]["probe_H_kN"]) for name, s in steps.items()}
limit = H["k6"] + (H["k6"] - H["k5"]) / 9.
print("  probe_H: contact %.12g, kappa 1e5 %.12g, 1e6 %.12g, "
      "extrapolated %.12g kN; probe_M %s kN m"
      % (H["contact"], H["k5"], H["k6"], limit, c[-1]["probe_M_kNm"]))
that(all(abs(float(r["rotation_rad"]) - float(r["horizontal_m"])) <= 1e-12
          for r in c),
     "L theta = u at every step (L = 1 m), to 1e-12 m")
ratios = [float(r["probe_H_kN"]) / float(r["horizontal_m"]) for r in c]
that(max(ratios) - min(ratios) <= 1e-8 * abs(ratios[-1]),
     "probe_H / u equal at every step to 1e-8 (%s kN/m)" % ratios[-1])
that(steps["k5"][-1]["open"] == steps["k6"][-1]["open"],
     "the penalties open the same samples at kappa = 1e5 and 1e6 (%s, %s)"
      % (steps["k5"][-1]["open"], steps["k6"][-1]["open"]))
that(abs(H["contact"] - limit) <= 1e-7 * abs(limit),
     "contact probe_H = the penalties' 1/kappa limit to 1e-7 (%.2e)"
      % (abs(H["contact"] - limit) / abs(limit)))
that(0. < float(c[-1]["probe_M_kNm"]) <= 1e3,
     "0 < probe_M <= 1e3 kN m")
updates = {name: [int(r["iterations"]) for r in s]
           for name, s in steps.items()}
that(all(1 <= n <= 15 for u in updates.values() for n in u),
     "Newton updates per step in [1, 15] (%s)" % updates)
finish()
