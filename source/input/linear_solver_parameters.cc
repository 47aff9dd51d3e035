#include <fourier_ssi/input/choice.h>
#include <fourier_ssi/input/linear_solver_parameters.h>

namespace FourierSSI
{
  namespace
  {
    const Choices<SolverMethod> &
    methods()
    {
      static const Choices<SolverMethod> choices{
        {"direct", SolverMethod::cholesky},
        {"direct-lu", SolverMethod::lu},
        {"cg-amg", SolverMethod::cg_amg}};
      return choices;
    }

    /** Linear solver/Distributed: always (true) or only on several ranks. */
    const Choices<bool> &
    distributed_choices()
    {
      static const Choices<bool> choices{{"auto", false}, {"always", true}};
      return choices;
    }
  } // namespace

  void
  LinearSolverParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    prm.declare_entry("Method",
                      "direct",
                      Patterns::Selection(methods().selection()),
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
                      Patterns::Selection(distributed_choices().selection()),
                      "auto: the Trilinos path (MUMPS for direct, CG + ML "
                      "for cg-amg, doc/scaling.md) when run on more than "
                      "one MPI rank, the serial solvers otherwise; always: "
                      "the Trilinos path on one rank too (a one-rank "
                      "baseline for scaling measurements). With plastic "
                      "soil and Newton (Soil plasticity/Stiffness = "
                      "tangent), always makes the coupled tangent of all "
                      "harmonics one matrix over the ranks, factorized by "
                      "MUMPS; the harmonics' own systems stay serial.");
    prm.leave_subsection();
  }

  void
  LinearSolverParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    method    = methods().value_of(prm.get("Method"), "Linear solver/Method");
    tolerance = prm.get_double("Tolerance");
    // CG cannot reduce the residual below round-off: 0 would run to Max
    // iterations and report "did not converge" at a residual of 0.
    AssertThrow(method != SolverMethod::cg_amg ||
                  (tolerance >= 1e-15 && tolerance < 1.),
                ExcMessage("Linear solver/Tolerance: " + prm.get("Tolerance") +
                           " with Method = cg-amg; give 1e-15 <= Tolerance < "
                           "1 (a relative residual reduction)"));
    max_iterations = prm.get_integer("Max iterations");
    residual_check = prm.get_double("Residual check");
    distributed_always =
      distributed_choices().value_of(prm.get("Distributed"),
                                     "Linear solver/Distributed");
    prm.leave_subsection();
  }

  std::string
  LinearSolverParameters::method_name() const
  {
    return methods().name_of(method);
  }
} // namespace FourierSSI
