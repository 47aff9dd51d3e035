#!/usr/bin/python3
"""Turn benchmarks/harmonic_cost.csv into a markdown table with the ratio of
each harmonic's assembly and solve time to the vector-Laplace floor."""
import csv
import sys

rows = list(csv.DictReader(open(sys.argv[1])))
floor = {(r["degree"], r["cells"]): r for r in rows if r["kind"] == "laplace"}
print("| p | cells | DoFs | n | assembly [s] | solve [s] | peak RSS [MiB] "
      "| assembly / Laplace | solve / Laplace |")
print("|---|---|---|---|---|---|---|---|---|")
for r in rows:
    if r["kind"] != "harmonic":
        continue
    f = floor[(r["degree"], r["cells"])]
    print(f"| {r['degree']} | {r['cells']}x{r['cells']} | {r['dofs']} | {r['n']} "
          f"| {float(r['assembly_s']):.3f} | {float(r['solve_s']):.3f} "
          f"| {float(r['peak_rss_MiB']):.0f} "
          f"| {float(r['assembly_s']) / float(f['assembly_s']):.2f} "
          f"| {float(r['solve_s']) / float(f['solve_s']):.2f} |")
print()
print("Laplace floor rows (same element, mesh, DoFs, UMFPACK):")
print()
print("| p | cells | DoFs | assembly [s] | solve [s] | peak RSS [MiB] |")
print("|---|---|---|---|---|---|")
for f in floor.values():
    print(f"| {f['degree']} | {f['cells']}x{f['cells']} | {f['dofs']} "
          f"| {float(f['assembly_s']):.3f} | {float(f['solve_s']):.3f} "
          f"| {float(f['peak_rss_MiB']):.0f} |")
