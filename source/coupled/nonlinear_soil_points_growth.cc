// The plastic soil's part of harmonics chosen by the solution (Load
// path/Maximum harmonic, doc/soil-plasticity.md section 3e): the theta
// spectrum of the soil's stress at a converged state, and the points'
// per-harmonic data extended when the set grows.
#include <fourier_ssi/coupled/nonlinear_soil_points.h>
#include <fourier_ssi/harmonic/stress_postprocessor.h>

namespace FourierSSI
{
  void
  NonlinearSoilPoints::grow(const ThetaSampling &grown)
  {
    const unsigned int first = operators.size();
    harmonics                = set.get_harmonics();
    for (unsigned int h = first; h < harmonics.size(); ++h)
      operators.emplace_back(harmonics[h]);
    sampling = grown;
    // The cells are in the order of their active index (make_points): one
    // walk over each added harmonic's cells finds them all.
    const unsigned int n_dofs = component.size();
    for (unsigned int h = first; h < harmonics.size(); ++h)
      {
        auto it = set.problem(h).get_dof_handler().begin_active();
        for (SoilCell &cell : cells)
          {
            while (it->active_cell_index() != cell.active_cell_index)
              ++it;
            std::vector<types::global_dof_index> indices(n_dofs);
            it->get_dof_indices(indices);
            cell.dof_indices.push_back(std::move(indices));
          }
      }
  }

  std::vector<double>
  NonlinearSoilPoints::stress_spectrum(const std::vector<StrainVector> &strain,
                                       const std::vector<StrainVector> &plastic,
                                       const ThetaSampling &candidates) const
  {
    const unsigned int  N = sampling.n_samples();
    std::vector<double> samples(N, 0.), amplitude;
    // One amplitude per candidate, also on a rank that owns no point.
    candidates.project(samples, ThetaFactor::in_plane, amplitude);
    std::vector<double> norm_sqr(amplitude.size(), 0.);
    for (unsigned int p = 0; p < points.size(); ++p)
      {
        if (!owns_point(p))
          continue; // its samples are on its own rank
        const SoilPoint          &point = points[p];
        std::vector<StrainVector> change(N);
        for (unsigned int j = 0; j < N; ++j)
          {
            // sigma - sigma_0 = D eps - s_p (s_p = sigma_0 + D eps - sigma).
            change[j] = hooke_stress(strain[p * N + j],
                                     point.lambda,
                                     point.shear_modulus);
            for (unsigned int k = 0; k < 6; ++k)
              change[j][k] -= plastic[p * N + j][k];
          }
        for (unsigned int k = 0; k < 6; ++k)
          {
            for (unsigned int j = 0; j < N; ++j)
              samples[j] = change[j][k];
            candidates.project(samples, strain_theta_factor(k), amplitude);
            for (unsigned int h = 0; h < amplitude.size(); ++h)
              norm_sqr[h] += point.dV * amplitude[h] * amplitude[h];
          }
      }
    // Each point is on one rank; the sum gives every rank the same
    // spectrum, so every rank adds the same harmonics.
    if (point_stride > 1)
      set.sum_over_ranks(norm_sqr);
    return norm_sqr;
  }
} // namespace FourierSSI
