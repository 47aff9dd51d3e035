"""The relative check the python test scripts share: one printed line per
check (value, reference, relative error, tolerance) and the names of the
failed ones in `failed`, for the script's exit code."""

failed = []


def check(name, value, reference, tol):
    """|value - reference| / |reference| <= tol; prints the line."""
    err = abs(value - reference) / max(abs(reference), 1e-300)
    ok = err <= tol
    print(f"{'ok  ' if ok else 'FAIL'} {name}: {value:.10g} vs {reference:.10g} "
          f"(rel {err:.2e}, tol {tol:g})")
    if not ok:
        failed.append(name)


passed = 0


def that(ok, what):
    """A check of a condition: prints `what` as ok or FAIL and counts it."""
    global passed
    print(("  ok   " if ok else "  FAIL ") + what)
    if ok:
        passed += 1
    else:
        failed.append(what)


def finish():
    """The summary line and the exit code of the script."""
    import sys
    print("%d passed, %d failed" % (passed, len(failed)))
    sys.exit(1 if failed else 0)
