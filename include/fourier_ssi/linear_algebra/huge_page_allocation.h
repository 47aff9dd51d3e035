/**
 * Large blocks of memory on transparent huge pages.
 *
 * The first touch of every 4 KiB page of fresh memory is a page fault. The
 * large arrays of a harmonic (the sparse matrix, the copies CHOLMOD's
 * analysis makes, the Cholesky factor) are allocated fresh for every mesh,
 * so on a machine whose page faults are slow (about 6 ms per MiB measured on
 * the 2-core benchmark machine, a virtual machine) the faults were a quarter
 * of the CPU time of a Target accuracy run (doc/accuracy-vs-time.md, "Where
 * the time goes"). Blocks of at least 2 MiB are therefore aligned to 2 MiB
 * and advised as huge pages (Linux madvise(MADV_HUGEPAGE)): one fault per
 * 2 MiB. Where the kernel gives no huge page the block stays on small pages;
 * the contents and the results are the same either way.
 *
 * Freed memory is kept in the process (keep_freed_memory()): a block of a
 * later mesh, or of CHOLMOD's next temporary copy, then reuses pages that
 * are already touched instead of faulting in fresh ones. The rough 1e-4
 * design's solve time fell by about a fifth with it (doc/accuracy-vs-time.md,
 * "Freed memory kept"); the peak resident memory is the same.
 *
 * The blocks are freed with std::free. The program's global operator new
 * uses huge_page_malloc (source/linear_algebra/huge_page_allocation.cc), and SparseDirect
 * hands huge_page_malloc and huge_page_calloc to SuiteSparse.
 */
#ifndef fourier_ssi_huge_page_allocation_h
#define fourier_ssi_huge_page_allocation_h

#include <cstddef>

namespace FourierSSI
{
  /** std::malloc, with blocks >= 2 MiB aligned and advised as huge pages. */
  void *
  huge_page_malloc(std::size_t size);

  /** std::calloc on huge_page_malloc. */
  void *
  huge_page_calloc(std::size_t count, std::size_t size);

  /**
   * Let glibc's malloc serve every block from its heap and never give freed
   * memory back to the system (mallopt: no mmap'ed blocks, no trimming).
   * Call once, at the start of main.
   */
  void
  keep_freed_memory();
} // namespace FourierSSI

#endif
