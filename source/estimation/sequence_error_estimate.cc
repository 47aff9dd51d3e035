#include <cmath>
#include <deal.II/base/exceptions.h>
#include <fourier_ssi/estimation/sequence_error_estimate.h>
#include <fourier_ssi/input/material.h>

namespace FourierSSI
{
  double
  design_member_ratio(const double largest_poisson_ratio,
                      const bool   slip_wedges)
  {
    return largest_poisson_ratio >= locking_poisson_ratio || slip_wedges ? 0.6 :
                                                                           0.4;
  }


  SequenceErrorEstimate
  estimate_sequence_error(const std::vector<double> &values,
                          const double               assumed_ratio,
                          const double               ratio_floor)
  {
    AssertThrow(values.size() >= 2,
                dealii::ExcMessage("an error estimate needs the values on "
                                   "two nested meshes at least"));
    const unsigned int    k = values.size() - 1;
    const double          d = values[k] - values[k - 1];
    SequenceErrorEstimate e;
    e.ratio = assumed_ratio;
    if (k >= 2 && values[k - 1] != values[k - 2])
      {
        const double r = d / (values[k - 1] - values[k - 2]);
        if (r > 0. && r < 1.)
          {
            e.asymptotic = true;
            e.ratio      = std::max(r, ratio_floor);
          }
      }
    e.absolute = std::abs(d) * e.ratio / (1. - e.ratio);
    e.relative =
      values[k] != 0. ? e.absolute / std::abs(values[k]) : e.absolute;
    return e;
  }
} // namespace FourierSSI
