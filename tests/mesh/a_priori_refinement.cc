// A priori refinements of the Adaptivity subsection (doc/accuracy-vs-time.md,
// "A priori refinement"), on the bundled footing recipes:
//  - Layer refinement 'z=0, r=1..20: k' cuts the surface cells in z only:
//    after k passes the thinnest cell on the ground surface beyond the
//    footing is the base top-layer height times 2^-k (exact), and the
//    widest surface cell keeps its width (cut in z only: an isotropic
//    refinement would halve it);
//  - Box refinement refines exactly the cells whose centre lies in the box;
//  - accuracy: prm/embedded-footing-precise.prm gives K_H, K_M, K_MH within
//    1e-6 of the converged 10.7991035 / 18.9791563 / -8.76923033 (graded
//    meshes G = 0, 1, 2 extrapolated, confirmed to a few 1e-7 by a 431k-DoF
//    run); measured 3.5e-7 / 2.4e-7 / 6.2e-7;
//  - nested refinements lower K_H and K_M (conforming upper bounds): the
//    precise recipe without its layers gives larger values.
#include "check.h"
#include "test_support.h"

#include <fourier_ssi/driver/simulator.h>
#include <fourier_ssi/mesh/mesh_builder.h>

using namespace FourierSSI;

namespace
{
  /** Smallest height, largest width of the cells with a face on z = 0, r > r0.
   */
  std::pair<double, double>
  surface_cells(const Triangulation<2> &tria, const double r0)
  {
    double height = 1e300, width = 0.;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && std::abs(face->center()[1]) < 1e-12 &&
            std::abs(face->vertex(0)[1]) < 1e-12 &&
            std::abs(face->vertex(1)[1]) < 1e-12 && face->center()[0] > r0)
          {
            height = std::min(height, cell->extent_in_direction(1));
            width  = std::max(width, cell->extent_in_direction(0));
          }
    return {height, width};
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Harmonic                   h{1, Family::symmetric};
  const std::string                precise =
    test_support::bundled_prm("prm/embedded-footing-precise.prm") +
    "subsection Output\n set Write vtu = false\n"
    " set Write interface tractions = false\nend\n";

  // Geometry of the layers and boxes on the graded recipe (cheap).
  const std::string graded =
    test_support::bundled_prm("prm/embedded-footing-graded.prm") +
    "subsection Output\n set Write vtu = false\n"
    " set Write interface tractions = false\nend\n";
  double base_height = 0., base_width = 0.;
  for (const unsigned int k : {0u, 3u})
    {
      const AllParameters parameters = test_support::parameters_from(
        graded +
        "subsection Adaptivity\n set Layer refinement = z=0, "
        "r=1..20: " +
        std::to_string(k) + "\nend\n");
      Simulator simulator(parameters);
      simulator.run(std::cout, false);
      const auto &tria           = simulator.get_triangulation();
      const auto [height, width] = surface_cells(tria, 2.);
      if (k == 0)
        {
          base_height = height, base_width = width;
          continue;
        }
      check::relative("thinnest surface cell = base height * 2^-3",
                      height,
                      base_height / 8.,
                      1e-12);
      check::relative("the widest surface cell keeps its width (cut in z "
                      "only)",
                      width,
                      base_width,
                      1e-12);
    }
  {
    const AllParameters parameters = test_support::parameters_from(
      graded + "subsection Adaptivity\n set Point refinement = \n"
               " set Box refinement = 0, 3, -3, 0: 1\nend\n");
    Simulator simulator(parameters);
    simulator.run(std::cout, false);
    const AllParameters base_parameters = test_support::parameters_from(
      graded + "subsection Adaptivity\n set Point refinement = \nend\n");
    Triangulation<2> base;
    build_mesh(base_parameters.mesh, base);
    unsigned int in_box = 0;
    for (const auto &cell : base.active_cell_iterators())
      if (cell->center()[0] < 3. && cell->center()[1] > -3.)
        ++in_box;
    check::that("box refinement: 3 more cells per cell in the box (" +
                  std::to_string(in_box) + " cells)",
                simulator.get_triangulation().n_active_cells() ==
                  base.n_active_cells() + 3 * in_box);
  }

  // Accuracy of the precise recipe, and monotonicity.
  const double       reference[3] = {10.7991035, 18.9791563, -8.76923033};
  const char        *names[3]     = {"K_H", "K_M", "K_MH"};
  const ResultsTable full         = test_support::run(precise);
  const ResultsTable no_layers    = test_support::run(
    precise + "subsection Adaptivity\n set Layer refinement = \nend\n");
  for (unsigned int q = 0; q < 3; ++q)
    {
      check::relative(std::string(names[q]) + ": precise recipe vs reference",
                      full.get(names[q], h, 0),
                      reference[q],
                      1e-6);
      if (q < 2)
        check::that(std::string(names[q]) + " decreases with the layers",
                    full.get(names[q], h, 0) < no_layers.get(names[q], h, 0));
    }
  return check::summary();
}
