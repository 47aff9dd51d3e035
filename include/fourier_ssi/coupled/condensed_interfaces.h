/**
 * The linearisation of a coupled step whose only nonlinear source is the
 * interfaces (linearisation.h): condensed onto the interface DoFs
 * (InterfaceCondensation). K^-1 dc is a dense product with the flexibility
 * blocks, exact at the DoFs the interfaces read while a step iterates and
 * made whole once it converged (complete()); Newton (Stiffness = tangent)
 * is on the dense condensed Jacobian, and harmonics are added where the
 * interface traction calls for them (Load path/Maximum harmonic).
 */
#ifndef fourier_ssi_condensed_interfaces_h
#define fourier_ssi_condensed_interfaces_h

#include <fourier_ssi/coupled/interface_condensation.h>
#include <fourier_ssi/coupled/linearisation.h>
#include <fourier_ssi/coupled/load_control.h>
#include <fourier_ssi/coupled/nonlinear_sources.h>
#include <memory>

namespace FourierSSI
{
  class CondensedInterfaces : public Linearisation
  {
  public:
    CondensedInterfaces(const HarmonicSet      &set,
                        const AllParameters    &parameters,
                        const NonlinearSources &sources,
                        const LoadControl      &control);

    std::string
    name() const override;

    /**
     * Up to 4 full steps may go on without a new best |R| (a gap that
     * closes or a slip that reverses beyond the tangent's foresight is put
     * right by the next tangent), then the line search from the best
     * iterate halves down to 2^-16; its iterations are cheap, so no step is
     * given up early.
     */
    NewtonSettings
    newton_settings() const override;

    LoadPathParameters::Acceleration
    acceleration() const override;

    /**
     * One initial-stiffness update (exact and cheap) moves off the kink of
     * the return mapping at the iterate: Newton never cuts a step for want
     * of descent.
     */
    NoDescent
    no_descent(const bool persistent, const bool stalled) const override;

    CoupledCorrection
    newton_direction(const CoupledEvaluation &e,
                     const CoupledStepState  &state) override;

    /**
     * c and R live on the write DoFs: the acceleration works there, and
     * K^-1 dc follows through the flexibility blocks.
     */
    CoupledCorrection
    initial_stiffness_correction(FixedPointAcceleration  &acceleration,
                                 const CoupledStepState  &state,
                                 const CoupledEvaluation &e) const override;

    void
    add(const double             alpha,
        const CoupledCorrection &correction,
        CoupledStepState        &state) const override;

    bool
    keeps_partial_solution() const override
    {
      return true;
    }

    /**
     * K^-1 c complete (InterfaceCondensation::complete), and the
     * controlled motion from it.
     */
    void
    complete(CoupledStepState &state) const override;

    void
    grow(const unsigned int first) override;

    std::string
    rank_sums() const override;

  private:
    const LoadPathParameters::Control      control_kind;
    const NonlinearSources                &sources;
    const LoadControl                     &control;
    std::unique_ptr<InterfaceCondensation> condensation;
  };
} // namespace FourierSSI

#endif
