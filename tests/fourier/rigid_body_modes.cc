// Rigid-body modes of the harmonic operator carry zero strain energy
// (doc/theory.md), on a distorted mesh that contains the axis, for p = 2 and 4.
// Reference: a rigid motion has zero strain exactly (doc/theory.md, checked
// symbolically by doc/derivations/operator.py); the FE interpolant of these
// polynomial (degree <= 1) fields is exact, so only round-off remains.
// Tolerance 1e-12 relative to the energy of a deformation of the same size:
// sums of O(100) quadrature terms of magnitude ~1 in double precision.
// The same fields with the family sign flipped are NOT rigid and must have
// energy of order one: this shows the check can fail.
#include "check.h"
#include "test_support.h"

#include <deal.II/grid/tria.h>
#include <deal.II/numerics/vector_tools.h>
#include <fourier_ssi/harmonic/harmonic_problem.h>
#include <fourier_ssi/mesh/mesh_builder.h>

using namespace FourierSSI;

namespace
{
  const char *mesh_prm = R"(
subsection Mesh
  set R breakpoints = 0, 0.4, 1
  set R cells = 2, 2
  set R growth = 1, 1.5
  set Z breakpoints = -1, 0.5
  set Z cells = 4
  set Distortion = 0.25
end
subsection Materials
  set Materials = 0: E=2e4, nu=0.35
end
)";

  double
  energy_of(const AllParameters    &parameters,
            const Harmonic         &harmonic,
            const Triangulation<2> &triangulation,
            const std::string      &U,
            const std::string      &V,
            const std::string      &W)
  {
    HarmonicProblem problem(parameters, harmonic, triangulation);
    problem.setup_system();
    FunctionParser<2> mode(3);
    mode.initialize("r,z", std::vector<std::string>{U, V, W}, {});
    Vector<double> field(problem.get_dof_handler().n_dofs());
    VectorTools::interpolate(problem.get_dof_handler(), mode, field);
    return problem.strain_energy(field);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const unsigned int degree : {2u, 4u})
    {
      AllParameters parameters = test_support::parameters_from(
        std::string(mesh_prm) +
        "subsection Discretization\n set Polynomial degree = " +
        std::to_string(degree) + "\nend\n");
      Triangulation<2> triangulation;
      build_mesh(parameters.mesh, triangulation);
      const std::string p = " (p=" + std::to_string(degree) + ")";

      struct Mode
      {
        Harmonic    harmonic;
        std::string name, U, V, W, U_bad, V_bad, W_bad;
      };
      const std::vector<Mode> modes = {{{0, Family::symmetric},
                                        "axial translation",
                                        "0",
                                        "1",
                                        "0",
                                        "0.1",
                                        "1",
                                        "0"},
                                       {{0, Family::antisymmetric},
                                        "torsional rotation",
                                        "0",
                                        "0",
                                        "r",
                                        "0",
                                        "0",
                                        "1"},
                                       {{1, Family::symmetric},
                                        "lateral translation",
                                        "1",
                                        "0",
                                        "-1",
                                        "1",
                                        "0",
                                        "1"},
                                       {{1, Family::symmetric},
                                        "rotation about horizontal axis",
                                        "z",
                                        "-r",
                                        "-z",
                                        "z",
                                        "r",
                                        "-z"},
                                       {{1, Family::antisymmetric},
                                        "lateral translation",
                                        "1",
                                        "0",
                                        "1",
                                        "1",
                                        "0",
                                        "-1"},
                                       {{1, Family::antisymmetric},
                                        "rotation about horizontal axis",
                                        "z",
                                        "-r",
                                        "z",
                                        "z",
                                        "-r",
                                        "-z"}};
      for (const Mode &m : modes)
        {
          const double e_rigid =
            energy_of(parameters, m.harmonic, triangulation, m.U, m.V, m.W);
          const double e_bad = energy_of(
            parameters, m.harmonic, triangulation, m.U_bad, m.V_bad, m.W_bad);
          check::small(m.harmonic.name() + " " + m.name +
                         ": energy / energy of a non-rigid field" + p,
                       e_rigid / e_bad,
                       1e-12);
          check::that(m.harmonic.name() + " " + m.name +
                        ": the sign-flipped field is strained" + p,
                      e_bad > 1.);
        }
    }
  return check::summary();
}
