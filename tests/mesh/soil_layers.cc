// Layered soil (Mesh/Soil layers, input/soil_layers.h) on the rigid surface
// disc of prm/surface-disc-stiffness.prm (a = 1 m, nu = 0.3), one mesh:
//  - coverage: two strata of materials 1 and 2, both G = 1000 kPa, with no
//    material 0 defined, give the homogeneous run's K_V, K_H, K_M, K_T to
//    1e-12 (round-off: the same matrices; a cell the strata missed would
//    keep material 0 and stop the run, a stratum shifted by a cell would
//    not change the numbers, so the next check sees the boundaries);
//  - placement: a soft stratum, H = 2 a thick, over a base 1e4 times
//    stiffer gives the stiffness of the same soft stratum on a rigid base
//    (the mesh cut at z = -H, its bottom fixed) within 1e-3: the limit of a
//    stiff base, whose own compliance adds about G_soft / G_base = 1e-4 of
//    the stratum's (measured 2e-6 ... 7e-5). A stratum boundary one cell
//    (0.25 m) deeper gives K_V 5.1 % lower (9211.9 against 9711.1 kN/m,
//    measured with a rigid base at 2.25 m), so misplaced strata fail here;
//  - the stratum's stiffening against the layer-on-bedrock fit K_V =
//    4 G a / (1 - nu) (1 + 1.28 a / H) = 1.64 x 4 G a / (1 - nu) (Gazetas
//    1991, H/a = 2): the ratio within [1.5, 1.8], the fit's own accuracy of
//    several per cent plus this coarse mesh, 6 % stiff on the half-space
//    (measured 1.699);
//  - precedence: a Material region (a stiff column 0 < r < 0.5, -1 < z < 0)
//    keeps its id inside a stratum, every other cell has the id of the
//    stratum holding its centre (computed here from the cell centres).
#include "check.h"
#include "test_support.h"

#include <fourier_ssi/driver/simulator.h>

using namespace FourierSSI;

namespace
{
  const double a = 1., G = 1000., nu = 0.3, H = 2.;

  std::string
  disc_scene(const std::string &mesh, const std::string &materials)
  {
    return test_support::bundled_prm("prm/surface-disc-stiffness.prm") +
           "subsection Discretization\n set Target accuracy =\n"
           " set Refinement cycles = 1\nend\n"
           "subsection Rigid foundation\n set Reference Poisson ratio = 0.3\n"
           "end\n"
           "subsection Mesh\n set R breakpoints = 0, 1, 60\n"
           " set R cells = 4, 20\n set R growth = 1, 1.25\n" +
           mesh + "end\nsubsection Materials\n set Materials = " + materials +
           "\nend\n";
  }

  // Soft stratum 0..H over a deep base, and the same stratum alone.
  const std::string deep_mesh    = " set Z breakpoints = -60, -2, 0\n"
                                   " set Z cells = 12, 8\n"
                                   " set Z growth = 0.7, 1\n";
  const std::string stratum_mesh = " set Z breakpoints = -2, 0\n"
                                   " set Z cells = 8\n set Z growth = 1\n";

  struct Stiffness
  {
    double V, H, M, T;
  };

  Stiffness
  stiffness_of(const std::string &prm)
  {
    const ResultsTable r = test_support::run(prm);
    return {r.get("K_V", {0, Family::symmetric}, 0),
            r.get("K_H", {1, Family::symmetric}, 0),
            r.get("K_M", {1, Family::symmetric}, 0),
            r.get("K_T", {0, Family::antisymmetric}, 0)};
  }

  void
  check_all(const std::string &what,
            const Stiffness   &value,
            const Stiffness   &reference,
            const double       tolerance)
  {
    check::relative(what + ": K_V", value.V, reference.V, tolerance);
    check::relative(what + ": K_H", value.H, reference.H, tolerance);
    check::relative(what + ": K_M", value.M, reference.M, tolerance);
    check::relative(what + ": K_T", value.T, reference.T, tolerance);
  }

  void
  check_precedence()
  {
    const std::string prm =
      disc_scene(deep_mesh + " set Soil layers = 1: 0, 2; 2: 2, 60\n"
                             " set Material regions = 3: 0, 0.5, -1, 0\n",
                 "1: G=1000, nu=0.3; 2: G=1e7, nu=0.3; 3: G=1e6, nu=0.3");
    // The simulator keeps a reference to its parameters.
    const AllParameters parameters = test_support::parameters_from(prm);
    Simulator           simulator(parameters);
    simulator.run(std::cout, false);
    unsigned int wrong = 0, in_column = 0;
    for (const auto &cell :
         simulator.get_triangulation().active_cell_iterators())
      {
        const Point<2> c        = cell->center();
        const bool     column   = c[0] < 0.5 && c[1] > -1.;
        const unsigned expected = column ? 3 : (c[1] > -H ? 1 : 2);
        in_column += column;
        wrong += cell->material_id() != expected;
      }
    check::that("the column has cells", in_column > 0);
    check::equal("cells whose id is not the region's or the stratum's",
                 wrong,
                 0);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const Stiffness homogeneous =
    stiffness_of(disc_scene(deep_mesh, "0: G=1000, nu=0.3"));
  const Stiffness two_equal_strata = stiffness_of(
    disc_scene(deep_mesh + " set Soil layers = 1: 0, 2; 2: 2, 60\n",
               "1: G=1000, nu=0.3; 2: G=1000, nu=0.3"));
  check_all("equal strata = homogeneous", two_equal_strata, homogeneous, 1e-12);

  const Stiffness stiff_base = stiffness_of(
    disc_scene(deep_mesh + " set Soil layers = 1: 0, 2; 2: 2, 60\n",
               "1: G=1000, nu=0.3; 2: G=1e7, nu=0.3"));
  const Stiffness rigid_base =
    stiffness_of(disc_scene(stratum_mesh, "0: G=1000, nu=0.3"));
  check_all("base 1e4 stiffer = rigid base", stiff_base, rigid_base, 1e-3);

  const double half_space_V = 4. * G * a / (1. - nu);
  std::cout << "  K_V on the half-space mesh " << homogeneous.V
            << " kN/m, on the stratum " << stiff_base.V << " kN/m, ratio "
            << stiff_base.V / homogeneous.V << std::endl;
  check::in_range("stratum H = 2a: K_V / (4 G a / (1 - nu)), fit 1.64",
                  stiff_base.V / half_space_V,
                  1.5,
                  1.8);

  check_precedence();
  return check::summary();
}
