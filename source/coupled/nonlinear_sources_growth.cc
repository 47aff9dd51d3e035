// The harmonics a converged step of a scene whose only nonlinear source is
// the interfaces calls for (Load path/Maximum harmonic,
// doc/nonlinear-interfaces.md section 5): the set grows where the interface
// traction has them, and the step is solved again (CoupledSolver::grows).
#include <algorithm>
#include <cmath>
#include <fourier_ssi/coupled/nonlinear_sources.h>
#include <iomanip>
#include <sstream>

namespace FourierSSI
{
  namespace
  {
    bool
    contains(const std::vector<Harmonic> &list, const Harmonic &h)
    {
      return std::any_of(list.begin(), list.end(), [&](const Harmonic &g) {
        return g.n == h.n && g.family == h.family;
      });
    }
  } // namespace

  std::vector<Harmonic>
  NonlinearSources::harmonics_called_for(const InterfaceSnapshot &snapshot,
                                         std::ostream            &log) const
  {
    std::vector<Harmonic> added;
    if (candidates.empty())
      return added;
    // 1. The spectrum of t - t0: per candidate harmonic, the amplitudes of
    //    the three components at every point, squared and weighted by the
    //    point's area (an L2 norm over the interface of that harmonic).
    const std::vector<InterfacePoint> &points = interface->get_points();
    const unsigned int                 N      = interface_samples.n_samples();
    std::vector<double> norm_sqr(candidates.size(), 0.), samples(N), amplitude;
    for (unsigned int i = 0; i < points.size(); ++i)
      for (unsigned int c = 0; c < 3; ++c)
        {
          for (unsigned int j = 0; j < N; ++j)
            samples[j] =
              snapshot.traction[i * N + j][c] - points[i].initial_traction[c];
          spectrum.project(samples,
                           c == 2 ? ThetaFactor::circumferential :
                                    ThetaFactor::in_plane,
                           amplitude);
          for (unsigned int h = 0; h < candidates.size(); ++h)
            norm_sqr[h] +=
              points[i].area_per_radian * amplitude[h] * amplitude[h];
        }
    // 2. Harmonics not solved whose amplitude has not decayed below the
    //    tolerance relative to the largest one.
    const double largest =
      std::sqrt(*std::max_element(norm_sqr.begin(), norm_sqr.end()));
    std::ostringstream why;
    for (unsigned int h = 0; h < candidates.size(); ++h)
      {
        const double relative =
          largest > 0. ? std::sqrt(norm_sqr[h]) / largest : 0.;
        if (contains(harmonics, candidates[h]) ||
            relative <= settings.harmonic_tolerance)
          continue;
        added.push_back(candidates[h]);
        why << ' ' << candidates[h].name() << " (" << std::setprecision(3)
            << relative << ')';
      }
    if (!added.empty())
      log << "  harmonics added, interface-traction amplitude relative to "
             "the largest above "
          << settings.harmonic_tolerance << ":" << why.str()
          << "; the step is solved again\n";
    return added;
  }

} // namespace FourierSSI
