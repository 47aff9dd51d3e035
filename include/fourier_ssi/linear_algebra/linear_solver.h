/**
 * Linear solvers for one harmonic's system: sparse direct (CHOLMOD
 * Cholesky, the default, or UMFPACK LU, sparse_direct.h) or CG preconditioned
 * by Trilinos ML algebraic multigrid with the per-component constant near-null
 * space. A failure is an error with a one-line message, never a silent result.
 */
#ifndef fourier_ssi_linear_solver_h
#define fourier_ssi_linear_solver_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <string>

namespace FourierSSI
{
  using namespace dealii;

  struct SolverReport
  {
    std::string  method;
    unsigned int iterations        = 0;  // 0 for the direct solver
    double       relative_residual = 0.; // ||b - A x|| / ||b||
  };

  /** Linear solver/Method, parsed once. */
  enum class SolverMethod
  {
    cholesky, // "direct": CHOLMOD supernodal Cholesky
    lu,       // "direct-lu": UMFPACK LU
    cg_amg    // "cg-amg": CG + Trilinos ML
  };

  class LinearSolver
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /** Solve A x = b; x is the initial guess for iterative methods. */
    SolverReport
    solve(const SparseMatrix<double> &A,
          Vector<double>             &x,
          const Vector<double>       &b,
          const DoFHandler<2>        &dof_handler) const;

    /**
     * The accepted-solution test shared by every solve path (serial, shared
     * factorization, distributed): returns ||b - A x|| / ||b|| (or
     * ||b - A x|| for b = 0) and throws a one-line error above 'Residual
     * check'.
     */
    double
    checked_relative_residual(const double residual_norm,
                              const double rhs_norm) const;

    /** Throw the one-line error of a CG run that did not converge. */
    [[noreturn]] static void
    fail_to_converge(const SolverControl::NoConvergence &e);

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
