#!/usr/bin/python3
"""Same answers: every bundled scene gives the same results.csv and
load-displacement.csv text from two builds, except for wall times.

    python3 benchmarks/same-answers/run.py NEW_EXE OLD_EXE [SCENE,...]
        [--skip SCENE,...] [--new-commit C] [--old-commit C] [--no-write]

Every prm/*.prm (not its subfolders; a comma-separated list runs only
those scenes) runs once with each binary, as shipped, from a copy of the prm
in its own temporary directory: the scene's relative Output/Directory lands
there, and a relative Mesh/Mesh file is made absolute (it is relative to the
folder of the .prm, so the copy would not find it). Two runs at a time (the
machine has 2 cores), the old and the new run of a scene side by side;
OPENBLAS_NUM_THREADS and OMP_NUM_THREADS are 1 unless set (two runs on two
cores; the rounding of a threaded BLAS could depend on its thread count).

Then every *.csv and *.txt file of the output folder (results.csv,
load-displacement.csv, foundation-stiffness.csv, interface-state.csv, the
soil-reaction curves, ...) is compared line by line as text. Ignored, and
only these:
  * rows of a quantity,n,family,cycle,value,unit file whose quantity is a
    wall time: time_<phase> (time_setup, time_solve, time_error_estimate,
    ...) and step_wall_time, all in s;
  * columns whose header names a wall time or a memory reading: time_s,
    wall_time, wall_s, *_seconds, *[s], peak_rss*, rss_*, memory_*, *_MiB
    (of the bundled scenes' files only load-displacement.csv's time_s).
Per scene: identical, differs (file, first differing line, both texts), or
failed (which binary, exit code, its last line on stderr). A file that only
one build writes is a difference. The VTU files are not compared.

Writes results.md beside this script (the table, both commits, the date and
the total time) unless --no-write; exits 1 if any scene differs or fails.
The commits come from --new-commit/--old-commit or FSSI_NEW_COMMIT /
FSSI_OLD_COMMIT (else: this tree's HEAD for a NEW_EXE inside it, and
"unknown").
"""
import argparse
import concurrent.futures
import csv
import datetime
import glob
import io
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.normpath(os.path.join(HERE, "..", ".."))
TIMEOUT = 1800.
COMPARED = ("*.csv", "*.txt")

# A results.csv row (quantity,n,family,cycle,value,unit) that is a wall time.
TIME_QUANTITY = re.compile(r"^(time_[a-z_]+|step_wall_time)$")
# A column of a table that is a wall time or a memory reading.
TIME_COLUMN = re.compile(r"^(time_s|wall_time(_s)?|wall_s|.*_seconds|.*\[s\]"
                         r"|peak_rss.*|rss_.*|memory_.*|.*_MiB)$", re.I)


def uncommented(text):
    return "\n".join(line.split("#", 1)[0] for line in text.splitlines())


def output_directory(text):
    found = re.findall(r"^\s*set\s+Directory\s*=\s*(\S+)", uncommented(text),
                       re.M)
    return found[-1] if found else "output"


def with_absolute_mesh_file(text, prm_dir):
    """Mesh/Mesh file is relative to the folder of the .prm: the copy names
    the file where the original points."""
    def absolute(m):
        path = m.group(2).strip()
        if not path or os.path.isabs(path):
            return m.group(0)
        return m.group(1) + os.path.normpath(os.path.join(prm_dir, path))
    return re.sub(r"^(\s*set\s+Mesh file\s*=\s*)([^#\n]*)", absolute, text,
                  flags=re.M)


def last_line(text):
    lines = [l for l in text.strip().splitlines() if l.strip()]
    return lines[-1].strip() if lines else ""


def run_scene(exe, prm_path, work):
    """Runs EXE on a copy of PRM_PATH in WORK; returns the run's record."""
    name = os.path.basename(prm_path)
    text = open(prm_path).read()
    with open(os.path.join(work, name), "w") as f:
        f.write(with_absolute_mesh_file(text,
                                        os.path.dirname(prm_path)))
    env = dict(os.environ)
    env.setdefault("OPENBLAS_NUM_THREADS", "1")
    env.setdefault("OMP_NUM_THREADS", "1")
    start = time.time()
    try:
        p = subprocess.run([exe, name], cwd=work, capture_output=True,
                           text=True, timeout=TIMEOUT, env=env)
        code, err = p.returncode, p.stderr
    except subprocess.TimeoutExpired:
        code, err = "timeout", "no answer after %.0f s" % TIMEOUT
    return {"exit": code, "wall": time.time() - start,
            "message": last_line(err.replace(work + "/", "")),
            "output": os.path.join(work, output_directory(text))}


def output_files(folder):
    found = set()
    for pattern in COMPARED:
        for path in glob.glob(os.path.join(folder, "**", pattern),
                              recursive=True):
            found.add(os.path.relpath(path, folder))
    return found


def comparable_lines(path):
    """The file's lines with the wall-time rows and columns taken out, each
    as (line number in the file, text compared, the line as written); and
    what was taken out."""
    text = open(path, newline="").read()
    lines = text.split("\n")
    whole = [(i, line, line) for i, line in enumerate(lines, 1)]
    if not path.endswith(".csv") or not lines or "," not in lines[0]:
        return whole, []
    header = next(csv.reader([lines[0]]))
    names = [h.strip() for h in header]
    if names[:1] == ["quantity"] and "unit" in names:
        kept, dropped = [], set()
        for i, line in enumerate(lines, 1):
            quantity = line.split(",", 1)[0]
            if i > 1 and TIME_QUANTITY.match(quantity):
                dropped.add(quantity)
            else:
                kept.append((i, line, line))
        return kept, sorted(dropped)
    ignored = [k for k, h in enumerate(names) if TIME_COLUMN.match(h)]
    if not ignored:
        return whole, []
    kept = []
    for i, line in enumerate(lines, 1):
        fields = next(csv.reader([line])) if line else []
        kept.append((i, ",".join(f for k, f in enumerate(fields)
                                 if k not in ignored), line))
    return kept, [names[k] for k in ignored]


def compare(new_folder, old_folder):
    """(None, ignored) if every compared file is the same text but for the
    ignored fields, else (the first difference, ignored)."""
    new_files, old_files = output_files(new_folder), output_files(old_folder)
    ignored = set()
    for name in sorted(new_files | old_files):
        if name not in old_files:
            return "%s: written by the new build only" % name, ignored
        if name not in new_files:
            return "%s: written by the old build only" % name, ignored
        new, ignored_new = comparable_lines(os.path.join(new_folder, name))
        old, ignored_old = comparable_lines(os.path.join(old_folder, name))
        ignored |= {"%s: %s" % (name, f) for f in ignored_new + ignored_old}
        for (i, a, a_line), (j, b, b_line) in zip(new, old):
            if a != b:
                return ("%s line %d: new `%s`, old `%s`" %
                        (name, i, a_line[:200], b_line[:200]), ignored)
        if len(new) != len(old):
            return ("%s: %d lines new, %d old" % (name, len(new), len(old)),
                    ignored)
    return None, ignored


def commit_of(exe, given, env_name):
    if given:
        return given
    if os.environ.get(env_name):
        return os.environ[env_name]
    if os.path.abspath(exe).startswith(SOURCE + os.sep):
        p = subprocess.run(["git", "-C", SOURCE, "rev-parse", "--short",
                            "HEAD"], capture_output=True, text=True)
        if p.returncode == 0:
            return p.stdout.strip() + " (HEAD of this tree)"
    return "unknown"


def main():
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("new_exe")
    parser.add_argument("old_exe")
    parser.add_argument("scenes", nargs="?", default="",
                        help="comma-separated scene stems (default: all)")
    parser.add_argument("--skip", default="",
                        help="comma-separated scene stems not to run")
    parser.add_argument("--new-commit", default="")
    parser.add_argument("--old-commit", default="")
    parser.add_argument("--no-write", action="store_true",
                        help="do not write results.md")
    args = parser.parse_args()

    exes = {"new": os.path.abspath(args.new_exe),
            "old": os.path.abspath(args.old_exe)}
    for exe in exes.values():
        if not os.access(exe, os.X_OK):
            sys.exit("run.py: %s: not an executable" % exe)
    all_scenes = sorted(os.path.splitext(os.path.basename(p))[0]
                        for p in glob.glob(os.path.join(SOURCE, "prm",
                                                        "*.prm")))
    wanted = [s for s in args.scenes.split(",") if s] or all_scenes
    unknown = [s for s in wanted if s not in all_scenes]
    if unknown:
        sys.exit("run.py: no prm/%s.prm" % ".prm, prm/".join(unknown))
    skipped = [s for s in args.skip.split(",") if s]
    scenes = [s for s in wanted if s not in skipped]

    start = time.time()
    started = datetime.datetime.now(datetime.timezone.utc)
    load_before = os.getloadavg()
    root = tempfile.mkdtemp(prefix="same-answers-")
    rows = []
    try:
        with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
            futures = {}
            for scene in scenes:
                prm = os.path.join(SOURCE, "prm", scene + ".prm")
                for binary in ("old", "new"):
                    work = os.path.join(root, scene, binary)
                    os.makedirs(work)
                    futures[(scene, binary)] = pool.submit(
                        run_scene, exes[binary], prm, work)
            for scene in scenes:
                runs = {b: futures[(scene, b)].result()
                        for b in ("old", "new")}
                failed = [b for b in ("new", "old") if runs[b]["exit"] != 0]
                ignored = set()
                if failed:
                    verdict = "failed"
                    detail = "; ".join("%s: exit %s, %s" % (
                        b, runs[b]["exit"], runs[b]["message"])
                        for b in failed)
                else:
                    difference, ignored = compare(runs["new"]["output"],
                                                  runs["old"]["output"])
                    verdict = "differs" if difference else "identical"
                    detail = difference or ", ".join(
                        sorted(output_files(runs["new"]["output"])))
                rows.append({"scene": scene, "verdict": verdict,
                             "detail": detail, "ignored": ignored,
                             "old_s": runs["old"]["wall"],
                             "new_s": runs["new"]["wall"]})
                print("%-28s %-9s %s" % (scene, verdict, detail), flush=True)
                shutil.rmtree(os.path.join(root, scene), ignore_errors=True)
    finally:
        shutil.rmtree(root, ignore_errors=True)
    total = time.time() - start
    load_after = os.getloadavg()

    counts = {v: sum(r["verdict"] == v for r in rows)
              for v in ("identical", "differs", "failed")}
    summary = ("%d scenes: %d identical, %d differ, %d failed; %.0f s in all"
               % (len(rows), counts["identical"], counts["differs"],
                  counts["failed"], total))
    print(summary)
    if not args.no_write:
        write_table(rows, skipped, exes, args, started, total, summary,
                    load_before, load_after)
    return 1 if counts["differs"] or counts["failed"] else 0


def write_table(rows, skipped, exes, args, started, total, summary,
                load_before, load_after):
    new_commit = commit_of(exes["new"], args.new_commit, "FSSI_NEW_COMMIT")
    old_commit = commit_of(exes["old"], args.old_commit, "FSSI_OLD_COMMIT")
    ignored = sorted(set().union(*[r["ignored"] for r in rows]))
    out = io.StringIO()
    out.write("# Same answers: every bundled scene, new build against old\n\n")
    out.write("Generated by `python3 benchmarks/same-answers/run.py` on %s "
              "(UTC); %s.\n\n" % (started.strftime("%Y-%m-%d %H:%M"), summary))
    out.write("- new: commit %s, `%s`\n" % (new_commit, exes["new"]))
    out.write("- old: commit %s, `%s`\n" % (old_commit, exes["old"]))
    out.write("- machine: %d cores, load average %.1f before and %.1f after "
              "(other jobs running); two runs at a time, old and new side by "
              "side, OPENBLAS_NUM_THREADS=%s\n" % (
                  os.cpu_count(), load_before[0], load_after[0],
                  os.environ.get("OPENBLAS_NUM_THREADS", "1")))
    out.write("- skipped: %s\n\n" % (", ".join(skipped) if skipped else
                                     "none"))
    out.write("Compared: every *.csv and *.txt file of each scene's output "
              "folder, line by line as text. Ignored, and only these: the "
              "wall-time rows of results.csv (quantity `time_<phase>`, "
              "`step_wall_time`) and the wall-time columns of the tables "
              "(`time_s` of load-displacement.csv). Ignored in this run: %s."
              "\n\n" % (", ".join("`%s`" % i for i in ignored) or "nothing"))
    out.write("| scene | result | files compared, or the first difference "
              "| old [s] | new [s] |\n")
    out.write("|---|---|---|---|---|\n")
    for r in rows:
        out.write("| %s | %s | %s | %.1f | %.1f |\n" % (
            r["scene"], r["verdict"], r["detail"].replace("|", "\\|"),
            r["old_s"], r["new_s"]))
    with open(os.path.join(HERE, "results.md"), "w") as f:
        f.write(out.getvalue())


if __name__ == "__main__":
    sys.exit(main())
