/**
 * Boundary conditions and loads of one harmonic, all given as amplitude
 * expressions in (r, z) (deal.II FunctionParser syntax, constants pi, n):
 *   Dirichlet: prescribed amplitude of any of u (radial), v (axial),
 *              w (circumferential) on a boundary id;
 *   Traction:  amplitudes (r, z, theta) of the surface traction [kPa];
 *   Body force amplitudes (r, z, theta) [kN/m^3].
 * The amplitudes carry the trigonometric factors of the harmonic's family
 * (thesis eq. 3.1): (r, z) with cos n t and theta with sin n t (symmetric),
 * or sin n t and cos n t (antisymmetric).
 */
#ifndef fourier_ssi_boundary_conditions_h
#define fourier_ssi_boundary_conditions_h

#include <array>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /** Split at separators that are not inside parentheses. */
  std::vector<std::string>
  split_top_level(const std::string &text, const char separator);

  /** True if an expression is a literal zero ("0", "0.0", "-0", or empty). */
  bool
  is_literal_zero(const std::string &expression);

  /** Three optional component expressions, e.g. from "u=0, w=0.01*z". */
  struct ComponentExpressions
  {
    std::array<std::string, 3> expression;
    std::array<bool, 3>        given = {{false, false, false}};

    /** True if every given component is a literal zero. */
    bool
    is_zero() const
    {
      for (unsigned int c = 0; c < 3; ++c)
        if (given[c] && !is_literal_zero(expression[c]))
          return false;
      return true;
    }
  };

  /**
   * Initialize a 3-component FunctionParser from the expressions (missing
   * ones are 0) and evaluate it once at `probe`, so that a bad expression
   * fails now with one line naming `entry`. muparser prints its own message
   * on std::cerr first; that stream is silenced meanwhile (one thread at a
   * time: std::cerr is process-wide and harmonics are set up concurrently).
   * Defined for dim = 2 (variables r, z) and 3 (r, z, theta).
   */
  template <int dim>
  void
  initialize_parser(FunctionParser<dim>                 &function,
                    const ComponentExpressions          &expressions,
                    const std::string                   &variables,
                    const std::map<std::string, double> &constants,
                    const std::string                   &entry);

  /** A 3-component FunctionParser in the variables r, z, theta. */
  std::shared_ptr<FunctionParser<3>>
  make_theta_function(const ComponentExpressions &expressions,
                      const std::string          &entry);

  class BoundaryConditions
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Parse "id: key=expr, ...; id: ..." with keys `keys` (component order).
     * `entry` names the .prm entry in error messages.
     */
    static std::map<types::boundary_id, ComponentExpressions>
    parse_boundary_map(const std::string                &text,
                       const std::array<std::string, 3> &keys,
                       const std::string                &entry);

    /** A 3-component FunctionParser for the given expressions (missing=0). */
    static std::unique_ptr<FunctionParser<2>>
    make_function(const ComponentExpressions &expressions,
                  const unsigned int          harmonic_n,
                  const std::string          &entry);

    std::map<types::boundary_id, ComponentExpressions> dirichlet;
    std::map<types::boundary_id, ComponentExpressions> traction;
    ComponentExpressions                               body_force;
  };
} // namespace FourierSSI

#endif
