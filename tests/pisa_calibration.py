#!/usr/bin/python3
"""tools/pisa/calibrate.py end to end on a tiny space (2 fitted piles and
one left out in the clay of prm/monopile-clay-lateral.prm, 6 cells along the pile, 4 steps to 0.05 D,
4 depths) with the program: every output file is written, every fitted
value is finite and within the PISA constraints, the 1D model's H at the
end of the push is within 30 % of the FE's (a coarse, two-pile model;
doc/pisa-design-model.md gives the measured differences), and bad input
gets one line and exit 1 (a space with one L/D; an unknown key); a pile
whose run left no curves gets one line naming it and the others are kept.
Usage: pisa_calibration.py EXE SOURCE_DIR WORK_DIR."""
import csv
import json
import os
import shutil
import subprocess
import sys

exe, source, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
tool = os.path.join(source, "tools", "pisa", "calibrate.py")
failed = []


def expect(name, ok, detail=""):
    print(f"{'ok  ' if ok else 'FAIL'} {name} {detail}")
    if not ok:
        failed.append(name)


site = os.path.join(work, "site.txt")
with open(site, "w") as f:
    f.write(f"base scene = {os.path.join(source, 'prm', 'monopile-clay-lateral.prm')}\n"
            "diameters = 4\nL/D = 3, 5\nleft out = 4@4\nwall t/D = 0.0122\nstick-up h/D = 1\n"
            "target v/D = 0.05\nload steps = 4\ninitial v/D = 0.002\ndepths = 4\ncells along pile = 6\n")
run = subprocess.run(["/usr/bin/python3", tool, site, "--out", os.path.join(work, "out"), "--exe", exe,
                      "--no-plot"], capture_output=True, text=True)
print(run.stdout[-3000:], run.stderr[-2000:])
expect("calibration exits 0", run.returncode == 0, f"(exit {run.returncode})")
out = os.path.join(work, "out")
for name in ("fits.csv", "model.json", "head-curves.csv", "summary.json",
             "openpile-D4-LD3.json", "openpile-D4-LD5.json"):
    expect(f"{name} written", os.path.isfile(os.path.join(out, name)))
if os.path.isfile(os.path.join(out, "model.json")):
    with open(os.path.join(out, "model.json")) as f:
        params = json.load(f)["params"]
    for c, P in params.items():
        for ly in P["layers"]:
            for which in ("top", "bottom"):
                q = ly[which]
                ok = 0 <= q["n"] <= 1 and q["xu"] > 0 and q["yu"] > 0 and q["k"] * q["xu"] >= q["yu"] * (1 - 1e-12)
                expect(f"model {c} {which} within the constraints", ok, str(q))
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    for name, s in summary.items():
        expect(f"{name}: |H_1D/H_FE - 1| at the end below 0.3", abs(s["end_dH"]) < 0.3, f"({s['end_dH']:+.3f})")
    with open(os.path.join(out, "fits.csv")) as f:
        rows = list(csv.DictReader(f))
    expect("fits.csv has the 4 components' per-curve fits",
           {r["component"] for r in rows if r["kind"] == "curve"} == {"py", "mt", "Hb", "Mb"})
# a pile whose run left no curves: one line naming it, the rest kept
os.remove(os.path.join(out, "runs", "D4-LD4-left-out", "soil-reaction-curves.csv"))
r = subprocess.run(["/usr/bin/python3", tool, site, "--out", out, "--exe", exe, "--reuse", "--no-plot"],
                   capture_output=True, text=True)
named = [l for l in r.stdout.splitlines() if l.startswith("FAILED") and "D4-LD4-left-out" in l]
expect("a pile without curves: exit 0, one FAILED line naming it, the others compared",
       r.returncode == 0 and len(named) == 1 and "D4-LD5 (fitted)" in r.stdout, f"(exit {r.returncode}: {named})")
# bad input: one line, exit 1
for text, what in (("L/D = 4\n", "one L/D"), ("diameter = 4\n", "an unknown key")):
    bad = os.path.join(work, "bad.txt")
    with open(bad, "w") as f:
        f.write(text)
    r = subprocess.run(["/usr/bin/python3", tool, bad, "--out", os.path.join(work, "bad"), "--exe", exe],
                       capture_output=True, text=True)
    lines = (r.stdout + r.stderr).strip().splitlines()
    expect(f"bad input ({what}): exit 1 and one line", r.returncode == 1 and len(lines) == 1,
           f"(exit {r.returncode}: {lines})")
print(f"{len(failed)} failed")
sys.exit(1 if failed else 0)
