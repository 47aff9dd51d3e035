#!/usr/bin/python3
"""Output/Write vtu on coupled runs writes the last converged step per
harmonic, as the log says (doc/output-files.md).

Coulomb interface (the disc of tests/prm/nonconverging_coulomb_step.prm,
displacement control, the foundation pushed horizontally by the Target
delta = 1e-3 m at the reference elevation z = 0, two steps): a rigid
translation delta in x is u_r = delta cos(theta), u_theta = -delta
sin(theta), so on the foundation's nodes at z = 0 the n = 1 amplitudes are
U = delta and W = -delta exactly, and the n = 0 and n = 2 amplitudes are
zero; the stress amplitudes are written and not zero in the soil.
Plastic soil (prm/footing-capacity.prm, two steps to Target w = -0.01 m):
on the footing's contact nodes (z = 0, r < 1) the n = 0 axial amplitude is
w; no stress field is written (C eps(u) is not the stress of plastic soil)
and the log says so.
Tolerance 1e-6 relative: the VTU stores Float32 (about 6e-8).
Usage: coupled_vtu_output.py FOURIER_SSI_EXE SOURCE_DIR WORK_DIR
"""
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtu_reader import data_arrays  # noqa: E402

exe, source_dir, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
passed = failed = 0


def check(ok, what):
    global passed, failed
    print(("  ok   " if ok else "  FAIL ") + what)
    passed += ok
    failed += not ok


def run(name, scene, extra):
    text = open(os.path.join(source_dir, scene)).read() + extra
    open(os.path.join(work, name + ".prm"), "w").write(text)
    result = subprocess.run([exe, name + ".prm"], cwd=work,
                            capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(name + " failed: " + result.stderr)
    return result.stdout


def nodes_at(arrays, z, r_max):
    """Indices of the VTU points at elevation z with 0 < r < r_max."""
    points = arrays["Points"][1]
    return [i for i in range(len(points) // 3)
            if abs(points[3 * i + 1] - z) < 1e-12 and
            1e-12 < points[3 * i] < r_max * (1 - 1e-9)]


def relative_error(values, reference):
    return max(abs(v - reference) for v in values) / abs(reference)


# Coulomb interface.
delta = 1e-3
log = run("coulomb", "tests/prm/nonconverging_coulomb_step.prm", """
subsection Load path
  set Load steps = 2
  set Maximum iterations = 60
end
subsection Output
  set Directory = coulomb
  set Write vtu = true
end
""")
check("VTU per harmonic of the last converged step (displacement and stress "
      "amplitudes) written" in log, "coulomb: the log says what is written")
fields = {n: data_arrays(os.path.join(
    work, "coulomb", "solution-n%d-symmetric-cycle0.vtu" % n))
    for n in (0, 1, 2)}
on_foundation = nodes_at(fields[1], 0., 0.5)
check(len(on_foundation) >= 3,
      "coulomb: %d foundation nodes at z = 0" % len(on_foundation))
U = [fields[1]["U_radial"][1][i] for i in on_foundation]
W = [fields[1]["W_circumferential"][1][i] for i in on_foundation]
error = relative_error(U, delta)
check(error < 1e-6, "coulomb: n = 1 U on the foundation = delta = %g: "
      "relative error %.2g (tol 1e-6)" % (delta, error))
error = relative_error(W, -delta)
check(error < 1e-6, "coulomb: n = 1 W on the foundation = -delta: "
      "relative error %.2g (tol 1e-6)" % error)
for n in (0, 2):
    largest = max(abs(fields[n]["U_radial"][1][i]) for i in on_foundation)
    check(largest <= 1e-6 * delta, "coulomb: n = %d U on the foundation "
          "%.2g <= 1e-6 delta" % (n, largest))
check("sigma_r" in fields[1] and
      max(abs(v) for v in fields[1]["sigma_r"][1]) > 0.,
      "coulomb: stress amplitudes written and not zero")

# Plastic soil.
w = -0.01
log = run("plastic", "prm/footing-capacity.prm", """
subsection Load path
  set Load steps = 2
  set Target = %g
end
subsection Output
  set Directory = plastic
  set Write vtu = true
end
""" % w)
check("stresses not written with plastic soil" in log and
      "(displacement amplitudes) written" in log,
      "plastic: the log says displacements only")
arrays = data_arrays(os.path.join(work, "plastic",
                                  "solution-n0-symmetric-cycle0.vtu"))
contact = nodes_at(arrays, 0., 1.)
V = [arrays["V_axial"][1][i] for i in contact]
error = relative_error(V, w)
check(len(contact) >= 3 and error < 1e-6,
      "plastic: n = 0 V on the %d contact nodes = w = %g: relative error "
      "%.2g (tol 1e-6)" % (len(contact), w, error))
check(not any(name.startswith("sigma") for name in arrays),
      "plastic: no stress field in the VTU")
print("%d passed, %d failed" % (passed, failed))
sys.exit(1 if failed else 0)
