#!/usr/bin/python3
"""A linear stiffness run says of a harmonic whose scene load is zero what
happens to it: its own solution is zero and not solved, while its
stiffness terms (the unit-load solves) are computed. The log must not read
as if the harmonic were skipped just before its K_ line.

prm/surface-disc-stiffness.prm (no load of its own: every harmonic's scene
load is zero) on a coarse mesh, one mesh, run three ways:
  serial       the serial solvers;
  distributed  Linear solver/Distributed = always (the Trilinos path on
               one rank, whose solve has its own zero-load shortcut);
  loaded       serial with a vertical force of -1 kN, so n = 0 symmetric
               has a scene load and is solved.
For each run:
(1) it exits 0;
(2) each harmonic's line (`cycle 0, n=...`) is followed by its stiffness
    line, K_V (n = 0 symmetric), K_T (n = 0 antisymmetric), K_H (n = 1
    symmetric): right after it where the scene load is zero (no
    reactions to report), below its reactions otherwise;
(3) the harmonic's line says "(scene load zero: its solution is 0, not
    solved)" exactly where its scene load is zero (loaded: not for n = 0
    symmetric);
(4) no line saying "skipped" comes just before a line with a K_ term.
Usage: zero_scene_load_log.py FOURIER_SSI_EXE SOURCE_DIR WORK_DIR
"""
import os
import re
import shutil
import subprocess
import sys

exe, source_dir, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
environment = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
failed = 0
SHRUNK = """
subsection Discretization
  set Target accuracy   =
  set Refinement cycles = 1
end
subsection Mesh
  set R cells = 2, 8
  set Z cells = 8
end
subsection Output
  set Directory = out
end
"""
RUNS = {
    "serial": ("", set()),
    "distributed": ("subsection Linear solver\n  set Distributed = always\n"
                    "end\n", set()),
    "loaded": ("subsection Rigid foundation\n  set Vertical force = -1\n"
               "end\n", {"n=0 symmetric"}),
}
STIFFNESS = {"n=0 symmetric": "K_V = ", "n=0 antisymmetric": "K_T = ",
             "n=1 symmetric": "K_H = "}
ZERO_LOAD = "(scene load zero: its solution is 0, not solved)"


def check(what, ok):
    global failed
    print(("  ok   " if ok else "  FAIL ") + what)
    failed += 0 if ok else 1


scene = open(os.path.join(source_dir, "prm/surface-disc-stiffness.prm")).read()
for name, (extra, loaded) in RUNS.items():
    folder = os.path.join(work, name)
    os.makedirs(folder)
    open(os.path.join(folder, "scene.prm"), "w").write(scene + SHRUNK + extra)
    run = subprocess.run([exe, "scene.prm"], cwd=folder, env=environment,
                         capture_output=True, text=True)
    print("%s:" % name)
    check("exits 0 (%s)" % run.stderr.strip()[-200:], run.returncode == 0)
    lines = run.stdout.splitlines()
    for harmonic, term in STIFFNESS.items():
        at = [i for i, line in enumerate(lines)
              if line.startswith("cycle 0, %s:" % harmonic)]
        if len(at) != 1:
            check("one log line for %s (found %d)" % (harmonic, len(at)),
                  False)
            continue
        line, zero = lines[at[0]], harmonic not in loaded
        block = []
        for following in lines[at[0] + 1:]:
            if following.startswith("cycle "):
                break
            block.append(following)
        # With a load its reactions come first; without, nothing to report.
        where = [i for i, b in enumerate(block) if term in b]
        check("%s: its stiffness line (%s...) %s"
              % (harmonic, term, "right after it" if zero else "below it"),
              where == [0] if zero else len(where) == 1)
        check("%s: %s the zero scene load: %s"
              % (harmonic, "says" if zero else "does not claim", line),
              (ZERO_LOAD in line) == zero)
    before_term = [lines[i - 1] for i in range(1, len(lines))
                   if re.search(r"\bK_", lines[i])]
    check("no 'skipped' line just before a K_ line (%d K_ lines)"
          % len(before_term),
          before_term and not any("skipped" in b for b in before_term))
print("%d failed" % failed)
sys.exit(1 if failed else 0)
