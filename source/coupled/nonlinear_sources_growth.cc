// The harmonics a converged step calls for (Load path/Maximum harmonic,
// doc/nonlinear-interfaces.md section 5, doc/soil-plasticity.md section
// 3e): the set grows where the soil's stress or the interface traction has
// them, and the step is solved again (CoupledSolver::grows).
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

    /**
     * A spectrum's L2 norms (square roots of the weighted sums of squares)
     * relative to its largest: all zero where the source has no content
     * (an unloaded state).
     */
    std::vector<double>
    relative_amplitudes(const std::vector<double> &norm_sqr)
    {
      std::vector<double> relative(norm_sqr.size(), 0.);
      if (norm_sqr.empty())
        return relative;
      const double largest =
        std::sqrt(*std::max_element(norm_sqr.begin(), norm_sqr.end()));
      if (largest > 0.)
        for (unsigned int h = 0; h < norm_sqr.size(); ++h)
          relative[h] = std::sqrt(norm_sqr[h]) / largest;
      return relative;
    }
  } // namespace

  std::vector<double>
  NonlinearSources::interface_spectrum(const InterfaceSnapshot &snapshot) const
  {
    // Per candidate harmonic, the amplitudes of the three components of
    // t - t0 at every point, squared and weighted by the point's area (an
    // L2 norm over the interface of that harmonic).
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
    return norm_sqr;
  }

  std::vector<double>
  NonlinearSources::soil_stress_spectrum(const CoupledStepState &state) const
  {
    // sigma - sigma_0 = D eps - s_p at the state's samples; D eps is
    // band-limited to the harmonics solved, so the others see s_p only.
    return soil.stress_spectrum(strain_samples(state.correction_solution,
                                               state.load_factor,
                                               state.held_fraction,
                                               state.swipe_force),
                                state.plastic,
                                soil_spectrum);
  }

  std::vector<Harmonic>
  NonlinearSources::harmonics_called_for(const CoupledStepState  &state,
                                         const InterfaceSnapshot &snapshot,
                                         const unsigned int       step,
                                         std::ostream            &log) const
  {
    std::vector<Harmonic> added;
    if (candidates.empty())
      return added;
    // 1. Each source's spectrum relative to its own largest amplitude (a
    //    stress and a traction have no common scale).
    std::vector<std::vector<double>> relative;
    std::vector<std::string>         source;
    if (soil.size() > 0)
      {
        relative.push_back(relative_amplitudes(soil_stress_spectrum(state)));
        source.emplace_back("soil-stress");
      }
    if (interface)
      {
        relative.push_back(relative_amplitudes(interface_spectrum(snapshot)));
        source.emplace_back("interface-traction");
      }
    // 2. Harmonics not solved that some source has above the tolerance.
    std::ostringstream why;
    why << std::setprecision(3);
    for (unsigned int h = 0; h < candidates.size(); ++h)
      {
        if (contains(harmonics, candidates[h]) ||
            std::none_of(relative.begin(),
                         relative.end(),
                         [&](const std::vector<double> &r) {
                           return r[h] > settings.harmonic_tolerance;
                         }))
          continue;
        added.push_back(candidates[h]);
        why << ' ' << candidates[h].name() << " (";
        for (unsigned int s = 0; s < relative.size(); ++s)
          why << (s > 0 ? " / " : "") << relative[s][h];
        why << ')';
      }
    if (added.empty())
      return added;
    log << "  step " << step << ": harmonics added, ";
    for (unsigned int s = 0; s < source.size(); ++s)
      log << (s > 0 ? " / " : "") << source[s];
    log << " amplitude relative to the largest above "
        << settings.harmonic_tolerance << ":" << why.str()
        << "; the step is solved again\n";
    return added;
  }

} // namespace FourierSSI
