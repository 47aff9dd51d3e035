#!/usr/bin/env python3
"""Includes run downward only: a file of layer Y includes
<fourier_ssi/X/...> only if X is Y or a layer below Y in LAYERS. No layer is
exempt: input/, the lowest, holds every parameter struct (one header per
subsection, gathered by parameters.h), so that each layer can read the
parameters it needs without input/ including any model.

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


def violation(from_layer, to_layer):
    """Why this include breaks the order, or None if it does not."""
    if to_layer not in LAYERS:
        return f"unknown layer {to_layer} (not in LAYERS)"
    if LAYERS.index(to_layer) <= LAYERS.index(from_layer):
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
            why = violation(from_layer, to_layer)
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
