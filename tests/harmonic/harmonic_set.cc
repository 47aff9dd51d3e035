// The harmonic set keeps one factorization per harmonic and re-solves every
// harmonic for new right-hand sides without refactorizing (the building
// block of the coupled, theta-sampled nonlinear iteration).
//
// Scene: prm/wind-pressure.prm (a half-cosine surface pressure, 14
// harmonics, homogeneous supports). Checks:
//  - one factorization per harmonic after factorize(), none added by any
//    number of re-solves (counted);
//  - a NEW load (the pressure tripled, assembled by a fresh problem) solved
//    on the kept factorizations equals the fresh solve to 1e-12 relative
//    (both are the same direct solve of the same matrix; round-off only);
//  - a random load b: ||K x - b|| / ||b|| <= 1e-10 on the condensed rows
//    (backward-stable Cholesky, cond(K) ~ 1e5 here: eps * cond ~ 1e-11).
#include "check.h"
#include "test_support.h"

#include <deal.II/base/mpi.h>
#include <fourier_ssi/driver/scene_plan.h>
#include <fourier_ssi/harmonic/harmonic_set.h>
#include <fourier_ssi/mesh/mesh_builder.h>
#include <random>

using namespace FourierSSI;

int
main()
{
  const std::string scene = test_support::bundled_prm("prm/wind-pressure.prm");
  const AllParameters parameters = test_support::parameters_from(scene);
  const AllParameters tripled    = test_support::parameters_from(
    scene + "subsection Loads\n set Traction = 4: z = "
               "-300*max(cos(theta), 0)\nend\n");

  Triangulation<2> triangulation;
  build_mesh(parameters.mesh, triangulation);
  const ScenePlan plan         = plan_scene(parameters, triangulation);
  const ScenePlan tripled_plan = plan_scene(tripled, triangulation);
  check::equal("harmonics planned", plan.harmonics.size(), 14);

  HarmonicSet set(
    parameters, plan.harmonics, triangulation, plan.loads, MPI_COMM_SELF, 2);
  set.setup_and_assemble();
  set.factorize();
  check::equal("factorizations after factorize()",
               set.n_factorizations(),
               set.size());
  set.factorize();
  check::equal("factorize() again adds none",
               set.n_factorizations(),
               set.size());

  // New loads: the tripled pressure (assembled by fresh problems) and a
  // random vector on the unconstrained rows.
  std::vector<std::vector<Vector<double>>> loads(set.size());
  std::vector<Vector<double>>              fresh(set.size());
  std::vector<Vector<double>>              random_loads(set.size());
  std::mt19937                             generator(12345);
  std::uniform_real_distribution<double>   uniform(-1., 1.);
  for (unsigned int i = 0; i < set.size(); ++i)
    {
      HarmonicProblem problem(tripled,
                              set.harmonic(i),
                              triangulation,
                              &tripled_plan.loads);
      problem.run();
      fresh[i] = problem.get_solution();
      loads[i].push_back(problem.get_system_rhs());

      Vector<double> b(problem.get_system_rhs().size());
      for (auto &value : b)
        value = uniform(generator);
      set.problem(i).get_homogeneous_constraints().set_zero(b);
      random_loads[i] = b;
      loads[i].push_back(b);
    }
  std::vector<std::vector<Vector<double>>> second_round(loads);
  set.solve_increments(loads);
  set.solve_increments(second_round);
  check::equal("factorizations after two rounds of re-solves",
               set.n_factorizations(),
               set.size());

  double worst_fresh = 0., worst_repeat = 0., worst_random = 0.;
  for (unsigned int i = 0; i < set.size(); ++i)
    {
      Vector<double> difference(loads[i][0]);
      difference -= fresh[i];
      worst_fresh =
        std::max(worst_fresh, difference.l2_norm() / fresh[i].l2_norm());
      difference = second_round[i][1];
      difference -= loads[i][1];
      worst_repeat = std::max(worst_repeat, difference.linfty_norm());
    }
  check::small("tripled load on kept factorizations vs fresh solve "
               "(worst harmonic, relative l2)",
               worst_fresh,
               1e-12);
  check::small("second re-solve round equals the first (max abs)",
               worst_repeat,
               0.);

  // Random loads: one more solve and the residual.
  std::vector<std::vector<Vector<double>>> random(set.size());
  for (unsigned int i = 0; i < set.size(); ++i)
    random[i].push_back(random_loads[i]);
  set.solve_increments(random);
  for (unsigned int i = 0; i < set.size(); ++i)
    {
      Vector<double> x(random[i][0]);
      set.problem(i).get_homogeneous_constraints().set_zero(x);
      Vector<double> residual(x.size());
      set.problem(i).get_system_matrix().vmult(residual, x);
      residual -= random_loads[i];
      set.problem(i).get_homogeneous_constraints().set_zero(residual);
      worst_random =
        std::max(worst_random, residual.l2_norm() / random_loads[i].l2_norm());
    }
  check::small("random load: ||K x - b|| / ||b|| (worst harmonic)",
               worst_random,
               1e-10);
  check::equal("factorizations at the end", set.n_factorizations(), set.size());
  return check::summary();
}
