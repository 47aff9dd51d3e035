/**
 * Checks of the parameters alone, made as soon as every subsection is read
 * and before any output is touched: entries that are legal one by one but
 * together describe no problem to solve.
 */
#ifndef fourier_ssi_problem_checks_h
#define fourier_ssi_problem_checks_h

#include <fourier_ssi/input/parameters.h>

namespace FourierSSI
{
  /**
   * Throw a one-line error, naming the entry, for parameters that are legal
   * one by one but together describe no problem to solve (a displacement-
   * controlled path to a target of 0, a load-controlled path with every load
   * zero, error norms a coupled run never computes). Called by
   * AllParameters::parse_parameters once every subsection is read, so that
   * the refusal comes before any output is touched.
   */
  void
  check_problem_is_meaningful(const AllParameters &parameters);

  /**
   * The "not yet" limits every coupled (nonlinear) load path shares, one line
   * each naming Load path: one refinement cycle, the harmonics (not one
   * harmonic's system) over the MPI ranks, and no linear stiffness
   * coefficients. `with` names what makes the run nonlinear ("a coulomb
   * interface", "plastic soil") for the message.
   */
  void
  check_coupled_path_supported(const AllParameters &parameters,
                               const std::string   &with);
} // namespace FourierSSI

#endif
