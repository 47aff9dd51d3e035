#!/usr/bin/python3
"""tools/cyclic_stiffness.py on a small rigid caisson in Tresca clay
(tests/prm/cyclic-stiffness-caisson.prm: D = 2 m, L = 2 m, G = 10 MPa,
nu = 0.49, s_u = 50 kPa), about a mean state H = 100 kN, M = 100 kN m, at
two amplitudes, the horizontal drive's load H with M = 1.5 m x H (so that
both drives change both loads and the 2x2 inverse is a full one): 0.0004 m
(with the rotation drive's default amplitude, the elastic theta/u of that
load times it), where the soil stays below first
yield (checked: no plastic sample in any step), and 0.004 m, where it
yields. About 10 s wall on 2 cores.

Checks, with the reason for each tolerance:
- below first yield the soil is linear elastic, so the secant 6x6 is the
  program's elastic 6x6 of the same scene without plasticity
  (foundation-stiffness.csv of a run made here, independent of the tool):
  every term within 1e-7 of the largest term of its block. The secant comes
  from coupled Newton solves converged to Tolerance = 1e-10 of the load and
  differences of turning points; measured 6.4e-11 of the largest term, 1.9e-10
  of K_xx itself;
- below first yield the secant 2x2 is symmetric (Betti's reciprocal
  theorem holds for the linear soil): |k_Hr - k_rH| / sqrt(k_HH k_rr)
  below 1e-8 (measured 3e-12, round-off of the 2x2 inverse and the
  solver tolerance). Above first yield the two columns come from two
  different plastic fields and need not be reciprocal: the asymmetry is
  reported, not bounded;
- the mean state the cycles are centred on: u_m and theta_m of the held
  loads equal the elastic flexibility times (H, M) within 1e-7 (the held
  stage is elastic here), and each cycle's turning points lie at
  u_m +- a (theta_m +- r) to 1e-12 m (rad): the targets are set so;
- the SubDyn file, read by SubDyn's rules (labels in any order and any
  case, comment lines !, #, %), equals secant-stiffness-N.csv to 1e-9 of
  each term (10 significant digits printed); at the elastic amplitude its
  value lines are the program's own foundation-stiffness-subdyn.txt line
  for line within the last printed digit (relative 1e-8) and it has the
  same labels in the same order and the same comment-line count;
- damping.csv's xi_lateral, xi_rocking and their errors are load-cycles.csv's
  damping_ratio (and _error) of the last cycle of each drive, to 1e-8 (the
  tool prints 12 digits); c_xx = 2 xi_lateral K_xx / omega, c_ryry = 2
  xi_rocking K_ryry / omega at 0.25 Hz to 1e-8;
- the SoilDyn file has CalcOption 1, its stiffness block equals the CSV 6x6
  to 1e-6 (7 digits printed) and its damping block the table's c to 1e-6;
- above first yield the lateral secant stiffness is below the elastic one
  and the lateral damping ratio is positive (the loop opens);
- the tangent at the mean state (--tangent-step 0.0004 m), its x, z, ry
  block: at the elastic mean state its drives stay elastic, so the block
  is the elastic one (x-z and z-ry terms zero) within 1e-7 of its largest
  term (the same solver tolerance as the
  secant) with error bars below 1e-7 of it; at a mean state that yields
  (H = 400 kN, M = 600 kN m: plastic samples at the mean state), the bar
  of the 0.0004 m steps contains the tangent from steps 20 times smaller
  (the reference: its bar is below 0.1 of the coarse one, so it has
  converged that much further), and the tangent lies below the elastic
  one, also for K_zz; the x-z and z-ry terms that plasticity couples are
  held by the same bars. About 12 s more;
- bad input (--tangent-step -1) into the first run's folder: one line,
  exit 1, and none of that run's result files left.
Usage: cyclic_stiffness.py FOURIER_SSI_EXE SOURCE_DIR WORK_DIR
"""
import csv
import math
import os
import re
import shutil
import subprocess
import sys

import numpy as np

exe, source_dir, work = sys.argv[1:4]
sys.path.insert(0, os.path.join(source_dir, "tests"))
import relative_checks as rc  # noqa: E402

shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
scene = os.path.join(source_dir, "tests", "prm", "cyclic-stiffness-caisson.prm")
tool = os.path.join(source_dir, "tools", "cyclic_stiffness.py")
out = os.path.join(work, "out")
H_m, M_m = 100.0, 100.0
status = subprocess.call(
    ["/usr/bin/python3", tool, scene, "--mean-h", repr(H_m), "--mean-m", repr(M_m),
     "--amplitudes", "0.0004,0.004", "--lever", "1.5", "--exe", exe, "--np", "2", "--out", out,
     "--no-plot", "--tangent-step", "0.0004"], cwd=work)
rc.that(status == 0, "the tool runs (exit %d)" % status)
if status != 0:
    rc.finish()

# The independent elastic reference: the scene without plasticity and its
# Load path, Stiffness matrix = true, run here.
text = open(scene).read()
text = re.sub(r"subsection Soil plasticity\n.*?\nend\n", "", text, flags=re.S)
text = re.sub(r"subsection Load path\n.*?\nend\n", "", text, flags=re.S)
text = text.replace("set Harmonics         = 0, 1, 2", "set Harmonics         = auto")
text = text.replace("set Family            = symmetric\n", "")
text = text.replace("set Reference elevation = 0",
                    "set Reference elevation = 0\n  set Stiffness matrix = true")
text = text.replace("output/cyclic-stiffness-caisson", "elastic")
open(os.path.join(work, "elastic.prm"), "w").write(text)
subprocess.check_call([exe, "elastic.prm"], cwd=work, stdout=subprocess.DEVNULL)
DOFS = ("x", "y", "z", "rx", "ry", "rz")


def matrix(path):
    K = np.zeros((6, 6))
    for r in csv.DictReader(open(path)):
        _, i, j = r["term"].split("_")
        K[DOFS.index(i), DOFS.index(j)] = K[DOFS.index(j), DOFS.index(i)] = float(r["value"])
    return K


def rows(path):
    return list(csv.DictReader(open(path)))


K_el = matrix(os.path.join(work, "elastic", "foundation-stiffness.csv"))
K1 = matrix(os.path.join(out, "secant-stiffness-1.csv"))
K2 = matrix(os.path.join(out, "secant-stiffness-2.csv"))
summary = rows(os.path.join(out, "secant-stiffness.csv"))
damping = rows(os.path.join(out, "damping.csv"))
runs = os.path.join(out, "runs")

# Below first yield: no plastic sample in either drive.
for drive in ("horizontal-1", "rotation-1"):
    steps = rows(os.path.join(runs, drive, "load-displacement.csv"))
    rc.that(all(int(s["plastic"]) == 0 for s in steps),
            "%s: no plastic sample in any of its %d steps" % (drive, len(steps)))

lateral = [0, 1, 3, 4]
scale = np.abs(K_el[np.ix_(lateral, lateral)]).max()
worst = np.abs(K1[np.ix_(lateral, lateral)] - K_el[np.ix_(lateral, lateral)]).max() / scale
rc.that(worst <= 1e-7, "elastic amplitude: secant lateral-rocking block = elastic 6x6, "
        "largest difference %.2e of the largest term (tol 1e-7)" % worst)
for i, j in ((0, 0), (0, 4), (4, 4), (1, 3)):
    rc.check("K_%s_%s at 0.0004 m" % (DOFS[i], DOFS[j]), K1[i, j], K_el[i, j], 1e-7)
for i in (2, 5):
    rc.check("K_%s_%s (elastic term, copied)" % (DOFS[i], DOFS[i]), K1[i, i], K_el[i, i], 1e-9)
zero = [(i, j) for i in range(6) for j in range(6) if K_el[i, j] == 0.0]
rc.that(all(K1[i, j] == 0.0 and K2[i, j] == 0.0 for i, j in zero),
        "the %d terms zero by axisymmetry are zero in both secant matrices" % len(zero))
asym = [float(s["asymmetry"]) for s in summary]
rc.that(asym[0] < 1e-8, "elastic amplitude: secant 2x2 symmetric, asymmetry %.2e (tol 1e-8)" % asym[0])
print("  info above first yield (0.004 m): asymmetry %.3e, K_xx/K_xx,el %.5f, K_ryry/K_ryry,el %.5f"
      % (asym[1], K2[0, 0] / K_el[0, 0], K2[4, 4] / K_el[4, 4]))

# The mean state and the centring of the cycles.
F = np.linalg.inv(K_el[np.ix_([0, 4], [0, 4])])
u_ref, th_ref = F @ np.array([H_m * 1e3, M_m * 1e3])
held = [s for s in rows(os.path.join(runs, "mean-state", "load-displacement.csv"))
        if float(s["held_fraction"]) == 1.0][0]
rc.check("mean state u_m = elastic flexibility x (H, M)", float(held["horizontal_m"]), u_ref, 1e-7)
rc.check("mean state theta_m", float(held["rotation_rad"]), th_ref, 1e-7)
for k, (a, r) in enumerate(((float(s["amplitude_m"]), float(s["rotation_amplitude_rad"]))
                            for s in summary)):
    for drive, key, centre, amp in (("horizontal", "horizontal_m", u_ref, a),
                                    ("rotation", "rotation_rad", th_ref, r)):
        steps = rows(os.path.join(runs, "%s-%d" % (drive, k + 1), "load-displacement.csv"))
        ends = [[s for s in steps if int(s["segment"]) == g][-1] for g in (1, 2, 3)]
        vals = [float(e[key]) for e in ends]
        centre_run = float(held[key])
        ok = (abs(vals[0] - centre_run - amp) < 1e-12 and abs(vals[1] - centre_run + amp) < 1e-12
              and abs(vals[2] - vals[0]) < 1e-12)
        rc.that(ok, "%s drive %d: turning points at the mean +- %g, +- 1e-12" % (drive, k + 1, amp))
motion = F @ np.array([1.0, 1.5])
ratio = motion[1] / motion[0]
rc.check("rotation drive's default amplitude = a |theta/u| (H, M = 1.5 m x H, elastic)",
         float(summary[0]["rotation_amplitude_rad"]), 0.0004 * abs(ratio), 1e-7)


# The SubDyn file by SubDyn's reading rules.
def subdyn(path):
    names = ["k%s%s" % (("x", "y", "z", "tx", "ty", "tz")[i], ("x", "y", "z", "tx", "ty", "tz")[j])
             for i in range(6) for j in range(6)]
    K = np.zeros((6, 6))
    for line in open(path):
        if not line.strip() or line.lstrip()[0] in "!#%":
            continue
        value, label = line.split()[:2]
        k = names.index(label.lower())
        i, j = divmod(k, 6)
        K[i, j] = K[j, i] = float(value)
    return K


for k, Kc in ((1, K1), (2, K2)):
    Ks = subdyn(os.path.join(out, "secant-stiffness-subdyn-%d.txt" % k))
    err = max(abs(Ks[i, j] - Kc[i, j]) / abs(Kc[i, j]) for i in range(6) for j in range(6)
              if Kc[i, j] != 0)
    rc.that(err <= 1e-9 and all(Ks[i, j] == 0 for i, j in zero),
            "SubDyn file %d = secant-stiffness-%d.csv (largest rel. difference %.1e, tol 1e-9)"
            % (k, k, err))
mine = open(os.path.join(out, "secant-stiffness-subdyn-1.txt")).read().splitlines()
theirs = open(os.path.join(work, "elastic", "foundation-stiffness-subdyn.txt")).read().splitlines()
c_mine = [l for l in mine if l.startswith("!")]
c_theirs = [l for l in theirs if l.startswith("!")]
v_mine = [l for l in mine if not l.startswith("!")]
v_theirs = [l for l in theirs if not l.startswith("!")]
layout = re.compile(r"^ [ -]\d\.\d{9}e[+-]\d\d   K[a-z]+$")
same = (len(c_mine) == len(c_theirs) and len(v_mine) == len(v_theirs) == 21 and
        all(layout.match(a) and layout.match(b) and a.split()[1] == b.split()[1]
            for a, b in zip(v_mine, v_theirs)))
rc.that(same, "SubDyn file: the program's layout (comment lines, '%17.9e   label', order)")
worst = max(abs(float(a.split()[0]) - float(b.split()[0])) /
            max(abs(float(b.split()[0])), 1e-300)
            for a, b in zip(v_mine, v_theirs) if float(b.split()[0]) != 0)
rc.that(worst <= 1e-8, "SubDyn file at the elastic amplitude = the program's file, "
        "largest rel. difference %.1e (tol 1e-8)" % worst)

# Damping: load-cycles.csv's own values, and c = 2 xi k / omega.
omega = 2 * math.pi * 0.25
for k, d in enumerate(damping):
    for drive, key in (("horizontal", "xi_lateral"), ("rotation", "xi_rocking")):
        cyc = rows(os.path.join(runs, "%s-%d" % (drive, k + 1), "load-cycles.csv"))[-1]
        for col, ref in ((key, "damping_ratio"), (key + "_error", "damping_ratio_error")):
            a, b = float(d[col]), float(cyc[ref])
            rc.that(abs(a - b) <= 1e-8 * max(abs(b), 1e-12),
                    "amplitude %d: %s %.6g = load-cycles.csv %s %.6g" % (k + 1, col, a, ref, b))
    Kk = (K1, K2)[k]
    for col, xi, kk in (("c_x_x_N_s_per_m", float(d["xi_lateral"]), Kk[0, 0]),
                        ("c_ry_ry_N_m_s_per_rad", float(d["xi_rocking"]), Kk[4, 4])):
        ref = 2 * max(xi, 0.0) * kk / omega
        rc.that(abs(float(d[col]) - ref) <= 1e-8 * max(abs(ref), 1e-30) + 1e-30,
                "amplitude %d: %s = 2 xi k / omega (%.6g)" % (k + 1, col, ref))
d2 = damping[1]
rc.that(float(d2["xi_lateral"]) > 0 and K2[0, 0] < K_el[0, 0],
        "above first yield: xi_lateral %.4g > 0 and K_xx %.6g < elastic %.6g N/m"
        % (float(d2["xi_lateral"]), K2[0, 0], K_el[0, 0]))

# The SoilDyn file.
lines = open(os.path.join(out, "soildyn-2.dat")).read().splitlines()
rc.that(lines[5].split()[0] == "1" and lines[5].split()[1] == "CalcOption", "SoilDyn: CalcOption 1")
k0 = next(i for i, l in enumerate(lines) if "STIFFNESS MATRIX" in l)
c0 = next(i for i, l in enumerate(lines) if "DAMPING MATRIX" in l)
Ksd = np.array([[float(v) for v in lines[k0 + 1 + i].split()] for i in range(6)])
Csd = np.array([[float(v) for v in lines[c0 + 1 + i].split()] for i in range(6)])
rc.that(np.abs(Ksd - K2).max() <= 1e-6 * np.abs(K2).max(), "SoilDyn stiffness block = secant 6x6")
rc.that(abs(Csd[0, 0] - float(d2["c_x_x_N_s_per_m"])) <= 1e-6 * abs(Csd[0, 0]) and
        abs(Csd[4, 4] - float(d2["c_ry_ry_N_m_s_per_rad"])) <= 1e-6 * abs(Csd[4, 4]) and
        np.allclose(Csd, Csd.T, rtol=0, atol=1e-12 * np.abs(Csd).max()),
        "SoilDyn damping block: the table's c on the diagonal, symmetric")


def tangent_matrix(path):
    """The tangent 6x6 and its error bars (0 where none) from its CSV."""
    K, E = np.zeros((6, 6)), np.zeros((6, 6))
    for r in csv.DictReader(open(path)):
        _, i, j = r["term"].split("_")
        i, j = DOFS.index(i), DOFS.index(j)
        K[i, j] = K[j, i] = float(r["value"])
        E[i, j] = E[j, i] = float(r["error_bar"] or 0.0)
    return K, E


# The tangent at the elastic mean state.
Kt, Et = tangent_matrix(os.path.join(out, "tangent-stiffness.csv"))
for drive in ("tangent-horizontal-1", "tangent-vertical-1", "tangent-rotation-1"):
    steps = rows(os.path.join(runs, drive, "load-displacement.csv"))
    rc.that(all(int(s["plastic"]) == 0 for s in steps), "%s: elastic (no plastic sample)" % drive)
block = np.ix_([0, 2, 4], [0, 2, 4])
worst = np.abs(Kt[block] - K_el[block]).max() / np.abs(K_el[block]).max()
rc.that(worst <= 1e-7 and Et[block].max() <= 1e-7 * np.abs(K_el[block]).max(),
        "elastic mean state: tangent (x, z, ry) = elastic 3x3 (its x-z and z-ry terms zero) within "
        "%.2e of the largest term, bars up to %.2e of it (tol 1e-7)"
        % (worst, Et[block].max() / np.abs(K_el[block]).max()))

# The tangent at a mean state that yields, against steps 20 times smaller.
tangents = {}
for step in ("0.0004", "0.00002"):
    target = os.path.join(work, "tangent-" + step)
    status = subprocess.call(
        ["/usr/bin/python3", tool, scene, "--mean-h", "400", "--mean-m", "600", "--amplitudes", "0.0004",
         "--lever", "1.5", "--exe", exe, "--np", "2", "--out", target, "--no-plot", "--tangent-step", step],
        cwd=work, stdout=subprocess.DEVNULL)
    rc.that(status == 0, "the tool with --tangent-step %s at H = 400 kN, M = 600 kN m (exit %d)" % (step, status))
    if status != 0:
        rc.finish()
    tangents[step] = tangent_matrix(os.path.join(target, "tangent-stiffness.csv"))
mean_steps = rows(os.path.join(work, "tangent-0.0004", "runs", "mean-state", "load-displacement.csv"))
rc.that(int(mean_steps[-1]["plastic"]) > 0, "the mean state H = 400 kN yields (%s plastic samples)"
        % mean_steps[-1]["plastic"])
(K_c, E_c), (K_f, E_f) = tangents["0.0004"], tangents["0.00002"]
for i, j in ((0, 0), (0, 4), (4, 4), (2, 2), (0, 2), (2, 4)):
    rc.that(abs(K_c[i, j] - K_f[i, j]) <= E_c[i, j] and E_f[i, j] <= 0.1 * E_c[i, j],
            "yielded mean state: tangent K_%s_%s %.6g +- %.3g (steps 4e-4 m) holds %.6g +- %.3g "
            "(steps 2e-5 m)" % (DOFS[i], DOFS[j], K_c[i, j], E_c[i, j], K_f[i, j], E_f[i, j]))
rc.that(K_f[0, 0] < K_el[0, 0] and K_f[4, 4] < K_el[4, 4] and K_f[2, 2] < K_el[2, 2],
        "yielded mean state: tangent below elastic (K_xx %.4f, K_ryry %.4f, K_zz %.4f of it)"
        % (K_f[0, 0] / K_el[0, 0], K_f[4, 4] / K_el[4, 4], K_f[2, 2] / K_el[2, 2]))

# Bad input into the folder of the first run: one line, exit 1, and none of
# that run's result files left behind (runs/ aside).
bad = subprocess.run(["/usr/bin/python3", tool, scene, "--mean-h", "100", "--amplitudes", "0.0004",
                      "--exe", exe, "--out", out, "--tangent-step", "-1"], cwd=work,
                     capture_output=True, text=True)
lines = (bad.stdout + bad.stderr).strip().splitlines()
left = sorted(f for f in os.listdir(out) if f != "runs")
rc.that(bad.returncode == 1 and len(lines) == 1 and not left,
        "--tangent-step -1: exit %d, %d line(s) (%s), result files left: %s"
        % (bad.returncode, len(lines), lines[:1], left))
rc.finish()
