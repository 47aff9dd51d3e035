/**
 * The load path of coulomb interfaces on elastic soil, condensed onto the
 * interfaces (doc/nonlinear-interfaces.md): its goal on nested meshes is
 * the load at the end of the path; its output the step rows, the interface
 * state and the last step as a field, then the 3D output of a linear run.
 */
#ifndef fourier_ssi_interface_load_path_run_h
#define fourier_ssi_interface_load_path_run_h

#include <fourier_ssi/driver/coupled_scene_run.h>

namespace FourierSSI
{
  class InterfaceLoadPathRun : public CoupledSceneRun
  {
  public:
    /** Refuses, one line each, what this path does not do yet. */
    explicit InterfaceLoadPathRun(const CoupledRunContext &context);

    std::string
    goal_prefix() const override;

    bool
    has_plateau() const override;

  protected:
    CoupledGoal
    goal_of(const CoupledSolver &solver) const override;
  };
} // namespace FourierSSI

#endif
