#!/usr/bin/python3
"""A long stage of a coupled load path says how long it will take
(doc/input-checks.md, "Long stages of a load path"): after the stage's
first converged step, if that step's time times the steps still to come
exceeds 60 s, the log prints
    estimated: about N s for the remaining M steps of this stage, at this
    step's T s each

prm/pile-free-head.prm (plastic clay) with 64 theta samples, run twice with
the same elastic first step (1e-5 m) and stopped by SIGTERM once step 2 is
printed (the estimate comes after step 1, so nothing later matters):
  long   Load steps = 10000 to the scene's 0.1 m: step 1 took 0.13-0.5 s
         on the shared 2-core machine, so the estimate is about 1300-5000
         s, 20 times the 60 s bound or more: only a machine 20 times
         faster per step would not print it;
  short  Load steps = 10 to 1e-4 m: about 1.1-4.5 s still to come, 1/13 of
         the bound or less: only a machine 13 times slower would print it.
(The bound has no entry or hook to lower it, hence the step counts.)
Checks:
(1) long: exactly one estimate line, between step 1 and step 2, with
    M = 9999 (the steps after the first), T the step 1 line's time to 3
    significant digits, and N = M T to within their rounding (lround: 0.5 s;
    T's 3 digits: 0.5 % of it);
(2) short: no estimate line.
Usage: long_stage_estimate.py FOURIER_SSI_EXE SOURCE_DIR WORK_DIR
"""
import os
import re
import shutil
import signal
import subprocess
import sys

exe, source_dir, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
environment = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
scene = open(os.path.join(source_dir, "prm/pile-free-head.prm")).read()
failed = 0
ESTIMATE = re.compile(r"^  estimated: about (\d+) s for the remaining (\d+) "
                      r"steps of this stage, at this step's (\S+) s each$")
STEP = re.compile(r"^  step (\d+): .*; ([0-9.e+-]+) s$")


def check(what, ok):
    global failed
    print(("  ok   " if ok else "  FAIL ") + what)
    failed += 0 if ok else 1


def first_steps(name, load_steps, target):
    """The log lines up to step 2 of the scene with `load_steps` steps to
    the motion `target`."""
    open(os.path.join(work, name + ".prm"), "w").write(
        scene + "\nsubsection Load path\n  set Load steps = %d\n"
        "  set Target = %g\n  set Theta samples = 64\nend\n"
        "subsection Output\n  set Directory = %s\n  set Write vtu = false\n"
        "end\n" % (load_steps, target, name))
    run = subprocess.Popen([exe, name + ".prm"], cwd=work, env=environment,
                           stdout=subprocess.PIPE,
                           stderr=subprocess.DEVNULL, text=True)
    lines = []
    for line in run.stdout:
        lines.append(line.rstrip("\n"))
        if line.startswith("  step 2:"):
            break
    run.send_signal(signal.SIGTERM)
    run.communicate()
    return lines


lines = first_steps("long", 10000, 0.1)
estimates = [i for i, line in enumerate(lines) if "estimated:" in line]
steps = {int(m.group(1)): (i, float(m.group(2)))
         for i, m in ((i, STEP.match(line)) for i, line in enumerate(lines))
         if m}
if len(estimates) != 1 or sorted(steps) != [1, 2]:
    check("long: one estimate line (%d) and the lines of steps 1 and 2 (%s)"
          % (len(estimates), sorted(steps)), False)
else:
    line = lines[estimates[0]]
    match = ESTIMATE.match(line)
    print("  " + line.strip())
    check("long: the estimate comes between step 1 and step 2",
          steps[1][0] < estimates[0] < steps[2][0])
    if not match:
        check("long: the estimate line reads as documented", False)
    else:
        total, remaining, each = int(match.group(1)), int(match.group(2)), \
            float(match.group(3))
        step_time = steps[1][1]
        check("long: %d remaining steps = 10000 - 1" % remaining,
              remaining == 9999)
        check("long: %g s each = step 1's %g s to 3 digits"
              % (each, step_time), each == float("%.3g" % step_time))
        check("long: about %d s = %d x %g s (to 0.5 s + 0.5 %%)"
              % (total, remaining, each),
              abs(total - remaining * each) <= 0.5 + 0.005 * remaining * each)
        check("long: %d s is above the 60 s bound" % total, total > 60)

lines = first_steps("short", 10, 1e-4)
check("short: steps 1 and 2 printed, no estimate line (%d lines)"
      % len(lines),
      any(line.startswith("  step 2:") for line in lines) and
      not any("estimated:" in line for line in lines))
print("%d failed" % failed)
sys.exit(1 if failed else 0)
