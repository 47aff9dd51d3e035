#!/usr/bin/env bash
# The monopile in multi-surface (iwan) clay against the same scene in Tresca
# clay, side by side in one run (doc/cyclic-loading.md section 5):
#   1. pushed to 0.1 D monotonically (prm/monopile-clay-iwan.prm and its
#      Tresca twin), and to 0.01 D in 20 steps for the PISA p-v curves of
#      both as a figure;
#   2. 10 cycles of mudline displacement at 0.001 D and at 0.005 D (4 steps
#      a segment), secant stiffness and damping ratio of the first and the
#      last cycle, and the loops of the iwan clay as a figure.
#   bash benchmarks/cyclic-monopile/run.sh [build/fourier-ssi]
# Writes benchmarks/cyclic-monopile/results.md, doc/figures/
# monopile-iwan-loops.png and doc/figures/monopile-iwan-pisa.png.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
exe="$(realpath "${1:-$root/build/fourier-ssi}")"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
iwan="$root/prm/monopile-clay-iwan.prm"
# The Tresca twin: the same G (60 MPa) and s_u.
sed -e 's/set Laws = 0: iwan, su=100, gref=0.003, surfaces=20/set Laws = 0: tresca, su=100/' \
    "$iwan" > tresca.prm
cp "$iwan" iwan.prm
variant() { # law amplitude: the cyclic variant of law.prm
  sed -e "s/  set Target             = 0.9/  set Targets            = $2, -$2\n  set Cycles             = 10/" \
      -e 's/set Load steps         = 10/set Load steps         = 4/' \
      -e "s#output/monopile-clay-iwan#$1-$2#" \
      -e '/Soil reaction/d' -e '/Capacity normalisation/d' "$1.prm" > "$1-$2.prm"
}
run() { # name: the run and its wall time and peak memory
  /usr/bin/time -f "%e %M" -o "time-$1" "$exe" "$1.prm" > "log-$1" 2>&1 ||
    { echo "$1 failed:"; tail -3 "log-$1"; exit 1; }
}
for law in iwan tresca; do
  sed "s#output/monopile-clay-iwan#$law-monotonic#" "$law.prm" > "$law-monotonic.prm"
  run "$law-monotonic"
  # The PISA curves at small displacement: 20 steps to 0.01 D.
  sed -e "s#output/monopile-clay-iwan#$law-curves#" \
      -e 's/  set Target             = 0.9/  set Target             = 0.09/' \
      -e 's/set Load steps         = 10/set Load steps         = 20/' \
      "$law.prm" > "$law-curves.prm"
  run "$law-curves"
  for a in 0.009 0.045; do variant "$law" "$a"; run "$law-$a"; done
done
/usr/bin/python3 - "$here/results.md" "$root/doc/figures/monopile-iwan-pisa.png" <<'PY'
import csv, sys, datetime, os
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
out, figure = sys.argv[1:3]

def cost(name):
    t, m = open("time-" + name).read().split()
    steps = list(csv.DictReader(open(name + "/load-displacement.csv")))
    its = [int(s["iterations"]) for s in steps]
    return float(t), float(m) / 1e6, len(steps), min(its), max(its)

lines = ["# The monopile in iwan clay against Tresca (%s, %d cores)" %
         (datetime.date.today(), os.cpu_count()), "",
         "Script: benchmarks/cyclic-monopile/run.sh, every run side by side in",
         "one invocation. prm/monopile-clay-iwan.prm (G0 = 60 MPa, s_u = 100 kPa,",
         "gamma_ref = 0.003, 20 surfaces) and its Tresca twin (same G, s_u); D = 9 m.",
         "Wall time and peak memory of each whole run.", "",
         "## Monotonic to 0.1 D (10 steps)", "",
         "| law | H at 0.1 D [kN] | steps | Newton updates per step | wall time [s] | peak memory [GB] |",
         "|---|---|---|---|---|---|"]
for law in ("iwan", "tresca"):
    rows = list(csv.DictReader(open(law + "-monotonic/load-displacement.csv")))
    t, m, n, lo, hi = cost(law + "-monotonic")
    lines.append("| %s | %.0f | %d | %d–%d | %.1f | %.2f |" %
                 (law, float(rows[-1]["H_kN"]), n, lo, hi, t, m))
lines += ["", "## 10 cycles (4 steps a segment, 84 steps)", "",
          "| law | amplitude | secant stiffness, cycle 1 / 10 [kN/m] | damping ratio, cycle 1 / 10 | u at zero load, cycle 10 [m] | Newton updates per step | wall time [s] | peak memory [GB] |",
          "|---|---|---|---|---|---|---|---|"]
for law in ("iwan", "tresca"):
    for a in ("0.009", "0.045"):
        c = list(csv.DictReader(open("%s-%s/load-cycles.csv" % (law, a))))
        t, m, n, lo, hi = cost("%s-%s" % (law, a))
        z = c[-1]["zero_load_horizontal_m"]
        lines.append("| %s | %s m (%.3f D) | %.4g / %.4g | %.4f ± %.4f / %.4f | %s | %d–%d | %.1f | %.2f |" % (
            law, a, float(a) / 9., float(c[0]["secant_stiffness_kN_per_m"]),
            float(c[-1]["secant_stiffness_kN_per_m"]),
            float(c[0]["damping_ratio"]), float(c[0]["damping_ratio_error"]),
            float(c[-1]["damping_ratio"]), ("%.3g" % float(z)) if z else "–",
            lo, hi, t, m))
open(out, "w").write("\n".join(lines) + "\n")
print("\n".join(lines))

# The PISA p-v curves of both laws at three depths, dimensional (the
# normalisation divides by each run's G).
fig, ax = plt.subplots(figsize=(7, 4.5))
for law, style in (("iwan", "-"), ("tresca", "--")):
    rows = list(csv.DictReader(open(law + "-curves/soil-reaction-curves.csv")))
    for depth, colour in (("4.5", "C0"), ("9", "C1"), ("18", "C2")):
        pts = [(float(r["v [m]"]), float(r["p [kN/m]"])) for r in rows
               if abs(float(r["depth [m]"]) - float(depth)) < 1e-9]
        if not pts:
            continue
        pts = [(0., 0.)] + pts
        ax.plot([p[0] for p in pts], [p[1] for p in pts], style, color=colour,
                marker="o", ms=2, label="%s, %s m" % (law, depth))
ax.set_xlabel("v [m]")
ax.set_ylabel("p [kN/m]")
ax.grid(alpha=0.3)
ax.legend(fontsize=7)
ax.set_title("PISA p-v curves of the monopile to 0.01 D (20 steps): iwan "
             "(G0 = 60 MPa) against Tresca (G = 60 MPa)", fontsize=9)
fig.tight_layout()
fig.savefig(figure, dpi=130)
PY
/usr/bin/python3 "$root/tools/plot_cycles.py" iwan-0.009 iwan-0.045 \
  --label "iwan, u = 0.001 D" --label "iwan, u = 0.005 D" \
  -o "$root/doc/figures/monopile-iwan-loops.png"
