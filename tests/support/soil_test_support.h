// Helpers of the plastic-soil tests: the bundled footing scene with entries
// changed, set up on a HarmonicSet with its CoupledSolver, and the
// bearing-capacity check (doc/soil-plasticity.md section 5).
#ifndef fourier_ssi_tests_soil_test_support_h
#define fourier_ssi_tests_soil_test_support_h

#include "check.h"
#include "test_support.h"

#include <deal.II/grid/tria.h>
#include <fourier_ssi/coupled/coupled_solver.h>
#include <fourier_ssi/coupled/linearisation_choice.h>
#include <fourier_ssi/driver/scene_plan.h>
#include <fourier_ssi/harmonic/harmonic_set.h>
#include <fourier_ssi/mesh/mesh_builder.h>
#include <random>
#include <regex>

namespace soil_test
{
  using namespace FourierSSI;

  inline std::string
  scene(const std::vector<std::pair<std::string, std::string>> &changes)
  {
    return test_support::bundled_prm("prm/footing-capacity.prm", changes);
  }

  /**
   * The shipped footing mesh (10 + 14 by 20 cells) or, coarse, the same
   * mesh with half the cells in each direction (growth ratios squared: the
   * coarse cells are pairs of the shipped ones).
   */
  inline std::vector<std::pair<std::string, std::string>>
  footing_mesh(const bool coarse)
  {
    if (coarse)
      return {{"R cells", "5, 7"},
              {"R growth", "0.7225, 1.44"},
              {"Z cells", "10"},
              {"Z growth", "0.7225"}};
    return {{"R cells", "10, 14"},
            {"R growth", "0.85, 1.2"},
            {"Z cells", "20"},
            {"Z growth", "0.85"}};
  }

  /**
   * The free-head rigid pile of prm/pile-free-head.prm (d = 1 m, L = 10 m,
   * Tresca s_u = 10 kPa) with `law` on its shaft, n = 0 and 1, pushed to
   * u = 0.01 m at the head in 4 steps, without soil-reaction curves;
   * `more` changes on top.
   */
  inline std::string
  free_head_pile(
    const std::string                                      &law,
    const std::vector<std::pair<std::string, std::string>> &more = {})
  {
    std::vector<std::pair<std::string, std::string>> changes = {
      {"Harmonics", "0, 1"},
      {"Interfaces", "5: " + law},
      {"Target", "0.01"},
      {"Load steps", "4"},
      {"Soil reaction depths", ""}};
    changes.insert(changes.end(), more.begin(), more.end());
    return test_support::bundled_prm("prm/pile-free-head.prm", changes);
  }

  /** changes followed by more changes (one list for scene()). */
  inline std::vector<std::pair<std::string, std::string>>
  joined(std::vector<std::pair<std::string, std::string>>        changes,
         const std::vector<std::pair<std::string, std::string>> &more)
  {
    changes.insert(changes.end(), more.begin(), more.end());
    return changes;
  }

  struct Run
  {
    AllParameters                  parameters;
    Triangulation<2>               triangulation;
    std::unique_ptr<HarmonicSet>   set;
    std::unique_ptr<CoupledSolver> solver;

    explicit Run(const std::string &text)
      : parameters(test_support::parameters_from(text))
    {
      build_mesh(parameters.mesh, triangulation);
      choose_interface_linearisation(parameters, triangulation);
      const ScenePlan plan = plan_scene(parameters, triangulation);
      set                  = std::make_unique<HarmonicSet>(parameters,
                                          plan.harmonics,
                                          triangulation,
                                          plan.loads,
                                          MPI_COMM_SELF,
                                          0);
      set->setup_and_assemble();
      set->factorize();
      solver = std::make_unique<CoupledSolver>(*set, parameters);
    }
  };

  /**
   * Every converged step in equilibrium (|R| / |applied load| <= 1e-8, the
   * stopping rule's tolerance) and on or inside the yield surface
   * (f <= 1e-9 * 2 s_u: round-off of the return mapping).
   */
  inline void
  check_equilibrium_and_yield(const std::string                 &name,
                              const std::vector<LoadStepResult> &steps,
                              const double                       su)
  {
    double worst_residual = 0., worst_f = -1e300;
    for (const LoadStepResult &s : steps)
      {
        worst_residual = std::max(worst_residual, s.residual);
        worst_f        = std::max(worst_f, s.largest_yield_value);
      }
    check::small(name + "equilibrium: max |R| / |applied load|",
                 worst_residual,
                 1e-8);
    check::in_range(name + "max f(sigma) over every point [kPa]",
                    worst_f,
                    -1e300,
                    1e-9 * 2. * su);
  }

  /**
   * N_c = V_ult / (pi a^2 s_u) of the footing (a = 1 m, s_u = 10 kPa) at
   * the end of the curve against `reference` within 2 %; equilibrium and
   * the yield condition at every converged step.
   */
  inline void
  check_capacity(const std::string &name,
                 const std::string &tied,
                 const double       reference)
  {
    std::cout << name << " footing, n = 0" << std::endl;
    // The bundled curve to w = 0.04 m = 0.04 a in 8 steps: V there is
    // within 0.05 % of V at w = 0.1 a (doc/soil-plasticity.md table 1).
    Run run(scene(
      {{"Tied components", tied}, {"Load steps", "8"}, {"Target", "-0.04"}}));
    run.solver->run(std::cout);
    const auto  &steps = run.solver->get_steps();
    const double su = 10., a = 1.;
    const double V  = -run.solver->applied_loads(steps.back().load_factor)[2];
    const double Nc = V / (numbers::PI * a * a * su);
    const double V9 =
      -run.solver->applied_loads(steps[steps.size() - 3].load_factor)[2];
    std::cout << "  N_c = " << Nc
              << " at w = " << steps.back().motion.vertical_displacement
              << " m; change over the last 3 steps " << (V - V9) / V * 100.
              << " %" << std::endl;
    check::relative(name + " N_c vs the published limit", Nc, reference, 0.02);
    check_equilibrium_and_yield(name + " ", steps, su);
  }

  /** Random fields of every harmonic in [-size, size], constraints kept. */
  inline std::vector<Vector<double>>
  random_fields(const HarmonicSet &set, std::mt19937 &rng, const double size)
  {
    std::uniform_real_distribution<double> u(-size, size);
    std::vector<Vector<double>>            fields;
    for (unsigned int h = 0; h < set.size(); ++h)
      {
        Vector<double> x(set.problem(h).get_dof_handler().n_dofs());
        for (double &v : x)
          v = u(rng);
        set.problem(h).get_homogeneous_constraints().distribute(x);
        fields.push_back(x);
      }
    return fields;
  }

  /** How far the coupled tangent is from differences of the load. */
  struct TangentMismatch
  {
    /** max |K_t x - (K x - dG/du x)| over the unconstrained DoFs. */
    double error = 0.;
    /** max |dG/du x| and max |K_t x|. */
    double softened = 0., tangent = 0.;
  };

  /**
   * The coupled tangent at u applied to x against K x minus the central
   * difference (G(u + e x) - G(u - e x)) / 2e of the out-of-balance load:
   * only the return mapping and the projection are shared.
   */
  inline TangentMismatch
  tangent_mismatch(Run                               &run,
                   const std::vector<Vector<double>> &u,
                   const std::vector<Vector<double>> &x,
                   const double                       e)
  {
    auto plus = u, minus = u;
    for (unsigned int h = 0; h < u.size(); ++h)
      {
        plus[h].add(e, x[h]);
        minus[h].add(-e, x[h]);
      }
    const auto      g_plus  = run.solver->out_of_balance_load(plus);
    const auto      g_minus = run.solver->out_of_balance_load(minus);
    const auto      tangent = run.solver->tangent_product(u, x);
    TangentMismatch result;
    for (unsigned int h = 0; h < u.size(); ++h)
      {
        Vector<double> Kx(x[h].size());
        run.set->problem(h).get_system_matrix().vmult(Kx, x[h]);
        const auto &constraints = run.set->problem(h).get_constraints();
        for (unsigned int i = 0; i < Kx.size(); ++i)
          if (!constraints.is_constrained(i))
            {
              const double dG = (g_plus[h][i] - g_minus[h][i]) / (2. * e);
              result.error =
                std::max(result.error, std::abs(Kx[i] - dG - tangent[h][i]));
              result.tangent =
                std::max(result.tangent, std::abs(tangent[h][i]));
              result.softened = std::max(result.softened, std::abs(dG));
            }
      }
    return result;
  }

  /**
   * Every interface sample of every converged step on or inside its slip
   * surface: max f(t) <= bound [kPa] (the bound and its reason are the
   * caller's).
   */
  inline void
  check_interface_admissible(const std::string                 &name,
                             const std::vector<LoadStepResult> &steps,
                             const double                       bound)
  {
    double worst = -1e300;
    for (const LoadStepResult &s : steps)
      worst = std::max(worst, s.largest_interface_yield_value);
    check::in_range(name + ": max f(t) over the interface [kPa]",
                    worst,
                    -1e300,
                    bound);
  }

  /**
   * Check (0) of the coulomb-interface tests on plastic soil: at random
   * fields u with jumps of ~1e-2 m, the coupled tangent applied to a random
   * x equals K x minus the central difference (e = 1e-9) of the
   * out-of-balance load, to 1e-6 of the largest entry (the reasons are in
   * tests/coupled/soil_coulomb_interface.cc). Only meaningful if the
   * interface softens: dG/du, of the order of the interface stiffness
   * times the shape functions' area, must exceed 1 kN/m.
   */
  inline void
  check_interface_tangent(Run &run)
  {
    std::cout << "(0) interface part of K_t x = K x - dG/du x" << std::endl;
    std::mt19937 rng(11);
    const auto   u = random_fields(*run.set, rng, 1e-2);
    const auto   x = random_fields(*run.set, rng, 1.);
    const auto   m = tangent_mismatch(run, u, x, 1e-9);
    check::in_range("max |dG/du x| (the interface softens) [kN/m]",
                    m.softened,
                    1.,
                    1e300);
    check::small("max |K_t x - (K x - dG/du x)| / max |dG/du x|",
                 m.error / m.softened,
                 1e-6);
  }
} // namespace soil_test

#endif
