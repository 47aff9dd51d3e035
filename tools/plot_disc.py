#!/usr/bin/python3
"""Stresses around the rigid disc in an elastic ring (thesis Hernoune 2007,
chapter 5, Figs 5.6-5.11 family: sigma_r, sigma_theta, tau_rtheta vs r/r0
for an imposed displacement 0.001 D, rough and smooth interfaces).

Usage: tools/plot_disc.py [--exe build/fourier-ssi] [--out doc/figures]

Runs prm/disc-rough.prm and prm/disc-smooth.prm (one after the other) into
a temporary directory with VTU output, reads the n = 1 stress amplitudes from
the VTU (deal.II zlib-compressed binary), averages the (discontinuous,
z-independent) values at equal r and plots the amplitudes Sr, St (the values
at theta = 0) and T (the value at theta = pi/2; tau_rtheta = T sin theta
vanishes on theta = 0) against r/r0, with the plane-strain closed form
(doc/disc.md; the 4 constants solved numerically here) as lines.
Writes OUT/disc-stresses.png and OUT/disc-stresses.csv.

--converged: the thesis family of Figs 5.6-5.24 instead, each case driven by
Discretization/Target accuracy (1e-4 rough, 1e-3 smooth, on U_h; FE_Q(4),
doc/accuracy-vs-time.md), all in one 'fourier-ssi --batch' process: rough
and smooth for nu = 0.1, 0.2, 0.3, 0.4, 0.499, each with H = the closed-form
P for ubar = 1e-3 m at its nu. The stresses are linear in ubar: the thesis's
0.004 D and 0.007 D figures (5.12-5.23) are these times 4 and 7. Every
station (soil node) is compared with the closed form (true error) and with
the answer's mesh one member coarser (the nested estimate the program uses
for its goal values). Writes OUT/disc-stresses-converged.csv (every case and
station), OUT/disc-stresses-converged.png (Figs 5.7, 5.9, 5.11 c/d: nu = 0.3
and 0.499, rough and smooth) and OUT/disc-stresses-poisson.png (Fig 5.24),
and prints the largest errors per case and the wall time.
"""
import argparse
import base64
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib
from collections import defaultdict

from batch_runs import run_batch

# Debian's python3-matplotlib / python3-numpy import under /usr/bin/python3
# only; another python3 first on PATH may lack them: re-run under Debian's.
try:
    import numpy as np
    import matplotlib
except ImportError:
    if sys.executable != "/usr/bin/python3":
        os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
    sys.exit(sys.argv[0] + ": needs numpy and matplotlib (Debian: apt-get "
             "install python3-matplotlib python3-numpy)")

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
E, NU, A, R, UBAR = 1e5, 0.3, 0.5, 10.0, 1e-3


def decode(text, dtype):
    text = text.strip()
    head = base64.b64decode(text[:8])
    nblocks = struct.unpack("<I", head[:4])[0]
    hlen = 4 * (3 + nblocks)
    hchars = 4 * ((hlen + 2) // 3)
    header = struct.unpack("<%dI" % (3 + nblocks), base64.b64decode(text[:hchars])[:hlen])
    raw = base64.b64decode(text[hchars:])
    out, pos = b"", 0
    for size in header[3:]:
        out += zlib.decompress(raw[pos:pos + size])
        pos += size
    return np.frombuffer(out, dtype=dtype)


def read_vtu(path):
    with open(path) as f:
        xml = f.read()
    arrays = {}
    for m in re.finditer(r'<DataArray type="(\w+)"([^>]*)>(.*?)</DataArray>', xml, re.S):
        typ, attrs, body = m.groups()
        name = re.search(r'Name="([^"]+)"', attrs)
        name = name.group(1) if name else "points"
        dtype = {"Float32": "<f4", "Float64": "<f8", "Int32": "<i4", "UInt8": "u1"}[typ]
        arrays.setdefault(name, decode(body, dtype))
    arrays["points"] = arrays["points"].reshape(-1, 3)
    return arrays


def closed_form(interface, r, nu=NU, with_force=False):
    """Plane strain n = 1 amplitudes (Sr, St, T) from the ansatz of doc/disc.md
    for ubar = UBAR; with_force: also the force per unit length P [kN/m]."""
    lam = E * nu / ((1 + nu) * (1 - 2 * nu))
    mu = E / (2 * (1 + nu))
    kap = 3 - 4 * nu
    c = (4 * nu - 1) / (4 * nu - 5)

    def basis(x):  # rows U, W, U', W' as linear maps of (b1, b2, b3, b4)
        U = np.array([c * x * x, x ** -2, -1.0, 1 / kap - np.log(x)])
        W = np.array([x * x, x ** -2, 1.0, np.log(x)])
        dU = np.array([2 * c * x, -2 * x ** -3, 0.0, -1 / x])
        dW = np.array([2 * x, -2 * x ** -3, 0.0, 1 / x])
        return U, W, dU, dW

    def stresses(x):
        U, W, dU, dW = basis(x)
        er, et, g = dU, (U + W) / x, dW - (U + W) / x
        return (lam + 2 * mu) * er + lam * et, lam * er + (lam + 2 * mu) * et, mu * g

    Ua, Wa, _, _ = basis(A)
    UR, WR, _, _ = basis(R)
    second = Wa if interface == "rough" else stresses(A)[2]
    rhs2 = -UBAR if interface == "rough" else 0.0
    b = np.linalg.solve(np.array([Ua, second, UR, WR]), [UBAR, rhs2, 0.0, 0.0])
    values = [np.array([s @ b for s in stresses(x)]) for x in r]
    if with_force:  # P = 4 pi E (1 - nu) b4 / ((1 + nu) kappa), doc/disc.md
        return values, 4 * np.pi * E * (1 - nu) * b[3] / ((1 + nu) * kap)
    return values


def soil_stations(vtu):
    """(r, [Sr, St, T]) averaged over the VTU points of the soil at equal r."""
    arr = read_vtu(vtu)
    acc = defaultdict(list)
    for k, p in enumerate(arr["points"]):
        if p[0] > A + 1e-9:  # soil only (the disc itself is rigid)
            acc[round(float(p[0]), 9)].append(
                (arr["sigma_r"][k], arr["sigma_theta"][k], arr["tau_rtheta"][k]))
    rs = np.array(sorted(acc))
    return rs, np.array([np.mean(acc[x], axis=0) for x in rs])


CONVERGED_NUS = (0.1, 0.2, 0.3, 0.4, 0.499)
TARGETS = {"rough": 1e-4, "smooth": 1e-3}


def converged(args):
    """The Figs 5.6-5.24 family driven by Target accuracy (module docstring)."""
    import time
    work = tempfile.mkdtemp(prefix="disc-converged-")
    cases = [(itf, nu) for itf in ("rough", "smooth") for nu in CONVERGED_NUS]
    for itf, nu in cases:
        with open(os.path.join(ROOT, f"prm/disc-{itf}.prm")) as f:
            text = f.read()
        _, force = closed_form(itf, [A * 2], nu, with_force=True)
        out = os.path.join(work, f"{itf}-{nu}")
        text += ("\n# ---- overrides written by tools/plot_disc.py --converged ----\n"
                 f"subsection Discretization\n  set Target accuracy = {TARGETS[itf]:g}\nend\n"
                 f"subsection Materials\n  set Materials = 0: E={E:g}, nu={nu:g}; "
                 f"1: E={E:g}, nu=0.3\nend\n"
                 f"subsection Rigid foundation\n  set Horizontal force = {force:.12g}\nend\n"
                 f"subsection Output\n  set Directory = {out}\n  set Write vtu = true\nend\n")
        with open(out + ".prm", "w") as f:
            f.write(text)
    wall = run_batch(args.exe, work,
                     [os.path.join(work, f"{itf}-{nu}.prm") for itf, nu in cases])
    data, lines = {}, []
    csv_rows = ["interface,nu,r_over_r0,Sr_fe,St_fe,T_fe,Sr_exact,St_exact,T_exact,"
                "Sr_nested,St_nested,T_nested"]
    for itf, nu in cases:
        out = os.path.join(work, f"{itf}-{nu}")
        vtus = sorted(v for v in os.listdir(out) if v.startswith("solution-n1"))
        rs, vals = soil_stations(os.path.join(out, vtus[-1]))
        r0, v0 = soil_stations(os.path.join(out, vtus[-2]))
        # the coarser member at the stations both meshes have (its nodes
        # stay nodes of the finer one); NaN elsewhere
        coarser = np.full_like(vals, np.nan)
        for i, x in enumerate(rs):
            k = np.searchsorted(r0, x)
            for kk in (k - 1, k):
                if 0 <= kk < len(r0) and abs(r0[kk] - x) < 1e-9:
                    coarser[i] = v0[kk]
        ex = np.array(closed_form(itf, rs, nu))
        data[(itf, nu)] = (rs, vals, ex)
        scale = np.max(np.abs(ex), axis=0)  # each stress's largest amplitude
        true = np.max(np.abs(vals - ex), axis=0) / scale
        nested = np.nanmax(np.abs(vals - coarser), axis=0) / scale
        dofs = [r for r in open(os.path.join(out, "results.csv")) if r.startswith("n_dofs,")][-1]
        lines.append(f"{itf} nu={nu:g}: largest |FE - exact| / largest |exact|: Sr {true[0]:.1e}, "
                     f"St {true[1]:.1e}, T {true[2]:.1e}; one member coarser: Sr {nested[0]:.1e}, "
                     f"St {nested[1]:.1e}, T {nested[2]:.1e} "
                     f"({int(float(dofs.split(',')[4]))} DoFs, {len(rs)} stations)")
        for x, v, e, c in zip(rs, vals, ex, coarser):
            csv_rows.append(f"{itf},{nu:g},{x / A:.8g}," + ",".join(f"{q:.8g}" for q in (*v, *e, *c)))
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "disc-stresses-converged.csv"), "w") as f:
        f.write("\n".join(csv_rows) + "\n")
    labels = [r"$\sigma_r$ at $\theta=0$", r"$\sigma_\theta$ at $\theta=0$",
              r"$\tau_{r\theta}$ at $\theta=\pi/2$"]
    worst = max(float(w) for line in lines for w in re.findall(r"(\d\.\de-\d+)", line.split(";")[0]))
    # Figs 5.7, 5.9, 5.11 (c: nu = 0.3, d: nu = 0.499), rough against smooth
    fig, axes = plt.subplots(2, 3, figsize=(14, 7.6))
    for i, nu in enumerate((0.3, 0.499)):
        for j, ax in enumerate(axes[i]):
            for itf, col in (("rough", "C0"), ("smooth", "C3")):
                rs, vals, ex = data[(itf, nu)]
                # markers at about 30 stations spread evenly in log r
                shown = np.unique(np.minimum(np.searchsorted(
                    rs, np.geomspace(rs[0], rs[-1], 30)), len(rs) - 1))
                ax.plot(rs / A, ex[:, j], color=col, lw=1.0, label=f"{itf}, closed form")
                ax.plot(rs[shown] / A, vals[shown, j], "o", ms=3.5, color=col, mfc="none",
                        label=f"{itf}, FE at target")
            ax.set_xscale("log")
            ax.set_xlabel(r"$r / r_0$")
            ax.set_ylabel("kPa")
            ax.set_title(f"{labels[j]}, $\\nu_s$ = {nu:g}")
            ax.grid(alpha=0.3)
    axes[0][0].legend(fontsize=8)
    fig.suptitle(r"Rigid disc in a ring, $\bar u$ = 0.001 D (0.004 D, 0.007 D: $\times$4, "
                 r"$\times$7), E = 1e5 kPa, R/r$_0$ = 20, tension +; largest FE error "
                 f"{worst:.0e} of each stress's largest amplitude")
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "disc-stresses-converged.png"), dpi=100)
    # Fig 5.24: the effect of nu, rough (left) and smooth (right)
    fig, axes = plt.subplots(3, 2, figsize=(11, 10))
    for k, itf in enumerate(("rough", "smooth")):
        for j in range(3):
            ax = axes[j][k]
            for m, nu in enumerate(CONVERGED_NUS):
                rs, vals, ex = data[(itf, nu)]
                ax.plot(rs / A, vals[:, j], "-", lw=1.2, color=f"C{m}", label=f"$\\nu_s$ = {nu:g}")
            ax.set_xscale("log")
            ax.set_xlabel(r"$r / r_0$")
            ax.set_ylabel("kPa")
            ax.set_title(f"{labels[j]}, {itf}")
            ax.grid(alpha=0.3)
    axes[0][0].legend(fontsize=8)
    fig.suptitle(r"Effect of $\nu_s$ (thesis Fig. 5.24), $\bar u$ = 0.001 D, FE at target "
                 f"accuracy; largest error {worst:.0e} of each stress's largest amplitude")
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "disc-stresses-poisson.png"), dpi=100)
    shutil.rmtree(work, ignore_errors=True)
    for line in lines:
        print(line)
    print(f"disc stresses: {len(cases)} cases in {wall:.1f} s wall (one --batch process) -> "
          f"{args.out}/disc-stresses-converged.csv, .png, disc-stresses-poisson.png")
    return 0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", default=os.path.join(ROOT, "build/fourier-ssi"))
    ap.add_argument("--out", default=os.path.join(ROOT, "doc/figures"))
    ap.add_argument("--converged", action="store_true",
                    help="the Figs 5.6-5.24 family at target accuracy (module docstring)")
    args = ap.parse_args()
    if args.converged:
        return converged(args)
    work = tempfile.mkdtemp(prefix="disc-")
    data = {}
    for itf in ("rough", "smooth"):
        with open(os.path.join(ROOT, f"prm/disc-{itf}.prm")) as f:
            text = f.read()
        out = os.path.join(work, itf)
        text += ("\nsubsection Output\n  set Directory = %s\n  set Write vtu = true\nend\n" % out)
        prm = out + ".prm"
        with open(prm, "w") as f:
            f.write(text)
        subprocess.run([args.exe, prm], check=True, stdout=subprocess.DEVNULL)
        vtu = [p for p in os.listdir(out) if p.startswith("solution-n1") and p.endswith(".vtu")]
        arr = read_vtu(os.path.join(out, sorted(vtu)[-1]))
        acc = defaultdict(list)
        for k, p in enumerate(arr["points"]):
            if p[0] > A + 1e-9:  # soil only (the disc itself is rigid)
                acc[round(float(p[0]), 9)].append(
                    (arr["sigma_r"][k], arr["sigma_theta"][k], arr["tau_rtheta"][k]))
        rs = np.array(sorted(acc))
        vals = np.array([np.mean(acc[x], axis=0) for x in rs])
        data[itf] = (rs, vals)
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "disc-stresses.csv"), "w") as f:
        f.write("interface,r_over_r0,Sr_fe,St_fe,T_fe,Sr_exact,St_exact,T_exact\n")
        for itf, (rs, vals) in data.items():
            ex = closed_form(itf, rs)
            for x, v, e in zip(rs, vals, ex):
                f.write(f"{itf},{x / A:.6g},{v[0]:.6g},{v[1]:.6g},{v[2]:.6g},"
                        f"{e[0]:.6g},{e[1]:.6g},{e[2]:.6g}\n")
    fig, axes = plt.subplots(1, 3, figsize=(14, 4.2))
    labels = [r"$\sigma_r$ at $\theta=0$", r"$\sigma_\theta$ at $\theta=0$",
              r"$\tau_{r\theta}$ at $\theta=\pi/2$"]
    rr = np.linspace(A * 1.0001, R, 400)
    for j, ax in enumerate(axes):
        for itf, col in (("rough", "C0"), ("smooth", "C3")):
            rs, vals = data[itf]
            ex = np.array(closed_form(itf, rr))
            ax.plot(rr / A, ex[:, j], color=col, lw=1.2, label=f"{itf}, closed form")
            ax.plot(rs / A, vals[:, j], "o", ms=3, color=col, mfc="none",
                    label=f"{itf}, FE (VTU)")
        ax.set_xscale("log")
        ax.set_xlabel(r"$r / r_0$")
        ax.set_ylabel("kPa")
        ax.set_title(labels[j])
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=8)
    fig.suptitle(r"Rigid disc in a ring, $\bar u$ = 0.001 D, $\nu_s$ = 0.3, E = 1e5 kPa, "
                 r"R/r$_0$ = 20 (tension +)")
    fig.tight_layout()
    png = os.path.join(args.out, "disc-stresses.png")
    fig.savefig(png, dpi=110)
    print("wrote", png)
    for itf in ("rough", "smooth"):
        rs, vals = data[itf]
        ex = np.array(closed_form(itf, rs))
        m = rs / A >= 1.5
        err = np.max(np.abs(vals[m] - ex[m]), axis=0) / np.max(np.abs(ex[m]), axis=0)
        print(f"{itf}: max |FE - exact| / max |exact| for r/r0 >= 1.5: "
              f"Sr {err[0]:.1e}, St {err[1]:.1e}, T {err[2]:.1e}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
