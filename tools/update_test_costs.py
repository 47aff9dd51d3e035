#!/usr/bin/env python3
"""Write tests/test_costs.txt from a build's measured test times.

ctest runs the longest tests first when it knows their cost. A fresh clone
has no measured times (build/Testing/Temporary/CTestCostData.txt), so without
this table the long scene runs start in definition order, and the last of
them can run alone on one core at the end of the suite. The table is a
scheduling hint only: no test reads it.

    python3 tools/update_test_costs.py [build]      # after a full ctest run
"""
import pathlib
import sys

SHORTEST_LISTED_S = 10.0  # shorter tests cannot leave a tail worth ordering

root = pathlib.Path(__file__).resolve().parent.parent
build = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else root / "build"
measured = build / "Testing" / "Temporary" / "CTestCostData.txt"
rows = []
for line in measured.read_text().splitlines():
    fields = line.split()
    if line.startswith("---"):
        break  # the failed-tests section follows
    if len(fields) == 3 and float(fields[2]) >= SHORTEST_LISTED_S:
        rows.append((fields[0], float(fields[2])))
rows.sort(key=lambda row: -row[1])
with open(root / "tests" / "test_costs.txt", "w") as table:
    table.write("# test  seconds (written by tools/update_test_costs.py; "
                "ctest's scheduling hint for a fresh clone)\n")
    for name, seconds in rows:
        table.write(f"{name} {seconds:.0f}\n")
print(f"{len(rows)} tests of at least {SHORTEST_LISTED_S:g} s listed")
