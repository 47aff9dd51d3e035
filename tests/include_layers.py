#!/usr/bin/env python3
"""Includes run downward only: a file of layer Y includes
<fourier_ssi/X/...> only if X is Y or a layer below Y in LAYERS.

input/ is read by all layers. Its parameters.h gathers the parameter structs
that each layer declares next to its code (deal.II step-44's habit), so a file
of input/ may include a header of a higher layer, provided that header reaches
no file of input/ through its own includes: otherwise the includes would run
in a loop.

Usage: include_layers.py SOURCE_DIR. Prints one line per violation
(file:line: from-layer -> to-layer, the included header) and exits 1 if there
is any.
"""
import re
import sys
from pathlib import Path

# The layer order, lowest first: the one statement of it (doc/running.md,
# "Source layout", describes it).
LAYERS = [
    "input",
    "linear_algebra",
    "fourier",
    "mesh",
    "interfaces",
    "harmonic",
    "estimation",
    "postprocess",
    "coupled",
    "driver",
    "app",
]
READ_BY_ALL = "input"

INCLUDE = re.compile(r'^\s*#\s*include\s*<fourier_ssi/([^/>]+)/([^>]+)>')


def layer_of(path, root):
    """The layer folder of a file under include/fourier_ssi/ or source/."""
    parts = path.relative_to(root).parts
    return parts[2] if parts[0] == "include" else parts[1]


def includes_of(path):
    """(line number, layer, header path relative to include/) of each
    #include <fourier_ssi/...> in the file."""
    found = []
    for number, line in enumerate(path.read_text().splitlines(), start=1):
        match = INCLUDE.match(line)
        if match:
            layer, name = match.groups()
            found.append((number, layer, f"fourier_ssi/{layer}/{name}"))
    return found


def reaches_read_by_all(header, root, seen):
    """Whether the header, through its includes, reaches a file of input/."""
    if header in seen:
        return False
    seen.add(header)
    path = root / "include" / header
    if not path.exists():
        return False
    for _, layer, included in includes_of(path):
        if layer == READ_BY_ALL or reaches_read_by_all(included, root, seen):
            return True
    return False


def violation(from_layer, to_layer, header, root):
    """Why this include breaks the order, or None if it does not."""
    if to_layer not in LAYERS:
        return f"unknown layer {to_layer} (not in LAYERS)"
    if LAYERS.index(to_layer) <= LAYERS.index(from_layer):
        return None
    if from_layer == READ_BY_ALL:
        if reaches_read_by_all(header, root, set()):
            return "loop: the header reaches input/ again"
        return None
    return "climbs up"


def main():
    root = Path(sys.argv[1]).resolve()
    files = sorted(
        [p for p in (root / "include" / "fourier_ssi").rglob("*") if p.is_file()]
        + [p for p in (root / "source").rglob("*") if p.is_file()]
    )
    violations = 0
    for path in files:
        from_layer = layer_of(path, root)
        if from_layer not in LAYERS:
            print(f"{path.relative_to(root)}: folder {from_layer} is not in LAYERS")
            violations += 1
            continue
        for number, to_layer, header in includes_of(path):
            why = violation(from_layer, to_layer, header, root)
            if why:
                print(
                    f"{path.relative_to(root)}:{number}: {from_layer} -> "
                    f"{to_layer} ({header}): {why}"
                )
                violations += 1
    print(f"{len(files)} files, {violations} includes against the layer order "
          f"{' < '.join(LAYERS)}")
    return 1 if violations else 0


if __name__ == "__main__":
    sys.exit(main())
