#!/usr/bin/python3
"""CalculiX (ccx) beside fourier-ssi on two capacity problems: accuracy
against wall time and peak memory.

    python3 benchmarks/nonlinear-accuracy/calculix/run.py
        [--exe build/fourier-ssi] [--problems disc,pile]
        [--codes ccx,fssi] [--levels coarse,medium,fine]
        [--fssi-cases shipped,target] [--disc-targets 5e-2,2e-2]
        [--pile-targets 5e-2] [--checks elastic-disc,elastic-pile]
        [--quick] [--timeout 360] [--keep DIR] [--fresh] [--no-write]
        [--render]

The whole default set takes about 26 min on 2 shared cores (two of the
fourier-ssi target runs end at the 6-min cap); --quick about 2.5 min.

Problems:
  disc  prm/disc-tresca.prm: rigid rough disc (D = 1 m) in a Tresca ring
        (s_u = 10 kPa, G = 3000 kPa, nu = 0.49) to 5 m, plane strain,
        pushed to 0.05 D. Reference P/(s_u D) = 4 sqrt(2) + 2 pi = 11.94
        (Randolph & Houlsby 1984, exact).
  pile  prm/pile-free-head.prm: free-head rigid pile d = 1 m, L = 10 m,
        bonded, in the same clay to 10 m radius and 15 m depth, pushed at
        the head to 0.1 d. Limit equilibrium 4.946 s_u d L (not a converged
        value; both codes' sequences are reported).

Every run goes one at a time under `nice -n 5`; wall time and peak
resident memory of each process come from os.wait4. ccx decks are written
by models.py into a temporary folder (kept with --keep DIR). fourier-ssi
runs the scene as shipped and with Discretization/Target accuracy
appended (5e-2 and 2e-2 disc, 5e-2 pile; the pile's soil-reaction curves
dropped, which a target does not take yet), each capped at --timeout
seconds.
Checks: the elastic disc of prm/disc-rough.prm through the same ccx
generator against its closed form, and the elastic pile (ccx against
fourier-ssi with s_u raised out of reach).

Rows are merged into results.csv beside this script (a run replaces the
row of the same code, problem and level; --fresh starts empty), and
results.md is written from the whole CSV, unless --no-write. --quick runs
the coarse ccx levels, the shipped scenes and the checks only.
"""
import argparse
import csv
import datetime
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(HERE)))
sys.path.insert(0, HERE)
import models  # noqa: E402

S_U = 10.                      # kPa
E_CLAY = 2 * 3000. * 1.49      # kPa, from G = 3000 kPa, nu = 0.49
SIGMA_Y = math.sqrt(3.) * S_U  # von Mises with the plane-strain Tresca limit
DISC_REF = 4 * math.sqrt(2.) + 2 * math.pi   # 11.94, exact
PILE_LE = 4.946                              # limit equilibrium, not converged
DISC_ELASTIC_CLOSED = 139817.35              # kN/m per m, prm/disc-rough.prm
DISC_ELASTIC_FSSI = 139816.84                # kN/m per m, the scene's value
CCX_THREADS = "2"

# level: generator arguments (disc: cells over the half circle, radial
# cells; pile: m = cells per eighth of the circle, k = core-to-arc cells,
# radial cells, cells along the pile, cells below the tip).
DISC_LEVELS = {"coarse": (24, 12), "medium": (48, 24), "fine": (96, 48)}
PILE_LEVELS = {"coarse": (2, 1, 8, 8, 3), "medium": (2, 1, 12, 12, 4),
               "fine": (3, 1, 16, 16, 5)}
FSSI_TARGETS = {"disc": "5e-2,2e-2", "pile": "5e-2"}
# The levels run unless --levels names others. The pile's "fine" is not
# run: m = 3 at the medium level's r and z cells alone (27 870 equations)
# took 8.9 s per linear solve here, so about 7 min for the ~45 Newton
# iterations of the path, and "fine" refines r and z once more.
DEFAULT_LEVELS = {"disc": ["coarse", "medium", "fine"],
                  "pile": ["coarse", "medium"]}
SCENES = {"disc": "prm/disc-tresca.prm", "pile": "prm/pile-free-head.prm"}
UNITS = {"disc": "P/(s_u D)", "pile": "H/(s_u d L)"}
FIELDS = ["code", "problem", "level", "dofs", "nodes", "value", "unit",
          "reference", "rel_error", "own_bar", "plateau_rise", "wall_s",
          "peak_gb", "status", "detail", "date", "load_start", "load_end"]


# ------------------------------------------------------------------ runs

def timed(cmd, cwd, timeout, env=None):
    """Runs cmd under nice -n 5 in cwd; returns (returncode or None on
    timeout, wall s, peak RSS GB, stdout text). The child's RSS comes from
    wait4 (nice execs the program, so the pid is the program's)."""
    out_path = os.path.join(cwd, "stdout.txt")
    with open(out_path, "w") as out:
        start = time.time()
        proc = subprocess.Popen(["nice", "-n", "5"] + cmd, cwd=cwd,
                                stdout=out, stderr=subprocess.STDOUT,
                                env=env)
        status = None
        while True:
            pid, wstatus, usage = os.wait4(proc.pid, os.WNOHANG)
            if pid:
                status = os.waitstatus_to_exitcode(wstatus)
                break
            if time.time() - start > timeout:
                proc.kill()
                pid, wstatus, usage = os.wait4(proc.pid, 0)
                status = None
                break
            time.sleep(0.2)
        proc.returncode = status if status is not None else -9
        wall = time.time() - start
    return status, wall, usage.ru_maxrss / 1024. ** 2, open(out_path).read()


def ccx_forces(dat, set_name):
    """(time, fx) of every increment's totals of `set_name` in a .dat."""
    text = open(dat).read()
    pattern = (r"total force \(fx,fy,fz\) for set %s and time\s+(\S+)\s+"
               r"(\S+)\s+(\S+)\s+(\S+)" % set_name)
    return [(float(t), float(fx)) for t, fx, _, _ in
            re.findall(pattern, text)]


def ccx_vector(dat, set_name):
    """The last (vx, vy, vz) printed for the one node of `set_name`."""
    text = open(dat).read()
    blocks = re.findall(r"displacements \(vx,vy,vz\) for set %s and time"
                        r"\s+\S+\s+\d+\s+(\S+)\s+(\S+)\s+(\S+)" % set_name,
                        text)
    return [float(v) for v in blocks[-1]] if blocks else None


def plateau_rise(curve):
    """Relative rise of the load over the last tenth of the path."""
    if len(curve) < 2:
        return float("nan")
    ts = [t for t, _ in curve]
    fs = [f for _, f in curve]
    t0 = 0.9 * ts[-1]
    for k in range(1, len(ts)):
        if ts[k] >= t0:
            a = (t0 - ts[k - 1]) / (ts[k] - ts[k - 1])
            f0 = fs[k - 1] + a * (fs[k] - fs[k - 1])
            return (fs[-1] - f0) / abs(fs[-1])
    return float("nan")


def run_ccx(problem, level, work, timeout, elastic=False):
    """One ccx run: problem disc or pile (elastic: the checks)."""
    name = "%s-%s%s" % (problem, level, "-elastic" if elastic else "")
    folder = os.path.join(work, "ccx-" + name)
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    if problem == "disc" and elastic:
        # prm/disc-rough.prm: ring to 10 m, E = 1e5 kPa, nu = 0.3, 1 mm.
        deck, info = models.disc_deck(*DISC_LEVELS[level], R=10., E=1e5,
                                      nu=0.3, sigma_y=None, ubar=1e-3)
    elif problem == "disc":
        deck, info = models.disc_deck(*DISC_LEVELS[level], E=E_CLAY,
                                      nu=0.49, sigma_y=SIGMA_Y, ubar=0.05)
    else:
        deck, info = models.pile_deck(*PILE_LEVELS[level], E=E_CLAY,
                                      nu=0.49,
                                      sigma_y=None if elastic else SIGMA_Y,
                                      u_head=0.1)
    open(os.path.join(folder, "model.inp"), "w").write(deck)
    env = dict(os.environ, OMP_NUM_THREADS=CCX_THREADS)
    status, wall, rss, log = timed(["ccx", "-i", "model"], folder, timeout,
                                   env)
    row = {"code": "ccx", "problem": problem + ("-elastic" if elastic
                                                else ""),
           "level": level, "nodes": info["nodes"], "wall_s": wall,
           "peak_gb": rss}
    m = re.search(r"number of equations\s+(\d+)", log)
    row["dofs"] = int(m.group(1)) if m else ""
    iterations = len(re.findall(r"^ iteration \d+", log, re.M))
    cuts = len(re.findall(r"increment size is decreased", log))
    if status is None:
        row.update(status="timeout", detail="killed after %d s" % timeout)
        return row
    curve = ccx_forces(os.path.join(folder, "model.dat"),
                       "NDISC" if problem == "disc" else "NPILE")
    if status != 0 or not curve or abs(curve[-1][0] - 1.) > 1e-6:
        row.update(status="failed", detail="exit %s, last time %s" % (
            status, curve[-1][0] if curve else "none"))
        return row
    force = 2 * abs(curve[-1][1])   # the full model: twice the half
    if problem == "disc" and elastic:
        row.update(value=force / info["ubar"], unit="P/ubar kN/m per m",
                   reference=DISC_ELASTIC_CLOSED)
    elif problem == "disc":
        row.update(value=force / (S_U * 1. * 1.), unit=UNITS["disc"],
                   reference=DISC_REF)
    else:
        row.update(value=force / (S_U * 1. * 10.), unit=UNITS["pile"],
                   reference="" if elastic else PILE_LE)
        if elastic:
            row["unit"] = "H/(s_u d L) at 0.1 d, elastic"
    if row.get("reference"):
        row["rel_error"] = (row["value"] - row["reference"]) / row["reference"]
    row["plateau_rise"] = "" if elastic else plateau_rise(curve)
    detail = "%d increments, %d Newton iterations, %d cuts, %d elements" % (
        len(curve), iterations, cuts, info["elements"])
    if problem == "pile":
        u = ccx_vector(os.path.join(folder, "model.dat"), "NREF")
        phi = ccx_vector(os.path.join(folder, "model.dat"), "NROT")
        if u and phi and phi[0]:
            detail += "; rotation %.5f rad, turns about %.2f m depth" % (
                phi[0], u[0] / phi[0])
    row.update(status="ok", detail=detail)
    return row


def read_results(path):
    rows = {}
    with open(path) as f:
        for r in csv.DictReader(f):
            rows.setdefault(r["quantity"], []).append(r)
    return rows


def mesh_dofs(text):
    """3 components x the FE_Q(p) nodes of the scene's rectangle x its
    harmonics: the size of the shipped mesh's problem (fourier-ssi prints
    no DoF count on a coupled run without a target)."""
    def entry(name):
        m = re.findall(r"^\s*set\s+%s\s*=\s*(.+)$" % name, text, re.M)
        return m[-1].split("#")[0] if m else ""
    p = int(entry("Polynomial degree") or 1)
    nr = sum(int(v) for v in entry("R cells").split(","))
    nz = sum(int(v) for v in entry("Z cells").split(","))
    nh = len(entry("Harmonics").split(","))
    return 3 * (p * nr + 1) * (p * nz + 1) * nh


def target_progress(log):
    """What a target run's log says of its members: the estimates, the
    harmonics doubled, the mesh it was in last."""
    out = ["mesh %s estimated %s" % e for e in re.findall(
        r"mesh (\d+), estimated relative error of the capacity H (\S+)",
        log)]
    out += ["harmonics doubled to n <= %s" % n for n in re.findall(
        r"harmonics doubled to n <= (\d+)", log)]
    meshes = re.findall(r"target accuracy \S+: mesh (\d+), (\d+) cells",
                        log)
    if meshes:
        out.append("last mesh started: %s (%s cells)" % meshes[-1])
    return out


def pile_turn(rows):
    """The pile's rotation at the last step and the depth it turns about."""
    if "step_rotation" not in rows:
        return ""
    phi = abs(float(rows["step_rotation"][-1]["value"]))
    u = abs(float(rows["step_horizontal_displacement"][-1]["value"]))
    return "rotation %.5f rad, turns about %.2f m depth" % (phi, u / phi) \
        if phi else ""


def run_fssi(exe, problem, case, work, timeout):
    """fourier-ssi on the shipped scene, or with a target appended (case
    a number), or (case elastic) with s_u raised out of reach and one load
    step."""
    folder = os.path.join(work, "fssi-%s-%s" % (problem, case))
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    text = open(os.path.join(ROOT, SCENES[problem])).read()
    if case not in ("shipped", "elastic"):
        text += ("\nsubsection Discretization\n  set Target accuracy = %g\n"
                 "end\n" % float(case))
        if re.search(r"^\s*set\s+Soil reaction depths", text, re.M):
            # Not yet allowed with a target: the curves are dropped.
            text += ("\nsubsection Output\n  set Soil reaction depths =\n"
                     "end\n")
    if case == "elastic":
        text += ("\nsubsection Soil plasticity\n  set Laws = 0: tresca, "
                 "su=1e6\nend\nsubsection Load path\n  set Load steps = 1\n"
                 "end\n")
    text += "\nsubsection Output\n  set Directory = out\n  set Write vtu = " \
            "false\nend\n"
    open(os.path.join(folder, "case.prm"), "w").write(text)
    waited = 0
    while not os.access(exe, os.X_OK):
        # The program is being rebuilt by someone else: wait for it.
        if waited > 1500:
            raise SystemExit("%s missing for 25 min" % exe)
        time.sleep(60)
        waited += 60
    status, wall, rss, log = timed([exe, "case.prm"], folder, timeout)
    label = {"shipped": "as shipped", "elastic": "elastic (s_u = 1e6 kPa)"
             }.get(case) or "Target accuracy %g" % float(case)
    row = {"code": "fourier-ssi", "problem": problem + (
        "-elastic" if case == "elastic" else ""), "level": label,
        "wall_s": wall, "peak_gb": rss, "dofs": mesh_dofs(text)}
    members = re.findall(r"starting mesh (\d+), (\d+) cells, about (\d+) "
                         r"DoFs", log)
    if members:
        row["dofs"] = int(members[-1][2])
    progress = target_progress(log)
    doubled = re.findall(r"harmonics doubled to n <= (\d+)", log)
    if doubled and not members:
        nh = len(re.findall(r"^\s*set\s+Harmonics\s*=\s*(.+)$", text,
                            re.M)[-1].split(","))
        row["dofs"] = row["dofs"] // nh * (int(doubled[-1]) + 1)
    if status is None:
        row.update(status="timeout", detail="; ".join(
            ["killed after %d s" % timeout] + progress))
        return row
    path = os.path.join(folder, "out", "results.csv")
    if not os.path.exists(path):
        tail = [l for l in log.strip().splitlines() if l.strip()][-1:]
        row.update(status="failed", detail="exit %s: %s" % (
            status, tail[0][:200] if tail else ""))
        return row
    rows = read_results(path)
    scale = {"disc": 1. / (S_U * 1. * 1.), "pile": 1. / (S_U * 1. * 10.)}
    turn = pile_turn(rows) if problem == "pile" else ""
    if case == "elastic":
        h = float(rows["step_horizontal_force"][-1]["value"])
        row.update(value=abs(h) * scale[problem],
                   unit="H/(s_u d L) at 0.1 d, elastic", status="ok",
                   detail=turn)
        return row
    value = abs(float(rows["capacity_normalised"][-1]["value"]))
    row.update(value=value, unit=UNITS[problem],
               reference=DISC_REF if problem == "disc" else PILE_LE)
    row["rel_error"] = (value - row["reference"]) / row["reference"]
    for name in ("capacity_H_error", "capacity_normalised_error"):
        if name in rows:
            bar = float(rows[name][-1]["value"])
            # capacity_H_error is relative; the normalised one absolute.
            row["own_bar"] = bar if name == "capacity_H_error" else \
                bar / value
            break
    if "capacity_H_plateau_rise" in rows:
        row["plateau_rise"] = float(
            rows["capacity_H_plateau_rise"][-1]["value"])
    detail = progress + ([turn] if turn else [])
    if "target_accuracy_reached" in rows:
        detail.append("target reached: %s" % rows[
            "target_accuracy_reached"][-1]["value"])
    if "cycle_capacity_H" in rows:
        detail.append("members %s" % ", ".join(
            "%.4f" % (abs(float(r["value"])) * scale[problem])
            for r in rows["cycle_capacity_H"]))
    if status != 0:
        detail.append("exit %d" % status)
    row.update(status="ok" if status == 0 else "not converged",
               detail="; ".join(detail))
    return row


# ---------------------------------------------------------------- output

def fmt(v, spec):
    if v in ("", None):
        return ""
    try:
        return spec % float(v)
    except (TypeError, ValueError):
        return str(v)


# The value against which "matched accuracy" is judged: the disc's exact
# limit; for the pile fourier-ssi's own extrapolation of three meshes and
# n <= 8 on the path to 0.1 d (doc/verification/soil-plasticity.md 7c,
# 4.728 +- 0.82), which is not independent of one of the two codes.
RATIO_REFERENCE = {"disc": DISC_REF, "pile": 4.728}


def matched_ratios(rows, problem):
    """For every fourier-ssi point of `problem`, the cheapest ccx run at
    least as accurate, and the reverse: (text lines)."""
    ok = [r for r in rows if r["problem"] == problem and r["status"] == "ok"
          and r.get("value") not in ("", None)]
    ref = RATIO_REFERENCE[problem]
    for r in ok:
        r["_err"] = abs(float(r["value"]) / ref - 1)
    lines = []
    for a, b in (("fourier-ssi", "ccx"), ("ccx", "fourier-ssi")):
        for ra in (r for r in ok if r["code"] == a):
            ea = ra["_err"]
            better = [rb for rb in ok if rb["code"] == b and
                      rb["_err"] <= ea]
            if not better:
                lines.append("| %s | %s %s: error %.2g, %.1f s | %s: no run "
                             "this accurate | |" % (
                                 problem, a, ra["level"], ea,
                                 float(ra["wall_s"]), b))
                continue
            rb = min(better, key=lambda r: float(r["wall_s"]))
            lines.append("| %s | %s %s: error %.2g, %.1f s | %s %s: error "
                         "%.2g, %.1f s | %.2f |" % (
                             problem, a, ra["level"], ea,
                             float(ra["wall_s"]), b, rb["level"],
                             rb["_err"],
                             float(rb["wall_s"]),
                             float(rb["wall_s"]) / float(ra["wall_s"])))
    return lines


def write_outputs(rows, meta):
    with open(os.path.join(HERE, "results.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, FIELDS)
        w.writeheader()
        for r in rows:
            w.writerow({k: r.get(k, "") for k in FIELDS})
    table = ["| code | problem | level / target | DoFs | nodes | value | "
             "unit | reference | rel. error vs reference | own bar (rel) | "
             "rise over last tenth | wall s | peak GB | status | detail |",
             "|---" * 15 + "|"]
    for r in rows:
        table.append("| %s |" % " | ".join([
            r["code"], r["problem"], r["level"], str(r.get("dofs", "")),
            str(r.get("nodes", "")), fmt(r.get("value"), "%.7g"),
            r.get("unit", ""), fmt(r.get("reference"), "%.8g"),
            fmt(r.get("rel_error"), "%+.3g"),
            fmt(r.get("own_bar"), "%.2g"), fmt(r.get("plateau_rise"),
                                               "%.2g"),
            fmt(r.get("wall_s"), "%.1f"), fmt(r.get("peak_gb"), "%.3f"),
            r.get("status", ""), r.get("detail", "")]))
    ratios = ["| problem (judged against) | point: error, wall | cheapest "
              "run of the other code at least as accurate | wall ratio "
              "(other / point) |", "|---|---|---|---|"]
    for problem in ("disc", "pile"):
        ratios += [l.replace("| %s |" % problem, "| %s (%.4g) |" % (
            problem, RATIO_REFERENCE[problem]), 1)
            for l in matched_ratios(rows, problem)]
    text = open(os.path.join(HERE, "results.md.in")).read()
    text = text.replace("@TABLE@", "\n".join(table))
    text = text.replace("@RATIOS@", "\n".join(ratios))
    text = text.replace("@META@", meta)
    with open(os.path.join(HERE, "results.md"), "w") as f:
        f.write(text)


def load_rows():
    path = os.path.join(HERE, "results.csv")
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return list(csv.DictReader(f))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--exe", default=os.path.join(ROOT, "build",
                                                 "fourier-ssi"))
    p.add_argument("--problems", default="disc,pile")
    p.add_argument("--codes", default="ccx,fssi")
    p.add_argument("--levels", default="",
                   help="ccx levels for every problem (default: disc "
                   "coarse,medium,fine; pile coarse,medium)")
    p.add_argument("--fssi-cases", default="shipped,target",
                   help="shipped, target (the --disc-targets or "
                   "--pile-targets)")
    p.add_argument("--disc-targets", default=FSSI_TARGETS["disc"])
    p.add_argument("--pile-targets", default=FSSI_TARGETS["pile"])
    p.add_argument("--checks", default="elastic-disc,elastic-pile",
                   help="comma list, or 'none'")
    p.add_argument("--quick", action="store_true")
    p.add_argument("--timeout", type=float, default=360.)
    p.add_argument("--keep", default="")
    p.add_argument("--fresh", action="store_true")
    p.add_argument("--no-write", action="store_true")
    p.add_argument("--render", action="store_true",
                   help="no runs: write results.md again from results.csv")
    args = p.parse_args()
    meta_path = os.path.join(HERE, "results-invocations.txt")
    if args.render:
        write_outputs(load_rows(), open(meta_path).read())
        return 0
    problems = args.problems.split(",")
    codes = args.codes.split(",")
    def levels_of(problem):
        if args.quick:
            return ["coarse"]
        return args.levels.split(",") if args.levels else \
            DEFAULT_LEVELS[problem]
    fssi_cases = ["shipped"] if args.quick else args.fssi_cases.split(",")
    checks = [] if args.checks == "none" else args.checks.split(",")
    work = args.keep or tempfile.mkdtemp(prefix="fssi-ccx-")
    os.makedirs(work, exist_ok=True)
    load_start = os.getloadavg()
    uptime_start = subprocess.run(["uptime"], capture_output=True,
                                  text=True).stdout.strip()
    ccx_version = re.search(r"Version (\S+)", subprocess.run(
        ["ccx", "-v"], capture_output=True, text=True).stdout)
    new = []

    def record(row):
        row["date"] = datetime.date.today().isoformat()
        row["load_start"] = "%.2f" % os.getloadavg()[0]
        print(", ".join("%s=%s" % (k, row.get(k, "")) for k in
                        ("code", "problem", "level", "dofs", "value",
                         "rel_error", "own_bar", "wall_s", "peak_gb",
                         "status", "detail")), flush=True)
        new.append(row)

    # The checks first: a model that fails them makes the rest moot.
    if "elastic-disc" in checks and "ccx" in codes:
        for level in levels_of("disc"):
            record(run_ccx("disc", level, work, args.timeout, elastic=True))
    if "elastic-pile" in checks:
        if "ccx" in codes:
            for level in levels_of("pile"):
                record(run_ccx("pile", level, work, args.timeout,
                               elastic=True))
        if "fssi" in codes:
            record(run_fssi(args.exe, "pile", "elastic", work, args.timeout))
    for problem in problems:
        if "fssi" in codes:
            for case in fssi_cases:
                if case == "target":
                    targets = getattr(args, problem + "_targets").split(",")
                else:
                    targets = [case]
                for t in targets:
                    record(run_fssi(args.exe, problem, t, work,
                                    args.timeout))
        if "ccx" in codes:
            for level in levels_of(problem):
                record(run_ccx(problem, level, work, args.timeout))
    load_end = os.getloadavg()
    for r in new:
        r["load_end"] = "%.2f" % load_end[0]
    if not args.keep:
        shutil.rmtree(work, ignore_errors=True)
    if args.no_write:
        return 0
    rows = [] if args.fresh else load_rows()
    keys = {(r["code"], r["problem"], r["level"]) for r in new}
    rows = [r for r in rows if (r["code"], r["problem"], r["level"])
            not in keys] + new
    # The elastic pile: ccx against fourier-ssi's elastic run.
    fssi_elastic = [r for r in rows if r["problem"] == "pile-elastic" and
                    r["code"] == "fourier-ssi" and r.get("value")]
    for r in rows:
        if r["problem"] == "pile-elastic" and r["code"] == "ccx" and \
                fssi_elastic and r.get("value") not in ("", None):
            ref = float(fssi_elastic[0]["value"])
            r["reference"] = ref
            r["rel_error"] = (float(r["value"]) - ref) / ref
    order = {"disc-elastic": 0, "pile-elastic": 1, "disc": 2, "pile": 3}
    rows.sort(key=lambda r: (order.get(r["problem"], 9), r["code"],
                             float(r["dofs"]) if r.get("dofs") not in
                             ("", None) else 0.))
    meta = ("Invocation (%s): `%s`; ccx %s (Debian calculix-ccx, "
            "SPOOLES, OMP_NUM_THREADS=%s); fourier-ssi %s. `uptime` at the "
            "start: %s; at the end: %s. Load average (1 min) %.2f at the "
            "start and %.2f at the end, on 2 cores shared with another "
            "engineer's builds: the times compare within this table only."
            % (datetime.datetime.now().strftime("%Y-%m-%d %H:%M"),
               " ".join(["python3", "benchmarks/nonlinear-accuracy/calculix/"
                         "run.py"] + sys.argv[1:]),
               ccx_version.group(1) if ccx_version else "?", CCX_THREADS,
               args.exe.replace(ROOT + "/", ""), uptime_start,
               subprocess.run(["uptime"], capture_output=True,
                              text=True).stdout.strip(),
               load_start[0], load_end[0]))
    old_meta = ""
    if os.path.exists(meta_path) and not args.fresh:
        old_meta = open(meta_path).read()
    with open(meta_path, "w") as f:
        f.write(old_meta + "- " + meta + "\n")
    write_outputs(rows, open(meta_path).read())
    return 0


if __name__ == "__main__":
    sys.exit(main())
