// A scene's harmonic set, assembled and factorized in this process: what
// every test of the coupled solvers starts from.
#ifndef fourier_ssi_tests_factorized_scene_h
#define fourier_ssi_tests_factorized_scene_h

#include "test_support.h"

#include <deal.II/base/mpi.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/coupled/linearisation_choice.h>
#include <fourier_ssi/driver/scene_plan.h>
#include <fourier_ssi/harmonic/harmonic_set.h>
#include <fourier_ssi/input/parameters.h>
#include <fourier_ssi/mesh/mesh_builder.h>
#include <string>
#include <vector>

namespace test_support
{
  /**
   * Members are built in declaration order: the set refers to the mesh and
   * the plan. With `distribute_over_ranks` every rank of MPI_COMM_WORLD
   * owns some harmonics (HarmonicSet::distribute_over), each solved serially.
   */
  class FactorizedScene
  {
  public:
    explicit FactorizedScene(const std::string &prm_text,
                             const bool         distribute_over_ranks = false)
      : parameters(parameters_from(prm_text))
      , plan(build_mesh_and_plan(parameters, triangulation))
      , set(parameters,
            plan.harmonics,
            triangulation,
            plan.loads,
            MPI_COMM_SELF,
            distribute_over_ranks ? 1 : 0)
    {
      if (distribute_over_ranks)
        set.distribute_over(MPI_COMM_WORLD);
      set.setup_and_assemble();
      set.factorize();
    }

    /** Every harmonic solved for the scene's own (linear) load. */
    std::vector<dealii::Vector<double>>
    linear_solutions()
    {
      std::vector<std::vector<dealii::Vector<double>>> b(set.size());
      for (unsigned int h = 0; h < set.size(); ++h)
        b[h] = {set.problem(h).get_system_rhs()};
      set.solve_increments(b);
      std::vector<dealii::Vector<double>> x;
      for (auto &v : b)
        x.push_back(v[0]);
      return x;
    }

    /** With the choices made on the mesh (choose_interface_linearisation). */
    FourierSSI::AllParameters   parameters;
    dealii::Triangulation<2>    triangulation;
    const FourierSSI::ScenePlan plan;
    FourierSSI::HarmonicSet     set;

  private:
    static FourierSSI::ScenePlan
    build_mesh_and_plan(FourierSSI::AllParameters &parameters,
                        dealii::Triangulation<2>  &triangulation)
    {
      build_mesh(parameters.mesh, triangulation);
      FourierSSI::choose_interface_linearisation(parameters, triangulation);
      return FourierSSI::plan_scene(parameters, triangulation);
    }
  };
} // namespace test_support

#endif
