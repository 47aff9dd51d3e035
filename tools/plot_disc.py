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
"""
import argparse
import base64
import os
import re
import struct
import subprocess
import sys
import tempfile
import zlib
from collections import defaultdict

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


def closed_form(interface, r):
    """Plane strain n = 1 amplitudes (Sr, St, T) from the ansatz of doc/disc.md."""
    lam = E * NU / ((1 + NU) * (1 - 2 * NU))
    mu = E / (2 * (1 + NU))
    kap = 3 - 4 * NU
    c = (4 * NU - 1) / (4 * NU - 5)

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
    return [np.array([s @ b for s in stresses(x)]) for x in r]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", default=os.path.join(ROOT, "build/fourier-ssi"))
    ap.add_argument("--out", default=os.path.join(ROOT, "doc/figures"))
    args = ap.parse_args()
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
