#!/usr/bin/env bash
# One cycle of a monopile in multi-surface (iwan) clay at two mudline
# amplitudes, 0.001 D and 0.005 D (doc/cyclic-loading.md section 5): the
# secant stiffness, the damping ratio and the cost, side by side in one run,
# and the loops as doc/figures/monopile-iwan-loops.png.
#   bash benchmarks/cyclic-monopile/run.sh [build/fourier-ssi]
# Writes benchmarks/cyclic-monopile/results.md.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
exe="$(realpath "${1:-$root/build/fourier-ssi}")"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
# The shipped monopile (D = 9 m, L = 42 m, n <= 2, 12 theta samples) with
# its clay made iwan: G0 = 60 MPa, s_u = 100 kPa, gamma_ref = 0.003.
for a in 0.009 0.045; do
  sed -e 's/0: G=30000, nu=0.49/0: G=60000, nu=0.49/' \
      -e 's/set Laws = 0: tresca, su=100/set Laws = 0: iwan, su=100, gref=0.003, surfaces=20/' \
      -e "s/  set Target             = 0.9/  set Targets            = $a, -$a\n  set Cycles             = 1/" \
      -e 's/set Load steps         = 10/set Load steps         = 8/' \
      -e "s#output/monopile-clay-lateral#amplitude-$a#" \
      -e '/Soil reaction/d' -e '/Capacity normalisation/d' \
      "$root/prm/monopile-clay-lateral.prm" > "amplitude-$a.prm"
  /usr/bin/time -f "%e %M" -o "time-$a" "$exe" "amplitude-$a.prm" > "log-$a" 2>&1
done
{
  echo "# One cycle of the monopile in iwan clay ($(date -u +%Y-%m-%d), $(nproc) cores)"
  echo
  echo "Script: benchmarks/cyclic-monopile/run.sh. Secant stiffness and damping ratio"
  echo "from load-cycles.csv (the ratio's bar: the steps' error, doc/cyclic-loading.md §3);"
  echo "wall time and peak memory of the whole run (24 steps)."
  echo
  echo "| amplitude | u/D | H at reversal [kN] | secant stiffness [kN/m] | damping ratio | zero-load u [m] | Newton updates per step | wall time [s] | peak memory [GB] |"
  echo "|---|---|---|---|---|---|---|---|---|"
  for a in 0.009 0.045; do
    /usr/bin/python3 - "$a" <<'PY'
import csv, sys
a = sys.argv[1]
c = list(csv.DictReader(open("amplitude-%s/load-cycles.csv" % a)))[0]
steps = list(csv.DictReader(open("amplitude-%s/load-displacement.csv" % a)))
its = [int(s["iterations"]) for s in steps]
t, m = open("time-" + a).read().split()
print("| %s m | %.3f | %.0f | %.4g | %.4f ± %.4f | %.3g | %d–%d | %.1f | %.2f |" % (
    a, float(a) / 9., float(c["reversal_H_kN"]),
    float(c["secant_stiffness_kN_per_m"]), float(c["damping_ratio"]),
    float(c["damping_ratio_error"]), float(c["zero_load_horizontal_m"]),
    min(its), max(its), float(t), float(m) / 1e6))
PY
  done
} > "$here/results.md"
/usr/bin/python3 "$root/tools/plot_cycles.py" amplitude-0.009 amplitude-0.045 \
  --label "u = 0.001 D" --label "u = 0.005 D" \
  -o "$root/doc/figures/monopile-iwan-loops.png"
cat "$here/results.md"
