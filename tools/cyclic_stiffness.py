#!/usr/bin/python3
"""Secant foundation stiffness and soil damping at a load level, for OpenFAST.

    tools/cyclic_stiffness.py SCENE.prm --mean-h H --amplitudes a1,a2,... \
        [--mean-m M] [--mean-v V] [--lever h] [--rotation-amplitudes r1,...] \
        [--frequency F] [--water-depth D] [--cycles N] [--steps N] [--np 2] [--exe PATH] --out DIR

SCENE is a plastic scene with a Rigid foundation (e.g. prm/monopile-clay-
iwan.prm). The tool
  1. runs the scene without plasticity with Stiffness matrix = true (the
     elastic 6x6, foundation-stiffness.csv) and the held loads alone (the
     mean state: H, M, V held, its motions u_m, theta_m);
  2. about that state, for each amplitude a, two cyclic runs in displacement
     control, all in one --batch: drive 1 the horizontal motion between
     u_m + a and u_m - a with the direction load H (and M = lever H), drive 2 the
     rotation between theta_m + r and theta_m - r with M alone;
  3. from the last cycle of each, the peak-to-peak loads and motions
     (load-displacement.csv at the cycle's turning points B and A'), the
     secant 2x2 K = L D^-1 of the lateral-rocking block (L the load changes,
     D the motion changes, one column per drive; doc/foundation-stiffness-
     at-load.md section 3) and the secant 6x6 in the layout of
     foundation-stiffness.csv, the vertical and torsional terms elastic;
  3b. with --tangent-step d: the tangent 3x3 (x, z, ry) at the mean state,
     from three monotonic drives per step size that continue the mean
     state's motion (u_m + d with the direction load, theta_m + r_d with M
     alone, w_m + d with V alone, one load step each) at d and d/2:
     K(d) = L D^-1 of their load and motion changes, the tangent K(d/2)
     with the error bar |K(d/2) - K(d)| / (sqrt(2) - 1), which holds while
     the error falls at least as d^0.5
     (points that start to yield within the step make it fall unevenly:
     d^0.5 to d^1 measured on the test caisson), written as a 6x6 like the
     secant one (tangent-stiffness.csv with its error bars, and a SubDyn
     file);
  4. writes per amplitude the 6x6 as CSV and as OpenFAST SubDyn's SSI file,
     the damping table (load-cycles.csv's damping ratio of each drive with
     its error, c = 2 xi k / omega) and a SoilDyn CalcOption 1 input file,
     and one PNG of the secant stiffness and the damping ratio against the
     amplitude.
Units: the program's kN, kN m, m, rad in, SI (N, N m, m, rad, s) in the
OpenFAST files and the 6x6 CSVs.
"""
import argparse
import csv
import glob
import math
import os
import re
import subprocess
import sys
import time

import numpy as np

DOFS = ("x", "y", "z", "rx", "ry", "rz")


# ---------------------------------------------------------------- prm text
def _section_span(lines, section):
    """(first, end) line indices of the top-level 'subsection section'."""
    depth, start = 0, None
    for i, line in enumerate(lines):
        words = line.split()
        if not words or words[0].startswith("#"):
            continue
        if words[0] == "subsection":
            if depth == 0 and " ".join(words[1:]) == section:
                start = i
            depth += 1
        elif words[0] == "end":
            depth -= 1
            if depth == 0 and start is not None:
                return start, i
    return None


def set_entry(text, section, key, value):
    """The prm text with 'set key = value' in section (added if missing)."""
    lines = text.splitlines()
    span = _section_span(lines, section)
    if span is None:
        lines += ["subsection " + section, "  set %s = %s" % (key, value), "end"]
        return "\n".join(lines) + "\n"
    pattern = re.compile(r"^\s*set\s+" + re.escape(key) + r"\s*=")
    for i in range(span[0] + 1, span[1]):
        if pattern.match(lines[i]):
            lines[i] = "  set %s = %s" % (key, value)
            return "\n".join(lines) + "\n"
    lines.insert(span[1], "  set %s = %s" % (key, value))
    return "\n".join(lines) + "\n"


def drop_entry(text, section, key):
    lines = text.splitlines()
    span = _section_span(lines, section)
    if span is None:
        return text
    pattern = re.compile(r"^\s*set\s+" + re.escape(key) + r"\s*=")
    keep = [l for i, l in enumerate(lines)
            if not (span[0] < i < span[1] and pattern.match(l))]
    return "\n".join(keep) + "\n"


def drop_section(text, section):
    lines = text.splitlines()
    span = _section_span(lines, section)
    if span is None:
        return text
    return "\n".join(lines[:span[0]] + lines[span[1] + 1:]) + "\n"


def get_entry(text, section, key):
    lines = text.splitlines()
    span = _section_span(lines, section)
    if span is None:
        return None
    pattern = re.compile(r"^\s*set\s+" + re.escape(key) + r"\s*=\s*(.*)$")
    for i in range(span[0] + 1, span[1]):
        m = pattern.match(lines[i])
        if m:
            return m.group(1).split("#")[0].strip()
    return None


# Entries of a monotonic capacity run that a cyclic or linear run refuses or
# does not need.
MONOTONIC_ONLY = (("Load path", "Target"), ("Load path", "Targets"),
                  ("Load path", "Cycles"),
                  ("Rigid foundation", "Capacity normalisation"),
                  ("Output", "Soil reaction pile"),
                  ("Output", "Soil reaction depths"),
                  ("Discretization", "Target accuracy"),
                  ("Discretization", "Refinement cycles"))

FOUNDATION_LOADS = ("Horizontal force", "Horizontal force y", "Moment",
                    "Moment x", "Vertical force", "Torque")


def base_scene(text, out_dir):
    for section, key in MONOTONIC_ONLY:
        text = drop_entry(text, section, key)
    for key in FOUNDATION_LOADS:
        text = drop_entry(text, "Rigid foundation", key)
    text = set_entry(text, "Output", "Directory", out_dir)
    text = set_entry(text, "Output", "Write vtu", "false")
    return text


def elastic_scene(text, out_dir):
    """The scene without plasticity, the 6x6 of the program (linear run)."""
    text = base_scene(text, out_dir)
    text = drop_section(text, "Soil plasticity")
    text = drop_section(text, "Load path")
    for key in ("Held horizontal force", "Held moment", "Held vertical force",
                "Held torque", "Held motions"):
        text = drop_entry(text, "Rigid foundation", key)
    text = set_entry(text, "Rigid foundation", "Stiffness matrix", "true")
    text = set_entry(text, "Rigid foundation", "Horizontal force", "1")
    text = set_entry(text, "Discretization", "Harmonics", "auto")
    text = drop_entry(text, "Discretization", "Family")
    return text


def held(text, mean):
    for key, value in zip(("Held horizontal force", "Held moment",
                           "Held vertical force"), mean):
        text = set_entry(text, "Rigid foundation", key, repr(value))
    return text


def mean_state_scene(text, out_dir, mean):
    """The held loads alone, then one load step of 1e-6 kN: the mean state."""
    text = held(base_scene(text, out_dir), mean)
    text = set_entry(text, "Rigid foundation", "Horizontal force", "1e-6")
    text = set_entry(text, "Load path", "Control", "load")
    text = set_entry(text, "Load path", "Load steps", "1")
    return text


def drive_scene(text, out_dir, mean, motion, low, high, cycles, steps, lever):
    """A cyclic run about the mean state: motion between high and low. The
    horizontal drive's direction load is H = 1 kN with M = lever kN m (the
    load ratio M/H of the structure above), the rotation drive's M alone,
    the vertical drive's V alone."""
    text = held(base_scene(text, out_dir), mean)
    if motion == "horizontal":
        text = set_entry(text, "Rigid foundation", "Horizontal force", "1")
        if lever:
            text = set_entry(text, "Rigid foundation", "Moment", repr(lever))
    elif motion == "vertical":
        text = set_entry(text, "Rigid foundation", "Vertical force", "1")
    else:
        text = set_entry(text, "Rigid foundation", "Moment", "1")
    text = set_entry(text, "Load path", "Control", "displacement")
    text = set_entry(text, "Load path", "Controlled motion", motion)
    text = set_entry(text, "Load path", "Targets", "%.12g, %.12g" % (high, low))
    text = set_entry(text, "Load path", "Cycles", str(cycles))
    if steps:
        text = set_entry(text, "Load path", "Load steps", str(steps))
    return text


# K(d) - K_tangent ~ d^p with p >= 1/2: K(d/2)'s error is at most
# |K(d/2) - K(d)| / (2^p - 1) <= |K(d/2) - K(d)| / (sqrt(2) - 1).
TANGENT_ERROR_DIVISOR = math.sqrt(2.0) - 1.0


def tangent_scene(text, out_dir, mean, motion, target, lever):
    """One monotonic load step from the mean state to the motion target,
    with the drive loads of drive_scene."""
    text = drive_scene(text, out_dir, mean, motion, target, target, 0, 1, lever)
    text = drop_entry(text, "Load path", "Targets")
    text = drop_entry(text, "Load path", "Cycles")
    return set_entry(text, "Load path", "Target", "%.12g" % target)


# ---------------------------------------------------------------- runs
def run_batch(exe, prms, n_ranks, work, log):
    """The cases in one --batch over n_ranks (serial when 1)."""
    listing = os.path.join(work, "batch.txt")
    with open(listing, "w") as f:
        f.write("\n".join(prms) + "\n")
    command = [exe, "--batch", "--csv", os.path.join(work, "batch.csv"), listing]
    if n_ranks > 1:
        command = ["mpirun", "--allow-run-as-root", "--oversubscribe",
                   "-np", str(n_ranks)] + command
    start = time.time()
    with open(log, "w") as f:
        status = subprocess.call(command, cwd=work, stdout=f,
                                 stderr=subprocess.STDOUT)
    if status != 0:
        sys.exit("cyclic_stiffness: the batch failed (exit %d); see %s" %
                 (status, log))
    return time.time() - start


def read_rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


# The loads and motions of load-displacement.csv that the drives change.
STATE_KEYS = ("H_kN", "V_kN", "M_kNm", "horizontal_m", "vertical_m", "rotation_rad")


def held_state(steps):
    """STATE_KEYS at the end of the held stage (segment 0, held fraction 1)
    of a run's load-displacement.csv rows; zeros without held loads (the
    state at rest)."""
    rows = [r for r in steps if float(r["held_fraction"]) == 1.0]
    return {k: float(rows[0][k]) if rows else 0.0 for k in STATE_KEYS}


def last_cycle(directory):
    """The last cycle: its load-cycles.csv row and the steps at B and A'."""
    cycles = read_rows(os.path.join(directory, "load-cycles.csv"))
    steps = read_rows(os.path.join(directory, "load-displacement.csv"))
    j = int(cycles[-1]["cycle"])

    def end_of(segment):
        return [s for s in steps if int(s["segment"]) == segment][-1]
    return cycles[-1], end_of(2 * j), end_of(2 * j + 1)


def from_mean_state(directory):
    """dH, dV [kN], dM [kN m], du, dw [m], dtheta [rad] from the end of the
    held stage to the last step."""
    steps = read_rows(os.path.join(directory, "load-displacement.csv"))
    start = held_state(steps)
    return {k: float(steps[-1][k]) - start[k] for k in STATE_KEYS}


def peak_to_peak(directory):
    """dH [kN], dM [kN m], du [m], dtheta [rad] from B to A', and the row."""
    row, b, a = last_cycle(directory)
    keys = ("H_kN", "M_kNm", "horizontal_m", "rotation_rad")
    return {k: float(a[k]) - float(b[k]) for k in keys}, row


def secant_block(horizontal, rotation):
    """The secant 2x2 [[k_HH, k_Hr], [k_rH, k_rr]] in kN/m, kN, kN m/rad.

    Columns j = 1 (horizontal drive), 2 (rotation drive): L = [dH_j; dM_j],
    D = [du_j; dtheta_j]. The secant flexibility F maps loads to motions,
    D = F L, so F = D L^-1 and K = F^-1 = L D^-1."""
    L = np.array([[horizontal["H_kN"], rotation["H_kN"]],
                  [horizontal["M_kNm"], rotation["M_kNm"]]])
    D = np.array([[horizontal["horizontal_m"], rotation["horizontal_m"]],
                  [horizontal["rotation_rad"], rotation["rotation_rad"]]])
    return L @ np.linalg.inv(D)


# The tangent's block: x, z, ry; its loads and motions in from_mean_state's
# names, and its rows and columns in the 6x6.
TANGENT_LOADS = ("H_kN", "V_kN", "M_kNm")
TANGENT_MOTIONS = ("horizontal_m", "vertical_m", "rotation_rad")
TANGENT_DOFS = (0, 2, 4)


def tangent_block(drives):
    """K = L D^-1 [kN units] of the x, z, ry block from the load and
    motion changes of the horizontal, vertical and rotation drives (one
    column each)."""
    L = np.array([[d[key] for d in drives] for key in TANGENT_LOADS])
    D = np.array([[d[key] for d in drives] for key in TANGENT_MOTIONS])
    return L @ np.linalg.inv(D)


def tangent_6x6(k3, e3, elastic):
    """The tangent 6x6 [SI] and its error bars from the x, z, ry block
    [kN units] (symmetric part; the bar the larger of the two): the y and rx
    terms copy the loading plane's (K_yy = K_xx, K_y,rx = -K_x,ry), the y-z
    and z-rx couplings are zero (the state is symmetric about the x-z
    plane), and K_rz,rz is elastic."""
    K, E = np.zeros((6, 6)), np.full((6, 6), np.nan)
    for a, i in enumerate(TANGENT_DOFS):
        for b, j in enumerate(TANGENT_DOFS):
            K[i, j] = 0.5 * (k3[a, b] + k3[b, a]) * 1e3
            E[i, j] = max(e3[a, b], e3[b, a]) * 1e3
    for (i, j), (k, l, sign) in (((1, 1), (0, 0, 1)), ((3, 3), (4, 4, 1)),
                                 ((1, 3), (0, 4, -1)), ((3, 1), (0, 4, -1))):
        K[i, j], E[i, j] = sign * K[k, l], E[k, l]
    K[5, 5] = elastic[5, 5]
    return K, E


def read_stiffness_csv(path):
    """The 6x6 [SI] and its error bars from a foundation-stiffness.csv."""
    K, E = np.zeros((6, 6)), np.full((6, 6), np.nan)
    for r in read_rows(path):
        _, i, j = r["term"].split("_")
        i, j = DOFS.index(i), DOFS.index(j)
        K[i, j] = K[j, i] = float(r["value"])
        if r["error_bar"] != "":
            E[i, j] = E[j, i] = float(r["error_bar"])
    return K, E


def secant_6x6(k2, elastic):
    """The 6x6 [SI] from the secant 2x2 [kN units] (symmetric part) and the
    elastic vertical and torsional terms."""
    kc = 0.5 * (k2[0, 1] + k2[1, 0]) * 1e3
    K = np.zeros((6, 6))
    K[0, 0] = K[1, 1] = k2[0, 0] * 1e3
    K[3, 3] = K[4, 4] = k2[1, 1] * 1e3
    K[0, 4] = K[4, 0] = kc
    K[1, 3] = K[3, 1] = -kc
    K[2, 2] = elastic[2, 2]
    K[5, 5] = elastic[5, 5]
    return K


def unit(i, j):
    t = sum(1 for k in (i, j) if k >= 3)
    return ("N/m", "N/rad", "N*m/rad")[t]


def write_stiffness_csv(path, K, source, errors=None):
    """The 6x6 [SI] as foundation-stiffness.csv lays it out; errors: the
    error bars of the terms that have one (NaN: none)."""
    with open(path, "w") as f:
        f.write("term,value,unit,error_bar,source\n")
        for j in range(6):
            for i in range(j + 1):
                src = source(i, j)
                bar = "" if errors is None or math.isnan(errors[i, j]) else "%.3g" % errors[i, j]
                f.write("K_%s_%s,%.12g,%s,%s,%s\n" % (DOFS[i], DOFS[j], K[i, j],
                                                     unit(i, j), bar, src))


SUBDYN_LABELS = ["K%s%s" % (("x", "y", "z", "tx", "ty", "tz")[i],
                            ("x", "y", "z", "tx", "ty", "tz")[j])
                 for j in range(6) for i in range(j + 1)]


def label_position(label):
    """(row, column) of a SubDyn label: the upper triangle column by column."""
    k = SUBDYN_LABELS.index(label)
    col = 0
    while (col + 1) * (col + 2) // 2 <= k:
        col += 1
    return k - col * (col + 1) // 2, col


def write_subdyn(path, K, template, first_comment):
    """K [SI] in the layout of the program's own SubDyn file (template): its
    comment lines (the first one replaced by first_comment, which says what
    the matrix is), then one value and label per line, '%17.9e   label', the
    labels in the template's order (checked to be SubDyn's, column by
    column)."""
    lines = open(template).read().splitlines()
    comments = [l for l in lines if l.startswith("!")]
    labels = [l.split()[1] for l in lines if l.strip() and not l.startswith("!")]
    if labels != SUBDYN_LABELS:
        sys.exit("cyclic_stiffness: unexpected label order in " + template)
    out = ["! " + first_comment] + comments[1:]
    for label in labels:
        row, col = label_position(label)
        out.append("%17.9e   %s" % (K[row, col], label))
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def damping_matrix(K, xi, omega):
    """C = (2/omega) S K S, S = diag(sqrt(xi_i)): c_ii = 2 xi_i k_ii / omega,
    symmetric and positive semi-definite as K (a congruence)."""
    S = np.diag(np.sqrt(np.clip(xi, 0.0, None)))
    return 2.0 / omega * S @ K @ S


def write_soildyn(path, K, C, location, header):
    """A SoilDyn input file, CalcOption 1 (stiffness and damping matrices)."""
    rows = ["------- SoilDyn v1.0 input file " + "-" * 40,
            header[:200],
            "---------------------- SIMULATION CONTROL " + "-" * 30,
            "False         Echo         - Echo input data to <RootName>.SlD.ech (flag)",
            "\"default\"     DT           - Time interval for soil calculations {or default} (s)",
            "1             CalcOption   - Calculation methodology {1: Stiffness / Damping matrices, 2: P-Y curves [unavailable], 3: coupled REDWIN DLL}",
            "============== Parameters for Stiffness and Damping matrix (CalcOption 1) " + "=" * 10,
            "%s   Location (X,Y,Z) - point of the matrices, global, at or below the mudline (m)" %
            "  ".join("%.6g" % v for v in location),
            "---------------------- STIFFNESS MATRIX (SI: N/m, N/rad, N*m/rad) " + "-" * 10]
    rows += ["  ".join("%14.6e" % v for v in K[i]) for i in range(6)]
    rows.append("---------------------- DAMPING MATRIX (SI: N*s/m, N*s/rad, N*m*s/rad) " + "-" * 5)
    rows += ["  ".join("%14.6e" % v for v in C[i]) for i in range(6)]
    rows += ["---------------------- OUTPUT " + "-" * 40,
             "False         SumPrint     - Print summary data to <RootName>.SlD.sum (flag)",
             "              OutList      - The next line(s) contains a list of output parameters (-)",
             "END of input file (the word \"END\" must appear in the first 3 columns of this last OutList line)",
             ""]
    open(path, "w").write("\n".join(rows))


# ---------------------------------------------------------------- main
# What the tool writes in --out (runs/ aside): an earlier run's files are
# removed first, so that a run that stops leaves none that looks like its
# result.
RESULT_FILES = ("secant-stiffness*.csv", "secant-stiffness-subdyn-*.txt", "soildyn-*.dat",
                "damping.csv", "cost.csv", "secant-stiffness-and-damping.png",
                "tangent-stiffness.csv", "tangent-stiffness-subdyn.txt")


def remove_results(out):
    for pattern in RESULT_FILES:
        for path in glob.glob(os.path.join(out, pattern)):
            os.remove(path)


def floats(text):
    return [float(v) for v in text.split(",") if v.strip()]


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("scene")
    p.add_argument("--mean-h", type=float, required=True,
                   help="held horizontal force H_x at the mean state [kN]")
    p.add_argument("--mean-m", type=float, default=0.0,
                   help="held moment M_y at the mean state [kN m]")
    p.add_argument("--mean-v", type=float, default=0.0,
                   help="held vertical force at the mean state [kN]")
    p.add_argument("--amplitudes", required=True,
                   help="horizontal drive: motion amplitudes a about the mean [m]")
    p.add_argument("--rotation-amplitudes",
                   help="rotation drive: amplitudes [rad], one per --amplitudes; "
                        "default a times the elastic theta/u of the horizontal "
                        "drive's load (H, lever H)")
    p.add_argument("--lever", type=float, default=0.0,
                   help="M/H of the horizontal drive's load [m] (0: H alone)")
    p.add_argument("--frequency", type=float, default=0.25,
                   help="frequency of the equivalent viscous damping [Hz]")
    p.add_argument("--cycles", type=int, default=1)
    p.add_argument("--steps", type=int, default=0,
                   help="Load steps a segment (0: the scene's)")
    p.add_argument("--np", type=int, default=2, help="MPI ranks of the batch")
    p.add_argument("--exe", default=os.path.join(
        os.path.dirname(os.path.dirname(os.path.realpath(__file__))), "build", "fourier-ssi"),
        help="the program (default: build/fourier-ssi of this checkout)")
    p.add_argument("--water-depth", type=float, default=0.0,
                   help="WtrDpth of the OpenFAST model, for the SoilDyn location [m]")
    p.add_argument("--tangent-step", type=float, default=0.0,
                   help="also the tangent (x, z, ry) at the mean state: monotonic drives "
                        "of this horizontal and vertical motion [m] (the rotation drive's "
                        "of the same elastic ratio as its amplitudes) and of half of it; "
                        "0: none")
    p.add_argument("--out", required=True)
    p.add_argument("--no-plot", action="store_true")
    args = p.parse_args(argv)

    exe = os.path.realpath(args.exe)
    out = os.path.realpath(args.out)
    work = os.path.join(out, "runs")
    os.makedirs(work, exist_ok=True)
    remove_results(out)
    scene = open(args.scene).read()
    amplitudes = floats(args.amplitudes)
    if not amplitudes or min(amplitudes) <= 0:
        sys.exit("cyclic_stiffness: --amplitudes: positive values [m]")
    if not args.tangent_step >= 0:
        sys.exit("cyclic_stiffness: --tangent-step: a motion >= 0 [m] (0: no tangent)")
    if get_entry(scene, "Rigid foundation", "Enabled") != "true":
        sys.exit("cyclic_stiffness: %s: Rigid foundation/Enabled must be true" % args.scene)
    if get_entry(scene, "Soil plasticity", "Laws") in (None, ""):
        sys.exit("cyclic_stiffness: %s: Soil plasticity/Laws: a plastic soil is needed" % args.scene)
    mean = (args.mean_h, args.mean_m, args.mean_v)
    cost = {}

    # Stage 1: the elastic 6x6 and the mean state (one batch of two).
    stage1 = {"elastic": elastic_scene(scene, "elastic"),
              "mean-state": mean_state_scene(scene, "mean-state", mean)}
    prms = []
    for name, text in stage1.items():
        open(os.path.join(work, name + ".prm"), "w").write(text)
        prms.append(name + ".prm")
    cost["elastic 6x6 and mean state"] = run_batch(
        exe, prms, min(args.np, 2), work, os.path.join(work, "stage1.log"))
    K_el, E_el = read_stiffness_csv(os.path.join(work, "elastic", "foundation-stiffness.csv"))
    template = os.path.join(work, "elastic", "foundation-stiffness-subdyn.txt")
    mean_state = held_state(read_rows(os.path.join(work, "mean-state", "load-displacement.csv")))
    u_m, w_m, th_m = (mean_state[k] for k in ("horizontal_m", "vertical_m", "rotation_rad"))
    F_el = np.linalg.inv(K_el[np.ix_([0, 4], [0, 4])])
    # theta/u of the horizontal drive's load (H, lever H), elastic [rad/m];
    # K_el is in N, m: lever in m is the same ratio in kN m / kN.
    motion = F_el @ np.array([1.0, args.lever])
    ratio = motion[1] / motion[0]
    if args.rotation_amplitudes:
        rotations = floats(args.rotation_amplitudes)
        if len(rotations) != len(amplitudes):
            sys.exit("cyclic_stiffness: --rotation-amplitudes: one per amplitude")
    else:
        rotations = [a * abs(ratio) for a in amplitudes]

    # Stage 2: two drives per amplitude, one batch.
    prms = []
    for i, (a, r) in enumerate(zip(amplitudes, rotations)):
        for motion, centre, amp in (("horizontal", u_m, a), ("rotation", th_m, r)):
            name = "%s-%d" % (motion, i + 1)
            open(os.path.join(work, name + ".prm"), "w").write(
                drive_scene(scene, name, mean, motion, centre - amp,
                            centre + amp, args.cycles, args.steps, args.lever))
            prms.append(name + ".prm")
    if args.tangent_step > 0:
        rotation_step = args.tangent_step * abs(ratio)
        for k, fraction in ((1, 1.0), (2, 0.5)):
            for motion, centre, step in (("horizontal", u_m, args.tangent_step),
                                         ("vertical", w_m, args.tangent_step),
                                         ("rotation", th_m, rotation_step)):
                name = "tangent-%s-%d" % (motion, k)
                # where the mean state has not moved: forward, and down
                # (compression) for the vertical drive
                start = centre or (-1.0 if motion == "vertical" else 1.0)
                target = centre + math.copysign(fraction * step, start)
                open(os.path.join(work, name + ".prm"), "w").write(
                    tangent_scene(scene, name, mean, motion, target, args.lever))
                prms.append(name + ".prm")
    cost["cycles"] = run_batch(exe, prms, args.np, work,
                               os.path.join(work, "stage2.log"))

    omega = 2 * math.pi * args.frequency
    z_ref = float(get_entry(scene, "Rigid foundation", "Reference elevation") or 0)
    summary, damping = [], []

    def source(i, j):
        if {i, j} <= {0, 1, 3, 4}:
            return "secant (cycles)" if K_el[i, j] != 0 or i == j else "zero (axisymmetry)"
        if i == j:
            return "elastic (Stiffness matrix = true, no plasticity)"
        return "zero (axisymmetry)"

    for i, (a, r) in enumerate(zip(amplitudes, rotations)):
        dh, row_h = peak_to_peak(os.path.join(work, "horizontal-%d" % (i + 1)))
        dr, row_r = peak_to_peak(os.path.join(work, "rotation-%d" % (i + 1)))
        k2 = secant_block(dh, dr)
        K = secant_6x6(k2, K_el)
        tag = "%d" % (i + 1)
        write_stiffness_csv(os.path.join(out, "secant-stiffness-%s.csv" % tag), K, source)
        header = ("fourier-ssi: secant rigid foundation stiffness at (x, y, z) = "
                  "(0, 0, %g) m (tools/cyclic_stiffness.py, %s, mean H %g kN, M %g kN m, "
                  "V %g kN, amplitude %g m / %g rad, cycle %d; Kzz, Ktztz elastic)" % (
                      z_ref, os.path.basename(args.scene), *mean, a, r,
                      int(row_h["cycle"])))
        write_subdyn(os.path.join(out, "secant-stiffness-subdyn-%s.txt" % tag), K, template, header)
        xi = np.array([float(row_h["damping_ratio"])] * 2 + [0.0] +
                      [float(row_r["damping_ratio"])] * 2 + [0.0])
        C = damping_matrix(K, xi, omega)
        write_soildyn(os.path.join(out, "soildyn-%s.dat" % tag), K, C,
                      (0.0, 0.0, z_ref - args.water_depth),
                      "fourier-ssi secant stiffness and equivalent viscous damping at "
                      "%g Hz; amplitude %g m / %g rad; mean H %g kN, M %g kN m" % (
                          args.frequency, a, r, mean[0], mean[1]))
        summary.append(dict(
            amplitude_m=a, rotation_amplitude_rad=r,
            K_x_x=K[0, 0], K_x_ry=k2[0, 1] * 1e3, K_ry_x=k2[1, 0] * 1e3, K_ry_ry=K[4, 4],
            asymmetry=abs(k2[0, 1] - k2[1, 0]) / math.sqrt(abs(k2[0, 0] * k2[1, 1])),
            H_peak_to_peak_kN=dh["H_kN"], M_peak_to_peak_kNm=dr["M_kNm"],
            u_peak_to_peak_m=dh["horizontal_m"], theta_h_peak_to_peak_rad=dh["rotation_rad"],
            u_r_peak_to_peak_m=dr["horizontal_m"], theta_peak_to_peak_rad=dr["rotation_rad"],
            K_x_x_elastic=K_el[0, 0], K_x_ry_elastic=K_el[0, 4], K_ry_ry_elastic=K_el[4, 4]))
        damping.append(dict(
            amplitude_m=a, rotation_amplitude_rad=r,
            xi_lateral=float(row_h["damping_ratio"]),
            xi_lateral_error=float(row_h["damping_ratio_error"]),
            xi_rocking=float(row_r["damping_ratio"]),
            xi_rocking_error=float(row_r["damping_ratio_error"]),
            frequency_Hz=args.frequency,
            c_x_x_N_s_per_m=C[0, 0], c_x_ry_N_s_per_rad=C[0, 4],
            c_ry_ry_N_m_s_per_rad=C[4, 4]))

    tangent = None
    if args.tangent_step > 0:
        K_d, K_half = (tangent_block([from_mean_state(os.path.join(work, "tangent-%s-%d" % (motion, k)))
                                      for motion in ("horizontal", "vertical", "rotation")])
                       for k in (1, 2))
        k3 = K_half
        K, E = tangent_6x6(k3, np.abs(K_half - K_d) / TANGENT_ERROR_DIVISOR, K_el)

        def tangent_source(i, j):
            if i == j == 5:
                return "elastic (Stiffness matrix = true, no plasticity)"
            if {i, j} <= {0, 2, 4} or {i, j} in ({1}, {3}, {1, 3}):
                return "tangent (continued loading)"
            return "zero (symmetry about the loading plane)"
        write_stiffness_csv(os.path.join(out, "tangent-stiffness.csv"), K, tangent_source, E)
        write_subdyn(os.path.join(out, "tangent-stiffness-subdyn.txt"), K, template,
                     "fourier-ssi: tangent rigid foundation stiffness at (x, y, z) = (0, 0, %g) m "
                     "(tools/cyclic_stiffness.py, %s, mean H %g kN, M %g kN m, V %g kN, continued "
                     "loading, steps %g and %g m; Ktztz elastic)" % (
                         z_ref, os.path.basename(args.scene), *mean, args.tangent_step,
                         args.tangent_step / 2))
        tangent = dict(K=K, E=E, asymmetry=abs(k3[0, 2] - k3[2, 0]) / math.sqrt(abs(k3[0, 0] * k3[2, 2])))

    def table(path, rows):
        with open(path, "w") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            w.writeheader()
            for r in rows:
                w.writerow({k: ("%.12g" % v if isinstance(v, float) else v)
                            for k, v in r.items()})
    table(os.path.join(out, "secant-stiffness.csv"), summary)
    table(os.path.join(out, "damping.csv"), damping)
    with open(os.path.join(out, "cost.csv"), "w") as f:
        f.write("stage,wall_time_s,ranks\n")
        f.write("elastic 6x6 and mean state,%.2f,%d\n" % (cost["elastic 6x6 and mean state"], min(args.np, 2)))
        f.write("cycles (%d runs),%.2f,%d\n" % (2 * len(amplitudes), cost["cycles"], args.np))
    print("mean state: u = %.6g m, rotation = %.6g rad (H %g kN, M %g kN m, V %g kN)"
          % (u_m, th_m, *mean))
    for s, d in zip(summary, damping):
        print("amplitude %g m / %g rad: K_xx %.5g N/m (elastic %.5g), K_x_ry %.5g N/rad, "
              "K_ry_x %.5g, K_ryry %.5g N m/rad (elastic %.5g), asymmetry %.2g; "
              "xi lateral %.4f +- %.4f, rocking %.4f +- %.4f" % (
                  s["amplitude_m"], s["rotation_amplitude_rad"], s["K_x_x"],
                  s["K_x_x_elastic"], s["K_x_ry"], s["K_ry_x"], s["K_ry_ry"],
                  s["K_ry_ry_elastic"], s["asymmetry"], d["xi_lateral"],
                  d["xi_lateral_error"], d["xi_rocking"], d["xi_rocking_error"]))
    if tangent:
        K, E = tangent["K"], tangent["E"]
        print("tangent at the mean state (continued loading, steps %g and %g m): K_xx %.5g +- %.2g N/m "
              "(elastic %.5g), K_x_ry %.5g +- %.2g N/rad, K_ryry %.5g +- %.2g N m/rad (elastic %.5g), "
              "K_zz %.5g +- %.2g N/m (elastic %.5g), K_x_z %.3g +- %.2g N/m, K_z_ry %.3g +- %.2g N/rad; "
              "asymmetry (x, ry) %.2g" % (
                  args.tangent_step, args.tangent_step / 2, K[0, 0], E[0, 0], K_el[0, 0], K[0, 4], E[0, 4],
                  K[4, 4], E[4, 4], K_el[4, 4], K[2, 2], E[2, 2], K_el[2, 2], K[0, 2], E[0, 2], K[2, 4],
                  E[2, 4], tangent["asymmetry"]))
    print("wall time: %.1f s (elastic and mean state), %.1f s (cycles, %d ranks)" % (
        cost["elastic 6x6 and mean state"], cost["cycles"], args.np))
    if not args.no_plot:
        plot(os.path.join(out, "secant-stiffness-and-damping.png"), summary, damping)
    print("written to", out)


def plot(path, summary, damping):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    a = [s["amplitude_m"] for s in summary]
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9, 3.8))
    for key, label in (("K_x_x", "K_xx / elastic"), ("K_ry_ry", "K_ryry / elastic"),
                       ("K_x_ry", "K_x,ry / elastic")):
        ax1.plot(a, [s[key] / s[key + "_elastic" if key != "K_x_ry" else "K_x_ry_elastic"]
                     for s in summary], "o-", label=label)
    ax1.set_xscale("log")
    ax1.set_xlabel("horizontal drive amplitude [m]")
    ax1.set_ylabel("secant / elastic (G0) stiffness [-]")
    ax1.grid(alpha=0.3)
    ax1.legend(fontsize=8)
    for key, label in (("xi_lateral", "lateral (H-u)"), ("xi_rocking", "rocking (M-theta)")):
        ax2.errorbar(a, [d[key] for d in damping], yerr=[d[key + "_error"] for d in damping],
                     fmt="o-", capsize=3, label=label)
    ax2.set_xscale("log")
    ax2.set_xlabel("horizontal drive amplitude [m]")
    ax2.set_ylabel("damping ratio xi [-]")
    ax2.grid(alpha=0.3)
    ax2.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


if __name__ == "__main__":
    main()
