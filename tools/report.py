#!/usr/bin/python3
"""One A4 page per run, read at a glance (doc/report.md): the geometry, the
load-displacement curve with its plateau and error bar, the interface state
around the circumference, the yielding of the soil and its plastic zone in
the loading plane, and the goal values with their units and error bars.

    /usr/bin/python3 tools/report.py OUTPUT_DIR [--prm PRM] [-o report.png]

It reads what the run left in OUTPUT_DIR (results.csv; load-displacement.csv
of a nonlinear run; interface-state.csv of a run with coulomb interfaces)
and the plastic field of the plane theta = 0 of plastic soil
(plastic-field-theta0-step<s>.vtu, the latest step; read with the standard
library and numpy, no VTK module), and, with --prm, the scene's Mesh,
Materials, Interfaces, Rigid foundation and Boundary conditions entries for
the geometry. A panel whose data the run
did not write is left out and named under "not shown" with the reason.

Besides the PNG it prints, one line each, the panels drawn, the panels left
out, and every goal value as it stands on the page next to the full value
read from results.csv (tests/report_page.py compares them).

Needs Debian's python3-matplotlib and python3-numpy (under /usr/bin/python3).
"""
import argparse
import csv
import math
import os
import re
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.gridspec import GridSpec  # noqa: E402
from matplotlib.patches import Patch, Rectangle  # noqa: E402

STATES = ["stick", "slip", "open"]
STATE_COLOURS = {"stick": "#4c72b0", "slip": "#dd8452", "open": "#c44e52"}
# load-displacement.csv: the load column and the motion column of each
# controllable motion (Load path/Controlled motion).
CURVE_COLUMNS = {"vertical": ("V", "V_kN", "vertical_m", "kN", "m"),
                 "horizontal": ("H", "H_kN", "horizontal_m", "kN", "m"),
                 "rotation": ("M", "M_kNm", "rotation_rad", "kN.m", "rad"),
                 "twist": ("T", "T_kNm", "twist_rad", "kN.m", "rad")}
# A stiffness K = F / u is computed at a prescribed load F, so its relative
# error is the relative error of its motion u (first order).
MOTION_OF_STIFFNESS = {"vertical": "foundation_vertical_displacement",
                       "horizontal": "foundation_horizontal_displacement",
                       "rocking": "foundation_rotation",
                       "torsional": "foundation_twist"}
PAGE_INCHES = (8.27, 11.69)  # A4 portrait
VALUE_FORMAT, BAR_FORMAT = "%.6g", "%.2g"


def fail(message):
    sys.exit("report.py: " + message)


# ---------------------------------------------------------------- reading


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def read_results(directory):
    path = os.path.join(directory, "results.csv")
    if not os.path.isfile(path):
        fail(path + ": missing (not an output folder of a finished run?)")
    rows = read_csv(path)
    if not rows or "quantity" not in rows[0]:
        fail(path + ": no rows quantity,n,family,cycle,value,unit")
    return rows


def read_prm(path):
    """The prm's entries as {"Subsection/Key": value} (innermost subsection
    names joined by '/'), comments and line continuations handled."""
    entries, sections, pending = {}, [], ""
    with open(path) as f:
        for raw in f:
            line = pending + raw.split("#", 1)[0].rstrip()
            pending = ""
            if line.endswith("\\"):
                pending = line[:-1] + " "
                continue
            words = line.split()
            if not words:
                continue
            if words[0] == "subsection":
                sections.append(" ".join(words[1:]))
            elif words[0] == "end":
                sections.pop()
            elif words[0] == "set" and "=" in line:
                key, value = line.split("=", 1)
                key = " ".join(key.split()[1:])
                entries["/".join(sections + [key])] = value.strip()
    return entries


# The Mesh entries' defaults (doc/parameters.prm), for a prm that omits them.
MESH_DEFAULTS = {"Mesh/R breakpoints": "0, 1", "Mesh/R cells": "4",
                 "Mesh/R growth": "1", "Mesh/Z breakpoints": "0, 1",
                 "Mesh/Z cells": "4", "Mesh/Z growth": "1"}


def mesh_entry(prm, key):
    return numbers(prm.get(key, MESH_DEFAULTS[key]))


def numbers(text):
    return [float(v) for v in text.split(",") if v.strip()]


def id_items(text):
    """'1: a, b; 2: c' -> [(1, 'a, b'), (2, 'c')]."""
    items = []
    for part in text.split(";"):
        if ":" in part:
            key, value = part.split(":", 1)
            items.append((int(key), value.strip()))
    return items


# ------------------------------------------------------------- goal values


class Goal:
    """One row of the goal table: a value from results.csv with its
    absolute error bar and where the bar comes from."""

    def __init__(self, row, bar, bar_from):
        self.row, self.bar, self.bar_from = row, bar, bar_from
        self.value = float(row["value"])


def row_key(row):
    return (row["quantity"], row["n"], row["family"], row["cycle"])


def find_row(rows, quantity, n, family, cycle=None):
    """The row of quantity at (n, family) and cycle, else its last one."""
    found = [r for r in rows if r["quantity"] == quantity and r["n"] == n
             and r["family"] == family
             and (cycle is None or r["cycle"] == cycle)]
    return found[-1] if found else None


def goals_with_own_bar(rows):
    """Every quantity Q with a row Q_error (relative; the program's error
    estimate under Refinement cycles or Target accuracy)."""
    goals = []
    for e in rows:
        q = e["quantity"]
        if not q.endswith("_error"):
            continue
        row = find_row(rows, q[:-len("_error")], e["n"], e["family"],
                       e["cycle"])
        if row is not None:
            relative = float(e["value"])
            goals.append(Goal(row, relative * abs(float(row["value"])), q))
    return goals


def stiffness_goals(rows, goals):
    """foundation_<case>_stiffness[_normalised]: the bar of its motion."""
    bars = {(g.row["quantity"], g.row["n"], g.row["family"]): g for g in goals}
    found = []
    for row in rows:
        m = re.fullmatch(r"foundation_(\w+?)_stiffness(_normalised)?",
                         row["quantity"])
        if not m or m.group(1) not in MOTION_OF_STIFFNESS:
            continue
        motion = bars.get((MOTION_OF_STIFFNESS[m.group(1)], row["n"],
                           row["family"]))
        if motion is not None and motion.row["cycle"] != row["cycle"]:
            continue  # the stiffness of another cycle than the answer's
        if motion is None and row is not find_row(rows, row["quantity"],
                                                  row["n"], row["family"]):
            continue  # no bar: show the last cycle's value only
        relative = motion.bar / abs(motion.value) if motion else math.nan
        found.append(Goal(row, relative * abs(float(row["value"])),
                          motion.bar_from if motion else ""))
    return found


def capacity_goals(rows, goals):
    """capacity_<L> without a total bar: its plateau's error (absolute)."""
    have = {row_key(g.row) for g in goals}
    found = []
    for row in rows:
        if not re.fullmatch(r"capacity_[VHMT]", row["quantity"]):
            continue
        if row_key(row) in have:
            continue
        plateau = find_row(rows, row["quantity"] + "_plateau_error", row["n"],
                           row["family"], row["cycle"])
        bar = float(plateau["value"]) if plateau else math.nan
        found.append(Goal(row, bar, plateau["quantity"] if plateau else ""))
    return found


def goal_values(rows):
    goals = goals_with_own_bar(rows)
    return goals + stiffness_goals(rows, goals) + capacity_goals(rows, goals)


def bar_parts(goal, rows):
    """The parts of a total bar that results.csv gives (relative):
    <goal>_error_mesh, _harmonics, _plateau (Target accuracy runs)."""
    r = goal.row
    parts = []
    for part in ("mesh", "harmonics", "plateau"):
        row = find_row(rows, goal.bar_from + "_" + part, r["n"], r["family"],
                       r["cycle"])
        if row is not None:
            name = "harm." if part == "harmonics" else part
            parts.append("%s %s" % (name, BAR_FORMAT % float(row["value"])))
    return ", ".join(parts)


def bar_note(goal, rows=()):
    if not goal.bar_from:
        return "no estimate in results.csv"
    if goal.bar_from.endswith("_plateau_error"):
        return "plateau only"
    if goal.bar_from != goal.row["quantity"] + "_error":
        return "its motion's (K = F/u)"
    parts = bar_parts(goal, rows)
    return parts if parts else "estimate"


# ---------------------------------------------------------------- geometry


def graded_edges(breakpoints, cells, growth, refinements):
    """Cell edges of one direction (Mesh/R or Z: h_{i+1} = q h_i within a
    segment, as mesh_builder.cc), each cell split 2^refinements times."""
    edges = [breakpoints[0]]
    for s in range(len(cells)):
        q, m = growth[s], int(cells[s])
        length = breakpoints[s + 1] - breakpoints[s]
        h = length / (m if q == 1. else (q ** m - 1.) / (q - 1.))
        for _ in range(m):
            step = h / 2 ** refinements
            start = edges[-1]
            edges += [start + step * (k + 1) for k in range(2 ** refinements)]
            h *= q
    return np.array(edges)


def material_label(prm, material_id):
    laws = dict(id_items(prm.get("Soil plasticity/Laws", "")))
    elastic = dict(id_items(prm.get("Materials/Materials", "")))
    text = "%d: %s" % (material_id, elastic.get(material_id, "?"))
    if material_id in laws:
        text += "; " + laws[material_id]
    return text


def interface_segments(text):
    """Mesh/Interface lines -> [(id, (r0, r1), (z0, z1))]."""
    segments = []
    for interface, spec in id_items(text):
        coords = {}
        for part in spec.split(","):
            name, value = part.split("=")
            ends = [float(v) for v in value.split("..")]
            coords[name.strip()] = ends if len(ends) == 2 else ends * 2
        segments.append((interface, coords["r"], coords["z"]))
    return segments


def foundation_outline(prm, regions):
    """The rigid foundation: the contact faces (Tie = boundary, id 4: the
    surface patch) or the box of its material (Tie = material)."""
    if prm.get("Rigid foundation/Enabled", "false") != "true":
        return None
    tie = prm.get("Rigid foundation/Tie", "boundary")
    tied = int(prm.get("Rigid foundation/Id", "4"))
    if tie == "material":
        boxes = [box for mid, box in regions if mid == tied]
        return ("material", boxes)
    if tied != 4:  # only the surface patch's faces are known here
        return None
    return ("boundary", float(prm.get("Mesh/Surface patch radius", "0")))


def dirichlet_sides(prm, r_edges, z_edges):
    """The rectangle's sides 1 (far), 2 (bottom) and 3 (top) that have a
    Boundary conditions/Dirichlet entry, as (r, z) end points."""
    sides = {1: ([r_edges[-1]] * 2, [z_edges[0], z_edges[-1]]),
             2: ([r_edges[0], r_edges[-1]], [z_edges[0]] * 2),
             3: ([r_edges[0], r_edges[-1]], [z_edges[-1]] * 2)}
    return [sides[side] for side, _ in
            id_items(prm.get("Boundary conditions/Dirichlet", ""))
            if side in sides]


def mesh_edges(prm, direction):
    refinements = int(prm.get("Mesh/Global refinements", "0"))
    return graded_edges(*[mesh_entry(prm, "Mesh/%s %s" % (direction, key))
                          for key in ("breakpoints", "cells", "growth")],
                        refinements)


def draw_geometry(ax, prm, window, zoomed):
    """Materials, removed regions, cell edges, Dirichlet sides, interface
    lines and the foundation in the (r, z) window; returns the edges and
    the material regions."""
    r, z = mesh_edges(prm, "R"), mesh_edges(prm, "Z")
    regions = [(mid, numbers(box)) for mid, box in
               id_items(prm.get("Mesh/Material regions", ""))]
    colours = plt.get_cmap("Pastel1")
    ax.add_patch(Rectangle((r[0], z[0]), r[-1] - r[0], z[-1] - z[0],
                           fc=colours(0), ec="none"))
    for mid, (r0, r1, z0, z1) in regions:
        ax.add_patch(Rectangle((r0, z0), r1 - r0, z1 - z0,
                               fc=colours(mid % 9), ec="none"))
    for box in prm.get("Mesh/Removed regions", "").split(";"):
        if box.strip():
            r0, r1, z0, z1 = numbers(box)
            ax.add_patch(Rectangle((r0, z0), r1 - r0, z1 - z0, fc="white",
                                   ec="0.5", hatch="////", lw=0.5))
    ax.vlines(r, z[0], z[-1], colors="0.55", lw=0.25)
    ax.hlines(z, r[0], r[-1], colors="0.55", lw=0.25)
    for rs, zs in dirichlet_sides(prm, r, z):
        ax.plot(rs, zs, color="#2a9d8f", lw=3, solid_capstyle="butt")
    for interface, rs, zs in interface_segments(
            prm.get("Mesh/Interface lines", "")):
        ax.plot(rs, zs, color="#c44e52", lw=2.2)
    draw_foundation(ax, foundation_outline(prm, regions), r[0], z[-1])
    ax.set_xlim(window[0], window[1])
    ax.set_ylim(window[2], window[3])
    ax.set_xlabel("r [m]", fontsize=7)
    ax.set_ylabel("z [m]", fontsize=7)
    ax.tick_params(labelsize=6)
    ax.set_title("near the foundation" if zoomed else "whole domain",
                 fontsize=7)
    return r, z, regions


def draw_foundation(ax, outline, r_axis, z_top):
    if outline is None:
        return
    kind, where = outline
    if kind == "boundary":
        ax.plot([r_axis, where], [z_top, z_top], color="k", lw=4,
                solid_capstyle="butt")
        return
    for r0, r1, z0, z1 in where:
        ax.add_patch(Rectangle((r0, z0), r1 - r0, z1 - z0, fc="0.25",
                               ec="k", hatch="xx", alpha=0.6))


def zoom_window(prm, r, z):
    """The box around the foundation, material regions and interface lines,
    widened so the soil next to them shows (3 times their radius, 1.5 times
    their depth); None if it is not much smaller than the domain."""
    boxes = [numbers(b) for _, b in id_items(prm.get("Mesh/Material regions",
                                                     ""))]
    boxes += [[min(rs), max(rs), min(zs), max(zs)] for _, rs, zs in
              interface_segments(prm.get("Mesh/Interface lines", ""))]
    patch = float(prm.get("Mesh/Surface patch radius", "0"))
    if patch > 0.:
        boxes.append([r[0], patch, z[-1], z[-1]])
    if not boxes:
        return None
    b = np.array(boxes)
    radius = max(b[:, 1].max() - r[0], 1e-9)
    depth = max(z[-1] - b[:, 2].min(), radius)
    window = [r[0], min(r[-1], r[0] + 3. * radius),
              max(z[0], z[-1] - 1.5 * depth), z[-1] + 0.05 * depth]
    whole = (r[-1] - r[0]) * (z[-1] - z[0])
    part = (window[1] - window[0]) * (window[3] - window[2])
    return window if part < 0.5 * whole else None


def geometry_legend(ax, prm, regions):
    """Materials (elastic entry and plastic law), then what the scene has of
    interfaces, rigid foundation and held sides."""
    ids = sorted({0} | {mid for mid, _ in regions})
    colours = plt.get_cmap("Pastel1")
    handles = [Patch(fc=colours(m % 9), label=material_label(prm, m))
               for m in ids]
    if prm.get("Mesh/Interface lines", ""):
        laws = ", ".join("%d: %s" % item for item in id_items(
            prm.get("Interfaces/Interfaces", "")))
        handles.append(Patch(fc="#c44e52", label="interface lines " + laws))
    if prm.get("Rigid foundation/Enabled", "false") == "true":
        handles.append(Patch(fc="k", label="rigid foundation"))
    if prm.get("Boundary conditions/Dirichlet", ""):
        handles.append(Patch(fc="#2a9d8f", label="Dirichlet sides"))
    for h in handles:
        h.set_label(textwrap.fill(h.get_label(), 34))
    ax.axis("off")
    ax.legend(handles=handles, fontsize=6, loc="center left", frameon=False)


def geometry_panel(fig, spec, prm):
    """The whole domain and, when the foundation is small in it, a zoom."""
    inner = spec.subgridspec(1, 3, wspace=0.35, width_ratios=[1, 1, 0.8])
    ax = fig.add_subplot(inner[0, 0])
    r, z = mesh_edges(prm, "R"), mesh_edges(prm, "Z")
    whole = [r[0], r[-1], z[0], z[-1]]
    r_edges, z_edges, regions = draw_geometry(ax, prm, whole, False)
    window = zoom_window(prm, r_edges, z_edges)
    if window is not None:
        draw_geometry(fig.add_subplot(inner[0, 1]), prm, window, True)
    geometry_legend(fig.add_subplot(inner[0, 2]), prm, regions)
    top = spec.get_position(fig)
    fig.text(top.x0, top.y1 + 0.02, "Geometry (the prm's mesh, %s global "
             "refinements; lines: cell edges)"
             % prm.get("Mesh/Global refinements", "0"), fontsize=9,
             weight="bold")


# ---------------------------------------------------- load-displacement


def controlled_motion(prm, rows):
    """The motion the curve drives: the prm's entry, else the load named by
    the capacity or end-load row, else the load that moved most."""
    if prm and "Load path/Controlled motion" in prm:
        return prm["Load path/Controlled motion"]
    for row in rows:
        m = re.fullmatch(r"(?:capacity|end_load)_([VHMT])", row["quantity"])
        if m:
            return next(k for k, v in CURVE_COLUMNS.items()
                        if v[0] == m.group(1))
    return None


def curve_goal(goals, letter):
    for g in goals:
        if g.row["quantity"] in ("capacity_" + letter, "end_load_" + letter):
            return g
    return None


def draw_curve(ax, curve, motion, goals, rows):
    """The controlled motion's load against it, from zero, with the
    capacity or end load of results.csv and its bars."""
    letter, load_col, motion_col, load_unit, motion_unit = \
        CURVE_COLUMNS[motion]
    u = np.array([0.] + [float(s[motion_col]) for s in curve])
    p = np.array([0.] + [float(s[load_col]) for s in curve])
    sign = -1. if p[-1] < 0. else 1.
    prefix = "-" if sign < 0. else ""
    ax.plot(sign * u, sign * p, "o-", ms=3, color="#4c72b0", label="steps")
    bad = [i + 1 for i, s in enumerate(curve)
           if s.get("converged", "1") != "1"]
    if bad:
        ax.plot(sign * u[bad], sign * p[bad], "x", color="r", ms=6,
                label="not converged")
    goal = curve_goal(goals, letter)
    title = "Load-displacement (%d steps)" % len(curve)
    if goal is not None:
        title += ": " + draw_plateau(ax, goal, sign, u[-1], rows, load_unit)
    ax.set_xlabel("%s%s [%s]" % (prefix, motion_col.rsplit("_", 1)[0],
                                 motion_unit), fontsize=7)
    ax.set_ylabel("%s%s [%s]" % (prefix, letter, load_unit), fontsize=7)
    ax.tick_params(labelsize=6)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=6, loc="lower right")
    ax.set_title(title, fontsize=8)


def draw_plateau(ax, goal, sign, u_last, rows, unit):
    """The capacity (dashed), its plateau's error as a band, the total bar
    at the last step; returns the text for the title."""
    value = sign * goal.value
    plateau = find_row(rows, goal.row["quantity"] + "_plateau_error",
                       goal.row["n"], goal.row["family"], goal.row["cycle"])
    is_capacity = goal.row["quantity"].startswith("capacity_")
    if is_capacity:
        ax.axhline(value, ls="--", lw=0.8, color="k",
                   label="capacity (plateau)")
    if plateau is not None and math.isfinite(float(plateau["value"])):
        ax.axhspan(value, value + float(plateau["value"]), color="0.8",
                   label="plateau's error (asymptote)")
    # A plateau-only bar is one-sided: the load still to come as the curve
    # rises to its asymptote, on the side of the band.
    one_sided = "plateau" in goal.bar_from
    rises = plateau is None or float(plateau["value"]) >= 0.
    if math.isfinite(goal.bar):
        yerr = ([[0.], [goal.bar]] if rises else [[goal.bar], [0.]]) \
            if one_sided else [goal.bar]
        ax.errorbar([sign * u_last], [value], yerr=yerr, color="k",
                    capsize=4, lw=1.2, label="error bar (%s)" % (
                        "plateau only, one-sided" if one_sided else "total"))
    name = "capacity" if is_capacity else "end load"
    spread = ("+ %s (one-sided: the rise still to come)" if one_sided
              else "± %s") % (BAR_FORMAT % goal.bar)
    return "%s %s = %s %s %s" % (name, goal.row["quantity"][-1],
                                 VALUE_FORMAT % goal.value, spread, unit)


# ------------------------------------------------------- interface state


def interface_bands(rows, per_line=4):
    """The last step's samples on a few positions of every interface line
    (faces of one orientation of one interface id): [(label, thetas,
    states)], positions evenly spread over each line."""
    last = max(int(r["step"]) for r in rows)
    rows = [r for r in rows if int(r["step"]) == last]
    lines = {}
    for r in rows:
        along = "z" if abs(float(r["normal_r"])) > abs(float(r["normal_z"])) \
            else "r"
        lines.setdefault((r["interface_id"], along), []).append(r)
    bands = []
    for (interface, along), group in sorted(lines.items()):
        coords = sorted({float(r[along + "_m"]) for r in group})
        picks = sorted({coords[int(round(i))] for i in np.linspace(
            0, len(coords) - 1, min(per_line, len(coords)))}, reverse=True)
        for c in picks:
            at = sorted((float(r["theta_deg"]), r["state"]) for r in group
                        if float(r[along + "_m"]) == c)
            label = "%s: %s = %.3g m" % (interface, along, c)
            bands.append((label, [t for t, _ in at], [s for _, s in at]))
    return last, bands


def draw_interface_state(ax, rows):
    """One band of stick / slip / open samples over theta per position;
    returns the step and the positions' labels."""
    step, bands = interface_bands(rows)
    for k, (label, thetas, states) in enumerate(bands):
        width = 360. / len(thetas)
        if thetas[0] == 0.:  # close the circle: 360 is 0
            thetas, states = thetas + [360.], states + states[:1]
        for t, s in zip(thetas, states):
            ax.add_patch(Rectangle((t - width / 2, -k - 0.4), width, 0.8,
                                   fc=STATE_COLOURS[s], ec="none"))
    ax.set_yticks([-k for k in range(len(bands))])
    ax.set_yticklabels([b[0] for b in bands], fontsize=6)
    ax.set_ylim(-len(bands) + 0.4, 0.6)
    ax.set_xlim(0, 360)
    ax.set_xticks([0, 90, 180, 270, 360])
    ax.tick_params(labelsize=6)
    ax.set_xlabel("theta [deg]", fontsize=7)
    ax.legend(handles=[Patch(fc=STATE_COLOURS[s], label=s) for s in STATES],
              fontsize=6, ncol=3, loc="upper right",
              bbox_to_anchor=(1.0, -0.08), frameon=False)
    ax.set_title("Interface state around the circumference at the last step "
                 "(%d); interface id: position of the sample row" % step,
                 fontsize=8)
    return step, [b[0] for b in bands]


# --------------------------------------------------------------- yielding


def yield_history(rows):
    """step_plastic_samples per step (plastic soil runs)."""
    steps = [(int(r["cycle"]), float(r["value"])) for r in rows
             if r["quantity"] == "step_plastic_samples"]
    return sorted(steps)


def draw_yielding(ax, history):
    steps = [s for s, _ in history]
    ax.plot(steps, [n for _, n in history], "o-", ms=3, color="#8172b2")
    ax.set_xlabel("load step", fontsize=7)
    ax.set_ylabel("plastic samples", fontsize=7)
    ax.tick_params(labelsize=6)
    ax.grid(True, alpha=0.3)
    ax.set_title("Yielding: plastic soil samples per step", fontsize=8)


# ---------------------------------------------------------- plastic zone


def vtu_arrays(path):
    """{name: numpy array (n_points, n_components)} of a VTU as fourier-ssi
    writes it (deal.II's DataOutBase: base64, zlib-compressed blocks or
    raw, Float32/Float64), and "Points"; the standard library and numpy
    only (no VTK module needed)."""
    import base64
    import struct
    import xml.etree.ElementTree as ElementTree
    import zlib
    root = ElementTree.parse(path).getroot()
    compressed = root.get("compressor") is not None
    header = "Q" if root.get("header_type") == "UInt64" else "I"
    size = struct.calcsize(header)
    kinds = {"Float32": np.float32, "Float64": np.float64,
             "Int32": np.int32, "Int64": np.int64, "UInt8": np.uint8}
    arrays = {}
    for piece in root.iter("Piece"):
        for parent in ("Points", "PointData"):
            for array in piece.find(parent).iter("DataArray"):
                text = array.text.strip()
                if array.get("format") == "ascii":
                    data = np.array(text.split(), dtype=float)
                elif compressed:
                    first = base64.b64decode(text[:((3 * size + 2) // 3) * 4])
                    n_blocks = struct.unpack(header, first[:size])[0]
                    length = (((3 + n_blocks) * size + 2) // 3) * 4
                    counts = struct.unpack(header * (3 + n_blocks),
                                           base64.b64decode(text[:length]))
                    raw, offset, blocks = base64.b64decode(text[length:]), \
                        0, []
                    for count in counts[3:]:
                        blocks.append(zlib.decompress(raw[offset:offset +
                                                          count]))
                        offset += count
                    data = np.frombuffer(b"".join(blocks),
                                         dtype=kinds[array.get("type")])
                else:
                    data = np.frombuffer(base64.b64decode(text)[size:],
                                         dtype=kinds[array.get("type")])
                components = int(array.get("NumberOfComponents", "1"))
                name = "Points" if parent == "Points" else array.get("Name")
                arrays[name] = data.astype(float).reshape(-1, components)
    return arrays


def plastic_plane_file(directory):
    """The loading plane's (theta = 0) plastic field of the latest step
    written, or None."""
    steps = []
    for name in os.listdir(directory):
        m = re.fullmatch(r"plastic-field-theta0-step(\d+)\.vtu", name)
        if m:
            steps.append((int(m.group(1)), name))
    return os.path.join(directory, max(steps)[1]) if steps else None


def plastic_window(x, z, quads, strain):
    """The box around the yielded cells, a third larger (None: none)."""
    yielded = quads[strain > 0]
    if len(yielded) == 0:
        return None
    x0, x1 = x[yielded].min(), x[yielded].max()
    z0, z1 = z[yielded].min(), z[yielded].max()
    grow = max(x1 - x0, z1 - z0) / 6
    return [max(x.min(), x0 - grow), min(x.max(), x1 + grow),
            max(z.min(), z0 - grow), min(z.max(), z1 + grow)]


def draw_plastic_plane(ax, a, quads, strain, window, arrows):
    """Cells filled by their plastic strain, its contours, and at most
    `arrows` displacement arrows inside the window."""
    from matplotlib.collections import PolyCollection
    from matplotlib.colors import PowerNorm
    x, z = a["Points"][:, 0], a["Points"][:, 2]
    cells = PolyCollection([np.column_stack([x[q], z[q]]) for q in quads],
                           array=strain, cmap="magma_r", edgecolors="face",
                           linewidths=0.2,
                           norm=PowerNorm(0.5, 0, max(strain.max(), 1e-30)))
    ax.add_collection(cells)
    if strain.max() > 0 and len(strain) >= 3:
        try:
            ax.tricontour(x[quads].mean(axis=1), z[quads].mean(axis=1),
                          strain, levels=strain.max() *
                          np.array([0.01, 0.1, 0.3, 0.6]),
                          colors="#1f77b4", linewidths=0.6)
        except (ValueError, RuntimeError):
            pass  # cell centres on one line: no triangulation
    inside = np.flatnonzero((x >= window[0]) & (x <= window[1]) &
                            (z >= window[2]) & (z <= window[3]))
    inside = inside[np.unique(np.round(np.column_stack(
        [x[inside], z[inside]]), 9), axis=0, return_index=True)[1]]
    shown = inside[::max(1, len(inside) // arrows)]
    ax.quiver(x[shown], z[shown], a["u_r"][shown, 0], a["u_z"][shown, 0],
              color="#2ca02c", width=0.004)
    ax.set_xlim(window[0], window[1])
    ax.set_ylim(window[2], window[3])
    ax.set_aspect("equal", adjustable="box")
    ax.tick_params(labelsize=6)
    ax.set_xlabel("r [m]", fontsize=7)
    ax.set_ylabel("z [m]", fontsize=7)
    return cells


def draw_plastic_zone(fig, spec, path):
    """The loading plane theta = 0: the whole soil and a zoom on the cells
    that yielded, filled by their equivalent plastic strain, with its
    contours and the displacement (u_r, u_z) as arrows."""
    a = vtu_arrays(path)
    x, z = a["Points"][:, 0], a["Points"][:, 2]
    # Each cell is a patch of its own 4 vertices, deal.II's lexicographic
    # order (0, 1, 3, 2 goes round the quadrilateral).
    quads = np.arange(len(x)).reshape(-1, 4)[:, [0, 1, 3, 2]]
    strain = a["plastic_strain"][quads[:, 0], 0]
    inner = spec.subgridspec(1, 2, wspace=0.35)
    whole = [x.min(), x.max(), z.min(), z.max()]
    draw_plastic_plane(fig.add_subplot(inner[0, 0]), a, quads, strain, whole,
                       120)
    window = plastic_window(x, z, quads, strain) or whole
    ax = fig.add_subplot(inner[0, 1])
    cells = draw_plastic_plane(ax, a, quads, strain, window, 200)
    bar = fig.colorbar(cells, ax=ax, fraction=0.05, pad=0.03)
    bar.ax.tick_params(labelsize=6)
    bar.set_label("equivalent plastic strain", fontsize=6)
    step = re.search(r"step(\d+)", os.path.basename(path)).group(1)
    top = spec.get_position(fig)
    fig.text(top.x0, top.y1 + 0.004, "Plastic zone in the loading plane "
             "(theta = 0), step %s: cell means, %d of %d cells yielded\n"
             "(right: near them); contours at 1, 10, 30, 60 %% of the "
             "largest; arrows: displacement (u_r, u_z)"
             % (step, int((strain > 0).sum()), len(strain)), fontsize=8,
             va="bottom")


# ----------------------------------------------------------------- table


def goal_table_cells(goals, rows):
    cells = []
    for g in goals:
        r = g.row
        cells.append([r["quantity"], "%s %s" % (r["n"], r["family"][:4]),
                      r["cycle"], VALUE_FORMAT % g.value,
                      ("+" if "plateau" in g.bar_from else "") +
                      BAR_FORMAT % g.bar if math.isfinite(g.bar) else "-",
                      r["unit"], bar_note(g, rows)])
    return cells


def draw_goal_table(ax, goals, rows):
    """The goal rows as a table, with whether the target was reached."""
    ax.axis("off")
    columns = ["quantity", "n family", "cycle/step", "value", "± (abs)",
               "unit", "bar (its relative parts)"]
    table = ax.table(cellText=goal_table_cells(goals, rows), colLabels=columns,
                     loc="upper center", cellLoc="left",
                     colWidths=[0.31, 0.07, 0.07, 0.1, 0.07, 0.12, 0.26])
    for cell in table.get_celld().values():
        cell.PAD = 0.03
    table.auto_set_font_size(False)
    table.set_fontsize(6)
    target = find_row(rows, "target_accuracy_reached", "0", "symmetric")
    note = ""
    if target is not None:
        accuracy = find_row(rows, "target_accuracy", target["n"],
                            target["family"], target["cycle"])
        note = "; Target accuracy %s %s" % (
            accuracy["value"] if accuracy else "?",
            "reached" if target["value"] == "1" else "NOT reached")
    ax.set_title("Goal values (results.csv; bars are absolute, from the "
                 "relative *_error rows)" + note, fontsize=8, loc="left")
    return table


def table_texts(table, n_rows):
    """The goal rows as drawn: the text of each cell of the table."""
    cells = table.get_celld()
    return [[cells[(i + 1, j)].get_text().get_text() for j in range(7)]
            for i in range(n_rows)]


# ------------------------------------------------------------------ page


def choose_panels(directory, prm, rows, goals):
    """The panels this run can fill, and the reasons for those left out."""
    shown, missing = [], []
    if prm is None:
        missing.append("geometry: no --prm given")
    elif prm.get("Mesh/Type", "rectangle") != "rectangle":
        missing.append("geometry: a gmsh mesh (Mesh/Mesh file), not drawn yet")
    else:
        shown.append("geometry")
    curve = os.path.join(directory, "load-displacement.csv")
    if not os.path.isfile(curve):
        missing.append("load-displacement: no load-displacement.csv "
                       "(a linear run)")
    elif not moves_foundation(read_csv(curve)):
        missing.append("load-displacement: no rigid-foundation load or "
                       "motion in load-displacement.csv (loads on "
                       "boundaries only; its load_factor column has them)")
    else:
        shown.append("load-displacement")
    state = os.path.join(directory, "interface-state.csv")
    if os.path.isfile(state):
        shown.append("interface-state")
    else:
        missing.append("interface-state: no interface-state.csv "
                       "(no coulomb interfaces)")
    if yield_history(rows):
        shown.append("yielding")
        if plastic_plane_file(directory):
            shown.append("plastic-zone")
        else:
            missing.append("plastic-zone: no plastic-field-theta0-step*.vtu "
                           "(Output/Write vtu = false, or Plastic field "
                           "planes without 0)")
    else:
        missing.append("plastic-zone: no plastic soil in this run")
    if goals:
        shown.append("goals")
    else:
        missing.append("goals: results.csv has no value with an error "
                       "estimate and no capacity (Discretization/Target "
                       "accuracy gives them)")
    return shown, missing


def layout(fig, shown, n_goals):
    """Rows of the page: title, geometry, curve | yielding, interface
    state, goal table; only those shown."""
    plan = [("title", 0.05)]
    if "geometry" in shown:
        plan.append(("geometry", 3.2))
    if "load-displacement" in shown or "yielding" in shown:
        plan.append(("curves", 2.6))
    if "interface-state" in shown:
        plan.append(("interface-state", 2.0))
    if "plastic-zone" in shown:
        plan.append(("plastic-zone", 2.2))
    if "goals" in shown:
        plan.append(("goals", 0.6 + 0.19 * n_goals))
    plan.append(("footer", 0.5))
    # Every panel keeps its size on every page: the space of the panels
    # left out stays blank at the bottom.
    full_page = 0.05 + 3.2 + 2.6 + 2.0 + 2.4 + 1.2 + 0.5
    plan.append(("blank", max(0., full_page - sum(h for _, h in plan))))
    grid = GridSpec(len(plan), 1, figure=fig,
                    height_ratios=[h for _, h in plan], hspace=0.6,
                    left=0.13, right=0.96, top=0.96, bottom=0.02)
    return {name: grid[i, 0] for i, (name, _) in enumerate(plan)}


def draw_page(directory, prm, prm_path, rows, out):
    """The page, written to out; returns the panels drawn, the reasons for
    those left out, the goals, the goal table's texts as drawn, and what
    the interface-state panel showed."""
    goals = goal_values(rows)
    shown, missing = choose_panels(directory, prm, rows, goals)
    fig = plt.figure(figsize=PAGE_INCHES)
    spots = layout(fig, shown, len(goals))
    fig.text(0.05, 0.985, "fourier-ssi run report: %s%s" % (
        directory,
        "  (prm: %s)" % prm_path if prm_path else ""), fontsize=9,
        weight="bold", va="top")
    extra = {}
    if "geometry" in shown:
        geometry_panel(fig, spots["geometry"], prm)
    if "curves" in spots:
        draw_curves_row(fig, spots["curves"], shown, directory, prm, rows,
                        goals)
    if "interface-state" in shown:
        ax = fig.add_subplot(spots["interface-state"])
        extra["interface-state"] = draw_interface_state(
            ax, read_csv(os.path.join(directory, "interface-state.csv")))
    if "plastic-zone" in shown:
        draw_plastic_zone(fig, spots["plastic-zone"],
                          plastic_plane_file(directory))
    texts = []
    if "goals" in shown:
        table = draw_goal_table(fig.add_subplot(spots["goals"]), goals, rows)
        texts = table_texts(table, len(goals))
    footer = fig.add_subplot(spots["footer"])
    footer.axis("off")
    footer.text(0., 1., "Not shown: " + "; ".join(missing), fontsize=6.5,
                va="top", wrap=True)
    fig.savefig(out, dpi=100)
    plt.close(fig)
    return shown, missing, goals, texts, extra


def draw_curves_row(fig, spec, shown, directory, prm, rows, goals):
    both = "load-displacement" in shown and "yielding" in shown
    inner = spec.subgridspec(1, 2 if both else 1, wspace=0.3)
    k = 0
    if "load-displacement" in shown:
        curve = [s for s in read_csv(os.path.join(directory,
                                                  "load-displacement.csv"))]
        motion = controlled_motion(prm, rows) or largest_motion(curve)
        draw_curve(fig.add_subplot(inner[0, k]), curve, motion, goals, rows)
        k += 1
    if "yielding" in shown:
        draw_yielding(fig.add_subplot(inner[0, k]), yield_history(rows))


def moves_foundation(curve):
    """Whether any step has a rigid-foundation load or motion."""
    return any(float(s[c]) != 0. for s in curve
               for columns in CURVE_COLUMNS.values() for c in columns[1:3])


def largest_motion(curve):
    """Without the prm: the motion whose load changed most (in kN or kN.m)."""
    return max(CURVE_COLUMNS, key=lambda m: max(
        abs(float(s[CURVE_COLUMNS[m][1]])) for s in curve))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("output_dir")
    parser.add_argument("--prm", help="the scene's .prm (for the geometry)")
    parser.add_argument("-o", "--output", default="report.png")
    args = parser.parse_args()
    if not os.path.isdir(args.output_dir):
        fail(args.output_dir + ": no such output folder")
    if args.prm and not os.path.isfile(args.prm):
        fail(args.prm + ": no such file (--prm)")
    prm = read_prm(args.prm) if args.prm else None
    rows = read_results(args.output_dir)
    shown, missing, goals, texts, extra = draw_page(
        args.output_dir, prm, args.prm, rows, args.output)
    print("panels: " + ", ".join(shown))
    for reason in missing:
        print("not shown: " + reason)
    if "interface-state" in extra:
        step, labels = extra["interface-state"]
        print("interface-state: step %d; %s" % (step, "; ".join(labels)))
    for g, t in zip(goals, texts):
        print("goal: %s,%s,%s,%s | value=%r | page_value=%s | page_bar=%s | "
              "unit=%s | bar_from=%s"
              % (t[0], g.row["n"], g.row["family"], t[2], g.value, t[3],
                 t[4], t[5], g.bar_from or "-"))
    print("wrote " + args.output)


if __name__ == "__main__":
    main()
