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
  LinearSolver::LinearSolver(const LinearSolverParameters &parameters)
    : parameters(parameters)
  {}

  SolverReport
  LinearSolver::solve(const SparseMatrix<double> &A,
                      Vector<double>             &x,
                      const Vector<double>       &b,
                      const DoFHandler<2>        &dof_handler) const
  {
    SolverReport report;
    report.method = parameters.method_name();
    // A zero load (e.g. a stiffness scene, whose unit-H/M cases are solved
    // separately) has the zero solution: skip the factorization.
    if (b.l2_norm() == 0.)
      {
        x = 0.;
        report.method += " (scene load zero: its solution is 0, not solved)";
        return report;
      }
    if (parameters.is_direct())
      {
        SparseDirect direct(parameters.direct_backend());
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
        SolverControl            control(parameters.max_iterations,
                              parameters.tolerance * b.l2_norm());
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
    AssertThrow(std::isfinite(relative) &&
                  relative <= parameters.residual_check,
                ExcMessage("Linear solver: relative residual " +
                           std::to_string(relative) +
                           " exceeds 'Residual check' = " +
                           std::to_string(parameters.residual_check) +
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
