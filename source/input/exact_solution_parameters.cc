#include <fourier_ssi/input/exact_solution_parameters.h>

namespace FourierSSI
{
  void
  ExactSolutionParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Exact solution");
    prm.declare_entry("Enabled",
                      "false",
                      Patterns::Bool(),
                      "Compute error norms against the amplitudes below.");
    prm.declare_entry("U", "0", Patterns::Anything(), "Radial amplitude [m].");
    prm.declare_entry("V", "0", Patterns::Anything(), "Axial amplitude [m].");
    prm.declare_entry("W",
                      "0",
                      Patterns::Anything(),
                      "Circumferential amplitude [m].");
    prm.leave_subsection();
  }

  void
  ExactSolutionParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Exact solution");
    enabled               = prm.get_bool("Enabled");
    amplitudes.expression = {{prm.get("U"), prm.get("V"), prm.get("W")}};
    amplitudes.given      = {{true, true, true}};
    prm.leave_subsection();
    if (enabled)
      BoundaryConditions::make_function(amplitudes, 1, "Exact solution");
  }
} // namespace FourierSSI
