"""Geometric mesh grading: the growth ratio of a segment's cells from the
size of its last cell (Mesh/R growth, Z growth). One definition for the
scripts that write graded meshes (tools/sweep.py, benchmarks/table-4-1/run.py)
and, through run.py, for tests/harmonic/table_4_1.cc."""


def growth_for(n, length, h_end):
    """Ratio g of n geometric cells summing to 'length' whose LAST cell is
    h_end (g < 1 shrinks toward the segment end)."""
    if abs(n * h_end - length) < 1e-12:
        return 1.0

    def total(g):  # first cell h_end / g^(n-1)
        return sum(h_end / g ** (n - 1 - i) for i in range(n))

    lo, hi = (1e-3, 1.0) if n * h_end < length else (1.0, 1e3)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if (total(mid) > length) == (n * h_end < length):
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)
