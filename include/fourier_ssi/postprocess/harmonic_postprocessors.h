/**
 * What one solved harmonic reports: each group of results (discretization,
 * reactions, foundation motion and stiffness, error norms) comes from its
 * own small postprocessor that appends rows of results.csv (quantity,
 * value, unit) and one part of the harmonic's log line, in the manner of
 * ASPECT's postprocessors (execute(statistics) -> screen text). Every
 * number written to the log carries its unit or its normalisation.
 */
#ifndef fourier_ssi_harmonic_postprocessors_h
#define fourier_ssi_harmonic_postprocessors_h

#include <deal.II/lac/vector.h>
#include <fourier_ssi/estimation/goal_estimator.h>
#include <fourier_ssi/harmonic/harmonic_problem.h>
#include <fourier_ssi/harmonic/rigid_motion.h>
#include <fourier_ssi/input/parameters.h>
#include <fourier_ssi/input/rigid_foundation_parameters.h>
#include <fourier_ssi/linear_algebra/linear_solver.h>
#include <fourier_ssi/postprocess/results_table.h>
#include <sstream>
#include <string>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /** A harmonic after its solve: the inputs of every postprocessor. */
  struct HarmonicSolution
  {
    const HarmonicProblem *problem = nullptr;
    SolverReport           report;
    /** The stiffness harmonic (n = 1 symmetric with a rigid foundation). */
    bool                   has_coefficients = false;
    FoundationCoefficients coefficients;
    /** Its unit-H and unit-M fields (constraints distributed). */
    std::vector<Vector<double>> unit_solutions;
    /**
     * An n = 0 harmonic of a stiffness-matrix scene: K_V (symmetric, kN/m)
     * or K_T (antisymmetric, kN.m/rad) from a unit V or T.
     */
    bool   has_axial_stiffness = false;
    double axial_stiffness     = 0.;
  };

  /** Rows and log text one harmonic produced. */
  struct HarmonicReport
  {
    struct Row
    {
      std::string quantity;
      double      value;
      std::string unit;
    };
    std::vector<Row>   rows;
    std::ostringstream log;

    void
    add(const std::string &quantity,
        const double       value,
        const std::string &unit)
    {
      rows.push_back({quantity, value, unit});
    }
  };

  namespace Postprocessors
  {
    /** Cells, DoFs, axis nodes, solver method and residual, strain energy. */
    void
    discretization(const HarmonicSolution &solution,
                   const unsigned int      cycle,
                   HarmonicReport         &report);

    /** Force, moment and work of the reactions on every Dirichlet boundary. */
    void
    reactions(const AllParameters    &parameters,
              const HarmonicSolution &solution,
              HarmonicReport         &report);

    /**
     * The load that holds each held motion (Rigid foundation/Held
     * motions): rows held_<motion>_reaction [kN or kN.m]; in a direction
     * probe (Motion direction) the H and M on the foundation: rows
     * probe_H, probe_M; a log line each.
     */
    void
    held_motion_reactions(
      const RigidFoundationParameters                        &foundation,
      const std::vector<std::pair<FoundationMotion, double>> &reactions,
      HarmonicReport                                         &report);

    /**
     * The rigid foundation's motion, and on the stiffness harmonic the
     * influence and stiffness coefficients (thesis eqs 4.2-4.5, 6.1-6.3)
     * with their normalisations and the reference point.
     */
    void
    foundation(const AllParameters    &parameters,
               const HarmonicSolution &solution,
               HarmonicReport         &report);

    /**
     * The goal-oriented estimate (Strategy = goal): estimated relative
     * errors of K_H, K_M, K_MH and the FE_Q(4) values on the same mesh.
     */
    void
    goal_estimate(const GoalEstimate &goal,
                  const std::string  &goal_name,
                  HarmonicReport     &report);

    /** L2 and H1 errors against the exact solution, and observed rates. */
    void
    error_norms(const HarmonicSolution &solution,
                const unsigned int      cycle,
                const ResultsTable     &previous,
                HarmonicReport         &report);
  } // namespace Postprocessors
} // namespace FourierSSI

#endif
