#include <cmath>
#include <fourier_ssi/harmonic/rigid_foundation.h>
#include <fourier_ssi/postprocess/harmonic_postprocessors.h>
#include <fourier_ssi/postprocess/pile_head_formulas.h>
#include <iomanip>

namespace FourierSSI
{
  namespace
  {
    /**
     * The stiffness of a foundation under one load in this harmonic
     * (V alone, M alone, H alone, T alone): load / motion, dimensional and
     * normalised with G and a, and with a Reference Poisson ratio the
     * closed form of a rigid disc on an elastic half-space next to it.
     */
    void
    single_load_stiffness(const RigidFoundationParameters &f,
                          const Harmonic                  &harmonic,
                          const RigidMotion               &m,
                          HarmonicReport                  &report)
    {
      struct Case
      {
        std::string name;      // row name
        double      load;      // kN or kN.m
        double      motion;    // m or rad
        std::string unit;      // of load / motion
        std::string symbol;    // normalised form
        int         power;     // a^power in the normalisation
        double      disc;      // half-space disc value / (G a^power)
        std::string reference; // of the closed form
      };
      const double      nu = f.reference_poisson_ratio;
      std::vector<Case> cases;
      if (harmonic.n == 0 && harmonic.family == Family::symmetric)
        cases.push_back({"vertical",
                         f.vertical_force,
                         m.vertical_displacement,
                         "kN/m",
                         "V/(G a W)",
                         1,
                         4. / (1. - nu),
                         "smooth rigid disc, Poulos & Davis 1974"});
      else if (harmonic.n == 0)
        cases.push_back({"torsional",
                         f.torque,
                         m.twist,
                         "kN.m/rad",
                         "T/(G a^3 Phi)",
                         3,
                         16. / 3.,
                         "rough rigid disc, Reissner & Sagoci 1944"});
      else if (harmonic.n == 1 && harmonic.family == Family::symmetric &&
               (f.moment == 0.) != (f.horizontal_force == 0.))
        {
          if (f.moment != 0.)
            cases.push_back({"rocking",
                             f.moment,
                             m.rotation,
                             "kN.m/rad",
                             "M/(G a^3 Theta)",
                             3,
                             8. / (3. * (1. - nu)),
                             "smooth rigid disc, Poulos & Davis 1974"});
          else
            cases.push_back({"horizontal",
                             f.horizontal_force,
                             m.horizontal_displacement,
                             "kN/m",
                             "H/(G a U_h)",
                             1,
                             32. * (1. - nu) / (7. - 8. * nu),
                             "rough rigid disc, approximate, Gazetas 1991"});
        }
      const double G = f.reference_shear_modulus, a = f.reference_length;
      for (const Case &c : cases)
        {
          if (c.load == 0. || c.motion == 0.)
            continue;
          const double stiffness  = c.load / c.motion;
          const double normalised = stiffness / (G * std::pow(a, c.power));
          report.add("foundation_" + c.name + "_stiffness", stiffness, c.unit);
          report.add("foundation_" + c.name + "_stiffness_normalised",
                     normalised,
                     c.symbol);
          report.log << "\n    " << c.name << " stiffness "
                     << std::setprecision(6) << stiffness << " " << c.unit
                     << ", " << c.symbol << " = " << normalised;
          if (nu < 0.)
            continue;
          report.log << " (half-space, " << c.reference << ": " << c.disc
                     << ", ratio " << normalised / c.disc << ")";
          if (c.name == "rocking")
            {
              // Thesis Table 4.1 tabulates theta E a^3 / M.
              const double compliance = 2. * (1. + nu) / normalised;
              report.add("theta_E_a3_over_M", compliance, "theta.E.a^3/M");
              report.log << "; theta E a^3/M = " << compliance
                         << " (E = 2 G (1 + nu), nu = " << nu << ")";
            }
        }
    }

    /**
     * Randolph's (1981) flexible-pile formula beside the computed K_H, K_M,
     * K_MH, normalised as they are (pile_head_formulas.h).
     */
    void
    pile_formula(const AllParameters          &parameters,
                 const FoundationCoefficients &c,
                 HarmonicReport               &report)
    {
      const RigidFoundationParameters &f    = parameters.rigid_foundation;
      const ElasticMaterial           &soil = parameters.materials.get(0);
      const PileHeadStiffness          k =
        randolph_flexible_pile(f.pile_diameter,
                               f.pile_modulus,
                               soil.poisson_ratio,
                               [&](double z) { return soil.shear_modulus(z); });
      const double G = f.reference_shear_modulus, a = f.reference_length;
      const double K_H = k.K_H / (G * a), K_M = k.K_M / (G * a * a * a),
                   K_MH = k.K_MH / (G * a * a);
      report.add("randolph_K_H", K_H, "H/(G.a.u)");
      report.add("randolph_K_M", K_M, "M/(G.a^3.theta)");
      report.add("randolph_K_MH", K_MH, "H/(G.a^2.theta)");
      report.add("randolph_critical_length", k.critical_length, "m");
      report.log << "\n    Randolph (1981) flexible pile (l_c = "
                 << std::setprecision(4) << k.critical_length
                 << " m, L/l_c = " << f.pile_length / k.critical_length
                 << ", rho_c = " << k.homogeneity_factor
                 << "; the formula holds for L >= l_c): K_H = " << K_H
                 << ", K_M = " << K_M << ", K_MH = " << K_MH
                 << "; computed / formula: K_H " << c.K_H / K_H << ", K_M "
                 << c.K_M / K_M << ", K_MH " << c.K_MH / K_MH;
    }
  } // namespace

  namespace Postprocessors
  {
    void
    held_motion_reactions(
      const RigidFoundationParameters                        &foundation,
      const std::vector<std::pair<FoundationMotion, double>> &reactions,
      HarmonicReport                                         &report)
    {
      for (const auto &[motion, load] : reactions)
        {
          report.add(foundation.reaction_row(motion),
                     load,
                     load_unit_of(motion));
          report.log << "\n    ";
          if (foundation.holds(motion))
            report.log << name_of(motion)
                       << " held at zero; the load that holds it: ";
          else
            report.log << "along Motion direction '"
                       << foundation.motion_direction
                       << "', the load on the foundation: ";
          report.log << load_name_of(motion) << " = " << std::setprecision(7)
                     << load << " " << load_unit_of(motion);
        }
    }

    void
    discretization(const HarmonicSolution &solution,
                   const unsigned int      cycle,
                   HarmonicReport         &report)
    {
      const HarmonicProblem &problem = *solution.problem;
      const double           n_dofs  = problem.get_dof_handler().n_dofs();
      report.add("n_cells",
                 problem.get_dof_handler().get_triangulation().n_active_cells(),
                 "-");
      report.add("n_dofs", n_dofs, "-");
      report.add("n_axis_nodes", problem.n_axis_nodes, "-");
      report.add("solver_iterations", solution.report.iterations, "-");
      report.add("solver_relative_residual",
                 solution.report.relative_residual,
                 "-");
      report.add("strain_energy",
                 problem.strain_energy(problem.get_solution()),
                 "kJ");
      report.log << "cycle " << cycle << ", "
                 << problem.get_operator().get_harmonic().name() << ": "
                 << n_dofs << " dofs, " << solution.report.method;
      if (solution.report.iterations > 0)
        report.log << " (" << solution.report.iterations << " it.)";
      report.log << ", relative residual " << std::setprecision(2)
                 << solution.report.relative_residual;
    }

    void
    reactions(const AllParameters    &parameters,
              const HarmonicSolution &solution,
              HarmonicReport         &report)
    {
      const auto &dirichlet = parameters.boundary_conditions.dirichlet;
      if (dirichlet.empty())
        return;
      const HarmonicProblem &problem   = *solution.problem;
      const Vector<double>   reactions = problem.nodal_reactions();
      for (const auto &[id, e] : dirichlet)
        {
          const BoundaryResultant R = problem.boundary_resultant(id, reactions);
          const std::string       b = "_boundary_" + std::to_string(id);
          report.add("reaction_force" + b, R.force, "kN");
          report.add("reaction_moment" + b, R.moment, "kN.m");
          report.add("reaction_work" + b, R.work, "kJ");
          if (R.force != 0. || R.moment != 0.)
            report.log << "\n    reactions on boundary " << id
                       << " (the supports on the body; moment about (r, z) "
                          "= (0, 0)): force "
                       << std::setprecision(6) << R.force << " kN, moment "
                       << R.moment << " kN.m";
        }
    }

    void
    foundation(const AllParameters    &parameters,
               const HarmonicSolution &solution,
               HarmonicReport         &report)
    {
      const RigidFoundation *foundation = solution.problem->get_foundation();
      if (!foundation)
        return;
      const RigidMotion m =
        foundation->motion(solution.problem->get_solution());
      report.add("foundation_horizontal_displacement",
                 m.horizontal_displacement,
                 "m");
      report.add("foundation_rotation", m.rotation, "rad");
      report.add("foundation_vertical_displacement",
                 m.vertical_displacement,
                 "m");
      report.add("foundation_twist", m.twist, "rad");
      const double z_ref = parameters.rigid_foundation.reference_elevation;
      if (foundation->holds_motion())
        held_motion_reactions(parameters.rigid_foundation,
                              foundation->held_reactions(
                                solution.problem->nodal_forces(
                                  solution.problem->get_solution())),
                              report);
      single_load_stiffness(parameters.rigid_foundation,
                            solution.problem->get_operator().get_harmonic(),
                            m,
                            report);
      if (solution.has_axial_stiffness)
        {
          // The stiffness matrix's V or T term, from its unit load.
          const bool vertical =
            solution.problem->get_operator().get_harmonic().family ==
            Family::symmetric;
          report.add(vertical ? "K_V" : "K_T",
                     solution.axial_stiffness,
                     vertical ? "kN/m" : "kN.m/rad");
          report.log << "\n    stiffness matrix term (unit "
                     << (vertical ? "V" : "T")
                     << "): " << (vertical ? "K_V = V/W = " : "K_T = T/Phi = ")
                     << std::setprecision(7) << solution.axial_stiffness
                     << (vertical ? " kN/m" : " kN.m/rad");
        }
      if (solution.has_coefficients)
        {
          const FoundationCoefficients &c = solution.coefficients;
          report.add("I_H", c.I_H, "u.G.a/H");
          report.add("I_M", c.I_M, "theta.G.a^3/M");
          report.add("I_MH_from_H", c.I_MH_from_H, "theta.G.a^2/H");
          report.add("I_MH_from_M", c.I_MH_from_M, "u.G.a^2/M");
          report.add("K_H", c.K_H, "H/(G.a.u)");
          report.add("K_M", c.K_M, "M/(G.a^3.theta)");
          report.add("K_MH", c.K_MH, "H/(G.a^2.theta)");
          report.log << "\n    stiffness (G = " << std::setprecision(6)
                     << parameters.rigid_foundation.reference_shear_modulus
                     << " kPa, a = "
                     << parameters.rigid_foundation.reference_length
                     << " m, about (r, z) = (0, " << z_ref
                     << ") m): K_H = H/(G a u) = " << std::setprecision(6)
                     << c.K_H << ", K_M = M/(G a^3 theta) = " << c.K_M
                     << ", K_MH = H/(G a^2 theta) = " << c.K_MH
                     << " (I_MH from H " << c.I_MH_from_H << ", from M "
                     << c.I_MH_from_M << ")";
          if (parameters.rigid_foundation.pile_diameter > 0.)
            pile_formula(parameters, c, report);
        }
      report.log << "\n    foundation at (r, z) = (0, " << z_ref << ") m: U_h "
                 << std::setprecision(6) << m.horizontal_displacement
                 << " m, Theta " << m.rotation << " rad, W "
                 << m.vertical_displacement << " m, Phi " << m.twist << " rad";
    }

    void
    goal_estimate(const GoalEstimate &g,
                  const std::string  &goal_name,
                  HarmonicReport     &report)
    {
      report.add("goal_error_K_H", g.relative_error[0], "-");
      report.add("goal_error_K_M", g.relative_error[1], "-");
      report.add("goal_error_K_MH", g.relative_error[2], "-");
      report.add("goal_error", g.goal_error, "-");
      report.add("goal_cell_share", g.cell_share, "-");
      report.add("enriched_n_dofs", g.enriched_dofs, "-");
      report.add("K_H_enriched", g.enriched.K_H, "H/(G.a.u)");
      report.add("K_M_enriched", g.enriched.K_M, "M/(G.a^3.theta)");
      report.add("K_MH_enriched", g.enriched.K_MH, "H/(G.a^2.theta)");
      report.log << "\n    goal (" << goal_name
                 << "): estimated relative error K_H " << std::setprecision(2)
                 << g.relative_error[0] << ", K_M " << g.relative_error[1]
                 << ", K_MH " << g.relative_error[2]
                 << "; FE_Q(4) on this mesh (" << g.enriched_dofs
                 << " dofs): K_H " << std::setprecision(7) << g.enriched.K_H
                 << ", K_M " << g.enriched.K_M << ", K_MH " << g.enriched.K_MH;
    }

    void
    error_norms(const HarmonicSolution &solution,
                const unsigned int      cycle,
                const ResultsTable     &previous,
                HarmonicReport         &report)
    {
      const HarmonicProblem &problem  = *solution.problem;
      const Harmonic        &harmonic = problem.get_operator().get_harmonic();
      const ErrorNorms       e        = problem.compute_errors();
      report.add("error_l2", e.l2, "m.m^1.5");
      report.add("error_h1_seminorm", e.h1_seminorm, "m.m^0.5");
      report.add("relative_error_l2", e.l2 / e.l2_exact, "-");
      report.add("relative_error_h1", e.h1_seminorm / e.h1_exact, "-");
      report.log << ", L2 error " << std::setprecision(4) << e.l2
                 << " m.m^1.5, H1 error " << e.h1_seminorm << " m.m^0.5";
      if (cycle == 0)
        return;
      const double rate_l2 =
        std::log2(previous.get("error_l2", harmonic, cycle - 1) / e.l2);
      const double rate_h1 = std::log2(
        previous.get("error_h1_seminorm", harmonic, cycle - 1) / e.h1_seminorm);
      report.add("rate_l2", rate_l2, "-");
      report.add("rate_h1", rate_h1, "-");
      report.log << " (rates " << std::setprecision(3) << rate_l2 << ", "
                 << rate_h1 << ")";
    }
  } // namespace Postprocessors
} // namespace FourierSSI
