// for_each_range (the soil points on the harmonic set's threads): every
// item in exactly one range, for item counts that are and are not multiples
// of the grain, on 1, 2 and 3 threads; an exception in one range reaches
// the caller. Exact counts: any miss or double visit is an integer error.
#include "check.h"

#include <atomic>
#include <fourier_ssi/linear_algebra/thread_ranges.h>
#include <stdexcept>
#include <vector>

using namespace FourierSSI;

int
main()
{
  for (const unsigned int n_items : {0u, 1u, 16u, 1000u, 1003u})
    for (const unsigned int threads : {1u, 2u, 3u})
      {
        std::vector<std::atomic<int>> visits(n_items);
        for (auto &v : visits)
          v = 0;
        std::atomic<unsigned int> ranges(0);
        for_each_range(n_items,
                       16,
                       threads,
                       [&](const unsigned int first, const unsigned int last) {
                         ++ranges;
                         for (unsigned int i = first; i < last; ++i)
                           ++visits[i];
                       });
        unsigned int wrong = 0;
        for (const auto &v : visits)
          wrong += v != 1;
        const std::string name = std::to_string(n_items) + " items, " +
                                 std::to_string(threads) + " threads: ";
        check::small(name + "items not visited exactly once", wrong, 0.);
        check::relative(name + "ranges of 16", ranges, (n_items + 15) / 16, 0.);
      }
  bool caught = false;
  try
    {
      for_each_range(100, 10, 2, [](const unsigned int first, unsigned int) {
        if (first == 50)
          throw std::runtime_error("range 50");
      });
    }
  catch (const std::runtime_error &e)
    {
      caught = std::string(e.what()) == "range 50";
    }
  check::that("an exception in one range reaches the caller", caught);
  return check::summary();
}
