/**
 * The points of a coupled iteration (soil quadrature points) on the threads
 * the harmonic set uses. deal.II's own thread pool is limited to one thread
 * in this program (command_line.cc: the parallelism is harmonics solved at
 * the same time, HarmonicSet::for_each), so its parallel::apply_to_subranges
 * runs serially here; loops over independent points use this instead.
 */
#ifndef fourier_ssi_thread_ranges_h
#define fourier_ssi_thread_ranges_h

#include <functional>

namespace FourierSSI
{
  /**
   * task(first, last) for consecutive ranges of about `grain` items that
   * cover [0, n_items), up to n_threads at once. Each item belongs to one
   * range; an exception in a task is rethrown (the first range's first).
   */
  void
  for_each_range(
    const unsigned int n_items,
    const unsigned int grain,
    const unsigned int n_threads,
    const std::function<void(const unsigned int, const unsigned int)> &task);
} // namespace FourierSSI

#endif
