#!/usr/bin/python3
"""The interface state around the circumference of a coulomb scene
(doc/nonlinear-interfaces.md section 9), from prm/disc-gap.prm (tensionless
frictionless, no initial stress, 4 displacement steps, 3 Gauss points x
N = 36 samples) run with Write 3D vtu = true:

(1) interface-state.csv has the header with units and steps x points x N
    rows (4 x 3 x 36 = 432), states only stick / slip / open, and the open
    count of every step equals the step's count in load-displacement.csv;
(2) the normal traction is never tensile: t_n <= 1e-9 max |t_n| (the law
    returns t_n <= sigma_t = 0 exactly; the bound is round-off), and the gap
    is never negative: d_n > 0 wherever a sample is open (no initial stress,
    so opening needs d_n above the last converged plastic opening >= 0);
(3) the contact arc is one arc symmetric about theta = 0 (the disc moves
    along +x, so the open samples are those behind it, theta in [90, 270]
    degrees with 180 among them (at exactly 90 and 270 the trial normal
    traction is zero up to round-off, either state is right), the same set
    at every step: homogeneity);
(4) the revolved 3D VTU of the last step is written, the interface samples
    of the last step as 3D points (interface-state-3d.vtu: 108 points, as
    many open as the CSV counts), and tools/plot_interface_state.py draws
    the PNG.
Usage: interface_state_output.py FOURIER_SSI_EXE SOURCE_DIR WORK_DIR
"""
import csv
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtu_reader import data_arrays  # noqa: E402

exe, source_dir, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
scene = open(os.path.join(source_dir, "prm/disc-gap.prm")).read()
scene += """
subsection Output
  set Directory    = out
  set Write 3D vtu = true
end
"""
open(os.path.join(work, "scene.prm"), "w").write(scene)
subprocess.run([exe, "scene.prm"], cwd=work, check=True,
               stdout=subprocess.DEVNULL)
out = os.path.join(work, "out")
failed = 0


def check(what, ok):
    global failed
    print(("  ok   " if ok else "  FAIL ") + what)
    failed += 0 if ok else 1


with open(os.path.join(out, "interface-state.csv")) as f:
    header = f.readline().strip().split(",")
    rows = list(csv.DictReader(f, fieldnames=header))
check("header with units", header == [
    "step", "interface_id", "point", "r_m", "z_m", "normal_r", "normal_z",
    "theta_deg", "state", "t_s_kPa", "t_n_kPa", "t_theta_kPa", "d_s_m",
    "d_n_m", "d_theta_m"])
check("rows = 4 steps x 3 points x 36 samples (%d)" % len(rows),
      len(rows) == 432)
check("states are stick/slip/open",
      all(r["state"] in ("stick", "slip", "open") for r in rows))
with open(os.path.join(out, "load-displacement.csv")) as f:
    curve = list(csv.DictReader(f))
for s in curve:
    n_open = sum(1 for r in rows if r["step"] == s["step"] and
                 r["state"] == "open")
    check("step %s: open samples %d = load-displacement.csv %s"
          % (s["step"], n_open, s["open"]), n_open == int(s["open"]))

largest = max(abs(float(r["t_n_kPa"])) for r in rows)
worst = max(float(r["t_n_kPa"]) for r in rows)
check("never tensile: max t_n = %.3g kPa <= 1e-9 x %.3g kPa" % (worst, largest),
      worst <= 1e-9 * largest)
gaps = [float(r["d_n_m"]) for r in rows if r["state"] == "open"]
check("gap never negative: min d_n over open samples %.3g m > 0" % min(gaps),
      min(gaps) > 0.)

open_angles = {}
for r in rows:
    if r["state"] == "open":
        open_angles.setdefault(r["step"], set()).add(round(float(r["theta_deg"]), 6))
arcs = list(open_angles.values())
check("same open arc at every step", all(a == arcs[0] for a in arcs))
check("open arc behind the disc, within [90, 270] deg",
      all(90. <= t <= 270. for t in arcs[0]) and 180. in arcs[0])
check("open arc symmetric about 180 deg",
      all(round(360. - t, 6) in arcs[0] for t in arcs[0]))

check("solution-3d.vtu written",
      os.path.getsize(os.path.join(out, "solution-3d.vtu")) > 0)
vtu = open(os.path.join(out, "interface-state-3d.vtu")).read()
check("interface-state-3d.vtu: 108 sample points",
      'NumberOfPoints="108"' in vtu)
states = data_arrays(os.path.join(out, "interface-state-3d.vtu"))["state"][1]
n_open_vtu = states.count(2.)
check("interface-state-3d.vtu: open points %d = last step's %s"
      % (n_open_vtu, curve[-1]["open"]), n_open_vtu == int(curve[-1]["open"]))
png = os.path.join(work, "state.png")
subprocess.run(["/usr/bin/python3",
                os.path.join(source_dir, "tools/plot_interface_state.py"),
                os.path.join(out, "interface-state.csv"), png], check=True,
               stdout=subprocess.DEVNULL)
check("plot_interface_state.py wrote the PNG", os.path.getsize(png) > 0)
print("%d failed" % failed)
sys.exit(1 if failed else 0)
