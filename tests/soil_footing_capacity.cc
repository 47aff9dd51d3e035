// Plastic soil on the coupled-harmonic iteration (include/fourier_ssi/
// coupled_soil_solver.h, doc/soil-plasticity.md sections 3 and 5), on the
// bundled scene prm/footing-capacity.prm (rigid circular surface footing,
// a = 1 m, Tresca s_u = 10 kPa, G = 3000 kPa, nu = 0.49, FE_Q(2) + B-bar):
//  (0) projection: with s_p = D eps (the whole strain "plastic") the
//      out-of-balance load is int Bbar^T D eps = K u, for random fields of
//      n = 0..3, both families, N = 9 theta samples: 1e-11 relative (both
//      are the same Gauss sums; the theta rule is exact for N > 2 n_max);
//  (1) elastic limit: s_u = 1e9 kPa, load control: 0 out-of-balance
//      iterations and the linear solution to 1e-13 relative;
//  (2) vertical bearing capacity, n = 0 only: N_c = V_ult / (pi a^2 s_u)
//      at the end of the displacement-controlled curve (w = 0.1 a) against
//      Eason & Shield (1960) 6.05 rough and Cox, Eason & Hopkins (1961)
//      5.69 smooth, within 2 % (the tolerance: the mesh error of
//      the footing-edge singularity at this resolution and the 1 % left
//      between w = 0.1 a and the plateau, measured in doc/soil-plasticity.md);
//  (3) at every converged step: equilibrium |R| <= 1e-8 |lambda F| and no
//      stress outside the yield surface by more than 1e-9 * 2 s_u.
#include "check.h"
#include "test_support.h"

#include <deal.II/grid/tria.h>
#include <fourier_ssi/coupled_soil_solver.h>
#include <fourier_ssi/harmonic_set.h>
#include <fourier_ssi/scene_plan.h>
#include <random>
#include <regex>

using namespace FourierSSI;

namespace
{
  std::string
  scene(const std::vector<std::pair<std::string, std::string>> &changes)
  {
    std::string text = test_support::bundled_prm("prm/footing-capacity.prm");
    for (const auto &[entry, value] : changes)
      text = std::regex_replace(text,
                                std::regex("set " + entry + " *= [^\n]*"),
                                "set " + entry + " = " + value);
    return text;
  }

  struct Run
  {
    AllParameters                      parameters;
    Triangulation<2>                   triangulation;
    std::unique_ptr<HarmonicSet>       set;
    std::unique_ptr<CoupledSoilSolver> solver;

    explicit Run(const std::string &text)
      : parameters(test_support::parameters_from(text))
    {
      parameters.mesh.build(triangulation);
      const ScenePlan plan = plan_scene(parameters, triangulation);
      set                  = std::make_unique<HarmonicSet>(parameters,
                                          plan.harmonics,
                                          triangulation,
                                          plan.loads,
                                          MPI_COMM_SELF,
                                          0);
      set->setup_and_assemble();
      set->factorize();
      solver = std::make_unique<CoupledSoilSolver>(*set, parameters);
    }
  };

  void
  check_projection()
  {
    std::cout << "(0) int Bbar^T D eps = K u, n = 0..3, both families"
              << std::endl;
    Run          run(scene({{"Harmonics", "0, 1, 2, 3"},
                            {"Family", "both"},
                            {"Theta samples", "9"}}));
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1., 1.);
    std::vector<Vector<double>>            fields;
    for (unsigned int h = 0; h < run.set->size(); ++h)
      {
        Vector<double> x(run.set->problem(h).get_dof_handler().n_dofs());
        for (double &v : x)
          v = u(rng);
        run.set->problem(h).get_homogeneous_constraints().distribute(x);
        fields.push_back(x);
      }
    const auto force = run.solver->soil_force(fields);
    double     error = 0., norm = 0.;
    for (unsigned int h = 0; h < run.set->size(); ++h)
      {
        Vector<double> Ku(fields[h].size());
        run.set->problem(h).get_system_matrix().vmult(Ku, fields[h]);
        const auto &constraints = run.set->problem(h).get_constraints();
        for (unsigned int i = 0; i < Ku.size(); ++i)
          if (!constraints.is_constrained(i))
            {
              error = std::max(error, std::abs(Ku[i] - force[h][i]));
              norm  = std::max(norm, std::abs(Ku[i]));
            }
      }
    check::small("max |G - K u| / max |K u|", error / norm, 1e-11);
  }

  void
  check_elastic_limit()
  {
    std::cout << "(1) elastic limit: s_u = 1e9 kPa" << std::endl;
    Run run(scene({{"Laws", "0: tresca, su=1e9"},
                   {"Control", "load"},
                   {"Load steps", "2"},
                   {"Vertical force", "-100"}}));
    run.solver->run(std::cout);
    unsigned int iterations = 0;
    for (const SoilStepResult &s : run.solver->get_steps())
      iterations += s.iterations;
    check::equal("out-of-balance iterations", iterations, 0);
    std::vector<std::vector<Vector<double>>> b = {
      {run.set->problem(0).get_system_rhs()}};
    run.set->solve_increments(b);
    Vector<double> difference = run.solver->solution(0);
    difference -= b[0][0];
    check::small("|u - u_linear| / |u_linear|",
                 difference.l2_norm() / b[0][0].l2_norm(),
                 1e-13);
  }

  void
  check_capacity(const std::string &name,
                 const std::string &tied,
                 const double       reference)
  {
    std::cout << "(2) " << name << " footing, n = 0" << std::endl;
    Run run(scene({{"Tied components", tied}}));
    run.solver->run(std::cout);
    const auto  &steps = run.solver->get_steps();
    const double su = 10., a = 1.;
    double       worst_residual = 0., worst_f = -1e300;
    for (const SoilStepResult &s : steps)
      {
        worst_residual = std::max(worst_residual, s.residual);
        worst_f        = std::max(worst_f, s.largest_yield_value);
      }
    const double V  = -run.solver->applied_loads(steps.back().load_factor)[2];
    const double Nc = V / (numbers::PI * a * a * su);
    const double V9 =
      -run.solver->applied_loads(steps[steps.size() - 3].load_factor)[2];
    std::cout << "  N_c = " << Nc
              << " at w = " << steps.back().motion.vertical_displacement
              << " m; change over the last 3 steps " << (V - V9) / V * 100.
              << " %" << std::endl;
    check::relative(name + " N_c vs the published limit", Nc, reference, 0.02);
    check::small(name + " equilibrium: max |R| / |lambda F|",
                 worst_residual,
                 1e-8);
    check::in_range(name + " max f(sigma) over every point [kPa]",
                    worst_f,
                    -1e300,
                    1e-9 * 2. * su);
  }
} // namespace

int
main()
{
  check_projection();
  check_elastic_limit();
  check_capacity("rough", "all", 6.05);
  check_capacity("smooth", "normal", 5.69);
  return check::summary();
}
