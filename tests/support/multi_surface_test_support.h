// What the element tests of both multi-surface laws (the iwan clay and the
// iwan-sand) share: the simple-shear strain, the damping ratio of Masing
// loops on the hyperbola, and the tangent errors sorted by how many elements
// yield.
#ifndef fourier_ssi_tests_multi_surface_test_support_h
#define fourier_ssi_tests_multi_surface_test_support_h

#include "check.h"

#include <algorithm>
#include <cmath>
#include <deal.II/base/numbers.h>
#include <fourier_ssi/fourier/harmonic_operator.h>
#include <iostream>
#include <string>

namespace multi_surface_test
{
  /** Simple shear in the rz plane: gamma_rz = gamma, nothing else. */
  inline FourierSSI::StrainVector
  simple_shear(const double gamma)
  {
    return {{0., 0., 0., gamma, 0., 0.}};
  }

  /**
   * The damping ratio of Masing loops on the hyperbola tau = G0 gamma /
   * (1 + gamma / gamma_ref) at x = gamma_a / gamma_ref
   * (doc/derivations/multi_surface_clay.md section 6).
   */
  inline double
  hyperbola_damping(const double x)
  {
    const double pi = dealii::numbers::PI;
    return 4. / pi * (1. + 1. / x) * (1. - std::log1p(x) / x) - 2. / pi;
  }

  /**
   * The worst tangent error of the samples in each class of yielding
   * elements: none, some, all (index 0, 1, 2).
   */
  struct TangentErrors
  {
    double       worst[3] = {0., 0., 0.};
    unsigned int count[3] = {0, 0, 0}, skipped = 0;

    /** One sample with `n_yielding` of `n` elements; error < 0: skipped. */
    void
    add(const double error, const unsigned int n_yielding, const unsigned n)
    {
      if (error < 0.)
        {
          ++skipped;
          return;
        }
      const unsigned int c = n_yielding == 0 ? 0 : (n_yielding < n ? 1 : 2);
      worst[c]             = std::max(worst[c], error);
      ++count[c];
    }

    /** At least 20 samples per class, each within `tolerance` of G0. */
    void
    check(const double tolerance) const
    {
      std::cout << "samples (none / some / all yielding): " << count[0] << " / "
                << count[1] << " / " << count[2] << ", skipped " << skipped
                << std::endl;
      const char *name[3] = {"no element yields",
                             "some elements yield",
                             "all elements yield"};
      for (unsigned int c = 0; c < 3; ++c)
        {
          check::that(std::string(name[c]) + ": at least 20 samples",
                      count[c] >= 20);
          check::small(std::string(name[c]) + ": |D - central difference| / G0",
                       worst[c],
                       tolerance);
        }
    }
  };
} // namespace multi_surface_test

#endif
