"""The FE runs of a calibration space: one .prm per pile, one `--batch`,
and the curves each run wrote (soil-reaction-curves.csv, load-displacement.csv)."""
import csv
import os
import subprocess
import time

from space import pile_overrides


def write_cases(spec, out):
    """Writes OUT/runs/<pile>.prm for every pile (and <pile>-initial.prm, the
    one step to `initial v/D` that resolves the curves' initial slope) and
    OUT/runs/batch.txt (one .prm a line); returns the list file."""
    runs = os.path.join(out, "runs")
    os.makedirs(runs, exist_ok=True)
    with open(spec["base"]) as f:
        base = f.read()
    lines = []
    for pile in spec["piles"]:
        cases = [(pile["name"], False)]
        if spec["initial_over_D"] > 0:
            cases.append((pile["name"] + "-initial", True))
        for name, initial in cases:
            prm = os.path.join(runs, name + ".prm")
            with open(prm, "w") as f:
                f.write(base + pile_overrides(spec, pile, os.path.join(runs, name), initial))
            lines.append(prm)
    listing = os.path.join(runs, "batch.txt")
    with open(listing, "w") as f:
        f.write("\n".join(lines) + "\n")
    return listing


def run_batch(exe, listing, out):
    """Runs the list as one batch; returns (wall time [s], names of the
    failed piles).  The batch keeps the cases that succeed and names the
    failed ones on stderr (doc/running.md)."""
    start = time.time()
    run = subprocess.run([exe, "--batch", "--csv", os.path.join(out, "runs", "batch.csv"), listing],
                         cwd=out, capture_output=True, text=True)
    wall = time.time() - start
    with open(os.path.join(out, "runs", "batch.log"), "w") as f:
        f.write(run.stdout + run.stderr)
    return wall, run.returncode, run.stderr


def read_pile(run_dir):
    """The curves of one run: dict with 'curves' (rows of
    soil-reaction-curves.csv as floats/strings) and 'head' (rows of
    load-displacement.csv), or None when the run left no curves."""
    curves = os.path.join(run_dir, "soil-reaction-curves.csv")
    head = os.path.join(run_dir, "load-displacement.csv")
    if not (os.path.isfile(curves) and os.path.isfile(head)):
        return None
    def rows(path):
        with open(path) as f:
            out = []
            for r in csv.DictReader(f):
                d = {}
                for k, v in r.items():
                    try:
                        d[k] = float(v)
                    except (TypeError, ValueError):
                        d[k] = v
                out.append(d)
            return out
    return dict(curves=rows(curves), head=rows(head))
