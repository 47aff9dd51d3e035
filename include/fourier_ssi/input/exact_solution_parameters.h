/**
 * Subsection "Exact solution" of the .prm file: amplitudes against which the
 * error norms of a solved harmonic are computed (tests, verification).
 */
#ifndef fourier_ssi_exact_solution_parameters_h
#define fourier_ssi_exact_solution_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <fourier_ssi/input/boundary_conditions.h>

namespace FourierSSI
{
  using namespace dealii;

  /** Optional exact amplitudes for error norms (tests, verification). */
  struct ExactSolutionParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    bool                 enabled = false;
    ComponentExpressions amplitudes;
  };
} // namespace FourierSSI

#endif
