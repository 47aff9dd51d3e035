"""CalculiX (ccx) input decks for the two capacity problems of
benchmarks/nonlinear-accuracy/calculix/run.py, written directly from Python
as structured meshes (no mesher):

* disc_deck: the plane-strain rigid disc in a ring (prm/disc-tresca.prm,
  and elastic, prm/disc-rough.prm), half model y >= 0, CPE8R, the disc face
  nodes given the disc's motion (rough, fully bonded), the outer ring fixed.
* pile_deck: the free-head rigid pile at a free surface
  (prm/pile-free-head.prm), half model y >= 0, C3D20R, the soil only; the
  nodes of the pile's shaft and base follow one rigid motion (translation
  U, W and rotation phi about the y axis, linear *EQUATION constraints),
  U prescribed at the head (z = 0), W and phi free (V = 0, M = 0).

Coordinates: x is the load direction, y across it (the half model keeps
y >= 0, symmetry u_y = 0 on y = 0), z vertical up (pile: ground surface at
z = 0). Units kN, m, kPa.

Both generators build 8-node quadrilaterals in the (x, y) plane from
blocks sampled at twice the cell resolution (so mid-side nodes lie on the
curves: arcs stay arcs), merge the blocks' nodes by position, orient every
element counter-clockwise, and (pile) extrude in z to 20-node bricks.
"""
import math


# ----------------------------------------------------------------- grading

def graded(x0, x1, n, first):
    """n + 1 breakpoints from x0 to x1, geometric, the first cell of
    length `first` (uniform if that is n times too long)."""
    length = x1 - x0
    if first * n >= length * (1 - 1e-12):
        return [x0 + length * i / n for i in range(n + 1)]
    lo, hi = 1.0, 10.0
    for _ in range(200):
        g = 0.5 * (lo + hi)
        if first * (g ** n - 1) / (g - 1) > length:
            hi = g
        else:
            lo = g
    g = 0.5 * (lo + hi)
    points = [x0]
    h = first
    for _ in range(n):
        points.append(points[-1] + h)
        h *= g
    scale = length / (points[-1] - x0)
    return [x0 + (p - x0) * scale for p in points]


def doubled(points):
    """The breakpoints with the midpoint of every cell inserted: the
    positions of the corner and mid-side nodes along a graded line."""
    out = []
    for a, b in zip(points[:-1], points[1:]):
        out += [a, 0.5 * (a + b)]
    return out + [points[-1]]


# ------------------------------------------------------------ 2D assembly

class QuadMesh:
    """8-node quadrilaterals in the plane, nodes merged by position."""

    def __init__(self, tol=1e-9):
        self.xy = []
        self.tol = tol
        self.grid = {}
        self.quads = []   # (8 node indices, tag)

    def node(self, x, y):
        kx, ky = int(round(x / 1e-6)), int(round(y / 1e-6))
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for i in self.grid.get((kx + dx, ky + dy), ()):
                    px, py = self.xy[i]
                    if abs(px - x) < self.tol and abs(py - y) < self.tol:
                        return i
        self.xy.append((x, y))
        self.grid.setdefault((kx, ky), []).append(len(self.xy) - 1)
        return len(self.xy) - 1

    def block(self, points, tag):
        """points[i][j]: (2 ns + 1) x (2 nt + 1) positions of a block at
        twice its cell resolution; adds its ns x nt quadrilaterals."""
        ns = (len(points) - 1) // 2
        nt = (len(points[0]) - 1) // 2
        ids = [[self.node(*points[i][j]) for j in range(2 * nt + 1)]
               for i in range(2 * ns + 1)]
        for a in range(ns):
            for b in range(nt):
                i, j = 2 * a, 2 * b
                q = [ids[i][j], ids[i + 2][j], ids[i + 2][j + 2],
                     ids[i][j + 2], ids[i + 1][j], ids[i + 2][j + 1],
                     ids[i + 1][j + 2], ids[i][j + 1]]
                if self.area(q) < 0:
                    q = [q[0], q[3], q[2], q[1], q[7], q[6], q[5], q[4]]
                assert self.area(q) > 0
                self.quads.append((q, tag))

    def area(self, q):
        p = [self.xy[k] for k in q[:4]]
        return 0.5 * sum(p[k][0] * p[(k + 1) % 4][1] -
                         p[(k + 1) % 4][0] * p[k][1] for k in range(4))


def polar_block(radii, angles):
    """Positions of a polar block: radii and angles already doubled."""
    return [[(r * math.cos(t), r * math.sin(t)) for t in angles]
            for r in radii]


def half_disc_with_core(mesh, r0, m, k, a_frac=0.5):
    """The half disc r <= r0, y >= 0, as an O-grid: a core rectangle
    [-a, a] x [0, a] (2m x m cells, a = a_frac r0) and three blocks of k
    cells between its sides and the arc (m, 2m, m cells along the arc at
    uniform angle). Tagged 'core'."""
    a = a_frac * r0
    # The core rectangle.
    xs = [-a + 2 * a * i / (4 * m) for i in range(4 * m + 1)]
    ys = [a * j / (2 * m) for j in range(2 * m + 1)]
    mesh.block([[(x, y) for y in ys] for x in xs], "core")
    # The three blocks between the rectangle's sides and the arc; t runs
    # along the side (twice the resolution), s from the side to the arc.
    sides = [
        (lambda t: (a, a * t), lambda t: 0.25 * math.pi * t, m),
        (lambda t: (a * (1 - 2 * t), a), lambda t: 0.25 * math.pi +
         0.5 * math.pi * t, 2 * m),
        (lambda t: (-a, a * (1 - t)), lambda t: 0.75 * math.pi +
         0.25 * math.pi * t, m),
    ]
    for side, angle, n in sides:
        pts = []
        for i in range(2 * k + 1):
            s = i / (2. * k)
            row = []
            for j in range(2 * n + 1):
                t = j / (2. * n)
                sx, sy = side(t)
                cx, cy = r0 * math.cos(angle(t)), r0 * math.sin(angle(t))
                row.append(((1 - s) * sx + s * cx, (1 - s) * sy + s * cy))
            pts.append(row)
        mesh.block(pts, "core")


# ------------------------------------------------------------ deck writing

def lines_of(values, per_line=16):
    values = list(values)
    return "\n".join(", ".join(str(v) for v in values[i:i + per_line])
                     for i in range(0, len(values), per_line))


def material(E, nu, sigma_y):
    text = "*MATERIAL, NAME=CLAY\n*ELASTIC\n%.10g, %.10g\n" % (E, nu)
    if sigma_y is not None:
        # One line: sigma_y at zero plastic strain, perfectly plastic.
        text += "*PLASTIC\n%.10g, 0.\n" % sigma_y
    return text


def step_block(increments, boundary, prints, nonlinear):
    """One *STEP of `increments` equal increments of the prescribed motion
    (ccx may cut them), printing `prints` at every increment."""
    text = "*STEP, INC=%d\n" % (40 * increments)
    if nonlinear:
        # Start at a quarter of the increment (the first yield), let ccx
        # grow it to at most 1 / increments and cut it where needed.
        text += "*STATIC\n%.6g, 1., %.6g, %.6g\n" % (
            0.25 / increments, 1e-4 / increments, 1. / increments)
    else:
        text += "*STATIC\n"
    text += "*BOUNDARY\n" + boundary + prints + "*END STEP\n"
    return text


# ------------------------------------------------------------------- disc

def disc_deck(n_theta, n_r, r0=0.5, R=5., E=8940., nu=0.49, sigma_y=None,
              ubar=0.05, increments=10, first_ratio=1.0):
    """The rigid disc of radius r0 in a plane-strain ring to R, half model
    (0 <= theta <= pi, n_theta cells), n_r radial cells graded from a first
    cell of first_ratio times the arc cell at r0. The disc face nodes move
    by (ubar, 0) (rough, bonded), r = R fixed. Returns the deck and a dict
    of sizes and node sets."""
    mesh = QuadMesh()
    first = first_ratio * r0 * math.pi / n_theta
    radii = doubled(graded(r0, R, n_r, first))
    angles = [math.pi * j / (2 * n_theta) for j in range(2 * n_theta + 1)]
    mesh.block(polar_block(radii, angles), "soil")
    used = sorted({i for q, _ in mesh.quads for i in q})
    number = {i: k + 1 for k, i in enumerate(used)}
    disc, outer, sym = [], [], []
    for i in used:
        x, y = mesh.xy[i]
        r = math.hypot(x, y)
        if abs(r - r0) < 1e-9:
            disc.append(number[i])
        elif abs(r - R) < 1e-9:
            outer.append(number[i])
        elif abs(y) < 1e-12:
            sym.append(number[i])
    deck = ["*HEADING\nrigid disc in a ring, plane strain, half model "
            "(fourier-ssi benchmarks/nonlinear-accuracy/calculix)\n*NODE\n"]
    deck.append("\n".join("%d, %.12g, %.12g, 0." % (number[i], *mesh.xy[i])
                          for i in used) + "\n")
    deck.append("*ELEMENT, TYPE=CPE8R, ELSET=SOIL\n")
    deck.append("\n".join("%d, %s" % (e + 1, ", ".join(
        str(number[i]) for i in q)) for e, (q, _) in
        enumerate(mesh.quads)) + "\n")
    for name, ids in (("NDISC", disc), ("NOUT", outer), ("NSYM", sym)):
        deck.append("*NSET, NSET=%s\n%s\n" % (name, lines_of(sorted(ids))))
    deck.append(material(E, nu, sigma_y))
    deck.append("*SOLID SECTION, ELSET=SOIL, MATERIAL=CLAY\n1.\n")
    deck.append("*BOUNDARY\nNOUT, 1, 2\nNSYM, 2, 2\nNDISC, 2, 2\n")
    deck.append(step_block(
        increments if sigma_y is not None else 1,
        "NDISC, 1, 1, %.10g\n" % ubar,
        "*NODE PRINT, NSET=NDISC, TOTALS=ONLY\nRF\n", sigma_y is not None))
    return "".join(deck), {"nodes": len(used), "elements": len(mesh.quads),
                           "ubar": ubar}


# ------------------------------------------------------------------- pile

def pile_deck(m, k, n_r, nz_pile, nz_below, r0=0.5, R=10., L=10.,
              depth=15., E=8940., nu=0.49, sigma_y=17.32050808,
              u_head=0.1, increments=10, first_ratio=1.0):
    """The free-head rigid pile (radius r0, length L, head at z = 0) in a
    soil cylinder of radius R down to z = -depth, half model y >= 0. The
    section: an O-grid of the half disc r <= r0 (m: cells per eighth of
    the circle, k: cells from the core to the arc) and a polar ring to R
    of n_r graded cells; in z nz_pile uniform cells along the pile and
    nz_below cells below its tip, graded to the tip's cell size. The
    pile's cells are left out; the nodes of its shaft and base follow one
    rigid motion. Returns the deck and a dict of sizes."""
    mesh = QuadMesh()
    half_disc_with_core(mesh, r0, m, k)
    n_theta = 4 * m
    first = first_ratio * r0 * math.pi / n_theta
    radii = doubled(graded(r0, R, n_r, first))
    angles = [math.pi * j / (2 * n_theta) for j in range(2 * n_theta + 1)]
    mesh.block(polar_block(radii, angles), "ring")
    dz = L / nz_pile
    z_pile = [-L + L * i / nz_pile for i in range(nz_pile + 1)]
    # Below the tip: graded from the tip (cell dz) downwards.
    z_below = [-L - (z - 0.) for z in graded(0., depth - L, nz_below, dz)]
    z_nodes = doubled(sorted(z_below[1:]) + z_pile)
    nz = (len(z_nodes) - 1) // 2
    n2d = len(mesh.xy)

    def nid(i2d, kz):
        return kz * n2d + i2d

    bricks = []
    for q, tag in mesh.quads:
        for c in range(nz):
            k0, k1, k2 = 2 * c, 2 * c + 1, 2 * c + 2
            zc = z_nodes[k1]
            if tag == "core" and zc > -L:
                continue   # inside the pile: not meshed
            bricks.append([nid(i, k0) for i in q[:4]] +
                          [nid(i, k2) for i in q[:4]] +
                          [nid(i, k0) for i in q[4:]] +
                          [nid(i, k2) for i in q[4:]] +
                          [nid(i, k1) for i in q[:4]])
    used = sorted({i for b in bricks for i in b})
    number = {i: j + 1 for j, i in enumerate(used)}
    ref, rot = len(used) + 1, len(used) + 2

    def coords(i):
        x, y = mesh.xy[i % n2d]
        return x, y, z_nodes[i // n2d]

    pile, fixed, sym = [], [], []
    for i in used:
        x, y, z = coords(i)
        r = math.hypot(x, y)
        if r < r0 + 1e-9 and z > -L - 1e-9:
            pile.append(i)
        elif abs(r - R) < 1e-9 or abs(z + depth) < 1e-9:
            fixed.append(number[i])
        elif abs(y) < 1e-12:
            sym.append(number[i])
    deck = ["*HEADING\nfree-head rigid pile in clay, half model "
            "(fourier-ssi benchmarks/nonlinear-accuracy/calculix)\n*NODE\n"]
    deck.append("\n".join("%d, %.12g, %.12g, %.12g" % (number[i], *coords(i))
                          for i in used) + "\n")
    # The pile's two motion carriers: ref (U in x, W in z, at the head
    # centre) and rot (its x DoF carries the rotation phi about y).
    deck.append("%d, 0., 0., 0.\n%d, 0., 0., 0.\n" % (ref, rot))
    deck.append("*ELEMENT, TYPE=C3D20R, ELSET=SOIL\n")
    out = []
    for e, b in enumerate(bricks):
        ids = [str(number[i]) for i in b]
        out.append("%d, %s,\n%s" % (e + 1, ", ".join(ids[:15]),
                                     ", ".join(ids[15:])))
    deck.append("\n".join(out) + "\n")
    for name, ids in (("NPILE", [number[i] for i in pile]),
                      ("NFIX", fixed), ("NSYM", sym), ("NREF", [ref]),
                      ("NROT", [rot])):
        deck.append("*NSET, NSET=%s\n%s\n" % (name, lines_of(sorted(ids))))
    deck.append(material(E, nu, sigma_y))
    deck.append("*SOLID SECTION, ELSET=SOIL, MATERIAL=CLAY\n")
    # Rigid motion of the pile's nodes: u_x = U + phi z, u_z = W - phi x,
    # u_y = 0 (the symmetry of the half model).
    eqs = ["*EQUATION"]
    for i in pile:
        x, y, z = coords(i)
        n = number[i]
        for dof, ref_dof, coef in ((1, 1, -z), (3, 3, x)):
            if abs(coef) > 1e-12:
                eqs.append("3\n%d, %d, 1., %d, %d, -1., %d, 1, %.12g"
                           % (n, dof, ref, ref_dof, rot, coef))
            else:
                eqs.append("2\n%d, %d, 1., %d, %d, -1." % (n, dof, ref,
                                                            ref_dof))
    deck.append("\n".join(eqs) + "\n")
    deck.append("*BOUNDARY\nNFIX, 1, 3\nNSYM, 2, 2\nNPILE, 2, 2\n"
                "NREF, 2, 2\nNROT, 2, 3\n")
    deck.append(step_block(
        increments if sigma_y is not None else 1,
        "NREF, 1, 1, %.10g\n" % u_head,
        "*NODE PRINT, NSET=NPILE, TOTALS=ONLY\nRF\n"
        "*NODE PRINT, NSET=NREF\nU\n*NODE PRINT, NSET=NROT\nU\n",
        sigma_y is not None))
    return "".join(deck), {"nodes": len(used), "elements": len(bricks),
                           "u_head": u_head}
