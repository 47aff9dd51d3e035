#!/usr/bin/env bash
# The monopile in a multi-surface soil against the same scene in its
# perfectly plastic twin, side by side in one run (doc/cyclic-loading.md
# section 5): clay, the iwan clay of prm/monopile-clay-iwan.prm against
# Tresca; sand, the iwan-sand of prm/monopile-sand-iwan.prm against
# Mohr-Coulomb (doc/soil-plasticity.md section 11):
#   1. pushed to 0.1 D monotonically, and to 0.01 D in 20 steps for the
#      PISA p-v curves of both as a figure;
#   2. 10 cycles of mudline displacement at 0.001 D and at 0.005 D (4 steps
#      a segment), secant stiffness and damping ratio of the first and the
#      last cycle, and the loops of the multi-surface soil as a figure.
#   bash benchmarks/cyclic-monopile/run.sh [build/fourier-ssi] [clay|sand]
# Writes benchmarks/cyclic-monopile/results.md (clay) or results-sand.md,
# and doc/figures/monopile-iwan-{loops,pisa}.png (clay) or
# monopile-sand-iwan-{loops,pisa}.png.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
exe="$(realpath "${1:-$root/build/fourier-ssi}")"
site="${2:-clay}"
case "$site" in
  clay) scene=monopile-clay-iwan twin=tresca results=results.md
        figures=monopile-iwan label=iwan
        law='iwan, su=100, gref=0.003, surfaces=20' twin_law='tresca, su=100'
        about='prm/monopile-clay-iwan.prm (G0 = 60 MPa, s_u = 100 kPa, gamma_ref = 0.003, 20 surfaces) and its Tresca twin (same G, s_u)' ;;
  sand) scene=monopile-sand-iwan twin=mohr-coulomb results=results-sand.md
        figures=monopile-sand-iwan label=iwan-sand
        law='iwan-sand, c=2, phi=35, psi=0, rf=0.9, surfaces=10'
        twin_law='mohr-coulomb, c=2, phi=35, psi=0'
        about='prm/monopile-sand-iwan.prm (G0 = 60 MPa (z/10 m)^0.5, phi = 35, c = 2 kPa, R_f = 0.9, 10 surfaces) and its Mohr-Coulomb twin (same G0, c, phi)' ;;
  *) echo "run.sh: site '$site' is neither clay nor sand" >&2; exit 1 ;;
esac
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
iwan="$root/prm/$scene.prm"
grep -q "set Laws = 0: $law\$" "$iwan" ||
  { echo "run.sh: $iwan does not have 'Laws = 0: $law'" >&2; exit 1; }
# The perfectly plastic twin: the same G and strength.
sed -e "s/set Laws = 0: $law/set Laws = 0: $twin_law/" "$iwan" > "$twin.prm"
cp "$iwan" iwan.prm
variant() { # law amplitude: the cyclic variant of law.prm
  sed -e "s/  set Target             = 0.9/  set Targets            = $2, -$2\n  set Cycles             = 10/" \
      -e 's/set Load steps         = 10/set Load steps         = 4/' \
      -e "s#output/$scene#$1-$2#" \
      -e '/Soil reaction/d' -e '/Capacity normalisation/d' "$1.prm" > "$1-$2.prm"
}
run() { # name: the run and its wall time and peak memory
  /usr/bin/time -f "%e %M" -o "time-$1" "$exe" "$1.prm" > "log-$1" 2>&1 ||
    { echo "$1 failed:"; tail -3 "log-$1"; exit 1; }
}
for law in iwan "$twin"; do
  sed "s#output/$scene#$law-monotonic#" "$law.prm" > "$law-monotonic.prm"
  run "$law-monotonic"
  # The PISA curves at small displacement: 20 steps to 0.01 D.
  sed -e "s#output/$scene#$law-curves#" \
      -e 's/  set Target             = 0.9/  set Target             = 0.09/' \
      -e 's/set Load steps         = 10/set Load steps         = 20/' \
      "$law.prm" > "$law-curves.prm"
  run "$law-curves"
  for a in 0.009 0.045; do variant "$law" "$a"; run "$law-$a"; done
done
/usr/bin/python3 - "$here/$results" "$root/doc/figures/$figures-pisa.png" "$twin" "$site" "$about" <<'PY'
import csv, sys, datetime, os
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
out, figure, twin, site, about = sys.argv[1:6]
soil = {"clay": "iwan clay", "sand": "iwan-sand"}[site]


def name(law):
    """The law as the table names it: the runs' files say iwan."""
    return {"clay": "iwan", "sand": "iwan-sand"}[site] if law == "iwan" else law

def cost(name):
    t, m = open("time-" + name).read().split()
    steps = list(csv.DictReader(open(name + "/load-displacement.csv")))
    its = [int(s["iterations"]) for s in steps]
    return float(t), float(m) / 1e6, len(steps), min(its), max(its)

lines = ["# The monopile in %s against %s (%s, %d cores)" %
         (soil, twin, datetime.date.today(), os.cpu_count()), "",
         "Script: benchmarks/cyclic-monopile/run.sh (site %s), every run side by" % site,
         "side in one invocation. %s; D = 9 m." % about,
         "Wall time and peak memory of each whole run.", "",
         "## Monotonic to 0.1 D (10 steps)", "",
         "| law | H at 0.1 D [kN] | steps | Newton updates per step | wall time [s] | peak memory [GB] |",
         "|---|---|---|---|---|---|"]
for law in ("iwan", twin):
    rows = list(csv.DictReader(open(law + "-monotonic/load-displacement.csv")))
    t, m, n, lo, hi = cost(law + "-monotonic")
    lines.append("| %s | %.0f | %d | %d–%d | %.1f | %.2f |" %
                 (name(law), float(rows[-1]["H_kN"]), n, lo, hi, t, m))
lines += ["", "## 10 cycles (4 steps a segment, 84 steps)", "",
          "| law | amplitude | secant stiffness, cycle 1 / 10 [kN/m] | damping ratio, cycle 1 / 10 | u at zero load, cycle 10 [m] | Newton updates per step | wall time [s] | peak memory [GB] |",
          "|---|---|---|---|---|---|---|---|"]
for law in ("iwan", twin):
    for a in ("0.009", "0.045"):
        c = list(csv.DictReader(open("%s-%s/load-cycles.csv" % (law, a))))
        t, m, n, lo, hi = cost("%s-%s" % (law, a))
        z = c[-1]["zero_load_horizontal_m"]
        lines.append("| %s | %s m (%.3f D) | %.4g / %.4g | %.4f ± %.4f / %.4f | %s | %d–%d | %.1f | %.2f |" % (
            name(law), a, float(a) / 9., float(c[0]["secant_stiffness_kN_per_m"]),
            float(c[-1]["secant_stiffness_kN_per_m"]),
            float(c[0]["damping_ratio"]), float(c[0]["damping_ratio_error"]),
            float(c[-1]["damping_ratio"]), ("%.3g" % float(z)) if z else "–",
            lo, hi, t, m))
open(out, "w").write("\n".join(lines) + "\n")
print("\n".join(lines))

# The PISA p-v curves of both laws at three depths, dimensional (the
# normalisation divides by each run's G).
fig, ax = plt.subplots(figsize=(7, 4.5))
for law, style in (("iwan", "-"), (twin, "--")):
    rows = list(csv.DictReader(open(law + "-curves/soil-reaction-curves.csv")))
    for depth, colour in (("4.5", "C0"), ("9", "C1"), ("18", "C2")):
        pts = [(float(r["v [m]"]), float(r["p [kN/m]"])) for r in rows
               if abs(float(r["depth [m]"]) - float(depth)) < 1e-9]
        if not pts:
            continue
        pts = [(0., 0.)] + pts
        ax.plot([p[0] for p in pts], [p[1] for p in pts], style, color=colour,
                marker="o", ms=2, label="%s, %s m" % (name(law), depth))
ax.set_xlabel("v [m]")
ax.set_ylabel("p [kN/m]")
ax.grid(alpha=0.3)
ax.legend(fontsize=7)
ax.set_title("PISA p-v curves of the monopile to 0.01 D (20 steps): %s "
             "against %s (the same G0)" % (soil, twin), fontsize=9)
fig.tight_layout()
fig.savefig(figure, dpi=130)
PY
/usr/bin/python3 "$root/tools/plot_cycles.py" iwan-0.009 iwan-0.045 \
  --label "$label, u = 0.001 D" --label "$label, u = 0.005 D" \
  -o "$root/doc/figures/$figures-loops.png"
