/**
 * Subsection "Nonlinear interfaces": how the coupled iteration of
 * CoupledInterfaceSolver loads the scene and when it has converged
 * (doc/nonlinear-interfaces.md, section 5).
 */
#ifndef fourier_ssi_nonlinear_interface_parameters_h
#define fourier_ssi_nonlinear_interface_parameters_h

#include <deal.II/base/parameter_handler.h>

namespace FourierSSI
{
  using namespace dealii;

  /** Subsection "Nonlinear interfaces" of the .prm file. */
  struct NonlinearInterfaceParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    enum class Control
    {
      load,
      displacement
    };
    /** Rigid-foundation motion that displacement control prescribes. */
    enum class Motion
    {
      vertical,
      twist,
      horizontal,
      rotation
    };

    /** 0: automatic, 4 (n_max + 1), at least 2 n_max + 1 (no aliasing). */
    unsigned int theta_samples = 0;
    unsigned int load_steps    = 10;
    Control      control       = Control::load;
    Motion       motion        = Motion::vertical;
    /** Final value of the controlled motion [m or rad]. */
    double       target             = 0.;
    double       tolerance          = 1e-10;
    unsigned int maximum_iterations = 2000;
    bool         aitken             = true;
    unsigned int maximum_step_cuts  = 4;
  };

} // namespace FourierSSI

#endif
