"""What the side-by-side benchmarks of two builds share
(nonlinear-accuracy/run.py, harmonic-scaling/run.py): their command line,
one timed run of a scene text, and the results.md they write.
"""
import argparse
import csv
import datetime
import os
import shutil
import subprocess


def arguments(cases):
    """NEW_EXE OLD_EXE [--cases] [--repeats] [--new-commit] [--old-commit]
    [--no-write] [--tag TAG], parsed."""
    parser = argparse.ArgumentParser()
    parser.add_argument("new")
    parser.add_argument("old")
    parser.add_argument("--cases", default=",".join(cases))
    parser.add_argument("--repeats", type=int, default=1)
    parser.add_argument("--new-commit", default="unknown")
    parser.add_argument("--old-commit", default="unknown")
    parser.add_argument("--no-write", action="store_true")
    # A run of some cases only, beside the full table (results-TAG.md).
    parser.add_argument("--tag", default="")
    return parser.parse_args()


def timed_run(exe, text, work):
    """Runs `exe` on the scene `text` (its Output/Directory set to `out`)
    in a fresh folder `work`. Returns wall [s], peak memory [GB] and the
    rows of results.csv (each quantity's rows in order), or the failure's
    one line."""
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    text += """
subsection Output
  set Directory = out
end
"""
    open(os.path.join(work, "case.prm"), "w").write(text)
    result = subprocess.run(["/usr/bin/time", "-f", "%e %M", exe,
                             "case.prm"], cwd=work, capture_output=True,
                            text=True)
    lines = result.stderr.strip().splitlines()
    wall, rss = lines[-1].split()
    if result.returncode != 0:
        return {"failed": lines[-2] if len(lines) > 1 else "no message"}
    rows = {}
    with open(os.path.join(work, "out", "results.csv")) as f:
        for row in csv.DictReader(f):
            rows.setdefault(row["quantity"], []).append(float(row["value"]))
    return {"wall": float(wall), "rss_gb": float(rss) / 1024. ** 2,
            "rows": rows}


def report(folder, columns, lines, title, what, args, load_start,
           reading):
    """The table of `columns` (the wall time's header says of how many
    runs it is the median) and `lines`, printed, and unless --no-write
    results.md in `folder`: the title, which builds and how they ran, the
    load average at the start and now, the table and what to read in it."""
    columns = [c % args.repeats if "%d" in c else c for c in columns]
    table = ("| " + " | ".join(columns) + " |\n" +
             "|---" * len(columns) + "|\n" + "\n".join(lines))
    print(table)
    if args.no_write:
        return
    name = "results-%s.md" % args.tag if args.tag else "results.md"
    with open(os.path.join(folder, name), "w") as f:
        f.write("# %s\n\nWritten by `run.py` (%s): new %s, old %s; %s One "
                "run at a time, the two builds alternating. Load average "
                "(1 min) %.1f at the start, %.1f at the end, on 2 cores: "
                "the times compare within this table only.\n\n%s\n\n%s\n"
                % (title, datetime.date.today(), args.new_commit,
                   args.old_commit, what, load_start, os.getloadavg()[0],
                   table, reading))
