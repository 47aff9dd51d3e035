#include <cmath>
#include <deal.II/fe/fe_tools.h>
#include <fourier_ssi/estimation/goal_estimator.h>

namespace FourierSSI
{
  GoalEstimator::GoalEstimator(const AllParameters         &parameters,
                               const std::vector<Harmonic> &planned_harmonics)
    : enriched_parameters(parameters)
    , goal(parameters.adaptivity.goal)
  {
    const auto &f = parameters.rigid_foundation;
    AssertThrow(f.enabled && f.stiffness_coefficients,
                ExcMessage("Adaptivity/Strategy = goal needs Rigid "
                           "foundation/Enabled and Stiffness coefficients = "
                           "true (the goals are K_H, K_M, K_MH)"));
    bool has_n1 = false;
    for (const Harmonic &h : planned_harmonics)
      has_n1 |= (h.n == 1 && h.family == Family::symmetric);
    AssertThrow(has_n1,
                ExcMessage("Adaptivity/Strategy = goal needs the harmonic "
                           "n = 1, symmetric family (Discretization/"
                           "Harmonics, or Harmonics = auto with the "
                           "stiffness coefficients)"));
    // The error is estimated with the next element of the nested pair
    // FE_Q(2) in FE_Q(4) (the only degrees with interface elements).
    AssertThrow(parameters.discretization.degree == 2,
                ExcMessage("Adaptivity/Strategy = goal needs Discretization/"
                           "Polynomial degree = 2 (the error is estimated "
                           "with FE_Q(4) on the same mesh)"));
    enriched_parameters.discretization.degree = 4;
  }

  GoalEstimate
  GoalEstimator::estimate(
    const Harmonic                    &harmonic,
    const Triangulation<2>            &triangulation,
    const HarmonicProblem             &primary,
    const std::vector<Vector<double>> &unit_solutions,
    const FoundationCoefficients      &primary_coefficients) const
  {
    AssertDimension(unit_solutions.size(), 2);
    GoalEstimate    result;
    HarmonicProblem enriched(enriched_parameters, harmonic, triangulation);
    enriched.setup_system();
    enriched.assemble_system();
    std::vector<Vector<double>> enriched_solutions;
    result.enriched = enriched.foundation_coefficients(&enriched_solutions);
    result.enriched_dofs = enriched.get_dof_handler().n_dofs();

    // e = u_4 - u_2, u_2 interpolated exactly into V_4 (nested spaces: the
    // interpolant satisfies the FE_Q(4) hanging-node, axis and rigid-body
    // constraints).
    std::array<Vector<double>, 2> error;
    for (unsigned int c = 0; c < 2; ++c)
      {
        Vector<double> u2_in_4(result.enriched_dofs);
        FETools::interpolate(primary.get_dof_handler(),
                             unit_solutions[c],
                             enriched.get_dof_handler(),
                             enriched.get_constraints(),
                             u2_in_4);
        error[c] = enriched_solutions[c];
        error[c] -= u2_in_4;
      }
    Vector<double> eHH, eMM, eHM;
    enriched.cell_energy_products(error[0], error[1], eHH, eMM, eHM);

    // Dimensionless influence increments (thesis eq. 4.4 scaling: I_H =
    // G a u_h, I_MH = G a^2 theta(H), I_M = G a^3 theta(M)).
    const double G =
      enriched_parameters.rigid_foundation.reference_shear_modulus;
    const double a   = enriched_parameters.rigid_foundation.reference_length;
    const double s_H = G * a, s_MH = G * a * a, s_M = G * a * a * a;

    const FoundationCoefficients &p          = primary_coefficients;
    const FoundationCoefficients &q          = result.enriched;
    const double                  dI_H_total = q.I_H - p.I_H;
    result.cell_share =
      dI_H_total != 0. ? s_H * eHH.l1_norm() / dI_H_total : 1.;

    const std::array<double, 3> K_p = {{p.K_H, p.K_M, p.K_MH}};
    const std::array<double, 3> K_q = {{q.K_H, q.K_M, q.K_MH}};
    for (unsigned int x = 0; x < 3; ++x)
      result.relative_error[x] = std::abs(K_q[x] - K_p[x]) / std::abs(K_q[x]);
    std::array<bool, 3> selected;
    for (unsigned int x = 0; x < 3; ++x)
      {
        selected[x] =
          goal == StiffnessGoal::all || goal == static_cast<StiffnessGoal>(x);
        if (selected[x])
          result.goal_error =
            std::max(result.goal_error, result.relative_error[x]);
      }

    // Cell indicators: first-order share of cell T in dK = -K dI K, with
    // K = [[K_H, K_MH], [K_MH, K_M]] of the enriched solve.
    result.indicators.reinit(eHH.size());
    for (unsigned int t = 0; t < eHH.size(); ++t)
      {
        const double dH = s_H * eHH(t), dM = s_M * eMM(t), dHM = s_MH * eHM(t);
        // (K dI K)_HH, (K dI K)_MM, (K dI K)_HM
        const std::array<double, 3> dK = {
          {q.K_H * q.K_H * dH + 2. * q.K_H * q.K_MH * dHM +
             q.K_MH * q.K_MH * dM,
           q.K_MH * q.K_MH * dH + 2. * q.K_MH * q.K_M * dHM +
             q.K_M * q.K_M * dM,
           q.K_H * q.K_MH * dH + (q.K_H * q.K_M + q.K_MH * q.K_MH) * dHM +
             q.K_MH * q.K_M * dM}};
        double eta = 0.;
        for (unsigned int x = 0; x < 3; ++x)
          if (selected[x])
            eta += std::abs(dK[x]) / std::abs(K_q[x]);
        result.indicators(t) = eta;
      }
    return result;
  }
} // namespace FourierSSI
