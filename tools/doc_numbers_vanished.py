#!/usr/bin/python3
"""Numbers that vanished from the docs when pages were split or rewritten.

    tools/doc_numbers_vanished.py REV OLD,PAGES NEW,PAGES

Reads the old pages as they were at the commit REV (`git show REV:path`) and
the new pages from the work tree, extracts every numeric token (1.3e-5,
0.23, 1 277 475 with thin thousands groups; signs dropped, so -53.39 and
−53.39 match) and prints the distinct tokens of the old pages that none of
the new pages contains. A page split keeps the number check honest this
way: every token listed is either superseded (say by what) or dropped on
purpose (say why).

Example, the split of a guide into guide and verification record:

    tools/doc_numbers_vanished.py main doc/offshore-foundations.md \\
        doc/offshore-foundations.md,doc/verification/offshore-foundations.md
"""
import re
import subprocess
import sys

NUMBER = re.compile(r"(?<![\w.])(?:\d{1,3}(?: \d{3})+(?![\d])|\d+)"
                    r"(?:\.\d+)?(?:e[−+-]?\d+)?(?![\w])")


def numbers(text):
    return {m.group(0).replace(" ", "") for m in NUMBER.finditer(text)}


def old_text(rev, path):
    run = subprocess.run(["git", "show", f"{rev}:{path}"],
                         capture_output=True, text=True)
    return run.stdout if run.returncode == 0 else ""


def new_text(path):
    try:
        with open(path, encoding="utf-8") as f:
            return f.read()
    except FileNotFoundError:
        return ""


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    rev, olds, news = sys.argv[1], sys.argv[2].split(","), sys.argv[3].split(",")
    before = set().union(*(numbers(old_text(rev, p)) for p in olds))
    after = set().union(*(numbers(new_text(p)) for p in news))
    vanished = sorted(before - after)
    print(f"{len(before)} distinct numbers before, {len(after)} after; "
          f"vanished: {len(vanished)}")
    for token in vanished:
        print("  ", token)


if __name__ == "__main__":
    main()
