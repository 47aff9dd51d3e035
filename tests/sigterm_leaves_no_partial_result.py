#!/usr/bin/python3
"""A run stopped by SIGTERM while it writes a result leaves no partial file
under a result's name (doc/output-files.md, the temporary-name rule).

prm/pile-lateral-slip.prm writes a 4 MB interface-state.csv. The run is
stopped with SIGTERM the moment that file appears in the output folder,
under its own name or under the temporary name `.interface-state.csv.partial`
(polled every 0.2 ms; writing the file takes tens of ms), so the signal
arrives while the file is written or just after. Whatever the moment:
(1) the run ended by SIGTERM;
(2) no file is left under a result's name: the files the run had already
    written whole (load-displacement.csv, ...) are removed by its signal
    handler, since without results.csv they are a run that did not finish
    (load-displacement-incomplete.csv, named for what it is, may stay);
(3) the next run into the folder, even one whose input is refused, removes
    the temporary file the stopped run left.
Usage: sigterm_leaves_no_partial_result.py FOURIER_SSI_EXE SOURCE_DIR WORK_DIR
"""
import os
import shutil
import signal
import subprocess
import sys
import time

exe, source_dir, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
scene = open(os.path.join(source_dir, "prm/pile-lateral-slip.prm")).read()
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


write_prm("stopped.prm", "stopped")
write_prm("refused.prm", "stopped",
          "subsection Output\n  set Frobnicate = 1\nend\n")

watched = [os.path.join(work, "stopped", name)
           for name in ("interface-state.csv", ".interface-state.csv.partial")]
run = subprocess.Popen([exe, "stopped.prm"], cwd=work, env=environment,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
while run.poll() is None and not any(os.path.exists(f) for f in watched):
    time.sleep(0.0002)
if run.poll() is None:
    run.send_signal(signal.SIGTERM)
run.wait()
check(run.returncode == -signal.SIGTERM,
      "the run ended by SIGTERM (exit status %d)" % run.returncode)
left = sorted(os.listdir(os.path.join(work, "stopped")))
print("  left in the folder: %s" % left)
# The converged steps' curve may stay, under its own name
# (sigterm_keeps_incomplete_curve.py).
named = [name for name in left if not name.startswith(".") and
         name != "load-displacement-incomplete.csv"]
check(named == [], "no file left under a result's name (the run did not "
      "finish, so the files it had written are removed): %s" % named)

subprocess.run([exe, "refused.prm"], cwd=work, capture_output=True)
left = sorted(os.listdir(os.path.join(work, "stopped")))
check(left == [], "the next (refused) run leaves an empty folder: %s" % left)
print("%d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
