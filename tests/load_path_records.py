#!/usr/bin/python3
"""The records of a coupled run show the nonlinear sources the scene has and
nothing else (doc/output-files.md, load-displacement.csv; doc/driver.md):

(1) load-displacement.csv has the leading columns, then elastic, plastic,
    max_yield_kPa only with plastic soil and stick, slip, open only with
    nonlinear interfaces, then harmonics, time_s, held_fraction, converged;
(2) the log has one step line per CSV row, and each line's numbers are the
    row's: load factor (6 digits), iterations, harmonics, the plastic and
    total samples (soil), the stick/slip/open counts (interfaces); a line
    names the soil's part only with plastic soil and the interfaces' only
    with nonlinear interfaces.
Three scenes, one per combination of sources, shortened where they are long:
  interfaces only   prm/disc-gap.prm (4 steps),
  soil only         prm/cylinder-mohr-coulomb.prm (8 steps),
  soil + interfaces prm/pile-adhesion.prm, 2 steps to 0.002 m.
Usage: load_path_records.py FOURIER_SSI_EXE SOURCE_DIR WORK_DIR
"""
import csv
import os
import re
import shutil
import subprocess
import sys

exe, source_dir, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
failed = 0

LEADING = ["step", "load_factor", "V_kN", "H_kN", "M_kNm", "T_kNm",
           "vertical_m", "horizontal_m", "rotation_rad", "twist_rad",
           "iterations", "residual"]
SOIL = ["elastic", "plastic", "max_yield_kPa"]
INTERFACES = ["stick", "slip", "open"]
TRAILING = ["harmonics", "time_s", "held_fraction", "converged"]

STEP = re.compile(r"^\s*step (\d+)(?: \(held loads\))?: factor ([-0-9.e+]+),"
                  r".*?; (\d+) iterations(.*); (\d+) harmonics; [0-9.e+-]+ s$")
PLASTIC = re.compile(r"; plastic samples (\d+) of (\d+); max f ")
CONTACT = re.compile(r"; interface stick/slip/open (\d+)/(\d+)/(\d+)")


def check(what, ok):
    global failed
    print(("  ok   " if ok else "  FAIL ") + what)
    failed += 0 if ok else 1


def run(name, prm, appended, soil, interfaces):
    directory = os.path.join(work, name)
    os.makedirs(directory)
    text = open(os.path.join(source_dir, prm)).read() + appended + """
subsection Output
  set Directory = out
end
"""
    open(os.path.join(directory, "scene.prm"), "w").write(text)
    p = subprocess.run([exe, "scene.prm"], cwd=directory, text=True,
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    check("%s: the run exits 0" % name, p.returncode == 0)
    with open(os.path.join(directory, "out", "load-displacement.csv")) as f:
        rows = list(csv.DictReader(f))
        header = list(rows[0].keys()) if rows else []
    expected = LEADING + (SOIL if soil else []) + \
        (INTERFACES if interfaces else []) + TRAILING
    check("%s: columns %s" % (name, ",".join(header[len(LEADING):])),
          header == expected)
    lines = [m for m in (STEP.match(l) for l in p.stdout.splitlines()) if m]
    check("%s: %d step lines = %d CSV rows" % (name, len(lines), len(rows)),
          len(lines) == len(rows) and len(rows) > 0)
    for m, row in zip(lines, rows):
        step = "%s step %s" % (name, m.group(1))
        check("%s: factor %s = CSV %s (6 digits)"
              % (step, m.group(2), row["load_factor"]),
              abs(float(m.group(2)) - float(row["load_factor"])) <=
              1e-5 * abs(float(row["load_factor"])))
        check("%s: %s iterations, %s harmonics as in the CSV"
              % (step, m.group(3), m.group(5)),
              m.group(3) == row["iterations"] and
              m.group(5) == row["harmonics"])
        parts = m.group(4)
        plastic, contact = PLASTIC.search(parts), CONTACT.search(parts)
        check("%s: the soil's part %s" % (step, "present" if soil else
                                          "absent"),
              (plastic is not None) == soil)
        check("%s: the interfaces' part %s"
              % (step, "present" if interfaces else "absent"),
              (contact is not None) == interfaces)
        if soil and plastic:
            check("%s: plastic samples %s of %s as in the CSV"
                  % (step, plastic.group(1), plastic.group(2)),
                  int(plastic.group(1)) == int(row["plastic"]) and
                  int(plastic.group(2)) ==
                  int(row["plastic"]) + int(row["elastic"]))
        if interfaces and contact:
            check("%s: stick/slip/open %s as in the CSV"
                  % (step, "/".join(contact.groups())),
                  [int(c) for c in contact.groups()] ==
                  [int(row[c]) for c in INTERFACES])


run("interfaces", "prm/disc-gap.prm", "", soil=False, interfaces=True)
run("soil", "prm/cylinder-mohr-coulomb.prm", "", soil=True, interfaces=False)
run("soil_and_interfaces", "prm/pile-adhesion.prm", """
subsection Load path
  set Target     = 0.002
  set Load steps = 2
end
""", soil=True, interfaces=True)

print("%d check(s) failed" % failed if failed else "all checks passed")
sys.exit(1 if failed else 0)
