"""The calibrated PISA model of a site: its four components' parameters
linear in z/D (p-v, m-psi) or L/D (H_B-v, M_B-psi), the soil profile s(z),
G0(z) read from the FE runs, and the springs of one pile for beam.py.

Clay normalisations (Byrne et al. 2020), s = s_u:
    p-v:    p/(s_u D)     against v G0/(s_u D)
    m-psi:  m/(s_u D^2)   against psi G0/s_u
    H_B-v:  H_B/(s_u D^2) against v G0/(s_u D)
    M_B-psi: M_B/(s_u D^3) against psi G0/s_u
Sand normalisations (Burd et al. 2020), s = sigma'_v: the same with
sigma'_v for s_u, except that the distributed moment is scaled by the
local lateral reaction,
    m-psi:  m/(|p| D)     against psi G0/sigma'_v,
so that m depends on v through p as well as on psi.  s and G0 are taken at
the depth (at the tip for the base)."""
import json

import numpy as np

from conic import conic, conic_slope
from fit import linear

COMPONENTS = ("py", "mt", "Hb", "Mb")
# the soil kind of a calibration: the normaliser's name in
# soil-reaction-curves.csv ("normalised by") and the model's name for it
SOIL_KINDS = {"s_u": "clay", "sigma'_v": "sand"}


class Model:
    def __init__(self, params, profile, soil_kind="clay"):
        """params[c] = dict(layers=[dict(top, bottom, s0, s1), ...]) (one
        fit_linear_family per layer of s; the base components one layer);
        profile = dict(depth, s, G): arrays [m], [kPa], [kPa], s = s_u
        (clay) or sigma'_v (sand)."""
        if soil_kind not in SOIL_KINDS.values():
            raise ValueError(f"soil kind '{soil_kind}' is not one of {', '.join(SOIL_KINDS.values())}")
        self.params = params
        self.profile = {k: np.asarray(v, float) for k, v in profile.items()}
        self.soil_kind = soil_kind

    def to_json(self, path, extra=None):
        d = dict(params=self.params, profile={k: v.tolist() for k, v in self.profile.items()},
                 soil_kind=self.soil_kind)
        d.update(extra or {})
        with open(path, "w") as f:
            json.dump(d, f, indent=1)

    @classmethod
    def from_json(cls, path):
        with open(path) as f:
            d = json.load(f)
        return cls(d["params"], d["profile"], d.get("soil_kind", "clay"))

    def soil(self, depth):
        """s [kPa] (s_u or sigma'_v) and G0 [kPa] at depth [m] (linear
        between the FE's depths, linear to zero at the mudline for sand's
        sigma'_v, constant beyond)."""
        order = np.argsort(self.profile["depth"])
        dz = self.profile["depth"][order]
        s = self.profile["s"][order]
        if self.soil_kind == "sand":
            s_above = np.interp(depth, [0.0, dz[0]], [0.0, s[0]])
            return (np.where(np.asarray(depth) < dz[0], s_above, np.interp(depth, dz, s)),
                    np.interp(depth, dz, self.profile["G"][order]))
        return np.interp(depth, dz, s), np.interp(depth, dz, self.profile["G"][order])

    def at(self, component, s, L_over_D=None):
        """(k, n, x_u, y_u) of a component at s (z/D or L/D), linear in s
        within each layer (clamped to the calibrated range: no
        extrapolation); s may be an array.  A layer whose 'yu_over' is
        'z/L' has y_u linear in z/L = s / L_over_D between 0 (top) and 1
        (bottom), so the pile's L/D is needed."""
        layers = self.params[component]["layers"]
        s = np.clip(np.asarray(s, float), layers[0]["s0"], layers[-1]["s1"])
        out = [np.zeros_like(s) for _ in range(4)]
        for i, ly in enumerate(layers):
            inside = (s >= ly["s0"]) & ((s < ly["s1"]) | (i == len(layers) - 1))
            for j, q in enumerate(("k", "n", "xu", "yu")):
                if q == "yu" and ly.get("yu_over") == "z/L":
                    if L_over_D is None:
                        raise ValueError(f"{component}: y_u varies with z/L; the pile's L/D is needed")
                    value = linear(ly["top"][q], ly["bottom"][q], np.clip(s / L_over_D, 0.0, 1.0), 0.0, 1.0)
                else:
                    value = linear(ly["top"][q], ly["bottom"][q], s, ly["s0"], ly["s1"])
                out[j] = np.where(inside, value, out[j])
        return tuple(float(o) if o.ndim == 0 else o for o in out)

    def springs(self, D, L):
        """The functions p(v, z), m(psi, z, v), H_B(v), M_B(psi) of
        beam.Beam for a pile of diameter D [m] and embedded length L [m].
        m returns (m, dm/dpsi, dm/dv): dm/dv = 0 for clay; for sand
        m = |p(v)| D mbar(psi G0/sigma'_v), so dm/dv = sign(p) p'(v) D mbar."""
        def p(v, z):
            depth = -z
            su, G = self.soil(depth)
            k, n, xu, yu = self.at("py", depth / D, L / D)
            x = v * G / (su * D)
            return su * D * conic(x, k, n, xu, yu), G * conic_slope(x, k, n, xu, yu)

        def m(psi, z, v):
            depth = -z
            su, G = self.soil(depth)
            k, n, xu, yu = self.at("mt", depth / D, L / D)
            x = psi * G / su
            if self.soil_kind == "clay":
                return (su * D * D * conic(x, k, n, xu, yu), D * D * G * conic_slope(x, k, n, xu, yu),
                        np.zeros_like(x))
            lateral, lateral_slope = p(v, z)
            mbar = conic(x, k, n, xu, yu)
            return (np.abs(lateral) * D * mbar, np.abs(lateral) * D * G / su * conic_slope(x, k, n, xu, yu),
                    np.sign(lateral) * lateral_slope * D * mbar)

        sb, Gb = self.soil(L)
        base_H = self.at("Hb", L / D)
        base_M = self.at("Mb", L / D)

        def HB(v):
            x = v * Gb / (sb * D)
            return sb * D * D * conic(x, *base_H), D * Gb * conic_slope(x, *base_H)

        def MB(psi):
            x = psi * Gb / sb
            return sb * D ** 3 * conic(x, *base_M), D ** 3 * Gb * conic_slope(x, *base_M)

        return p, m, HB, MB


class OwnCurvesModel(Model):
    """One pile's own per-curve conics (fit.fit_curve), linear in depth
    between the curves' depths and constant beyond: the 1D model without
    the depth and L/D fits, to tell the error of the conic and the beam from
    that of the fitted depth variation."""

    def __init__(self, own, profile, D, soil_kind="clay"):
        """own[c] = list of (z/D, (k, n, x_u, y_u)) for py, mt; own['Hb'],
        own['Mb'] = (k, n, x_u, y_u) of the pile's base."""
        super().__init__({}, profile, soil_kind)
        self.own = own
        self.D = D

    def at(self, component, s, L_over_D=None):
        if component in ("Hb", "Mb"):
            return self.own[component]
        pts = sorted(self.own[component])
        zs = np.array([p[0] for p in pts])
        vals = np.array([p[1] for p in pts])
        return tuple(np.interp(s, zs, vals[:, i]) for i in range(4))
