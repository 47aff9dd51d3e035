#!/usr/bin/env bash
# Secant stiffness and damping of the monopile in iwan clay at a mean load
# (doc/foundation-stiffness-at-load.md): tools/cyclic_stiffness.py on the
# monopile of prm/monopile-clay-lateral.prm (D = 9 m, L = 42 m) with its clay
# made iwan (G0 = 60 MPa, s_u = 100 kPa, gamma_ref = 0.003, 20 surfaces, as
# in benchmarks/cyclic-monopile), mean H = 10 MN, M = 300 MN m (a lever of
# 30 m), the horizontal drive's load with the same lever, one cycle at each
# of 0.002, 0.006 and 0.018 m (6 steps a segment), 2 MPI ranks.
#   bash benchmarks/cyclic-stiffness/run.sh [path/to/fourier-ssi] [work dir]
# Writes benchmarks/cyclic-stiffness/results.md and
# doc/figures/cyclic-stiffness-monopile.png.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
exe="$(realpath "${1:-$root/build/fourier-ssi}")"
work="${2:-$(mktemp -d)}"
mkdir -p "$work"
sed -e 's/set Laws = 0: tresca, su=100/set Laws = 0: iwan, su=100, gref=0.003, surfaces=20/' \
    -e 's/0: G=30000, nu=0.49/0: G=60000, nu=0.49/' \
    "$root/prm/monopile-clay-lateral.prm" > "$work/monopile-iwan.prm"
grep -q "iwan, su=100" "$work/monopile-iwan.prm" && grep -q "G=60000" "$work/monopile-iwan.prm"
/usr/bin/time -f "%e %M" -o "$work/time" /usr/bin/python3 "$root/tools/cyclic_stiffness.py" \
  "$work/monopile-iwan.prm" --mean-h 10000 --mean-m 300000 --lever 30 \
  --amplitudes 0.002,0.006,0.018 --steps 6 --np 2 --exe "$exe" --out "$work/out" \
  | tee "$work/log"
cp "$work/out/secant-stiffness-and-damping.png" "$root/doc/figures/cyclic-stiffness-monopile.png"
/usr/bin/python3 - "$work" "$here/results.md" <<'PY'
import csv, datetime, os, sys
work, out = sys.argv[1:3]
o = os.path.join(work, "out")
rows = lambda p: list(csv.DictReader(open(os.path.join(o, p))))
s, d, c = rows("secant-stiffness.csv"), rows("damping.csv"), rows("cost.csv")
wall, mem = open(os.path.join(work, "time")).read().split()
steps = [list(csv.DictReader(open(os.path.join(o, "runs", "%s-%d" % (k, i + 1), "load-displacement.csv"))))
         for i in range(len(s)) for k in ("horizontal", "rotation")]
its = [int(r["iterations"]) for st in steps for r in st]
el = s[0]
L = ["# Secant stiffness and damping of the monopile in iwan clay (%s, %d cores)" %
     (datetime.date.today(), os.cpu_count()), "",
     "Script: benchmarks/cyclic-stiffness/run.sh. The monopile of prm/monopile-clay-lateral.prm",
     "in iwan clay (G0 = 60 MPa, s_u = 100 kPa, gamma_ref = 0.003, 20 surfaces), mean H = 10 MN,",
     "M = 300 MN m held; the horizontal drive's load H with M = 30 m x H, the rotation",
     "drive's M alone; one cycle of each at each amplitude, 6 steps a segment. Stiffness in",
     "SI at the mudline's axis point; the vertical and torsional terms are the scene's",
     "elastic ones (no plasticity, G = G0).", "",
     "| amplitude u [m] / theta [rad] | K_xx [N/m] | K_x,ry [N/rad] | K_ry,x [N/rad] | K_ry,ry [N m/rad] | asymmetry | xi lateral | xi rocking | c_xx at 0.25 Hz [N s/m] | c_ry,ry [N m s/rad] |",
     "|---|---|---|---|---|---|---|---|---|---|",
     "| elastic (G0) | %.5g | %.5g | %.5g | %.5g | 0 | – | – | – | – |" % (
         float(el["K_x_x_elastic"]), float(el["K_x_ry_elastic"]), float(el["K_x_ry_elastic"]),
         float(el["K_ry_ry_elastic"]))]
for a, b in zip(s, d):
    L.append("| %s / %.4g | %.5g | %.5g | %.5g | %.5g | %.3f | %.4f ± %.4f | %.4f ± %.4f | %.4g | %.4g |" % (
        a["amplitude_m"], float(a["rotation_amplitude_rad"]), float(a["K_x_x"]), float(a["K_x_ry"]),
        float(a["K_ry_x"]), float(a["K_ry_ry"]), float(a["asymmetry"]), float(b["xi_lateral"]),
        float(b["xi_lateral_error"]), float(b["xi_rocking"]), float(b["xi_rocking_error"]),
        float(b["c_x_x_N_s_per_m"]), float(b["c_ry_ry_N_m_s_per_rad"])))
L += ["", "## Cost", "",
      "| stage | runs | wall time [s] | MPI ranks |", "|---|---|---|---|"]
for r in c:
    L.append("| %s | %s | %s | %s |" % (r["stage"], "2" if r["stage"].startswith("elastic") else "%d" % (2 * len(s)),
                                         r["wall_time_s"], r["ranks"]))
L += ["", "Whole tool: %s s wall, peak memory of one process %.2f GB; %d steps of the" % (
          wall, float(mem) / 1e6, sum(len(st) for st in steps)),
      "coupled problem in the cyclic runs, %d–%d Newton updates a step." % (min(its), max(its))]
open(out, "w").write("\n".join(L) + "\n")
print("\n".join(L))
PY
