"""A 1D Timoshenko beam on nonlinear soil-reaction springs (the PISA 1D
model): finite elements along the pile, Newton's method on the springs.

Coordinates: z is the elevation, 0 at the mudline (the pile's head, where H
and M act) and -L at the tip.  Each node carries the lateral displacement v
[m] along +x and the rotation psi [rad] of the cross-section about +y, psi >
0 when the head moves along +x relative to the tip (the convention of
soil-reaction-curves.csv).  The beam's energy is

    1/2 int EI (dpsi/dz)^2 + kappa G A (dv/dz - psi)^2 dz,

two-node elements with linear v and psi: bending integrated exactly, shear
with one Gauss point (reduced: no shear locking).  The soil works on the
pile through

    p(v, z)  [kN/m]    and  m(psi, z, v) [kN m/m]  (two Gauss points per element),
    H_B(v_tip) [kN]    and  M_B(psi_tip) [kN m] at the tip node,

each given as a function returning (value, derivative); m returns (value,
dm/dpsi, dm/dv), since a sand's m scales with the local p(v).  They
resist, so they enter the internal force with a + sign.  The head takes H = lam and
M = lam h (a load at height h above the mudline), driven either by lam
(load control) or by the mudline's v (displacement control; lam then
follows from the head's equation, a bordered Newton system)."""
import numpy as np


class Pile:
    """A steel tube: D [m] outer diameter, t [m] wall, L [m] embedded, E
    [kPa], nu; the shear coefficient kappa of a thin circular tube,
    2 (1 + nu) / (4 + 3 nu) (Cowper 1966)."""

    def __init__(self, D, t, L, E=2.1e8, nu=0.3, kappa=None):
        self.D, self.t, self.L = D, t, L
        ri = D / 2 - t
        self.EI = E * np.pi / 64.0 * (D ** 4 - (2 * ri) ** 4)
        A = np.pi / 4.0 * (D ** 2 - (2 * ri) ** 2)
        k = 2 * (1 + nu) / (4 + 3 * nu) if kappa is None else kappa
        self.kGA = k * E / (2 * (1 + nu)) * A


class Beam:
    def __init__(self, EI, kGA, L, n_elements, p=None, m=None, HB=None, MB=None):
        self.EI, self.kGA, self.L = EI, kGA, L
        self.ne = n_elements
        self.z = np.linspace(0.0, -L, n_elements + 1)
        self.p, self.m, self.HB, self.MB = p, m, HB, MB
        nd = 2 * (n_elements + 1)
        K = np.zeros((nd, nd))
        for e in range(n_elements):
            h = self.z[e] - self.z[e + 1]
            # element DoFs (v_a, psi_a, v_b, psi_b), a at the upper node;
            # d/dz with z decreasing from a to b: dv/dz = (v_a - v_b)/h
            g = np.array([1.0 / h, -0.5, -1.0 / h, -0.5])   # dv/dz - psi at the middle
            b = np.array([0.0, 1.0 / h, 0.0, -1.0 / h])     # dpsi/dz
            ke = EI * h * np.outer(b, b) + kGA * h * np.outer(g, g)
            idx = np.arange(2 * e, 2 * e + 4)
            K[np.ix_(idx, idx)] += ke
        self.K = K
        gp = np.array([-1.0, 1.0]) / np.sqrt(3.0)
        # Gauss points: z, weight, and the shape values of the upper node
        self.gauss = []
        for e in range(n_elements):
            h = self.z[e] - self.z[e + 1]
            for xi in gp:
                Na = 0.5 * (1 - xi)
                self.gauss.append((e, self.z[e] * Na + self.z[e + 1] * (1 - Na), 0.5 * h, Na))
        self._ge = np.array([g[0] for g in self.gauss])
        self._gz = np.array([g[1] for g in self.gauss])
        self._gw = np.array([g[2] for g in self.gauss])
        self._gN = np.array([g[3] for g in self.gauss])

    def soil(self, u):
        """The springs' internal force and tangent at the displacements u
        (the spring functions are called once with all Gauss points)."""
        nd = u.size
        f = np.zeros(nd)
        T = np.zeros((nd, nd))
        e = self._ge
        Na, w, zg = self._gN, self._gw, self._gz
        va, vb = 2 * e, 2 * e + 2
        v_gauss = Na * u[va] + (1 - Na) * u[vb]

        def add(rows, cols, val, der):
            """The spring's force on DoFs `rows` (a, b) and its derivative
            with respect to the DoFs `cols` (a, b), interpolated alike."""
            der = np.broadcast_to(der, Na.shape)
            ra, rb = rows
            ca, cb = cols
            if val is not None:
                np.add.at(f, ra, w * val * Na)
                np.add.at(f, rb, w * val * (1 - Na))
            np.add.at(T, (ra, ca), w * der * Na * Na)
            np.add.at(T, (ra, cb), w * der * Na * (1 - Na))
            np.add.at(T, (rb, ca), w * der * Na * (1 - Na))
            np.add.at(T, (rb, cb), w * der * (1 - Na) * (1 - Na))

        if self.p is not None:
            val, der = self.p(v_gauss, zg)
            add((va, vb), (va, vb), val, der)
        if self.m is not None:
            # m may depend on v as well (sand: m scales with |p|), which
            # makes the tangent unsymmetric
            pa, pb = va + 1, vb + 1
            val, der_psi, der_v = self.m(Na * u[pa] + (1 - Na) * u[pb], zg, v_gauss)
            add((pa, pb), (pa, pb), val, der_psi)
            add((pa, pb), (va, vb), None, der_v)
        it = 2 * self.ne
        if self.HB is not None:
            val, der = self.HB(u[it])
            f[it] += val
            T[it, it] += der
        if self.MB is not None:
            val, der = self.MB(u[it + 1])
            f[it + 1] += val
            T[it + 1, it + 1] += der
        return f, T

    def head_vector(self, h):
        fh = np.zeros(self.K.shape[0])
        fh[0], fh[1] = 1.0, h
        return fh

    def solve_load(self, H, M, u0=None, tol=1e-10, max_iter=100):
        """Load control: the displacements under H [kN] and M [kN m] at the
        head."""
        f_ext = np.zeros(self.K.shape[0])
        f_ext[0], f_ext[1] = H, M
        u = np.zeros_like(f_ext) if u0 is None else u0.copy()
        for _ in range(max_iter):
            fs, T = self.soil(u)
            r = self.K @ u + fs - f_ext
            if np.linalg.norm(r) <= tol * max(np.linalg.norm(f_ext), 1e-30):
                return u
            du = np.linalg.solve(self.K + T, r)
            u -= du
            if np.linalg.norm(du) <= 1e-9 * np.linalg.norm(u):
                return u
        raise RuntimeError("beam: Newton did not converge under load control")

    def push(self, target, h, steps, tol=1e-10, max_iter=50, max_cuts=8):
        """Displacement control: the mudline's v from 0 to target [m] in equal
        steps, H = lam, M = lam h; a step whose Newton fails is cut in halves
        (at most max_cuts times).  Returns arrays v0, psi0 [rad], H [kN],
        M [kN m] at the head, the origin first."""
        nd = self.K.shape[0]
        fh = self.head_vector(h)
        u = np.zeros(nd)
        lam = 0.0
        free = np.arange(1, nd)
        out = [(0.0, 0.0, 0.0, 0.0)]

        def newton(u, lam, v0):
            u = u.copy()
            u[0] = v0
            for it in range(max_iter):
                fs, T = self.soil(u)
                r = self.K @ u + fs - lam * fh
                scale = max(abs(lam), 1e-12) * np.linalg.norm(fh) + 1e-30
                if np.linalg.norm(r) <= tol * scale and it > 0:
                    return u, lam
                J = np.column_stack([(self.K + T)[:, free], -fh])
                d = np.linalg.solve(J, -r)
                u[free] += d[:-1]
                lam += d[-1]
                if not np.all(np.isfinite(u)):
                    return None
                if np.linalg.norm(d[:-1]) <= 1e-9 * np.linalg.norm(u) and abs(d[-1]) <= 1e-9 * abs(lam):
                    return u, lam
            return None

        for s in range(1, steps + 1):
            goal = target * s / steps
            cuts = 0
            while u[0] < goal * (1 - 1e-12):
                dv = (goal - u[0]) if cuts == 0 else (target / steps) / 2 ** cuts
                res = newton(u, lam, min(goal, u[0] + dv))
                if res is None:
                    cuts += 1
                    if cuts > max_cuts:
                        raise RuntimeError(f"beam: Newton did not converge at step {s} (v = {u[0] + dv:.4g} m) "
                                           f"after {max_cuts} cuts")
                    continue
                u, lam = res
            out.append((u[0], u[1], lam, lam * h))
        return tuple(np.array(c) for c in zip(*out))
