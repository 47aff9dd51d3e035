/**
 * The load path on the coupled tangent of all harmonics: plastic soil
 * (doc/soil-plasticity.md), with any coulomb interfaces in it, or a swipe
 * through coulomb interfaces on elastic soil (its second load multiplier
 * keeps w). Its goal on nested meshes is the capacity (displacement
 * control) or the work of the loads (load control); its output the step
 * rows with the plastic and contact state, the capacity, the soil-reaction
 * curves and the plastic field.
 */
#ifndef fourier_ssi_coupled_tangent_run_h
#define fourier_ssi_coupled_tangent_run_h

#include <fourier_ssi/driver/coupled_scene_run.h>

namespace FourierSSI
{
  class CoupledTangentRun : public CoupledSceneRun
  {
  public:
    /** Refuses, one line each, what this path does not do yet. */
    explicit CoupledTangentRun(const CoupledRunContext &context);

    std::string
    goal_prefix() const override;

    bool
    has_plateau() const override;

  protected:
    CoupledGoal
    goal_of(const CoupledSolver &solver) const override;

  private:
    /** Load control: the goal is the work of the loads, not a capacity. */
    bool
    load_control() const;
  };
} // namespace FourierSSI

#endif
