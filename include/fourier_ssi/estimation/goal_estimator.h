/**
 * Goal-oriented (dual-weighted residual) error estimate for the stiffness
 * coefficients K_H, K_M, K_MH of a rigid foundation (derivation in
 * doc/accuracy-vs-time.md, section "Goal-oriented refinement").
 *
 * The goals are compliances. With f_H, f_M the unit-H and unit-M load
 * vectors (virtual work of H = 1, M = 1 on the rigid motion) and u_H, u_M
 * the fields they produce,
 *   u_h(H) = f_H(u_H) = a(u_H, u_H),  theta(M) = a(u_M, u_M),
 *   theta(H) = f_M(u_H) = a(u_M, u_H),
 * so the dual solution of each goal is a unit-load primal field itself, and
 * Galerkin orthogonality gives, for any conforming subspace,
 *   I_H - I_H,h = a(e_H, e_H) >= 0,  I_M - I_M,h = a(e_M, e_M) >= 0,
 *   I_MH - I_MH,h = a(e_H, e_M)
 * (dimensionless with G a, G a^3, G a^2; thesis eq. 4.4). The FE stiffness
 * therefore converges from above. Here e is approximated by u_4 - u_2, u_4
 * the FE_Q(4) solution on the same mesh: V_2 is a subspace of V_4, so the
 * same identities hold exactly between the two discrete solutions, and
 * I(u_4) - I(u_2) is the estimate of I - I(u_2) (it misses I - I(u_4), so
 * the effectivity index is below 1 by that fraction). K = I^-1 gives, to
 * first order, dK = -K dI K; the indicator of cell T for goal K_X is
 * |(K dI_T K)_X| / |K_X|, dI_T the cell's share of the energy products.
 */
#ifndef fourier_ssi_goal_estimator_h
#define fourier_ssi_goal_estimator_h

#include <array>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/harmonic/harmonic_problem.h>
#include <fourier_ssi/harmonic/rigid_motion.h>
#include <fourier_ssi/input/parameters.h>
#include <string>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  struct GoalEstimate
  {
    /** Coefficients of the FE_Q(4) solve on the same mesh. */
    FoundationCoefficients enriched;
    /** Estimated |K_X - K_X,h| / |K_X| of the primary (FE_Q(2)) values for
     *  X = H, M, MH: |K_X(u_4) - K_X(u_2)| / |K_X(u_4)|. */
    std::array<double, 3> relative_error = {{0., 0., 0.}};
    /** The error of Adaptivity/Goal (all: the largest of the three). */
    double goal_error = 0.;
    /** Refinement indicator per active cell. */
    Vector<float> indicators;
    /**
     * Sum over the cells of a_T(e_H, e_H) divided by the global
     * a(e_H, e_H) = I_H(u_4) - I_H(u_2): the cells' share (the rest sits in
     * the interface springs, which the indicators leave out).
     */
    double cell_share = 0.;
    /** DoFs of the FE_Q(4) problem. */
    unsigned int enriched_dofs = 0;
  };

  class GoalEstimator
  {
  public:
    /** Throws a one-line message if the scene cannot use Strategy = goal. */
    GoalEstimator(const AllParameters         &parameters,
                  const std::vector<Harmonic> &planned_harmonics);

    /**
     * Estimate the goal error of the primary problem (harmonic n = 1,
     * symmetric, FE_Q(2)) from its unit-H and unit-M fields
     * (foundation_coefficients()) and an FE_Q(4) solve on the same mesh.
     */
    GoalEstimate
    estimate(const Harmonic                    &harmonic,
             const Triangulation<2>            &triangulation,
             const HarmonicProblem             &primary,
             const std::vector<Vector<double>> &unit_solutions,
             const FoundationCoefficients      &primary_coefficients) const;

  private:
    /** Copy of the run's parameters with Polynomial degree = 4. */
    AllParameters enriched_parameters;
    StiffnessGoal goal;
  };
} // namespace FourierSSI

#endif
