/**
 * Linear solvers for one harmonic's system: sparse direct (CHOLMOD
 * Cholesky, the default, or UMFPACK LU, sparse_direct.h) or CG preconditioned
 * by Trilinos ML algebraic multigrid with the per-component constant near-null
 * space. A failure is an error with a one-line message, never a silent result.
 */
#ifndef fourier_ssi_linear_solver_h
#define fourier_ssi_linear_solver_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/input/linear_solver_parameters.h>
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

  class LinearSolver
  {
  public:
    explicit LinearSolver(const LinearSolverParameters &parameters);

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

  private:
    const LinearSolverParameters &parameters;
  };
} // namespace FourierSSI

#endif
