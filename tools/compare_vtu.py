#!/usr/bin/python3
"""Compare two VTUs of the same output written two ways (e.g. before and after
a change of writer): corner by corner through each file's
connectivity, the point coordinates and every point field. Prints, per array,
the largest |after - before| over the array's largest magnitude, and the
largest difference in units of the float32 spacing of the value (DataOutBase
stores Float32 in deal.II 9.4).
Usage: compare_vtu.py BEFORE.vtu AFTER.vtu"""
import math
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                "..", "tests"))
from vtu_reader import data_arrays  # noqa: E402

before, after = data_arrays(sys.argv[1]), data_arrays(sys.argv[2])
cb, ca = before["connectivity"][1], after["connectivity"][1]
assert len(cb) == len(ca), "cell corners %d vs %d" % (len(cb), len(ca))
assert before["types"][1] == after["types"][1], "cell types differ"
print("%s: %d cells, %d corners, points before %d after %d" % (
    sys.argv[2], len(before["types"][1]), len(cb),
    len(before["Points"][1]) // 3, len(after["Points"][1]) // 3))
names = [n for n in before if n not in ("connectivity", "offsets", "types")]
assert sorted(names) == sorted(n for n in after if n not in
                               ("connectivity", "offsets", "types")), \
    "field names differ"
worst = 0.
for name in names:
    nc, vb = before[name]
    nca, va = after[name]
    assert nc == nca, name + ": components differ"
    scale = max(abs(v) for v in vb) or 1.
    diff = ulps = 0.
    for ib, ia in zip(cb, ca):
        for c in range(nc):
            x, y = vb[int(ib) * nc + c], va[int(ia) * nc + c]
            diff = max(diff, abs(x - y))
            spacing = math.ldexp(1., math.frexp(x)[1] - 24) if x else 1e-45
            ulps = max(ulps, abs(x - y) / spacing)
    worst = max(worst, diff / scale)
    print("  %-36s %d comp  max|diff|/max|value| = %.3g  (%.2f float32 "
          "spacings)" % (name, nc, diff / scale, ulps))
print("  worst relative difference %.3g" % worst)
