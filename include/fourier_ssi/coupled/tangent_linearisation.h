/**
 * The linearisation of a coupled step with plastic soil (or a swipe) on
 * the coupled tangent of every harmonic (linearisation.h): dc and K^-1 dc
 * re-solved for every harmonic with the kept factorizations of K_h, and
 * Newton (Stiffness = tangent) on
 *   K_t,hg = delta_hg K_h - int Bbar_h^T [theta integral of factor_h
 *            (D_e - D_ep) factor_g] Bbar_g
 * (coupled_tangent.h), rebuilt at every update: keeping it for 3-10
 * updates (modified Newton) was measured slower (doc/soil-plasticity.md
 * 3b).
 */
#ifndef fourier_ssi_tangent_linearisation_h
#define fourier_ssi_tangent_linearisation_h

#include <fourier_ssi/coupled/coupled_tangent.h>
#include <fourier_ssi/coupled/linearisation.h>
#include <fourier_ssi/coupled/load_control.h>
#include <fourier_ssi/coupled/load_path_states.h>
#include <fourier_ssi/coupled/nonlinear_sources.h>
#include <memory>
#include <vector>

namespace FourierSSI
{
  class TangentLinearisation : public Linearisation
  {
  public:
    TangentLinearisation(HarmonicSet            &set,
                         const AllParameters    &parameters,
                         const NonlinearSources &sources,
                         const LoadControl      &control,
                         const LoadPathStates   &states);

    std::string
    name() const override;

    /**
     * A full step that raises |R| is halved at once, down to 1/16, and
     * the step is cut if even that does not lower |R|. Going on from a
     * worse plastic state wanders off (measured: |R| / |F| up to 1e6 at a
     * plateau, where the tangent is near-singular; with 4 non-improving
     * steps allowed, pile-adhesion converged to a state 20 rad off), and
     * taking initial-stiffness updates instead of cutting made steps that
     * a cut settles 4-10 times slower (doc/soil-plasticity.md 3b). Those
     * updates are the retry after the last cut only (no_descent()).
     */
    NewtonSettings
    newton_settings() const override;

    /**
     * Newton updates are taken as they are (relaxing them by Aitken or
     * Anderson was measured to double the iterations,
     * doc/soil-plasticity.md section 3); the initial-stiffness iteration
     * takes Load path/Acceleration.
     */
    LoadPathParameters::Acceleration
    acceleration() const override;

    /**
     * The step is cut, unless this is its retry after the last cut: then
     * one initial-stiffness update, Newton starting again from there,
     * until |R| stalls.
     */
    NoDescent
    no_descent(const bool persistent, const bool stalled) const override;

    /** The tangent rebuilt at the iterate (tangent_correction). */
    CoupledCorrection
    newton_direction(const CoupledEvaluation &e,
                     const CoupledStepState  &state) override;

    CoupledCorrection
    initial_stiffness_correction(FixedPointAcceleration  &acceleration,
                                 const CoupledStepState  &state,
                                 const CoupledEvaluation &e) const override;

    void
    add(const double             alpha,
        const CoupledCorrection &correction,
        CoupledStepState        &state) const override;

    bool
    retries_persistently() const override
    {
      return newton;
    }

    void
    grow(const unsigned int first) override;

    std::string
    rank_sums() const override;

    /**
     * K_t(u) x: the coupled tangent built at the fields u (K^-1 c of a
     * state without loads, from the committed state) and applied to x.
     */
    std::vector<Vector<double>>
    tangent_product(const std::vector<Vector<double>> &fields,
                    const std::vector<Vector<double>> &x);

  private:
    /**
     * K_t at the strain samples and interface relative displacements given
     * (the interfaces' returns from `interface_origin`); factorized, with
     * K_t^-1 F.
     */
    void
    update_tangent(const std::vector<StrainVector> &strain,
                   const std::vector<LocalVector>  &relative,
                   const std::vector<LocalVector>  &interface_origin,
                   const bool                       displacement_control);

    /**
     * Displacement control: add alpha c c^T to K_t, c the controlled motion
     * as a functional of the controlled harmonic's master DoFs (m(u) =
     * c^T u), and in a swipe the same for w (kept by mu). The update du keeps
     * m(du) = 0, so alpha c c^T du = 0 and no update changes; but at a limit
     * load the collapse mechanism, which moves the foundation, is a null vector
     * of K_t, and K_t^-1 R and K_t^-1 F lose their digits there while K_t +
     * alpha c c^T stays regular (the bordered system of Riks-type control,
     * solved with one factorization).
     */
    void
    add_control_stiffening();

    /**
     * alpha c c^T on the master DoFs of the harmonic `wanted`, c_k = the
     * motion `component` of a unit master DoF k, alpha scaling it to the
     * masters' own stiffness (add_control_stiffening).
     */
    void
    stiffen_motion(const Harmonic                  &wanted,
                   const LoadPathParameters::Motion component);

    /**
     * The out-of-balance load correction of one tangent (Newton) step:
     * du = K_t^-1 (R + dlambda F), dlambda keeping the controlled motion
     * (displacement control; 0 under load control); returns
     * dc = K du - dlambda F, the change of the correction load that moves
     * the total displacement by du. In a swipe du = K_t^-1 (R + dlambda F +
     * dmu e_V), (dlambda, dmu) keeping the controlled motion and w
     * (LoadControl::newton_multiplier_changes), and dc = K du -
     * dlambda F - dmu e_V.
     */
    std::vector<Vector<double>>
    tangent_correction(const std::vector<Vector<double>> &residual) const;

    /** dc and its K^-1 dc (one solve per harmonic). */
    CoupledCorrection
    correction_of(std::vector<Vector<double>> load) const;

    HarmonicSet            &set;
    const NonlinearSources &sources;
    const LoadControl      &control;
    const LoadPathStates   &states;
    /** MUMPS over the ranks (Linear solver/Distributed = always). */
    const bool tangent_over_ranks;
    /** Stiffness = tangent: the coupled tangent and K_t^-1 F. */
    std::unique_ptr<CoupledTangent> tangent;
    std::vector<Vector<double>>     tangent_pattern;
  };
} // namespace FourierSSI

#endif
