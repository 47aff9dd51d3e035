/**
 * The nonlinear sources of a coupled load step (doc/driver.md, "one load
 * step"): the plastic soil's quadrature points (NonlinearSoilPoints) and
 * the nonlinear interfaces' Gauss points (NonlinearInterfacePoints), each
 * at its theta samples. With s_p = D eps_p at every (soil point, theta)
 * and d_p the plastic relative displacement (slip and gap) at every
 * (interface point, theta), the out-of-balance load of harmonic h is
 *   G_h = int Bbar_h^T [int factor_h s_p dtheta] r dr dz
 *       + int int B_h^T D d_p r ds dtheta.
 * evaluate() gives at an iterate steps 1-4 of one iteration:
 *   1. strain amplitudes of every harmonic at every soil point (Bbar u_h,
 *      the dilatation projected per cell) and relative displacements at
 *      every interface point, summed at N theta samples
 *      (ThetaSampling::evaluate);
 *   2. the return mapping at every (point, theta) from the last converged
 *      state;
 *   3. G_h, the theta-integrated plastic parts through the same B that
 *      gives K;
 *   4. R = G - c, with the force scale it is measured against
 *      (ForceScale: |lambda F| and the interfaces' |G|).
 * A scene of interfaces on elastic soil is one with no soil points.
 */
#ifndef fourier_ssi_nonlinear_sources_h
#define fourier_ssi_nonlinear_sources_h

#include <deal.II/lac/vector.h>
#include <fourier_ssi/coupled/coupled_step_state.h>
#include <fourier_ssi/coupled/coupled_tangent.h>
#include <fourier_ssi/coupled/load_pattern.h>
#include <fourier_ssi/coupled/load_step_result.h>
#include <fourier_ssi/coupled/nonlinear_interface_points.h>
#include <fourier_ssi/coupled/nonlinear_soil_points.h>
#include <fourier_ssi/fourier/theta_sampling.h>
#include <fourier_ssi/harmonic/harmonic_set.h>
#include <fourier_ssi/input/parameters.h>
#include <functional>
#include <memory>
#include <ostream>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  class NonlinearSources
  {
  public:
    using MultiplierUpdate = NonlinearInterfacePoints::MultiplierUpdate;

    /**
     * `condensed`: the step is linearised on the interfaces' DoFs
     * (interfaces only); it decides their theta samples and whether stiff
     * coulomb laws are augmented. With growth (Load path/Maximum harmonic
     * above the set's) every sample count is chosen for Maximum harmonic,
     * so that the samples, and the state kept at them, stay when
     * harmonics are added. `loads` are the run's (read_loads()).
     */
    NonlinearSources(const HarmonicSet   &set,
                     const AllParameters &parameters,
                     const LoadPattern   &loads,
                     const bool           condensed);

    /**
     * What the sources read of the loads' elastic solutions: their strains
     * at the soil points and relative displacements at the interfaces'
     * samples. Again after the harmonics grow.
     */
    void
    read_loads();

    /** The committed state before the first step. */
    void
    start_at_rest(CoupledStepState &state) const;

    /**
     * Steps 1-4 at `state`, the return mapping from `committed`; the
     * soil's counts into `result`.
     */
    CoupledEvaluation
    evaluate(const CoupledStepState &state,
             const CoupledStepState &committed,
             LoadStepResult         &result) const;

    /**
     * G(u) of displacement fields u (K^-1 c of a state without loads, one
     * per harmonic), the return mapping from `committed`.
     */
    std::vector<Vector<double>>
    out_of_balance_load(const std::vector<Vector<double>> &fields,
                        const CoupledStepState            &committed) const;

    /**
     * True if the contact multipliers move between converged iterations
     * of a step (augmented Lagrangian, NonlinearInterfacePoints).
     */
    bool
    augments() const;

    /**
     * The `update`-th (from 0) move of the contact multipliers in `state`
     * after the converged iteration `e`, and its test
     * (NonlinearInterfacePoints::update_and_test_multipliers, the force
     * allowed Load path/Tolerance times the iteration's force scale).
     */
    MultiplierUpdate
    update_multipliers(const CoupledEvaluation &e,
                       const double             tolerance,
                       const unsigned int       update,
                       CoupledStepState        &state) const;

    /**
     * A converged iterate `e` of `state`: its plastic state, and the
     * sources' parts of the step's record.
     */
    void
    accept(CoupledEvaluation &e,
           CoupledStepState  &state,
           LoadStepResult    &result) const;

    /**
     * G of a converged state, unconstrained (nodal forces): the soil's
     * plastic part and the interfaces' from their tractions in
     * `interface_state` (NonlinearInterfacePoints::spring_plastic).
     */
    std::vector<Vector<double>>
    nodal_load(const CoupledStepState  &state,
               const InterfaceSnapshot &interface_state) const;

    /**
     * Total strain samples [point * N + j] at lambda, rho and a swipe's mu,
     * at the points this rank owns (NonlinearSoilPoints::strain_samples;
     * zero at the others).
     */
    std::vector<StrainVector>
    strain_samples(const std::vector<Vector<double>> &correction,
                   const double                       load_factor,
                   const double                       held_fraction,
                   const double                       swipe_force = 0.) const;

    /**
     * The relative displacements at the interfaces' samples of K^-1 c
     * with the loads at lambda, rho, mu (empty without interfaces).
     */
    std::vector<LocalVector>
    relative_displacements(const std::vector<Vector<double>> &correction,
                           const double                       load_factor,
                           const double                       held_fraction,
                           const double swipe_force = 0.) const;

    /** The coupled tangent's sparsity: the soil cells and interface pairs. */
    std::vector<std::vector<std::vector<types::global_dof_index>>>
    tangent_dofs() const;

    /**
     * K_t -= the soil's softening at the points that yield and the
     * interfaces' at the samples that slip or open.
     */
    void
    add_softening(const std::vector<StrainVector> &strain,
                  const CoupledStepState          &committed,
                  const std::vector<LocalVector>  &relative,
                  const std::vector<LocalVector>  &interface_origin,
                  CoupledTangent                  &tangent) const;

    /**
     * Maximum harmonic above the set's: harmonics n <= Maximum harmonic,
     * not solved, that a source of the converged `state` calls for: the
     * amplitude of the soil's stress change sigma - sigma_0, or of the
     * interfaces' traction change t - t0 (`snapshot`), exceeds Harmonic
     * tolerance times that source's largest amplitude. One log line names
     * the step (`step`, from 1), each harmonic added, its relative
     * amplitudes and the source (nonlinear_sources_growth.cc).
     */
    std::vector<Harmonic>
    harmonics_called_for(const CoupledStepState  &state,
                         const InterfaceSnapshot &snapshot,
                         const unsigned int       step,
                         std::ostream            &log) const;

    /**
     * The set grew: the samples stay (chosen for Maximum harmonic), their
     * factors gain the added harmonics, the soil points their strain
     * operators and DoFs; read_loads() follows.
     */
    void
    resample();

    /** The nonlinear interfaces' log lines (NonlinearInterfacePoints). */
    void
    describe_interfaces(std::ostream &log) const;

    /**
     * No soil, and a coulomb interface with c = 0 and no Initial stress:
     * nothing gives it strength.
     */
    bool
    lacks_strength() const;

    /** The first words of the log's first line: what the sources are. */
    void
    describe_points(std::ostream &log) const;

    /** Growth is on (candidate harmonics up to Maximum harmonic). */
    bool
    grows() const
    {
      return !candidates.empty();
    }

    const NonlinearSoilPoints &
    soil_points() const
    {
      return soil;
    }

    /** The nonlinear interfaces (null: none). */
    const NonlinearInterfacePoints *
    interface_points() const
    {
      return interface.get();
    }

    /** The theta samples of the soil (of the interfaces without soil). */
    const ThetaSampling &
    soil_sampling() const
    {
      return sampling;
    }

    /** The interfaces' theta samples. */
    const ThetaSampling &
    interface_sampling() const
    {
      return interface_samples;
    }

    /** The interfaces' relative displacements of the loads' solutions. */
    const InterfaceLoadCases &
    interface_load_cases() const
    {
      return interface_cases;
    }

  private:
    /**
     * The nonlinear interfaces' part of an evaluation: their relative
     * displacements, return mapping and load added to the residual (the
     * residual, if empty: no soil); returns the norm of that load (part of
     * the force scale).
     */
    double
    add_interface_residual(const CoupledStepState &state,
                           CoupledEvaluation      &e) const;

    /**
     * Growth: per candidate harmonic, the area-weighted sum of squares of
     * the amplitudes of the interface traction change t - t0.
     */
    std::vector<double>
    interface_spectrum(const InterfaceSnapshot &snapshot) const;

    /**
     * Growth: per candidate harmonic, the volume-weighted sum of squares of
     * the amplitudes of the soil's stress change at `state`
     * (NonlinearSoilPoints::stress_spectrum; a collective under MPI).
     */
    std::vector<double>
    soil_stress_spectrum(const CoupledStepState &state) const;

    const HarmonicSet        &set;
    const LoadPathParameters &settings;
    const LoadPattern        &loads;
    const bool                condensed;
    std::vector<Harmonic>     harmonics;
    ThetaSampling             sampling;
    /** Every candidate harmonic n <= Maximum harmonic (growth only). */
    std::vector<Harmonic> candidates;
    /**
     * The nonlinear interfaces' samples: those of the soil, but with
     * `contact` or a stiff coulomb law that can open (through the
     * multipliers) always 2 n_max + 1, one per value of the band-limited
     * gap (minimum_theta_samples(); more make the multipliers drift,
     * constrained_theta_samples()), while Theta samples sets the soil's.
     * With growth n_max is Maximum harmonic.
     */
    ThetaSampling interface_samples;
    /** The candidates' factors at the interfaces' and the soil's samples. */
    ThetaSampling spectrum, soil_spectrum;
    /** The plastic soil's quadrature points and their laws. */
    NonlinearSoilPoints soil;
    /** Strain amplitudes of the load pattern, the held loads and e_V. */
    StrainAmplitudes pattern_strain, held_strain, swipe_strain;
    /**
     * Nonlinear interfaces (null: none): their points, and the relative
     * displacements of the loads' elastic solutions.
     */
    std::unique_ptr<NonlinearInterfacePoints> interface;
    InterfaceLoadCases                        interface_cases;
  };
} // namespace FourierSSI

#endif
