#!/usr/bin/env bash
# Cost of one harmonic (assembly, solve, peak memory) vs DoFs for p = 2, 4 and
# n = 0, 1, 2, next to the floor: a vector Laplace problem with the same
# element, mesh, DoFs and solver. Writes benchmarks/harmonic_cost.csv and the
# markdown table benchmarks/harmonic_cost.md.
# Usage: benchmarks/run.sh [BUILD_DIR]   (default: build)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../build}
exe=$build/benchmarks/benchmark_harmonic_cost
csv=$here/harmonic_cost.csv
echo "kind,degree,n,cells,dofs,setup_s,assembly_s,solve_s,peak_rss_MiB" > "$csv"
for degree in 2 4; do
  if [ $degree = 2 ]; then sizes="32 64 128"; else sizes="16 32 64"; fi
  for cells in $sizes; do
    for n in 0 1 2; do
      "$exe" harmonic $degree $n $cells >> "$csv"
    done
    "$exe" laplace $degree 0 $cells >> "$csv"
  done
done
/usr/bin/python3 "$here/table.py" "$csv" > "$here/harmonic_cost.md"
cat "$here/harmonic_cost.md"
