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
} // namespace FourierSSI

#endif
