#include <algorithm>
#include <atomic>
#include <exception>
#include <fourier_ssi/linear_algebra/serial_blas.h>
#include <fourier_ssi/linear_algebra/thread_ranges.h>
#include <thread>
#include <vector>

namespace FourierSSI
{
  void
  for_each_range(
    const unsigned int n_items,
    const unsigned int grain,
    const unsigned int n_threads,
    const std::function<void(const unsigned int, const unsigned int)> &task)
  {
    const unsigned int              size     = std::max(grain, 1u);
    const unsigned int              n_ranges = (n_items + size - 1) / size;
    std::vector<std::exception_ptr> errors(n_ranges);
    std::atomic<unsigned int>       next(0);
    const auto                      work = [&]() {
      for (unsigned int r = next++; r < n_ranges; r = next++)
        try
          {
            task(r * size, std::min(n_items, (r + 1) * size));
          }
        catch (...)
          {
            errors[r] = std::current_exception();
          }
    };
    const unsigned int threads = std::min(n_threads, n_ranges);
    if (threads <= 1)
      work();
    else
      {
        std::vector<std::thread> workers;
        for (unsigned int t = 0; t < threads; ++t)
          workers.push_back(serial_thread(work));
        for (auto &worker : workers)
          worker.join();
      }
    for (const std::exception_ptr &error : errors)
      if (error)
        std::rethrow_exception(error);
  }
} // namespace FourierSSI
