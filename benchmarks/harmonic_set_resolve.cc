// Re-solve cost of the harmonic set: one factorization per harmonic, then
// every harmonic re-solved for a new right-hand side on the kept
// factorizations (the step a coupled, theta-sampled nonlinear iteration
// repeats). Scene: prm/wind-pressure.prm with the harmonics 0, 1, 2, 4
// listed and `Global refinements` = argv[1].
// Usage: benchmark_harmonic_set_resolve GLOBAL_REFINEMENTS [REPEATS]
// Prints one CSV line:
//   dofs_per_harmonic,harmonics,threads,factorize_s,resolve_median_s,ratio
#include <algorithm>
#include <deal.II/base/timer.h>
#include <fourier_ssi/driver/scene_plan.h>
#include <fourier_ssi/harmonic/harmonic_set.h>
#include <fourier_ssi/mesh/mesh_builder.h>
#include <fstream>
#include <iostream>
#include <sstream>

using namespace dealii;
using namespace FourierSSI;

int
main(int argc, char **argv)
{
  const unsigned int refinements = argc > 1 ? std::stoi(argv[1]) : 2;
  const unsigned int repeats     = argc > 2 ? std::stoi(argv[2]) : 5;
  std::ifstream     in(std::string(FSSI_SOURCE_DIR) + "/prm/wind-pressure.prm");
  std::stringstream text;
  text << in.rdbuf()
       << "subsection Discretization\n set Harmonics = 0, 1, 2, 4\n"
          " set Family = symmetric\nend\n"
          "subsection Mesh\n set Global refinements = "
       << refinements << "\nend\n";
  AllParameters parameters;
  parameters.read_string(text.str());

  Triangulation<2> triangulation;
  build_mesh(parameters.mesh, triangulation);
  const ScenePlan plan = plan_scene(parameters, triangulation);
  HarmonicSet     set(
    parameters, plan.harmonics, triangulation, plan.loads, MPI_COMM_SELF, 0);
  set.setup_and_assemble();

  Timer timer;
  set.factorize();
  const double factorize = timer.wall_time();

  std::vector<double> resolve;
  for (unsigned int r = 0; r < repeats; ++r)
    {
      std::vector<std::vector<Vector<double>>> loads(set.size());
      for (unsigned int i = 0; i < set.size(); ++i)
        loads[i].push_back(set.problem(i).get_system_rhs());
      timer.restart();
      set.solve_increments(loads);
      resolve.push_back(timer.wall_time());
    }
  std::sort(resolve.begin(), resolve.end());
  const double median = resolve[resolve.size() / 2];
  std::cout << set.problem(0).get_dof_handler().n_dofs() << "," << set.size()
            << "," << set.n_threads() << "," << factorize << "," << median
            << "," << factorize / median << std::endl;
  return 0;
}
