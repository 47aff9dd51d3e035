#!/usr/bin/python3
"""Load path/Stiffness = auto (the default) on interface-only scenes: Newton
for a contact interface or a stiff coulomb penalty, the initial stiffness
below max(kn, ks) l / G = 5e3, and theta samples that follow the law, not
the solver (doc/nonlinear-interfaces.md section 5b). Scenes: the disc in a
ring (prm/disc-gap.prm: r0 = 0.5 m, l = 1 m, G = 38462 kPa).
Checks:
(1) disc-gap as shipped (kn l / G = 26): the run prints "initial
    stiffness" for auto; with Stiffness = tangent it prints Newton, and the
    two give the same end load H to 1e-8 relative (both solve the same
    discrete problem, 36 samples, to |R| <= 1e-10 |lambda F|; before the
    samples followed the law they were 4.2e-4 apart);
(2) the disc with n <= 32 and a tensionless Coulomb shaft (phi = 16.7 deg,
    mu = 0.3) at kappa = kn r0 / G = 1e6, every Load path entry at its
    default: it prints Newton, converges every step in at most 15 updates,
    and its end load lies within 3 / kappa of the exact-contact run's (the
    penalty's compliance error, about 1.2 / kappa by the log's estimate;
    measured 1.2e-6);
(3) the same disc with `contact` and the defaults: Newton, at most 15
    updates per step.
Usage: interface_linearisation_choice.py FOURIER_SSI_EXE SOURCE_DIR WORK_DIR
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

G = 1e5 / (2 * 1.3)  # kPa, E = 1e5, nu = 0.3
R0 = 0.5  # m
HARMONICS = ", ".join(str(n) for n in range(33))


def check(ok, what):
    global failed
    print(("PASS " if ok else "FAIL ") + what)
    if not ok:
        failed += 1


def run(name, appended):
    """The disc in a ring with `appended` overrides; (log, end H, steps)."""
    with open(os.path.join(source_dir, "prm", "disc-gap.prm")) as f:
        text = f.read()
    text += "subsection Output\n  set Directory = out-%s\nend\n" % name
    text += appended
    path = os.path.join(work, name + ".prm")
    with open(path, "w") as f:
        f.write(text)
    result = subprocess.run([exe, path], cwd=work, capture_output=True,
                            text=True)
    log = result.stdout + result.stderr
    check(result.returncode == 0, name + ": exits 0")
    with open(os.path.join(work, "out-" + name,
                           "load-displacement.csv")) as f:
        rows = list(csv.DictReader(f))
    return log, float(rows[-1]["H_kN"]), rows


def choice(log):
    match = re.search(r"^interface linearisation: (.*)$", log, re.M)
    return match.group(1) if match else ""


def disc_n32(law):
    return ("subsection Discretization\n  set Harmonics = %s\nend\n"
            "subsection Interfaces\n  set Interfaces = 5: %s\nend\n"
            % (HARMONICS, law))


# (1) The shipped disc-gap: auto is the initial stiffness, and Newton on
# the same samples gives the same answer.
log_auto, H_auto, _ = run("disc-gap-auto", "")
log_newton, H_newton, _ = run(
    "disc-gap-tangent", "subsection Load path\n  set Stiffness = tangent\nend\n")
check(choice(log_auto).startswith("initial stiffness, theta samples 4 "
                                  "(n_max + 1)"),
      "disc-gap, auto: prints the initial stiffness (" + choice(log_auto) +
      ")")
check(choice(log_newton).startswith("tangent (Newton), theta samples 4 "
                                    "(n_max + 1)") and
      "as set" in choice(log_newton),
      "disc-gap, Stiffness = tangent: prints Newton as set (" +
      choice(log_newton) + ")")
difference = abs(H_newton - H_auto) / abs(H_auto)
check(difference <= 1e-8,
      "disc-gap: end load H, Newton against the default: %.3e relative "
      "(%.10g against %.10g kN; bound 1e-8)" % (difference, H_newton, H_auto))

# (2), (3) The stiff penalty and exact contact, n <= 32, defaults.
kappa = 1e6
kn = kappa * G / R0
log_stiff, H_stiff, rows_stiff = run(
    "stiff", disc_n32("coulomb, kn=%.17g, ks=%.17g, c=0, phi=16.7, sigma_t=0"
                      % (kn, kn)))
log_contact, H_contact, rows_contact = run(
    "contact", disc_n32("contact, c=0, phi=16.7"))
for name, log, rows in (("kappa = 1e6", log_stiff, rows_stiff),
                        ("contact", log_contact, rows_contact)):
    check(choice(log).startswith("tangent (Newton), theta samples 2 n_max + 1")
          and "Load path/Stiffness = auto" in choice(log),
          name + ", auto: prints Newton on 2 n_max + 1 samples (" +
          choice(log) + ")")
    updates = [int(r["iterations"]) for r in rows]
    check(len(rows) == 4 and all(r["converged"] == "1" for r in rows),
          name + ": all 4 steps converge")
    check(max(updates) <= 15,
          name + ": Newton updates per step %s (at most 15)" % updates)
difference = abs(H_stiff - H_contact) / abs(H_contact)
check(difference <= 3 / kappa,
      "kappa = 1e6 against exact contact: end load %.3e relative (bound 3 / "
      "kappa = %.1e)" % (difference, 3 / kappa))

sys.exit(1 if failed else 0)
