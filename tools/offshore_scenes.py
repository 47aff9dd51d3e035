#!/usr/bin/python3
"""The verification tables of doc/verification/offshore-foundations.md §4:
the monopile, layered-monopile and suction-caisson scenes (prm/monopile.prm,
prm/monopile-layered.prm, prm/suction-caisson.prm) as shipped, finer runs of each, the caisson's modelling studies (domain size,
skirt thickness) and the published or closed-form values beside them.

Usage: tools/offshore_scenes.py [--exe build/fourier-ssi] [--out doc/figures]
                                [--only monopile|layered|caisson]

Every case is a shipped scene with a few entries appended (a later
subsection/set wins in deal.II's ParameterHandler), run by the program in
its own temporary folder; the script reads the last cycle of results.csv.

Cases:
  shipped        the scene as shipped (Target accuracy 1e-4), timed;
  monopile only: the base mesh of long wall cells (0.11 m x 3.5 m, 12 along
                 the pile, no grading at the wall's ends), to show the error
                 that the nested members do not see;
  finer          every segment of the base mesh with twice the cells (the
                 growth ratios square-rooted: the same grading), Target
                 accuracy 1e-5, the harmonics one after the other
                 (memory). Not tighter: a third member would be refused by
                 the hard guard Mesh/Maximum DoFs (an error, exit 1) before
                 Adaptivity/Maximum DoFs could stop the family as
                 unconverged (doc/offshore-foundations.md, "Limits");
  caisson only:  FE_Q(2) with B-bar on the shipped base mesh refined once,
                 the skirt's corners graded by hand (another element for
                 nu = 0.499: no volumetric locking in the answer);
                 nu = 0.2 (Doherty et al.'s other Poisson ratio); for
                 nu = 0.2 the skirt 0.02 and 0.01 m thick instead of
                 0.04 m, and the domain 2000, 8000, 16000 m instead of
                 4000 m.

References:
  monopile: Randolph (1981), Geotechnique 31(2) 247-259, eq. (7) for a
    flexible pile in homogeneous soil (rho_c = 1): with G* = G (1 + 3 nu/4),
    E_p the Young's modulus of the solid circular pile of the same EI
    (E_p = E_steel I / (pi r0^4 / 4)), l_c = 2 r0 (E_p/G*)^(2/7) and
    f = (E_p/G*)^(1/7) / G*,
      u     = f [0.27 H (l_c/2)^-1 + 0.3 M (l_c/2)^-2]
      theta = f [0.3  H (l_c/2)^-2 + 0.8 M (l_c/2)^-3]
    inverted to K_H, K_M, K_MH and normalised like the program. Valid for
    L >= l_c only; the monopile has L/l_c = 0.59.
  caisson: Doherty, Houlsby & Deeks (2005), J. Geotech. Geoenviron. Eng.
    131(12) 1498-1508, rigid caisson, L/D = 0.5, homogeneous soil:
    K_H = 9.09, K_M = 16.77 (nu = 0.2) and K_H = 10.95, K_M = 20.06
    (nu = 0.5), as quoted by a third party (the paper itself could not be
    read here; doc/verification/offshore-foundations.md §4c says so).

Writes OUT/offshore-scenes-<group>.{csv,md} for the groups monopile,
layered and caisson (--only: that group only); prints the
tables and the total wall time.
"""
import argparse
import csv
import math
import os
import subprocess
import sys
import tempfile
import time

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
GOALS = ["K_V", "K_H", "K_M", "K_MH"]

# The rows of results.csv behind each goal and its estimated relative error.
ROWS = {
    "K_V": ("foundation_vertical_stiffness_normalised", 0,
            "foundation_vertical_displacement_error"),
    "K_H": ("K_H", 1, "K_H_error"),
    "K_M": ("K_M", 1, "K_M_error"),
    "K_MH": ("K_MH", 1, "K_MH_error"),
}

# The layered monopile writes the 6x6 matrix: K_V is its K_V row [kN/m]
# (no Vertical force, so no normalised vertical stiffness).
LAYERED_ROWS = dict(ROWS, K_V=("K_V", 0, "K_V_error"))

DOHERTY_2005 = {  # rigid caisson, L/D = 0.5, homogeneous, as quoted
    0.2: {"K_H": 9.09, "K_M": 16.77},
    0.5: {"K_H": 10.95, "K_M": 20.06},
}


def mesh_entries(r_cells, r_growth, z_cells, z_growth, extra=""):
    """A Mesh subsection overriding the cell counts and growth ratios."""
    join = lambda values: ", ".join(str(v) for v in values)
    return ("subsection Mesh\n"
            f"  set R cells  = {join(r_cells)}\n"
            f"  set R growth = {join(r_growth)}\n"
            f"  set Z cells  = {join(z_cells)}\n"
            f"  set Z growth = {join(z_growth)}\n"
            f"{extra}end\n")


def doubled(r_cells, r_growth, z_cells, z_growth):
    """Twice the cells per segment with the same grading (q -> sqrt(q))."""
    root = lambda qs: [round(math.sqrt(q), 6) for q in qs]
    return mesh_entries([2 * c for c in r_cells], root(r_growth),
                        [2 * c for c in z_cells], root(z_growth))


FINER_RUN = """subsection Discretization
  set Target accuracy      = 1e-5
  set Concurrent harmonics = 1
end
subsection Adaptivity
  set Allow unconverged = true
  set Maximum DoFs      = 1.5e6
end
"""

# The shipped base meshes (kept equal to the .prm files by hand: the
# 'shipped' case runs the file itself, and finer = these doubled).
MONOPILE_MESH = ([6, 1, 20], [0.6, 1, 1.6], [16, 6, 32, 6, 1], [0.55, 1.6, 1, 0.625, 1])
LAYERED_MESH = ([6, 1, 20], [0.6, 1, 1.6], [16, 6, 24, 7, 2, 6, 1],
                [0.55, 1.6, 1, 1, 1, 0.625, 1])
CAISSON_MESH = ([8, 1, 23], [0.7, 1, 1.6], [22, 5, 12, 5, 1], [0.62, 1.5, 1, 0.6667, 1])

NU_02 = """subsection Materials
  set Materials = 0: G=1e4, nu=0.2; 1: G=1e4, nu=0.3
end
"""


def caisson_domain(size):
    """The caisson in a domain of radius and depth `size` [m]: the far
    segments keep their first cells and growth, one cell more or less per
    factor 1.6 of size."""
    extra_cells = round(math.log(size / 4000.) / math.log(1.6))
    r_cells, r_growth, z_cells, z_growth = CAISSON_MESH
    return mesh_entries(
        r_cells[:2] + [r_cells[2] + extra_cells], r_growth,
        [z_cells[0] + extra_cells] + z_cells[1:], z_growth,
        extra=(f"  set R breakpoints = 0, 3.96, 4, {size}\n"
               f"  set Z breakpoints = -{size}, -4, -3.5, -0.5, 0, 0.04\n"
               f"  set Removed regions = 4, {size}, 0, 0.04\n"))


# Another element for the incompressible limit: FE_Q(2) with B-bar instead
# of the target's FE_Q(4), the skirt's four corners graded 10 times by hand.
BBAR = """subsection Discretization
  set Target accuracy   =
  set Polynomial degree = 2
  set Volumetric strain = bbar
end
subsection Mesh
  set Global refinements = 1
end
subsection Adaptivity
  set Point refinement = 3.96, -4: 10; 4, -4: 10; 3.96, 0: 10; 4, 0: 10
end
"""


def skirt(thickness):
    """The skirt `thickness` [m] thick (shipped: 0.04 m), its outer face
    at r = R."""
    inner = 4. - thickness
    return ("subsection Mesh\n"
            f"  set R breakpoints    = 0, {inner}, 4, 4000\n"
            f"  set Material regions = 1: 0, 4, 0, 0.04; 1: {inner}, 4, -4, 0\n"
            "end\n")


def run_case(exe, scene, appended, name, goal_rows=ROWS):
    """Runs scene + appended entries; returns {goal: (value, error)}, the
    wall time [s] and the DoFs per harmonic of the answer."""
    with tempfile.TemporaryDirectory(prefix="offshore-") as work:
        prm = os.path.join(work, "case.prm")
        with open(os.path.join(ROOT, scene)) as f:
            text = f.read()
        text += "\n" + appended + "subsection Output\n  set Directory = out\nend\n"
        with open(prm, "w") as f:
            f.write(text)
        start = time.time()
        run = subprocess.run([exe, prm], cwd=work, capture_output=True, text=True)
        wall = time.time() - start
        if run.returncode != 0:
            sys.exit(f"{name}: fourier-ssi exited {run.returncode}:\n{run.stdout[-2000:]}{run.stderr[-2000:]}")
        with open(os.path.join(work, "out", "results.csv")) as f:
            rows = list(csv.DictReader(f))
    last = max(int(r["cycle"]) for r in rows)
    value = {(r["quantity"], int(r["n"])): float(r["value"])
             for r in rows if int(r["cycle"]) == last}
    result = {}
    for goal, (quantity, n, error) in goal_rows.items():
        result[goal] = (value[(quantity, n)], value.get((error, n), float("nan")))
    return result, wall, int(value[("n_dofs", 1)])


def randolph_flexible():
    """Randolph (1981) eq. (7), homogeneous soil, normalised like the
    program (G a, G a^3, G a^2 with a = r0); also E_p/G* and l_c."""
    D, t, L = 9.0, 0.11, 42.0
    r0 = D / 2.
    E_steel, E_soil, nu = 210e9, 30e6, 0.3
    G = E_soil / (2. * (1. + nu))
    G_star = G * (1. + 0.75 * nu)
    I = math.pi / 64. * (D**4 - (D - 2. * t)**4)
    E_p = E_steel * I / (math.pi * r0**4 / 4.)
    ratio = E_p / G_star
    l_c = 2. * r0 * ratio**(2. / 7.)
    half = l_c / 2.
    f = ratio**(1. / 7.) / G_star
    uH, uM = f * 0.27 / half, f * 0.3 / half**2
    tH, tM = f * 0.3 / half**2, f * 0.8 / half**3
    det = uH * tM - uM * tH
    return ({"K_H": tM / det / (G * r0), "K_M": uH / det / (G * r0**3),
             "K_MH": -uM / det / (G * r0**2)},
            {"E_p": E_p, "E_p/G*": ratio, "l_c": l_c, "L/l_c": L / l_c})


def fmt(value, error=None):
    text = f"{value:.6g}"
    if error is not None and not math.isnan(error):
        text += f" ± {error:.1e}"
    return text


LONG_WALL_CELLS = mesh_entries(
    [3, 1, 22], [1, 1, 1.3], [18, 12, 1], [0.75, 1, 1],
    extra="  set Z breakpoints = -2000, -42, 0, 0.11\n")


def scene_cases(group):
    """(case label, scene, appended entries) of one group."""
    if group == "monopile":
        scene = "prm/monopile.prm"
        return [("shipped", scene, ""),
                ("finer", scene, doubled(*MONOPILE_MESH) + FINER_RUN),
                ("wall cells 0.11 m x 3.5 m", scene, LONG_WALL_CELLS)]
    if group == "layered":
        scene = "prm/monopile-layered.prm"
        return [("shipped", scene, ""),
                ("finer", scene, doubled(*LAYERED_MESH) + FINER_RUN)]
    scene = "prm/suction-caisson.prm"
    cases = [("nu=0.499 shipped", scene, ""),
             ("nu=0.499 finer", scene, doubled(*CAISSON_MESH) + FINER_RUN),
             ("nu=0.499 FE_Q(2) B-bar", scene, BBAR),
             ("nu=0.2 shipped geometry", scene, NU_02),
             ("nu=0.2 skirt 0.02 m", scene, NU_02 + skirt(0.02)),
             ("nu=0.2 skirt 0.01 m", scene, NU_02 + skirt(0.01))]
    for size in (2000, 8000, 16000):
        cases.append((f"nu=0.2 domain {size} m", scene, NU_02 + caisson_domain(size)))
    return cases


def reference_lines(group):
    """The published or closed-form values printed under the table."""
    if group == "monopile":
        K, facts = randolph_flexible()
        return [f"Randolph (1981) flexible pile: K_H = {K['K_H']:.4g}, "
                f"K_M = {K['K_M']:.4g}, K_MH = {K['K_MH']:.4g}; "
                f"E_p = {facts['E_p'] / 1e9:.2f} GPa (the solid pile of the tube's EI), "
                f"E_p/G* = {facts['E_p/G*']:.0f}, l_c = {facts['l_c']:.1f} m, "
                f"L/l_c = {facts['L/l_c']:.2f}"]
    if group == "layered":
        return ["K_V in kN/m; K_H, K_M, K_MH normalised with G = 40 MPa "
                "(the deep sand) and a = 4.5 m; no published solution for "
                "this profile: the finer run is the reference"]
    return [f"Doherty et al. (2005), rigid, L/D = 0.5, nu = {nu} (as quoted): "
            f"K_H = {values['K_H']}, K_M = {values['K_M']}"
            for nu, values in DOHERTY_2005.items()]


def write_group(out, group, table):
    """OUT/offshore-scenes-<group>.csv and .md; returns the markdown."""
    with open(os.path.join(out, f"offshore-scenes-{group}.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["case", "wall_s", "dofs_per_harmonic"]
                        + [c for g in GOALS for c in (g, g + "_error")])
        for label, wall, dofs, result in table:
            writer.writerow([label, f"{wall:.1f}", dofs]
                            + [f"{x:.8g}" for g in GOALS for x in result[g]])
    lines = [f"| {group} | wall [s] | DoFs/harmonic | K_V | K_H | K_M | K_MH |",
             "|---|---|---|---|---|---|---|"]
    for label, wall, dofs, result in table:
        lines.append(f"| {label} | {wall:.0f} | {dofs} | "
                     + " | ".join(fmt(*result[g]) for g in GOALS) + " |")
    lines += [""] + reference_lines(group)
    text = "\n".join(lines) + "\n"
    with open(os.path.join(out, f"offshore-scenes-{group}.md"), "w") as f:
        f.write(text)
    return text


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--exe", default=os.path.join(ROOT, "build", "fourier-ssi"))
    parser.add_argument("--out", default=os.path.join(ROOT, "doc", "figures"))
    parser.add_argument("--only", choices=["monopile", "layered", "caisson"])
    args = parser.parse_args()
    exe = os.path.abspath(args.exe)
    os.makedirs(args.out, exist_ok=True)
    start = time.time()
    for group in ["monopile", "layered", "caisson"]:
        if args.only not in (None, group):
            continue
        table = []
        for label, scene, appended in scene_cases(group):
            rows = LAYERED_ROWS if group == "layered" else ROWS
            result, wall, dofs = run_case(exe, scene, appended,
                                          f"{group} {label}", rows)
            print(f"{group}, {label}: {wall:.1f} s, {dofs} DoFs per harmonic: "
                  + ", ".join(f"{g} {fmt(*result[g])}" for g in GOALS), flush=True)
            table.append((label, wall, dofs, result))
        print(write_group(args.out, group, table))
    print(f"total {time.time() - start:.0f} s")


if __name__ == "__main__":
    main()
