#include <cstdlib>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <fourier_ssi/linear_algebra/linear_solver.h>
#include <fourier_ssi/linear_algebra/sparse_direct.h>

namespace FourierSSI
{
  void
  LinearSolver::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    prm.declare_entry("Method",
                      "direct",
                      Patterns::Selection("direct|direct-lu|cg-amg"),
                      "direct: CHOLMOD sparse Cholesky (the systems are "
                      "symmetric positive definite); direct-lu: UMFPACK "
                      "sparse LU (the reference path); cg-amg: conjugate "
                      "gradients with Trilinos ML algebraic multigrid. With "
                      "MPI, both direct methods use MUMPS.");
    prm.declare_entry("Tolerance",
                      "1e-10",
                      Patterns::Double(0.),
                      "Relative residual reduction for cg-amg.");
    prm.declare_entry("Max iterations",
                      "2000",
                      Patterns::Integer(1, 1000000),
                      "Iteration limit for cg-amg; reaching it is an error.");
    prm.declare_entry("Residual check",
                      "1e-6",
                      Patterns::Double(0.),
                      "After any solve, ||b - A x|| / ||b|| above this value "
                      "is reported as a solver failure (catches singular "
                      "systems, e.g. a missing support).");
    prm.declare_entry("Distributed",
                      "auto",
                      Patterns::Selection("auto|always"),
                      "auto: the Trilinos path (MUMPS for direct, CG + ML "
                      "for cg-amg, doc/scaling.md) when run on more than "
                      "one MPI rank, the serial solvers otherwise; always: "
                      "the Trilinos path on one rank too (a one-rank "
                      "baseline for scaling measurements).");
    prm.leave_subsection();
  }

  void
  LinearSolver::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    const std::string method_entry = prm.get("Method");
    method    = method_entry == "direct-lu" ? SolverMethod::lu :
                method_entry == "cg-amg"    ? SolverMethod::cg_amg :
                                              SolverMethod::cholesky;
    tolerance = prm.get_double("Tolerance");
    // CG cannot reduce the residual below round-off: 0 would run to Max
    // iterations and report "did not converge" at a residual of 0.
    AssertThrow(method != SolverMethod::cg_amg ||
                  (tolerance >= 1e-15 && tolerance < 1.),
                ExcMessage("Linear solver/Tolerance: " + prm.get("Tolerance") +
                           " with Method = cg-amg; give 1e-15 <= Tolerance < "
                           "1 (a relative residual reduction)"));
    max_iterations     = prm.get_integer("Max iterations");
    residual_check     = prm.get_double("Residual check");
    distributed_always = prm.get("Distributed") == "always";
    prm.leave_subsection();
  }

  std::string
  LinearSolver::method_name() const
  {
    return method == SolverMethod::lu     ? "direct-lu" :
           method == SolverMethod::cg_amg ? "cg-amg" :
                                            "direct";
  }

  SolverReport
  LinearSolver::solve(const SparseMatrix<double> &A,
                      Vector<double>             &x,
                      const Vector<double>       &b,
                      const DoFHandler<2>        &dof_handler) const
  {
    SolverReport report;
    report.method = method_name();
    // A zero load (e.g. a stiffness scene, whose unit-H/M cases are solved
    // separately) has the zero solution: skip the factorization.
    if (b.l2_norm() == 0.)
      {
        x = 0.;
        report.method += " (zero load, skipped)";
        return report;
      }
    if (is_direct())
      {
        SparseDirect direct(direct_backend());
        direct.initialize(A, cell_interior_dofs(dof_handler));
        direct.vmult(x, b);
      }
    else
      {
        TrilinosWrappers::PreconditionAMG                 amg;
        TrilinosWrappers::PreconditionAMG::AdditionalData data;
        data.elliptic              = true;
        data.higher_order_elements = dof_handler.get_fe().degree > 1;
        data.smoother_sweeps       = 2;
        data.aggregation_threshold = 0.02;
        // Near-null space: a constant in each of the three components.
        std::vector<std::vector<bool>> constant_modes;
        DoFTools::extract_constant_modes(dof_handler,
                                         ComponentMask(3, true),
                                         constant_modes);
        data.constant_modes = constant_modes;
        amg.initialize(A, data);
        SolverControl control(max_iterations, tolerance * b.l2_norm());
        SolverCG<Vector<double>> cg(control);
        try
          {
            cg.solve(A, x, b, amg);
          }
        catch (const SolverControl::NoConvergence &e)
          {
            fail_to_converge(e);
          }
        report.iterations = control.last_step();
      }

    Vector<double> residual(b.size());
    A.vmult(residual, x);
    residual -= b;
    report.relative_residual =
      checked_relative_residual(residual.l2_norm(), b.l2_norm());
    return report;
  }

  double
  LinearSolver::checked_relative_residual(const double residual_norm,
                                          const double rhs_norm) const
  {
    const double relative =
      rhs_norm > 0. ? residual_norm / rhs_norm : residual_norm;
    AssertThrow(std::isfinite(relative) && relative <= residual_check,
                ExcMessage("Linear solver: relative residual " +
                           std::to_string(relative) +
                           " exceeds 'Residual check' = " +
                           std::to_string(residual_check) +
                           " (singular or ill-posed system: check supports "
                           "and interface stiffness)"));
    return relative;
  }

  void
  LinearSolver::fail_to_converge(const SolverControl::NoConvergence &e)
  {
    AssertThrow(false,
                ExcMessage("Linear solver: cg-amg did not converge in " +
                           std::to_string(e.last_step) +
                           " iterations (residual " +
                           std::to_string(e.last_residual) +
                           "); raise 'Max iterations' or use Method = direct"));
    std::abort(); // not reached: AssertThrow throws
  }
} // namespace FourierSSI
