#include <cmath>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/numerics/error_estimator.h>
#include <fourier_ssi/coupled/mechanism_indicator.h>

namespace FourierSSI
{
  Vector<float>
  mechanism_indicators(const HarmonicSet &set, const CoupledSolver &solver)
  {
    const unsigned int n_cells =
      set.problem(0).get_dof_handler().get_triangulation().n_active_cells();
    std::vector<double> squares(n_cells, 0.);
    Vector<float>       kelly(n_cells);
    for (unsigned int h = 0; h < set.size(); ++h)
      {
        const DoFHandler<2> &dof_handler = set.problem(h).get_dof_handler();
        const Vector<double> increment   = solver.last_step_increment(h);
        // Interface faces are boundary faces: the jump they allow is not
        // counted.
        KellyErrorEstimator<2>::estimate(dof_handler,
                                         QGauss<1>(dof_handler.get_fe().degree +
                                                   1),
                                         {},
                                         increment,
                                         kelly);
        const double weight = set.harmonic(h).n == 0 ? 2. * M_PI : M_PI;
        for (unsigned int c = 0; c < n_cells; ++c)
          squares[c] += weight * double(kelly(c)) * double(kelly(c));
      }
    Vector<float> indicators(n_cells);
    for (unsigned int c = 0; c < n_cells; ++c)
      indicators(c) = static_cast<float>(std::sqrt(squares[c]));
    return indicators;
  }
} // namespace FourierSSI
