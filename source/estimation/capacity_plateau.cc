#include <array>
#include <cmath>
#include <fourier_ssi/estimation/capacity_plateau.h>
#include <limits>

namespace FourierSSI
{
  double
  plateau_error(const std::vector<double> &motion,
                const std::vector<double> &load)
  {
    const std::size_t n = motion.size();
    if (n < 3 || load.size() != n)
      return std::numeric_limits<double>::infinity();
    std::array<double, 3> u, q;
    for (unsigned int i = 0; i < 3; ++i)
      {
        u[i] = std::abs(motion[n - 3 + i]);
        q[i] = u[i] / std::abs(load[n - 3 + i]);
      }
    const double mean_u = (u[0] + u[1] + u[2]) / 3.,
                 mean_q = (q[0] + q[1] + q[2]) / 3.;
    double covariance = 0., variance = 0.;
    for (unsigned int i = 0; i < 3; ++i)
      {
        covariance += (u[i] - mean_u) * (q[i] - mean_q);
        variance += (u[i] - mean_u) * (u[i] - mean_u);
      }
    const double b = covariance / variance;
    if (!(b > 0.))
      return std::numeric_limits<double>::infinity();
    return std::abs(1. / b - std::abs(load.back()));
  }
} // namespace FourierSSI
