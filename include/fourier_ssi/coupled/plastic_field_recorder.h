/**
 * The plastic field of the load steps chosen by Output/Plastic field steps
 * (doc/output-files.md, "The plastic field"): at each chosen converged
 * step, per soil cell and theta sample, the equivalent plastic strain and
 * its increment over the step, the yield state (plastic or elastic in the
 * step, f), the stress sigma = sigma_0 + D eps - s_p, and the harmonics'
 * displacement amplitudes at the cell's vertices. It is a step observer of
 * the CoupledSolver (add_step_observer); the files are written by
 * plastic_field_output.h.
 *
 * The equivalent plastic strain of a plastic strain eps_p = D^-1 s_p is
 *   eps_eq = sqrt(2/3 e_p : e_p),   e_p = eps_p - tr(eps_p) 1 / 3,
 * the tensor product with the tensor shears (half the engineering ones):
 * the von Mises measure, equal to |eps_1| of an isochoric uniaxial plastic
 * strain (eps_1, -eps_1/2, -eps_1/2). Tresca and Mohr-Coulomb with psi = 0
 * flow isochorically (tr eps_p = 0). It is the measure of the total
 * plastic strain of the state, not a sum along the path; the increment is
 * the same measure of the step's change of eps_p.
 *
 * Under mpirun every rank return-maps its own points: their samples are
 * summed over the ranks (each non-zero on one rank, exact), so every rank
 * holds the serial run's field.
 */
#ifndef fourier_ssi_plastic_field_recorder_h
#define fourier_ssi_plastic_field_recorder_h

#include <deal.II/dofs/dof_handler.h>
#include <fourier_ssi/coupled/coupled_solver.h>
#include <fourier_ssi/harmonic/harmonic_set.h>
#include <fourier_ssi/input/output_parameters.h>
#include <fourier_ssi/postprocess/plastic_field_output.h>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /** sqrt(2/3 e_p : e_p) of a plastic strain (engineering shears). */
  double
  equivalent_plastic_strain(const StrainVector &plastic_strain);

  class PlasticFieldRecorder
  {
  public:
    /** `solver` must have soil points; `output` gives the chosen steps. */
    PlasticFieldRecorder(const CoupledSolver    &solver,
                         const HarmonicSet      &set,
                         const OutputParameters &output);

    /**
     * After load step `step` (from 1) converged: keep its field if it is a
     * chosen one (a collective under mpirun).
     */
    void
    observe(const unsigned int step);

    /**
     * After the path of `n_steps` converged steps: with `last`, keep the
     * last step's field; one line naming Output/Plastic field steps if a
     * chosen step lies beyond the path (before any result is written).
     */
    void
    finish(const unsigned int n_steps);

    /** The fields kept, in step order. */
    const std::vector<PlasticFieldSnapshot> &
    snapshots() const
    {
      return kept;
    }

    /** Wall time of the captures [s]. */
    double
    wall_time() const
    {
      return seconds;
    }

  private:
    /** The field of the solver's last converged state as step `step`. */
    PlasticFieldSnapshot
    capture(const unsigned int step) const;

    /** The soil cells' vertices and displacement amplitudes. */
    std::vector<PlasticFieldCell>
    cell_geometry() const;

    /** Every sample of the state on every rank. */
    std::vector<SoilSample>
    samples_on_every_rank() const;

    /** The cell means of the samples, [cell * N + j]. */
    std::vector<PlasticCellValues>
    cell_values(const std::vector<SoilSample> &samples) const;

    const CoupledSolver      &solver;
    const HarmonicSet        &set;
    std::vector<unsigned int> chosen_steps;
    /** [h][active cell index]: the soil cells of each harmonic's DoFs. */
    std::vector<std::vector<DoFHandler<2>::active_cell_iterator>> cells;
    std::vector<PlasticFieldSnapshot>                             kept;
    double                                                        seconds = 0.;
  };
} // namespace FourierSSI

#endif
