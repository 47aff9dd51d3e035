// Sliding and spring interfaces against closed forms.
// Hollow block r in [0.5, 1], z in [0, 1], split with double nodes along
// z = 0.5 (interface 5; normal +z, side A below, tangent s = +r).
//
// 1. Smooth interface (ks = 0, kn = 1e6), n = 0 symmetric. Bottom block
//    material 0 (E0 = 1e5, nu0 = 0.3), top block material 1 (E1 = 2e5,
//    nu1 = 0.1); top pressure p = 100 kPa, bottom v = 0 only (smooth base),
//    free sides. With no shear transmitted, each block is in uniaxial stress
//    sigma_zz = -p:
//      u = nu_i p r / E_i,   v = -p z / E0 (z < 0.5),
//      v = -p 0.5 / E0 - p / kn - p (z - 0.5) / E1 (z > 0.5),
//    so the interface slips radially by (nu1/E1 - nu0/E0) p r (the blocks
//    expand differently) and closes by p / kn; its tractions are
//    t_n = -p, t_s = 0. The field is linear, so FE_Q(2) reproduces it to
//    round-off: tolerance 1e-9 relative (condition ~ kn h / E ~ 1e2).
// 2. Spring interface (ks = 2e4 kPa/m), n = 0 antisymmetric (torsion), one
//    material G = E / (2 (1 + nu)), fixed bottom, top traction t_theta = c r.
//    Saint-Venant torsion: tau_ztheta = c r everywhere, and the interface
//    slips by tau / ks:
//      W = r (c z / G)               (z < 0.5),
//      W = r (c z / G + c / ks)      (z > 0.5),
//    again polynomial: nodal W and the CSV slip/traction to 1e-9 relative.
// 3. Van Langen & Vermeer: mu = 50 on the two-material mesh uses the softer
//    material 0: ks = mu G0 / l, kn = mu G0 / ((1 - 2 nu0) l), l = 0.25
//    (exact up to round-off, 1e-12).
#include "check.h"
#include "test_support.h"

#include <cmath>
#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>
#include <fourier_ssi/harmonic/harmonic_problem.h>
#include <fourier_ssi/mesh/mesh_builder.h>
#include <fstream>

using namespace FourierSSI;

namespace
{
  const double p = 100., E0 = 1e5, nu0 = 0.3, E1 = 2e5, nu1 = 0.1, kn = 1e6,
               ks = 2e4, c = 10.;

  std::string
  prm(const std::string &interface, const std::string &bc)
  {
    return "subsection Mesh\n set R breakpoints = 0.5, 1\n set R cells = 2\n"
           " set Z breakpoints = 0, 0.5, 1\n set Z cells = 2, 2\n"
           " set Z growth = 1, 1\n set Interface lines = 5: z=0.5, r=0.5..1\n"
           "end\n"
           "subsection Materials\n set Materials = 0: E=1e5, nu=0.3; "
           "1: E=2e5, nu=0.1\nend\n"
           "subsection Boundary conditions\n" +
           bc +
           "end\nsubsection Interfaces\n set Interfaces = 5: " + interface +
           "\nend\n";
  }

  /** Solve one harmonic on the two-material mesh; return max nodal error. */
  double
  solve(const AllParameters                                     &parameters,
        const Harmonic                                          &harmonic,
        const std::function<double(const Point<2> &, unsigned)> &exact,
        const std::string                                       &csv,
        std::vector<InterfaceStiffness> *stiffness = nullptr)
  {
    Triangulation<2> triangulation;
    build_mesh(parameters.mesh, triangulation);
    for (const auto &cell : triangulation.active_cell_iterators())
      cell->set_material_id(cell->center()[1] > 0.5 ? 1 : 0);
    HarmonicProblem problem(parameters, harmonic, triangulation);
    problem.run();
    const auto &dof_handler = problem.get_dof_handler();
    std::map<types::global_dof_index, Point<2>> points;
    DoFTools::map_dofs_to_support_points(MappingQ1<2>(), dof_handler, points);
    std::vector<types::global_dof_index> dofs(
      dof_handler.get_fe().n_dofs_per_cell());
    double error = 0., scale = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          {
            const unsigned int comp =
              dof_handler.get_fe().system_to_component_index(i).first;
            // Both copies of a double node sit at the same point: decide the
            // side by the cell.
            Point<2> x = points[dofs[i]];
            x[1] += 1e-14 * (cell->center()[1] > 0.5 ? 1. : -1.);
            const double u = exact(x, comp);
            error =
              std::max(error, std::abs(problem.get_solution()(dofs[i]) - u));
            scale = std::max(scale, std::abs(u));
          }
      }
    problem.get_interfaces()->write_csv(5, problem.get_solution(), csv);
    if (stiffness)
      *stiffness = problem.get_interfaces()->get_stiffness();
    return error / scale;
  }
} // namespace

int
main()
{
  std::cout << "1. smooth interface, n=0 symmetric, two materials\n";
  {
    const AllParameters parameters = test_support::parameters_from(
      prm("kn=1e6, ks=0",
          " set Dirichlet = 2: v=0\n set Traction = 3: z=-100\n"));
    const auto exact = [](const Point<2> &x, unsigned comp) {
      const bool top = x[1] > 0.5;
      if (comp == 0)
        return (top ? nu1 / E1 : nu0 / E0) * p * x[0];
      if (comp == 1)
        return top ? -p * 0.5 / E0 - p / kn - p * (x[1] - 0.5) / E1 :
                     -p * x[1] / E0;
      return 0.;
    };
    const double error = solve(parameters,
                               {0, Family::symmetric},
                               exact,
                               "interface_smooth_sliding.csv");
    check::small("max nodal error / max |u|", error, 1e-9);
    const auto rows =
      test_support::read_csv_numbers("interface_smooth_sliding.csv");
    check::relative("CSV rows (2 faces x 3 nodes)", rows.size(), 6, 0.);
    for (const auto &row : rows)
      {
        const double r = row[2];
        check::relative("slip d_s at r=" + std::to_string(r),
                        row[4],
                        (nu1 / E1 - nu0 / E0) * p * r,
                        1e-9);
        check::relative("closure d_n", row[5], -p / kn, 1e-9);
        check::relative("traction t_n", row[7], -p, 1e-9);
        check::small("traction t_s (ks = 0)", row[8], 0.);
      }
  }

  std::cout << "2. spring interface ks = 2e4, n=0 antisymmetric (torsion)\n";
  {
    const AllParameters parameters = test_support::parameters_from(prm(
      "kn=1e6, ks=2e4",
      " set Dirichlet = 2: u=0, v=0, w=0\n set Traction = 3: theta=10*r\n"));
    // Torsion test uses one material: overwrite material 1 with material 0.
    AllParameters one_material = parameters;
    one_material.materials.set(1, parameters.materials.get(0));
    const double G     = E0 / (2. * (1. + nu0));
    const auto   exact = [G](const Point<2> &x, unsigned comp) {
      if (comp != 2)
        return 0.;
      return x[0] * (c * x[1] / G + (x[1] > 0.5 ? c / ks : 0.));
    };
    const double error = solve(one_material,
                               {0, Family::antisymmetric},
                               exact,
                               "interface_torsion.csv");
    check::small("max nodal error / max |W|", error, 1e-9);
    for (const auto &row :
         test_support::read_csv_numbers("interface_torsion.csv"))
      {
        const double r = row[2];
        check::relative("slip d_theta at r=" + std::to_string(r),
                        row[6],
                        c * r / ks,
                        1e-9);
        check::relative("traction t_theta = c r", row[9], c * r, 1e-9);
      }
  }

  std::cout << "3. Van Langen & Vermeer stiffness\n";
  {
    const AllParameters parameters = test_support::parameters_from(
      prm("vermeer, mu=50",
          " set Dirichlet = 2: v=0\n set Traction = 3: z=-100\n"));
    const auto exact = [](const Point<2> &, unsigned) { return 1.; };
    std::vector<InterfaceStiffness> k;
    solve(
      parameters, {0, Family::symmetric}, exact, "interface_vermeer.csv", &k);
    const double G0 = E0 / (2. * (1. + nu0)), l = 0.25;
    check::relative("ks = mu G0 / l", k.at(0).shear, 50. * G0 / l, 1e-12);
    check::relative("kn = mu G0 / ((1 - 2 nu0) l)",
                    k.at(0).normal,
                    50. * G0 / ((1. - 2. * nu0) * l),
                    1e-12);
  }
  return check::summary();
}
