"""What the table and figure scripts share: running a list of scenes in
one `fourier-ssi --batch` process, and reading the answer of a run (the
last cycle of its results.csv, the mesh the target accuracy stopped on)."""
import csv
import os
import subprocess
import sys
import time

# The rows of results.csv that add up to a run's computation time.
COMPUTATION_ROWS = ("time_setup", "time_assembly", "time_interface_assembly",
                    "time_solve", "time_postprocess")


def run_batch(exe, work, prm_files):
    """Run every prm file in one --batch process (batch.csv in `work`);
    exits with the program's message if it fails. Returns the wall time."""
    cases = os.path.join(work, "cases.txt")
    with open(cases, "w") as f:
        f.write("".join(p + "\n" for p in prm_files))
    start = time.time()
    p = subprocess.run([exe, "--batch", "--csv", os.path.join(work, "batch.csv"),
                        cases],
                       stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    wall = time.time() - start
    if p.returncode != 0:
        sys.exit(f"fourier-ssi --batch failed ({p.stderr.strip()}); cases in {work}")
    return wall


def read_last_cycle(path):
    """The values of the last cycle of a results.csv (the answer's mesh),
    with `members` (how many meshes were solved) and `seconds` (the
    computation summed over all of them)."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    last = max(int(r["cycle"]) for r in rows)
    values = {r["quantity"]: float(r["value"]) for r in rows
              if int(r["cycle"]) == last}
    values["members"] = last + 1
    values["seconds"] = sum(float(r["value"]) for r in rows
                            if r["quantity"] in COMPUTATION_ROWS)
    return values
