/**
 * One thread for the dense kernels (BLAS, OpenMP) inside a harmonic solve.
 *
 * The program's parallelism is harmonics solved at the same time
 * (Discretization/Harmonics in parallel, TBB) and MPI ranks; each harmonic's
 * assembly and factorization run on one thread (deal.II's thread limit is 1
 * in a serial run). A threaded BLAS (OpenBLAS) and CHOLMOD's OpenMP loops
 * would start their own threads inside that one thread: on the 2-core
 * benchmark machine, shared with other jobs, they spun and waited, and the
 * embedded footing's member 1 (53k DoFs) took 1.3–2.1 s with them against
 * 0.9–1.1 s without (doc/accuracy-vs-time.md, "Where the time goes"). Their
 * sums also differed from run to run at 3e-9 relative in K_H, the round-off
 * of the threaded kernels; with one thread the results repeat.
 *
 * OpenMP's thread count is a property of each thread (a new thread starts
 * from the default, all cores), so every thread the program starts runs its
 * work through serial_thread(); and OpenBLAS's pool, started when the
 * library loads, keeps polling (sched_yield) even when held to one thread:
 * it is stopped (doc/accuracy-vs-time.md, "Meshes 0 and 1 side by side").
 */
#ifndef fourier_ssi_serial_blas_h
#define fourier_ssi_serial_blas_h

#include <functional>
#include <thread>

namespace FourierSSI
{
  /**
   * Set the BLAS (OpenBLAS, if it is the BLAS loaded) to one thread and
   * stop its idle thread pool; OpenMP to one thread in the calling thread.
   * Call once, before any solve; a BLAS without such controls is left as
   * it is.
   */
  void
  use_serial_blas();

  /** OpenMP (CHOLMOD's loops) on one thread in the calling thread. */
  void
  use_serial_openmp_in_this_thread();

  /** A thread that runs `work` with use_serial_openmp_in_this_thread(). */
  std::thread
  serial_thread(std::function<void()> work);
} // namespace FourierSSI

#endif
