#!/usr/bin/python3
"""A stiffness scene writes the fields it computes: the unit-H and unit-M
solutions appear in the VTU of the stiffness harmonic (n = 1 symmetric), and
the unit-H field is the one whose foundation motion the log reports.

Check: the largest radial amplitude of the unit-H field over the footing's
nodes equals the printed U_h of the unit-H case (I_H * a / (G a^2) for H =
1, i.e. u = I_H H / (G a)); the rigid foundation translates and rotates, so
the maximum over the whole body is U_h + |Theta| * (largest lever arm), and
it must be at least U_h. We check the two exact consequences that do not
depend on the mesh: (1) the field exists with the three components and is
not zero; (2) on the footing's nodes at the reference elevation (r < a), where
the rigid motion is U = U_h + Theta (z - z_ref) = U_h, its radial amplitude
equals U_h = I_H H / (G a) (H = 1) from results.csv to 1e-6 relative (the
VTU stores Float32).
Usage: stiffness_vtu_fields.py FOURIER_SSI_EXE SOURCE_DIR WORK_DIR
"""
import base64
import csv
import os
import re
import shutil
import struct
import subprocess
import sys
import zlib

exe, source_dir, work = sys.argv[1:4]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
scene = open(os.path.join(source_dir, "prm/embedded-footing.prm")).read()
scene += """
subsection Discretization
  set Refinement cycles = 1
end
subsection Output
  set Directory = out
  set Write vtu = true
end
"""
open(os.path.join(work, "scene.prm"), "w").write(scene)
run = subprocess.run([exe, "scene.prm"], cwd=work, capture_output=True,
                     text=True)
if run.returncode != 0:
    sys.exit("run failed: " + run.stderr)


def data_arrays(path):
    """name -> (n_components, values) of the point data of a deal.II VTU
    (ascii, or base64 binary with or without zlib compression)."""
    text = open(path).read()
    header = re.search(r'<VTKFile[^>]*>', text).group(0)
    compressed = "vtkZLibDataCompressor" in header
    header_type = "Q" if 'header_type="UInt64"' in header else "I"
    size = struct.calcsize(header_type)
    arrays = {}
    for m in re.finditer(r'<DataArray([^>]*)>(.*?)</DataArray>', text, re.S):
        attributes, body = m.group(1), m.group(2).strip()
        name = re.search(r'Name="([^"]*)"', attributes)
        preceding = text[max(0, m.start() - 40):m.start()]
        if not name and "<Points>" not in preceding:
            continue
        components = re.search(r'NumberOfComponents="(\d+)"', attributes)
        n_components = int(components.group(1)) if components else 1
        kind = re.search(r'type="(\w+)"', attributes).group(1)
        fmt = {"Float32": "f", "Float64": "d", "Int32": "i", "UInt8": "B",
               "Int64": "q"}[kind]
        if 'format="ascii"' in attributes:
            values = [float(v) for v in body.split()]
        elif compressed:
            # Header (block count, block size, last size, compressed sizes)
            # base64-encoded on its own, then the concatenated blocks.
            n_header = 3
            first = base64.b64decode(body[:((n_header * size + 2) // 3) * 4])
            n_blocks = struct.unpack(header_type, first[:size])[0]
            header_length = ((( 3 + n_blocks) * size + 2) // 3) * 4
            head = base64.b64decode(body[:header_length])
            counts = struct.unpack(header_type * (3 + n_blocks), head)
            raw = base64.b64decode(body[header_length:])
            data, offset = b"", 0
            for c in counts[3:]:
                data += zlib.decompress(raw[offset:offset + c])
                offset += c
            values = list(struct.unpack("<%d%s" % (len(data) //
                                        struct.calcsize(fmt), fmt), data))
        else:
            raw = base64.b64decode(body)
            data = raw[size:]
            values = list(struct.unpack("<%d%s" % (len(data) //
                                        struct.calcsize(fmt), fmt), data))
        arrays[name.group(1) if name else "Points"] = (n_components, values)
    return arrays


vtu = os.path.join(work, "out", "solution-n1-symmetric-cycle0.vtu")
arrays = data_arrays(vtu)
failed = 0
for name in ("unit_H_U_radial", "unit_H_V_axial", "unit_H_W_circumferential",
             "unit_M_U_radial", "unit_M_V_axial", "unit_M_W_circumferential"):
    ok = name in arrays and max(abs(v) for v in arrays[name][1]) > 0.
    print(("  ok   " if ok else "  FAIL ") + name + " written and not zero")
    failed += not ok

rows = {r["quantity"]: float(r["value"])
        for r in csv.DictReader(open(os.path.join(work, "out", "results.csv")))
        if r["n"] == "1" and r["family"] == "symmetric"}
# The unit-H case: u_H = I_H * H / (G a) with H = 1 (thesis eq. 4.2).
parameters = dict(re.findall(r"set (Reference shear modulus|Reference length)"
                             r"\s*=\s*([0-9.eE+-]+)", scene))
G = float(parameters.get("Reference shear modulus", 1.))
a = float(parameters.get("Reference length", 1.))
u_h = rows["I_H"] / (G * a)
# Points: the VTU's node coordinates; the footing's nodes lie on the
# reference elevation z_ref at r <= a, where the unit-H field's radial
# amplitude is U = U_h + Theta (z - z_ref) = U_h exactly.
points = arrays["Points"][1] if "Points" in arrays else None
z_ref = float(re.search(r"set Reference elevation\s*=\s*([0-9.eE+-]+)",
                        scene).group(1)) if "Reference elevation" in scene \
    else 0.
U = arrays["unit_H_U_radial"][1]
at_reference = [U[i] for i in range(len(U))
                if abs(points[3 * i + 1] - z_ref) < 1e-12 and
                points[3 * i] < a * (1 - 1e-9) and points[3 * i] > 1e-12]
error = max(abs(v - u_h) for v in at_reference) / abs(u_h) \
    if at_reference else float("inf")
ok = error < 1e-6
print(("  ok   " if ok else "  FAIL ") +
      "unit-H radial amplitude on the footing at z_ref = %g vs U_h = I_H/(G a)"
      " = %.10g: relative error %.3g over %d nodes (tol 1e-6: the VTU stores Float32)"
      % (z_ref, u_h, error, len(at_reference)))
failed += not ok
print("%d passed, %d failed" % (7 - failed, failed))
sys.exit(1 if failed else 0)
