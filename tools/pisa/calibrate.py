#!/usr/bin/python3
"""A site's PISA design model from the FE in one command.

Usage: /usr/bin/python3 tools/pisa/calibrate.py SITE.txt --out DIR
           [--exe build/fourier-ssi] [--reuse] [--no-plot]

SITE.txt: the calibration space (tools/pisa/space.py: base scene, D, L/D,
left-out piles, wall t/D, stick-up h/D, the push); doc/pisa-design-model.md.
It writes DIR/runs/<pile>.prm (the base scene + appended overrides), runs
them as one `fourier-ssi --batch`, fits the PISA conic to the four reaction
curves at every depth of the fitted piles (fit.py), fits their depth and L/D
variation, runs the 1D Timoshenko model (beam.py) on every pile, fitted and
left out, against the FE's pile-head curve, and writes

    DIR/fits.csv           every fitted value with its fit error
    DIR/model.json         the calibrated model (linear in z/D and L/D)
    DIR/openpile-<pile>.json  OpenPile Custom_pisa_clay or _sand arguments per pile
    DIR/head-curves.csv    FE and 1D pile-head H-v, M-theta per pile
    DIR/sheet.png          the plot sheet (plot_sheet.py)

--reuse: take the runs already in DIR/runs (no FE).  A failing run gets one
line naming it; the others are kept.  Bad input: one line, exit 1.
"""
import argparse
import glob
import json
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from space import read_spec, SpecError, ROOT  # noqa: E402
import runs  # noqa: E402


# What calibrate.py writes in --out (runs/ aside, the FE runs that --reuse
# reads): an earlier calibration's files are removed first.
RESULT_FILES = ("fits.csv", "model.json", "head-curves.csv", "summary.json", "openpile-*.json", "sheet.png")


def remove_results(out):
    for pattern in RESULT_FILES:
        for path in glob.glob(os.path.join(out, pattern)):
            os.remove(path)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("site")
    ap.add_argument("--out", required=True)
    ap.add_argument("--exe", default=os.path.join(ROOT, "build", "fourier-ssi"))
    ap.add_argument("--reuse", action="store_true")
    ap.add_argument("--no-plot", action="store_true")
    args = ap.parse_args()
    args.exe = os.path.abspath(args.exe)
    out = os.path.abspath(args.out)
    os.makedirs(out, exist_ok=True)
    remove_results(out)
    try:
        spec = read_spec(args.site)
    except SpecError as e:
        sys.exit(f"calibrate.py: {e}")
    listing = runs.write_cases(spec, out)
    n_cases = sum(1 for _ in open(listing))
    if not args.reuse:
        if not os.access(args.exe, os.X_OK):
            sys.exit(f"calibrate.py: no executable fourier-ssi at {args.exe} (--exe)")
        wall, code, _ = runs.run_batch(args.exe, listing, out)
        print(f"FE: {n_cases} runs ({len(spec['piles'])} piles) in one batch, {wall:.1f} s wall")
    data = {}
    for pile in spec["piles"]:
        d = runs.read_pile(os.path.join(out, "runs", pile["name"]))
        if d is None:
            print(f"FAILED: pile {pile['name']} (D = {pile['D']:g} m, L/D = {pile['L_over_D']:g}) left no curves; "
                  f"see {os.path.join(out, 'runs', pile['name'] + '.prm')} and runs/batch.log; it is left out")
            continue
        init = runs.read_pile(os.path.join(out, "runs", pile["name"] + "-initial"))
        if spec["initial_over_D"] > 0 and init is None:
            print(f"FAILED: the initial step of pile {pile['name']} left no curves; its fit starts at the first step")
        d["initial"] = init
        data[pile["name"]] = d
    fitted = [p for p in spec["piles"] if p["fitted"] and p["name"] in data]
    if len({p["L_over_D"] for p in fitted}) < 2:
        sys.exit("calibrate.py: fewer than 2 fitted piles of different L/D ran; nothing to fit")
    from pipeline import calibrate_and_compare  # noqa: E402
    try:
        calibrate_and_compare(spec, data, out, plot=not args.no_plot)
    except BaseException:
        # a calibration that stops (bad input, a failed fit) leaves no
        # file that looks like its result
        remove_results(out)
        raise


if __name__ == "__main__":
    main()
