#!/usr/bin/python3
"""The 1D Timoshenko beam of tools/pisa/beam.py against closed forms, and
the OpenPile export read back (tools/pisa/export.py).

1. Hetenyi (1946), a long Euler-Bernoulli beam on Winkler springs k_s
   [kN/m^2], free head, beta = (k_s / (4 EI))^(1/4): under H,
   v0 = 2 H beta / k_s, psi0 = 2 H beta^2 / k_s; under M, v0 = 2 M beta^2 /
   k_s, psi0 = 4 M beta^3 / k_s (beta L = 8.9: a long beam; kappa G A
   large: no shear).  400 elements: O(h^2) within 2e-4.
2. A cantilever with shear deformation, clamped at the tip by stiff base
   springs: v_head = H L^3 / (3 EI) + H L / (kappa G A), within 1e-4
   (load control and displacement control).
3. A rigid pile (EI, kappa G A large) on uniform springs k_s with rotational
   springs k_m [kN m/m per rad] and base springs: with v(z) = v0 + psi z
   over -L <= z <= 0, H = k_s (L v0 - L^2/2 psi) + k_b (v0 - L psi) and
   M = k_s (-L^2/2 v0 + L^3/3 psi) + k_m L psi + k_b (-L v0 + L^2 psi) + k_mb psi;
   v0, psi from this 2x2 system within 1e-4 (EI = kappa G A = 1e11: the
   pile's own flexibility k_s L^4/EI = 6e-5).
4. The export of a model read back by export.read_openpile: every field
   of OpenPile's Custom_pisa_clay as [top, bottom] equal to the model's
   values (n capped at 0.999), and a broken file refused.
5. A rigid pile in a sand model (model.Model, soil kind sand): p = sigma'_v
   D pbar(v G/(sigma'_v D)) and m = |p| D mbar(psi G/sigma'_v), which
   couples m to v.  Reference: the rigid pile's two equilibrium equations,
   H = int p dz + H_B and M = int (p z + m) dz - L H_B + M_B with
   v(z) = v0 + psi z, integrated by adaptive quadrature (scipy quad, with
   the breakpoints where v = 0 and where a conic reaches x_u) and solved by
   scipy fsolve, under H = 100 kN and M = 200 kN m (the secant there 39 %
   softer than at half the load): within 1e-5 (G = 500 kPa against
   EI = kappa G A = 1e11: the pile's own flexibility G kbar L^4 / EI is
   1.6e-4, and the difference it makes 2.5e-6; 200 elements).  The beam's
   tangent, which is unsymmetric here, equals the central difference of
   its internal force within 1e-6 (relative to the tangent's largest entry;
   the difference step 1e-7 of the displacement).
6. The export of a sand model: Custom_pisa_sand fields, no Su, a layer
   weight gamma' + 10 kN/m^3 whose gamma' is the slope of sigma'_v, read
   back; a weight below 10 refused.
Usage: pisa_beam.py EXE SOURCE_DIR WORK_DIR (EXE unused)."""
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(sys.argv[2] if len(sys.argv) > 2 else ".", "tools", "pisa"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from relative_checks import check, failed  # noqa: E402
from beam import Beam  # noqa: E402
from model import Model  # noqa: E402
import export  # noqa: E402

work = sys.argv[3] if len(sys.argv) > 3 else "/tmp/pisa_beam"
os.makedirs(work, exist_ok=True)


def linear_spring(k):
    return lambda v, z=None: (k * v, k + 0 * v)


def rotational_spring(k):
    """m(psi, z, v) = k psi: no dependence on v."""
    return lambda psi, z=None, v=None: (k * psi, k + 0 * psi, 0 * psi)


# 1. Hetenyi
EI, ks, L = 1e6, 1e4, 40.0
beta = (ks / (4 * EI)) ** 0.25
b = Beam(EI, 1e9, L, 400, p=linear_spring(ks))
u = b.solve_load(100.0, 0.0)
check("Hetenyi, H: v0 [m]", u[0], 2 * 100 * beta / ks, 2e-4)
check("Hetenyi, H: psi0 [rad]", u[1], 2 * 100 * beta ** 2 / ks, 2e-4)
u = b.solve_load(0.0, 100.0)
check("Hetenyi, M: v0 [m]", u[0], 2 * 100 * beta ** 2 / ks, 2e-4)
check("Hetenyi, M: psi0 [rad]", u[1], 4 * 100 * beta ** 3 / ks, 2e-4)

# 2. cantilever with shear
kGA, Lc, H = 5e5, 10.0, 10.0
b = Beam(EI, kGA, Lc, 100, HB=linear_spring(1e12), MB=linear_spring(1e12))
ref = H * Lc ** 3 / (3 * EI) + H * Lc / kGA
check("cantilever with shear: v_head under H [m]", b.solve_load(H, 0.0)[0], ref, 1e-4)
v0, psi0, Hs, Ms = b.push(0.05, 0.0, 4)
check("cantilever with shear, displacement control: H at v = 0.05 m [kN]", Hs[-1], 0.05 / ref * H, 1e-4)

# 3. rigid pile on uniform springs
km, kb, kmb, Lr = 300.0, 2e3, 5e3, 5.0
b = Beam(1e11, 1e11, Lr, 5, p=linear_spring(ks), m=rotational_spring(km),
         HB=linear_spring(kb), MB=linear_spring(kmb))
u = b.solve_load(100.0, 250.0)
Kr = np.array([[ks * Lr + kb, -ks * Lr ** 2 / 2 - kb * Lr],
               [-ks * Lr ** 2 / 2 - kb * Lr, ks * Lr ** 3 / 3 + km * Lr + kb * Lr ** 2 + kmb]])
v0, psi = np.linalg.solve(Kr, [100.0, 250.0])
check("rigid pile: v0 against the rigid-body 2x2 solution [m]", u[0], v0, 1e-4)
check("rigid pile: psi0 against the rigid-body 2x2 solution [rad]", u[1], psi, 1e-4)
check("rigid pile: psi at the tip equals psi0 [rad]", u[-1], psi, 1e-4)

# 4. the export read back
params = {c: dict(layers=[dict(top=dict(k=8.0, n=0.4, xu=20.0, yu=10.0),
                               bottom=dict(k=6.0, n=1.0, xu=20.0, yu=12.0), s0=0.0, s1=5.0)])
          for c in ("py", "mt")}
params.update({c: dict(layers=[dict(top=dict(k=1.0, n=0.2, xu=3.0, yu=0.5),
                                    bottom=dict(k=2.0, n=0.6, xu=5.0, yu=0.7), s0=2.0, s1=6.0)])
               for c in ("Hb", "Mb")})
model = Model(params, dict(depth=[1.0, 9.0], s=[50.0, 90.0], G=[15000.0, 27000.0]))
path = os.path.join(work, "openpile.json")
export.write_openpile(model, dict(name="test", D=2.0, L_over_D=4.0), 0.02, path)
pile, layers = export.read_openpile(path)
layer, args = layers[-1], layers[-1]["Custom_pisa_clay"]
check("export: one layer", len(layers), 1, 0)
check("export: py_Y at the bottom (z/D = 4; read 1e-9 D inside the layer)", args["py_Y"][1], 10.0 + 2.0 * 4 / 5, 1e-9)
check("export: py_n at the bottom (z/D = 4)", args["py_n"][1], 0.4 + 0.6 * 4 / 5, 1e-9)
check("export: Hb_X at L/D = 4 (top = bottom)", args["Hb_X"][0], 4.0, 1e-12)
check("export: Su at the mudline (constant above the shallowest FE depth) [kPa]", args["Su"][0], 50.0, 1e-12)
check("export: G0 at the tip (depth 8 m) [kPa]", args["G0"][1], 15000 + 12000 * 7 / 8, 1e-12)
check("export: layer bottom = -L [m]", layer["bottom"], -8.0, 1e-15)


def refused_after(spoil, what):
    """The export at `path`, changed by spoil(doc), is refused by the reader
    with a ValueError."""
    with open(path) as f:
        doc = json.load(f)
    spoil(doc)
    with open(path, "w") as f:
        json.dump(doc, f)
    try:
        export.read_openpile(path)
        failed.append(what)
        print(f"FAIL {what}")
    except ValueError as e:
        print(f"ok   {what}: {e}")


refused_after(lambda doc: doc["layers"][0]["Custom_pisa_clay"].pop("mt_k"), "a file without mt_k is refused")
# two model layers: the export splits the pile at z/D = 2
params["py"]["layers"] = [dict(top=dict(k=8.0, n=0.4, xu=20.0, yu=10.0), bottom=dict(k=7.0, n=0.5, xu=20.0, yu=11.0),
                               s0=0.0, s1=2.0),
                          dict(top=dict(k=5.0, n=0.6, xu=30.0, yu=14.0), bottom=dict(k=4.0, n=0.7, xu=30.0, yu=15.0),
                               s0=2.0, s1=5.0)]
export.write_openpile(Model(params, model.profile), dict(name="test", D=2.0, L_over_D=4.0), 0.02, path)
pile, layers = export.read_openpile(path)
check("export, two layers: two OpenPile layers", len(layers), 2, 0)
check("export, two layers: the first ends at z = -2 D [m]", layers[0]["bottom"], -4.0, 1e-15)
check("export, two layers: py_Y at the top of the second (its own value)", layers[1]["Custom_pisa_clay"]["py_Y"][0],
      14.0, 1e-6)
check("export, two layers: py_Y at the bottom of the first", layers[0]["Custom_pisa_clay"]["py_Y"][1], 11.0, 1e-6)

# 5. a rigid pile in a sand model
from scipy.integrate import quad  # noqa: E402
from scipy.optimize import fsolve  # noqa: E402
from conic import conic  # noqa: E402

Ds, Ls, unit_weight, Gs = 2.0, 8.0, 10.0, 500.0
sand_params = {"py": dict(layers=[dict(top=dict(k=8.0, n=0.8, xu=60.0, yu=6.0),
                                       bottom=dict(k=5.0, n=0.9, xu=60.0, yu=4.0), s0=0.0, s1=4.0)]),
               "mt": dict(layers=[dict(top=dict(k=20.0, n=0.3, xu=5.0, yu=0.3),
                                       bottom=dict(k=15.0, n=0.5, xu=8.0, yu=0.2), s0=0.0, s1=4.0)]),
               "Hb": dict(layers=[dict(top=dict(k=0.5, n=0.6, xu=2.0, yu=0.4),
                                       bottom=dict(k=0.5, n=0.6, xu=2.0, yu=0.4), s0=3.0, s1=5.0)]),
               "Mb": dict(layers=[dict(top=dict(k=0.3, n=0.5, xu=10.0, yu=0.2),
                                       bottom=dict(k=0.3, n=0.5, xu=10.0, yu=0.2), s0=3.0, s1=5.0)])}
depths = np.linspace(0.5, Ls, 16)
sand = Model(sand_params, dict(depth=depths, s=unit_weight * depths, G=Gs + 0 * depths), "sand")
p_sand, m_sand, HB_sand, MB_sand = sand.springs(Ds, Ls)
b = Beam(1e11, 1e11, Ls, 200, p=p_sand, m=m_sand, HB=HB_sand, MB=MB_sand)
H_sand, M_sand = 100.0, 200.0
# tol 1e-5: the stiff pile (entries of K near 1e13, u near 0.04 m) leaves a
# round-off floor of about 1e-6 |f| in the residual
u = b.solve_load(H_sand, M_sand, tol=1e-5)


def rigid_equilibrium(q):
    v0, psi = q
    v = lambda z: v0 + psi * z  # noqa: E731
    # where v changes sign and where the lateral conic reaches x_u
    breaks = [z for z in (-v0 / psi if psi else 1.0,) if -Ls < z < 0]
    for depth in np.linspace(0.0, Ls, 401)[1:-1]:
        k, n, xu, yu = sand.at("py", depth / Ds)
        sv, G = sand.soil(depth)
        for edge in (xu, -xu):
            zc = (edge * sv * Ds / G - v0) / psi if psi else 1.0
            if -Ls < zc < 0 and abs(zc + depth) < Ls / 400:
                breaks.append(zc)
    pz = lambda z: p_sand(np.array([v(z)]), np.array([z]))[0][0]  # noqa: E731
    mz = lambda z: m_sand(np.array([psi]), np.array([z]), np.array([v(z)]))[0][0]  # noqa: E731
    opts = dict(points=sorted(breaks) or None, limit=400, epsabs=0.0, epsrel=1e-11)
    shaft_H = quad(pz, -Ls, 0.0, **opts)[0]
    shaft_M = quad(lambda z: pz(z) * z + mz(z), -Ls, 0.0, **opts)[0]
    base_H = HB_sand(v(-Ls))[0]
    base_M = MB_sand(psi)[0]
    return [shaft_H + base_H - H_sand, shaft_M - Ls * base_H + base_M - M_sand]


v0_ref, psi_ref = fsolve(rigid_equilibrium, [u[0], u[1]], xtol=1e-12)
check("sand, rigid pile: v0 against quadrature of the rigid-body equilibrium [m]", u[0], v0_ref, 1e-5)
check("sand, rigid pile: psi0 against quadrature of the rigid-body equilibrium [rad]", u[1], psi_ref, 1e-5)
f0, T = b.soil(u)
step = 1e-7 * np.abs(u).max()
T_fd = np.zeros_like(T)
for j in range(u.size):
    du = np.zeros_like(u)
    du[j] = step
    T_fd[:, j] = (b.soil(u + du)[0] - b.soil(u - du)[0]) / (2 * step)
check("sand: the beam's tangent against central differences of its internal force (largest entry)",
      np.abs(T - T_fd).max() / np.abs(T).max() + 1.0, 1.0, 1e-6)
check("sand: the tangent is unsymmetric (m depends on v) (largest asymmetry / largest entry)",
      float(np.abs(T - T.T).max() / np.abs(T).max() > 1e-3), 1.0, 0)

# 6. the export of a sand model
export.write_openpile(sand, dict(name="sand", D=Ds, L_over_D=Ls / Ds), 0.02, path)
pile, layers = export.read_openpile(path)
args = layers[0]["Custom_pisa_sand"]
check("sand export: one layer", len(layers), 1, 0)
check("sand export: no Su field", float("Su" in args), 0.0, 0)
check("sand export: weight = gamma' + 10 [kN/m^3]", layers[0]["weight"], unit_weight + 10.0, 1e-12)
check("sand export: sigma'_v at the tip [kPa]", layers[0]["sigma_v"][1], unit_weight * Ls, 1e-12)
check("sand export: mt_Y at the tip (z/D = 4)", args["mt_Y"][1], 0.2, 1e-9)
refused_after(lambda doc: doc["layers"][0].update(weight=9.0), "a sand layer of weight 9 is refused")
print(f"{len(failed)} failed")
sys.exit(1 if failed else 0)
