/**
 * Subsection "Linear solver" of the .prm file: the method that solves one
 * harmonic's system (sparse direct or CG with algebraic multigrid), its
 * tolerances and whether it runs distributed; LinearSolver
 * (linear_algebra/linear_solver.h) solves with them.
 */
#ifndef fourier_ssi_linear_solver_parameters_h
#define fourier_ssi_linear_solver_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <string>

namespace FourierSSI
{
  using namespace dealii;

  /** Linear solver/Method, parsed once. */
  enum class SolverMethod
  {
    cholesky, // "direct": CHOLMOD supernodal Cholesky
    lu,       // "direct-lu": UMFPACK LU
    cg_amg    // "cg-amg": CG + Trilinos ML
  };

  struct LinearSolverParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /** Method = direct or direct-lu. */
    bool
    is_direct() const
    {
      return method != SolverMethod::cg_amg;
    }

    /** The SparseDirect back end of a direct Method. */
    std::string
    direct_backend() const
    {
      return method == SolverMethod::lu ? "lu" : "cholesky";
    }

    /** The Method as written in the .prm (for the log). */
    std::string
    method_name() const;

    SolverMethod method         = SolverMethod::cholesky;
    double       tolerance      = 1e-10;
    unsigned int max_iterations = 2000;
    double       residual_check = 1e-6;
    /**
     * Distributed = always: the Trilinos path also on one rank (otherwise
     * only on more than one; uses_distributed_solve() decides).
     */
    bool distributed_always = false;
  };
} // namespace FourierSSI

#endif
