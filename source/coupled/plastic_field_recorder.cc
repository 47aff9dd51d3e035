#include <algorithm>
#include <chrono>
#include <cmath>
#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>
#include <fourier_ssi/coupled/plastic_field_recorder.h>
#include <limits>
#include <string>
#include <utility>

namespace FourierSSI
{
  namespace
  {
    /** Doubles per sample when the ranks' samples are summed. */
    constexpr unsigned int sample_size = 20;

    void
    pack(const SoilSample &s, double *out)
    {
      for (unsigned int c = 0; c < 6; ++c)
        {
          out[c]      = s.stress[c];
          out[6 + c]  = s.plastic_strain[c];
          out[12 + c] = s.plastic_strain_increment[c];
        }
      out[18] = s.yield_value;
      out[19] = s.plastic ? 1. : 0.;
    }

    SoilSample
    unpack(const double *in)
    {
      SoilSample s;
      for (unsigned int c = 0; c < 6; ++c)
        {
          s.stress[c]                   = in[c];
          s.plastic_strain[c]           = in[6 + c];
          s.plastic_strain_increment[c] = in[12 + c];
        }
      s.yield_value = in[18];
      s.plastic     = in[19] != 0.;
      return s;
    }

    bool
    has_plastic_strain(const StrainVector &plastic_strain)
    {
      return std::any_of(plastic_strain.begin(),
                         plastic_strain.end(),
                         [](const double e) { return e != 0.; });
    }
  } // namespace

  double
  equivalent_plastic_strain(const StrainVector &e)
  {
    const double mean   = (e[0] + e[1] + e[2]) / 3.;
    double       square = 0.;
    for (unsigned int k = 0; k < 3; ++k)
      square += (e[k] - mean) * (e[k] - mean);
    // Tensor shears are half the engineering ones, and count twice.
    for (unsigned int k = 3; k < 6; ++k)
      square += 0.5 * e[k] * e[k];
    return std::sqrt(2. / 3. * square);
  }

  PlasticFieldRecorder::PlasticFieldRecorder(const CoupledSolver    &solver,
                                             const HarmonicSet      &set,
                                             const OutputParameters &output)
    : solver(solver)
    , set(set)
    , chosen_steps(output.plastic_field_steps)
  {
    for (unsigned int h = 0; h < set.size(); ++h)
      {
        const DoFHandler<2> &dofs = set.problem(h).get_dof_handler();
        cells.emplace_back(dofs.get_triangulation().n_active_cells());
        for (const auto &cell : dofs.active_cell_iterators())
          cells[h][cell->active_cell_index()] = cell;
      }
  }

  void
  PlasticFieldRecorder::observe(const unsigned int step)
  {
    if (std::find(chosen_steps.begin(), chosen_steps.end(), step) ==
        chosen_steps.end())
      return;
    const auto start = std::chrono::steady_clock::now();
    kept.push_back(capture(step));
    seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
  }

  void
  PlasticFieldRecorder::finish(const unsigned int n_steps)
  {
    if (chosen_steps.empty())
      {
        AssertThrow(n_steps > 0,
                    ExcMessage("Output/Plastic field steps: the load path "
                               "has no converged step"));
        const auto start = std::chrono::steady_clock::now();
        kept             = {capture(n_steps)};
        seconds += std::chrono::duration<double>(
                     std::chrono::steady_clock::now() - start)
                     .count();
        return;
      }
    AssertThrow(chosen_steps.back() <= n_steps,
                ExcMessage("Output/Plastic field steps: step " +
                           std::to_string(chosen_steps.back()) +
                           " lies beyond the load path, which has " +
                           std::to_string(n_steps) + " converged steps"));
  }

  PlasticFieldSnapshot
  PlasticFieldRecorder::capture(const unsigned int step) const
  {
    PlasticFieldSnapshot snapshot;
    snapshot.step = step;
    for (unsigned int h = 0; h < set.size(); ++h)
      snapshot.harmonics.push_back(set.harmonic(h));
    snapshot.n_samples = solver.soil_points().n_theta_samples();
    snapshot.cells     = cell_geometry();
    const std::vector<SoilSample> samples = samples_on_every_rank();
    snapshot.values                       = cell_values(samples);
    snapshot.n_total                      = samples.size();
    snapshot.n_plastic =
      std::count_if(samples.begin(), samples.end(), [](const SoilSample &s) {
        return s.plastic;
      });
    return snapshot;
  }

  std::vector<PlasticFieldCell>
  PlasticFieldRecorder::cell_geometry() const
  {
    const NonlinearSoilPoints    &soil = solver.soil_points();
    std::vector<PlasticFieldCell> result(soil.n_cells());
    for (unsigned int h = 0; h < set.size(); ++h)
      {
        // A collective under mpirun: every rank asks for every harmonic.
        const Vector<double> u = solver.solution(h);
        for (unsigned int c = 0; c < soil.n_cells(); ++c)
          {
            const auto &cell = cells[h][soil.active_cell_index(c)];
            for (unsigned int v = 0; v < 4; ++v)
              {
                result[c].vertices[v] = cell->vertex(v);
                // The vertex DoFs of FE_Q are the field at the vertex;
                // components (u_r, u_z, u_theta).
                std::array<double, 3> a;
                for (unsigned int k = 0; k < 3; ++k)
                  a[k] = u(cell->vertex_dof_index(v, k));
                result[c].amplitudes[v].push_back(a);
              }
          }
      }
    return result;
  }

  std::vector<SoilSample>
  PlasticFieldRecorder::samples_on_every_rank() const
  {
    std::vector<SoilSample> samples = solver.committed_soil_samples();
    if (set.n_owning_ranks() <= 1)
      return samples;
    // Each sample is computed on the rank that owns its point and is zero
    // on the others: the sum is exact.
    std::vector<double> packed(samples.size() * sample_size);
    for (unsigned int k = 0; k < samples.size(); ++k)
      pack(samples[k], &packed[k * sample_size]);
    std::vector<double> summed(packed.size());
    Utilities::MPI::sum(make_array_view(std::as_const(packed)),
                        set.get_ranks(),
                        make_array_view(summed));
    for (unsigned int k = 0; k < samples.size(); ++k)
      samples[k] = unpack(&summed[k * sample_size]);
    return samples;
  }

  std::vector<PlasticCellValues>
  PlasticFieldRecorder::cell_values(
    const std::vector<SoilSample> &samples) const
  {
    const NonlinearSoilPoints     &soil = solver.soil_points();
    const unsigned int             N    = soil.n_theta_samples();
    std::vector<PlasticCellValues> result(soil.n_cells() * N);
    for (unsigned int c = 0; c < soil.n_cells(); ++c)
      for (unsigned int j = 0; j < N; ++j)
        {
          PlasticCellValues &values    = result[c * N + j];
          values.yield_value           = -std::numeric_limits<double>::max();
          double             volume    = 0.;
          unsigned int       n_plastic = 0, n_yielded = 0;
          const unsigned int first = soil.first_point(c),
                             last  = soil.first_point(c + 1);
          for (unsigned int p = first; p < last; ++p)
            {
              const SoilSample &s  = samples[p * N + j];
              const double      dV = soil.place(p).dV;
              volume += dV;
              values.plastic_strain +=
                dV * equivalent_plastic_strain(s.plastic_strain);
              values.plastic_strain_increment +=
                dV * equivalent_plastic_strain(s.plastic_strain_increment);
              for (unsigned int k = 0; k < 6; ++k)
                values.stress[k] += dV * s.stress[k];
              values.yield_value = std::max(values.yield_value, s.yield_value);
              n_plastic += s.plastic ? 1 : 0;
              n_yielded += has_plastic_strain(s.plastic_strain) ? 1 : 0;
            }
          values.plastic_strain /= volume;
          values.plastic_strain_increment /= volume;
          for (double &s : values.stress)
            s /= volume;
          values.plastic_points = double(n_plastic) / (last - first);
          values.yielded_points = double(n_yielded) / (last - first);
        }
    return result;
  }
} // namespace FourierSSI
