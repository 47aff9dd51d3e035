#!/usr/bin/python3
"""tools/pisa/calibrate.py end to end on a tiny sand space (2 fitted piles
of D = 4 m with L/D = 3 and 5 in the Mohr-Coulomb sand of
prm/monopile-sand-lateral.prm, 6 cells along the pile, 4 steps to 0.05 D,
4 depths) with the program:
- the curves are taken in the sand normalisation (the model is a sand's,
  m as m/(|p| D)), and y_u of p-v and m-psi varies with z/L (Burd et al.
  2020);
- every fitted value is within the PISA constraints;
- the 1D model's H at the end of the push is within 30 % of the FE's (a
  coarse two-pile model; doc/pisa-design-model.md gives the differences of
  the benchmark's space);
- the OpenPile export is a Custom_pisa_sand per layer, its weight
  gamma' + 10 kN/m^3 with the scene's gamma' = 10, read back;
- bad input gets one line and exit 1: y_u in z/L with two model layers, an
  unknown y_u depth variable; and it leaves no result file in the output
  folder, also not the good run's before it (runs/ with the FE runs stays).
Usage: pisa_calibration_sand.py EXE SOURCE_DIR WORK_DIR."""
import json
import os
import shutil
import subprocess
import sys

exe, source, work = sys.argv[1:4]
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(source, "tools", "pisa"))
from relative_checks import check, that, finish  # noqa: E402
import export  # noqa: E402

shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
tool = os.path.join(source, "tools", "pisa", "calibrate.py")
space = (f"base scene = {os.path.join(source, 'prm', 'monopile-sand-lateral.prm')}\n"
         "diameters = 4\nL/D = 3, 5\nleft out =\nwall t/D = 0.0122\nstick-up h/D = 1\n"
         "target v/D = 0.05\nload steps = 4\ninitial v/D = 0.002\ndepths = 4\ncells along pile = 6\n")


def calibrate(text, out, *extra):
    site = os.path.join(work, "site.txt")
    with open(site, "w") as f:
        f.write(text)
    return subprocess.run(["/usr/bin/python3", tool, site, "--out", os.path.join(work, out), "--exe", exe,
                           "--no-plot", *extra], capture_output=True, text=True)


run = calibrate(space, "out")
print(run.stdout[-3000:], run.stderr[-2000:])
that(run.returncode == 0, f"calibration exits 0 (exit {run.returncode})")
out = os.path.join(work, "out")
with open(os.path.join(out, "model.json")) as f:
    model = json.load(f)
that(model["soil_kind"] == "sand", f"the model is a sand's ({model['soil_kind']})")
that(model["normalisation"]["mt"] == "m/(|p| D) vs psi G0/sigma'_v", f"m-psi as m/(|p| D): {model['normalisation']['mt']}")
for c in ("py", "mt"):
    that(all(ly["yu_over"] == "z/L" for ly in model["params"][c]["layers"]), f"{c}: y_u linear in z/L")
for c, P in model["params"].items():
    for ly in P["layers"]:
        for which in ("top", "bottom"):
            q = ly[which]
            that(0 <= q["n"] <= 1 and q["xu"] > 0 and q["yu"] > 0 and q["k"] * q["xu"] >= q["yu"] * (1 - 1e-12),
                 f"model {c} {which} within the constraints {q}")
with open(os.path.join(out, "summary.json")) as f:
    summary = json.load(f)
that(set(summary) == {"D4-LD3", "D4-LD5"}, f"both piles compared: {sorted(summary)}")
for name, s in summary.items():
    that(abs(s["end_dH"]) < 0.3, f"{name}: |H_1D/H_FE - 1| at the end below 0.3 ({s['end_dH']:+.3f})")
pile, layers = export.read_openpile(os.path.join(out, "openpile-D4-LD5.json"))
that(all("Custom_pisa_sand" in ly for ly in layers), "the export is Custom_pisa_sand")
check("export: weight = gamma' + 10 [kN/m^3]", layers[0]["weight"], 20.0, 1e-9)
# bad input: one line, exit 1
for text, what in (("model layers z/D = 0, 2, 5\ny_u with depth = z/L\n", "y_u in z/L with two layers"),
                   ("y_u with depth = z/H\n", "an unknown y_u depth variable")):
    r = calibrate(space + text, "out", "--reuse")
    lines = (r.stdout + r.stderr).strip().splitlines()
    that(r.returncode == 1 and len(lines) == 1, f"bad input ({what}): exit 1 and one line (exit {r.returncode}: {lines})")
    left = sorted(f for f in os.listdir(out) if f != "runs")
    that(not left, f"bad input ({what}): no result file left in the output folder, the good run's "
                   f"included ({left})")
finish()
