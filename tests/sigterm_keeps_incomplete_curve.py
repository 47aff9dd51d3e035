#!/usr/bin/python3
"""A plastic run stopped from outside (a time limit's SIGTERM) keeps the
curve of the steps it had converged, under a name that says so, and nothing
under a result's name (doc/output-files.md, "A run stopped from outside").

prm/footing-capacity.prm (a tenth of a second to a second per step) runs
with 200 load steps, so that it is still running when the test stops it.
The run rewrites load-displacement-incomplete.csv after a step, at most
every 2 s. The test waits until that file holds at least two steps (so at
least one rewrite happened), then sends SIGTERM. Whatever the moment:
(1) the run ended by SIGTERM;
(2) load-displacement-incomplete.csv is there, with the header of a
    load-displacement curve and at least two steps, numbered 1, 2, ... in
    order, each with a finite vertical force that is negative (the footing
    is pushed down; N_c > 0);
(3) no file is left under a result's name (results.csv,
    load-displacement.csv);
(4) the next run into the folder, even a refused one, removes it (it
    belongs to a run that is over);
(5) a run that finishes (the same scene with 4 steps) leaves
    load-displacement.csv and no incomplete curve.
Usage: sigterm_keeps_incomplete_curve.py FOURIER_SSI_EXE SOURCE_DIR WORK_DIR
"""
import csv
import math
import os
import shutil
import signal
import subprocess
import sys
import time

exe, source_dir, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
scene = open(os.path.join(source_dir, "prm/footing-capacity.prm")).read()
environment = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
passed = failed = 0


def check(ok, what):
    global passed, failed
    print(("  ok   " if ok else "  FAIL ") + what)
    passed += ok
    failed += not ok


def write_prm(name, folder, extra=""):
    open(os.path.join(work, name), "w").write(
        scene + "\nsubsection Output\n  set Directory = %s\nend\n%s"
        % (folder, extra))


def steps_in(path):
    try:
        with open(path) as f:
            return list(csv.DictReader(f))
    except (OSError, csv.Error):
        return []


write_prm("stopped.prm", "stopped",
          "subsection Load path\n  set Load steps = 200\nend\n")
write_prm("refused.prm", "stopped",
          "subsection Output\n  set Frobnicate = 1\nend\n")
write_prm("finished.prm", "finished",
          "subsection Load path\n  set Load steps = 4\nend\n")

incomplete = os.path.join(work, "stopped", "load-displacement-incomplete.csv")
run = subprocess.Popen([exe, "stopped.prm"], cwd=work, env=environment,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
# Bound: 200 steps take minutes; two steps and a rewrite take seconds.
deadline = time.time() + 120.
while run.poll() is None and len(steps_in(incomplete)) < 2 and \
        time.time() < deadline:
    time.sleep(0.05)
if run.poll() is None:
    run.send_signal(signal.SIGTERM)
run.wait()
check(run.returncode == -signal.SIGTERM,
      "the run ended by SIGTERM (exit status %d)" % run.returncode)
rows = steps_in(incomplete)
check(len(rows) >= 2, "load-displacement-incomplete.csv keeps %d converged "
      "steps (at least 2)" % len(rows))
if rows:
    check("step" in rows[0] and "V_kN" in rows[0],
          "it has the header of a load-displacement curve: %s"
          % list(rows[0])[:4])
    numbers = [int(r.get("step", -1)) for r in rows]
    check(numbers == list(range(1, len(rows) + 1)),
          "its steps are numbered 1 .. %d in order" % len(rows))
    forces = [float(r.get("V_kN", "nan")) for r in rows]
    check(all(math.isfinite(v) and v < 0. for v in forces),
          "every step's V is finite and pushes down: %s" % forces[:3])
left = sorted(name for name in os.listdir(os.path.join(work, "stopped"))
              if not name.startswith("."))
check(left == ["load-displacement-incomplete.csv"],
      "nothing else under a result's name: %s" % left)

subprocess.run([exe, "refused.prm"], cwd=work, capture_output=True)
left = sorted(os.listdir(os.path.join(work, "stopped")))
check(left == [], "the next (refused) run removes it: %s" % left)

finished = subprocess.run([exe, "finished.prm"], cwd=work, env=environment,
                          capture_output=True)
left = sorted(os.listdir(os.path.join(work, "finished")))
check(finished.returncode == 0 and "load-displacement.csv" in left and
      "load-displacement-incomplete.csv" not in left,
      "a finished run leaves its curve and no incomplete one (exit %d): %s"
      % (finished.returncode, left))
print("%d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
