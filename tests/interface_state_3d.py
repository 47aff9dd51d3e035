#!/usr/bin/python3
"""Output/Interface state 3D (doc/output-files.md, "The interface state in
3D") on prm/disc-gap.prm: a rigid disc r0 = 0.5 m in a ring, tensionless
frictionless interface 5 on r = 0.5, z from -0.5 to 0.5 (one quadratic face,
3 Gauss points), N = 36 theta samples, pushed along +x in 4 steps. Run with
Interface state steps = 1, 2, 3, 4:

(1) interface-state-3d-step<s>.vtu parses (tests/vtu_reader.py) with
    3 x 36 = 108 quads of 4 own vertices each; every vertex lies on the
    cylinder, |sqrt(x^2 + y^2) - 0.5| <= 1e-12 x 0.5, with z in
    [-0.5, 0.5] (1e-12); the quads tile it: each spans the sector
    theta_j -+ 5 degrees of its sample (1e-9 degrees), their z-extents per
    sample add up to the line's length 1 m, the Gauss point of the CSV lies
    inside its quad's z-extent, and the flat quads' area is the chords',
    N 2 r0 sin(pi / N) L, to 1e-12;
(2) the physics of the disc pushed into the ring: open (state 2) on the
    trailing side, every sample with |theta - 180| < 90 degrees, and closed
    (0 or 1) on the leading side, |theta| < 90 degrees (at exactly 90 and
    270 the trial normal traction is zero to round-off, either is right);
(3) t_n, t_s, d_n, d_s and the state in the VTU equal those of
    interface-state.csv at the same (step, point, theta): the VTU is
    Float64, the CSV has 10 significant digits, so |VTU - CSV| <= 1e-9
    |CSV| + 1e-300;
(4) per step, the quads' stick / slip / open counts equal the log line's
    "interface stick/slip/open" of that step; interface-state-3d.pvd lists
    the 4 files at timestep = step;
(5) with the entry false (the default) no interface-state-3d-step*.vtu nor
    interface-state-3d.pvd is written.
Usage: interface_state_3d.py FOURIER_SSI_EXE SOURCE_DIR WORK_DIR
"""
import csv
import math
import os
import re
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtu_reader import data_arrays  # noqa: E402

exe, source_dir, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
scene = open(os.path.join(source_dir, "prm/disc-gap.prm")).read()
r0, z_low, z_high, N, n_points = 0.5, -0.5, 0.5, 36, 3
failed = 0


def check(what, ok):
    global failed
    print(("  ok   " if ok else "  FAIL ") + what)
    failed += 0 if ok else 1


def run(name, output):
    open(os.path.join(work, name + ".prm"), "w").write(
        scene + "\nsubsection Output\n  set Directory = " + name + "\n" +
        output + "end\n")
    log = subprocess.run([exe, name + ".prm"], cwd=work, check=True,
                         stdout=subprocess.PIPE, text=True).stdout
    return os.path.join(work, name), log


out, log = run("on", "  set Interface state 3D    = true\n"
                     "  set Interface state steps = 1, 2, 3, 4\n")
logged = [tuple(int(c) for c in m) for m in
          re.findall(r"step \d+:.*interface stick/slip/open (\d+)/(\d+)/(\d+)",
                     log)]
check("the log has 4 steps", len(logged) == 4)
with open(os.path.join(out, "interface-state.csv")) as f:
    csv_rows = {(int(r["step"]), int(r["point"]),
                 round(float(r["theta_deg"]), 6)): r
                for r in csv.DictReader(f)}
names = {"stick": 0, "slip": 1, "open": 2}
sector = 360. / N
for step in range(1, 5):
    tag = "step %d: " % step
    arrays = data_arrays(os.path.join(out,
                                      "interface-state-3d-step%d.vtu" % step))
    xyz = arrays["Points"][1]
    n_quads = len(arrays["state"][1])
    check(tag + "%d quads of 4 own vertices (3 points x 36 samples)" % n_quads,
          n_quads == n_points * N and len(xyz) == 3 * 4 * n_quads and
          arrays["connectivity"][1] == list(range(4 * n_quads)))
    vertices = [xyz[3 * v:3 * v + 3] for v in range(len(xyz) // 3)]
    radius_error = max(abs(math.hypot(x, y) - r0) for x, y, _ in vertices)
    check(tag + "on the cylinder: max |r - 0.5| = %.2g m <= 1e-12 x 0.5"
          % radius_error, radius_error <= 1e-12 * r0)
    check(tag + "z within the interface line [-0.5, 0.5]",
          all(z_low - 1e-12 <= z <= z_high + 1e-12 for _, _, z in vertices))

    field = {name: arrays[name][1] for name in (
        "state", "t_n_kPa", "t_s_kPa", "d_n_m", "d_s_m", "point",
        "theta_deg", "interface_id")}
    check(tag + "interface id 5 everywhere",
          all(i == 5. for i in field["interface_id"]))
    area, sector_error, span = 0., 0., {}
    inside = True
    for q in range(n_quads):
        quad = vertices[4 * q:4 * q + 4]
        # Around the quad: vertices 0, 1 at the sector's first angle,
        # 2, 3 at its second.
        theta = field["theta_deg"][q]
        for v, edge in ((0, -1), (1, -1), (2, 1), (3, 1)):
            off = (math.degrees(math.atan2(quad[v][1], quad[v][0])) -
                   (theta + edge * sector / 2)) % 360.
            sector_error = max(sector_error, min(off, 360. - off))
        zs = [z for _, _, z in quad]
        span[theta] = span.get(theta, 0.) + max(zs) - min(zs)
        row = csv_rows[(step, int(field["point"][q]), round(theta, 6))]
        inside &= min(zs) - 1e-12 <= float(row["z_m"]) <= max(zs) + 1e-12
        a, b, c = quad[0], quad[1], quad[3]
        area += math.dist(a, b) * math.dist(a, c)
    check(tag + "each quad spans its sample's sector +- 5 deg (%.2g deg off)"
          % sector_error, sector_error <= 1e-9)
    check(tag + "z-extents per sample add up to 1 m",
          len(span) == N and all(abs(s - 1.) <= 1e-12 for s in span.values()))
    check(tag + "every Gauss point lies in its quad's z-extent", inside)
    chords = N * 2. * r0 * math.sin(math.pi / N) * (z_high - z_low)
    check(tag + "area of the quads %.15g = N 2 r0 sin(pi/N) L %.15g (1e-12)"
          % (area, chords), abs(area - chords) <= 1e-12 * chords)

    trailing = [field["state"][q] for q in range(n_quads)
                if abs(field["theta_deg"][q] - 180.) < 90. - 1e-9]
    leading = [field["state"][q] for q in range(n_quads)
               if min(field["theta_deg"][q], 360. - field["theta_deg"][q]) <
               90. - 1e-9]
    check(tag + "open on the trailing side (%d samples, theta near 180)"
          % len(trailing), trailing and all(s == 2. for s in trailing))
    check(tag + "closed on the leading side (%d samples, theta near 0)"
          % len(leading), leading and all(s != 2. for s in leading))

    worst, same_state = 0., True
    for q in range(n_quads):
        row = csv_rows[(step, int(field["point"][q]),
                        round(field["theta_deg"][q], 6))]
        same_state &= names[row["state"]] == field["state"][q]
        for vtu_name, csv_name in (("t_n_kPa", "t_n_kPa"),
                                   ("t_s_kPa", "t_s_kPa"),
                                   ("d_n_m", "d_n_m"), ("d_s_m", "d_s_m")):
            expected = float(row[csv_name])
            worst = max(worst, abs(field[vtu_name][q] - expected) /
                        (1e-9 * abs(expected) + 1e-300))
    check(tag + "state = the CSV's at every sample", same_state)
    check(tag + "t_n, t_s, d_n, d_s = the CSV's: worst %.3f of 1e-9 |CSV|"
          % worst, worst <= 1.)
    counts = tuple(field["state"].count(float(s)) for s in range(3))
    check(tag + "stick/slip/open %s = the log's %s"
          % (counts, logged[step - 1] if step <= len(logged) else None),
          step <= len(logged) and counts == logged[step - 1])

pvd = open(os.path.join(out, "interface-state-3d.pvd")).read()
listed = re.findall(r'timestep="(\d+)"[^>]*file="([^"]*)"', pvd)
check("interface-state-3d.pvd lists steps 1 to 4",
      listed == [(str(s), "interface-state-3d-step%d.vtu" % s)
                 for s in range(1, 5)])

off, _ = run("off", "")
written = [f for f in os.listdir(off) if f.startswith("interface-state-3d")]
check("entry false: no interface-state-3d file (%s)" % written,
      written == [] and os.path.exists(os.path.join(off,
                                                    "interface-state.csv")))
print("%d failed" % failed)
sys.exit(1 if failed else 0)
