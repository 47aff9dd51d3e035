#!/usr/bin/python3
"""A run stopped by SIGTERM leaves no file under a result's name
(doc/output-files.md, the temporary-name rule), for each kind of writer:

  interface state  prm/pile-lateral-slip.prm writes a 4 MB
                   interface-state.csv; stopped the moment it appears,
                   under its own name or under the temporary name
                   `.interface-state.csv.partial` (writing it takes tens of
                   ms), so the signal arrives while it is written or just
                   after;
  stiffness        prm/surface-disc-stiffness.prm on a coarse mesh, one
                   mesh, stopped once foundation-stiffness-subdyn.txt (the
                   second of the two 6x6 files) appears, while the revolved
                   3D VTU is still to come;
  soil reaction    prm/pile-free-head.prm on a coarse mesh, two steps,
                   with Soil reaction depths, stopped once
                   soil-reaction-curves.csv appears (load-displacement.csv
                   written before it), while the VTU and plastic-field
                   files are still to come;
  vtu              prm/default.prm on its coarse mesh with Write vtu,
                   stopped once the first per-harmonic solution-n*.vtu
                   appears, while the other harmonic and the revolved 3D
                   VTU are still to come.

The scenes are shrunk by appended entries so that each run takes about a
second; the folder is polled every 0.2 ms, and each file of the last three
cases is followed by at least 0.4 s of work (measured), so the signal
arrives while the run still writes. For each case:
(1) the run ended by SIGTERM;
(2) no file is left under a result's name: the files the run had already
    written whole (listed as they were when the signal was sent) are
    removed by its signal handler, since without results.csv they are a
    run that did not finish (load-displacement-incomplete.csv, named for
    what it is, may stay: sigterm_keeps_incomplete_curve.py);
(3) the next run into the folder, even one whose input is refused, removes
    the temporary file the stopped run left.
Usage: sigterm_leaves_no_partial_result.py FOURIER_SSI_EXE SOURCE_DIR WORK_DIR
"""
import fnmatch
import os
import shutil
import signal
import subprocess
import sys
import time

exe, source_dir, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
environment = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
passed = failed = 0

# (name, bundled scene, entries appended, the file names whose appearance
# triggers the signal, the result files that must exist whole by then)
CASES = [
    ("interface-state", "prm/pile-lateral-slip.prm", "",
     ["interface-state.csv", ".interface-state.csv.partial"], []),
    ("stiffness", "prm/surface-disc-stiffness.prm", """
subsection Discretization
  set Target accuracy   =
  set Refinement cycles = 1
end
subsection Mesh
  set R cells = 2, 8
  set Z cells = 8
end
subsection Output
  set Write 3D vtu    = true
  set Theta divisions = 360
end
""", ["foundation-stiffness-subdyn.txt"],
     ["foundation-stiffness.csv", "foundation-stiffness-subdyn.txt"]),
    ("soil-reaction", "prm/pile-free-head.prm", """
subsection Discretization
  set Harmonics = 0, 1
end
subsection Mesh
  set R cells  = 1, 6
  set R growth = 1, 1.5
  set Z cells  = 1, 4
end
subsection Load path
  set Theta samples = 8
  set Load steps    = 2
  set Target        = 0.02
end
subsection Output
  set Write vtu            = true
  set Plastic field 3D     = true
  set Theta divisions      = 360
  set Soil reaction depths = 2, 8
end
""", ["soil-reaction-curves.csv"],
     ["load-displacement.csv", "soil-reaction-curves.csv"]),
    ("vtu", "prm/default.prm", """
subsection Mesh
  set Global refinements = 0
end
subsection Output
  set Write vtu    = true
  set Write 3D vtu = true
end
""", ["solution-n*-cycle0.vtu"], ["solution-n*-cycle0.vtu"]),
]


def check(ok, what):
    global passed, failed
    print(("  ok   " if ok else "  FAIL ") + what)
    passed += ok
    failed += not ok


def write_prm(name, scene, appended, folder, extra=""):
    text = open(os.path.join(source_dir, scene)).read() + appended
    open(os.path.join(work, name), "w").write(
        text + "\nsubsection Output\n  set Directory = %s\nend\n%s"
        % (folder, extra))


def matching(folder, patterns):
    try:
        names = os.listdir(folder)
    except FileNotFoundError:
        return []
    return [n for n in names if any(fnmatch.fnmatch(n, p) for p in patterns)]


for name, scene, appended, watched, whole in CASES:
    print("%s (%s):" % (name, scene))
    folder = "stopped-" + name
    path = os.path.join(work, folder)
    write_prm(folder + ".prm", scene, appended, folder)
    write_prm("refused-" + name + ".prm", scene, appended, folder,
              "subsection Output\n  set Frobnicate = 1\nend\n")
    run = subprocess.Popen([exe, folder + ".prm"], cwd=work, env=environment,
                           stdout=subprocess.DEVNULL,
                           stderr=subprocess.DEVNULL)
    while run.poll() is None and not matching(path, watched):
        time.sleep(0.0002)
    before = sorted(os.listdir(path)) if os.path.isdir(path) else []
    if run.poll() is None:
        run.send_signal(signal.SIGTERM)
    run.wait()
    check(run.returncode == -signal.SIGTERM,
          "the run ended by SIGTERM (exit status %d)" % run.returncode)
    # Without the whole files there, (2) would not test their removal.
    if whole:
        check(all(fnmatch.filter(before, p) for p in whole),
              "when the signal was sent the folder held %s (expected %s "
              "whole)" % (before, whole))
    else:
        print("  when the signal was sent the folder held %s" % before)
    left = sorted(os.listdir(path)) if os.path.isdir(path) else []
    print("  left in the folder: %s" % left)
    named = [n for n in left if not n.startswith(".") and
             n != "load-displacement-incomplete.csv"]
    check(named == [], "no file left under a result's name (the run did not "
          "finish, so the files it had written are removed): %s" % named)
    subprocess.run([exe, "refused-" + name + ".prm"], cwd=work,
                   capture_output=True)
    left = sorted(os.listdir(path)) if os.path.isdir(path) else []
    check(left == [], "the next (refused) run leaves an empty folder: %s"
          % left)
print("%d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
