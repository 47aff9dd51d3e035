// Cost of one harmonic solve vs the floor a per-harmonic solve can reach: a
// bare deal.II vector-valued (3 components) Laplace problem on the same mesh
// with the same element, the same number of DoFs and the same direct solver.
// Usage: benchmark_harmonic_cost harmonic|laplace DEGREE N_HARMONIC CELLS
// Prints one CSV line:
//   kind,degree,n,cells,dofs,setup_s,assembly_s,solve_s,peak_rss_MiB
#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/numerics/vector_tools.h>
#include <fourier_ssi/harmonic/harmonic_problem.h>
#include <fourier_ssi/mesh/mesh_builder.h>
#include <fstream>
#include <iostream>
#include <string>

using namespace dealii;
using namespace FourierSSI;

namespace
{
  double
  peak_rss_mib()
  {
    std::ifstream status("/proc/self/status");
    std::string   line;
    while (std::getline(status, line))
      if (line.rfind("VmHWM:", 0) == 0)
        return std::stod(line.substr(6)) / 1024.;
    return 0.;
  }

  const std::string
  prm(const unsigned int degree, const unsigned int n, const unsigned int cells)
  {
    return "subsection Discretization\n set Harmonics = " + std::to_string(n) +
           "\n set Polynomial degree = " + std::to_string(degree) +
           "\nend\nsubsection Mesh\n set R breakpoints = 0, 1\n set R cells = " +
           std::to_string(cells) +
           "\n set Z breakpoints = 0, 1\n set Z cells = " +
           std::to_string(cells) +
           "\nend\nsubsection Boundary conditions\n"
           " set Dirichlet = 2: u=0, v=0, w=0\n set Traction = 3: r=1, z=1, "
           "theta=1\nend\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc != 5)
    {
      std::cerr << "usage: benchmark_harmonic_cost harmonic|laplace DEGREE N "
                   "CELLS"
                << std::endl;
      return 1;
    }
  const std::string  kind   = argv[1];
  const unsigned int degree = std::stoi(argv[2]);
  const unsigned int n      = std::stoi(argv[3]);
  const unsigned int cells  = std::stoi(argv[4]);

  AllParameters parameters;
  parameters.read_string(prm(degree, n, cells));
  Triangulation<2> triangulation;
  build_mesh(parameters.mesh, triangulation);

  double       t_setup = 0, t_assembly = 0, t_solve = 0;
  unsigned int n_dofs = 0;
  Timer        timer;
  if (kind == "harmonic")
    {
      HarmonicProblem problem(parameters,
                              {n, Family::symmetric},
                              triangulation);
      problem.setup_system();
      t_setup = timer.wall_time();
      timer.restart();
      problem.assemble_system();
      t_assembly = timer.wall_time();
      timer.restart();
      problem.solve();
      t_solve = timer.wall_time();
      n_dofs  = problem.get_dof_handler().n_dofs();
    }
  else
    {
      // The floor: vector Laplace, same element, mesh, constraints, solver.
      const auto    fe = make_displacement_element(degree);
      DoFHandler<2> dof_handler(triangulation);
      dof_handler.distribute_dofs(*fe);
      AffineConstraints<double> constraints;
      VectorTools::interpolate_boundary_values(dof_handler,
                                               2,
                                               Functions::ZeroFunction<2>(3),
                                               constraints);
      constraints.close();
      DynamicSparsityPattern dsp(dof_handler.n_dofs());
      DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
      SparsityPattern sparsity;
      sparsity.copy_from(dsp);
      SparseMatrix<double> matrix(sparsity);
      Vector<double>       rhs(dof_handler.n_dofs()), x(dof_handler.n_dofs());
      t_setup = timer.wall_time();
      timer.restart();
      const QGauss<2> quadrature(degree + 2);
      FEValues<2>     fe_values(
        *fe, quadrature, update_values | update_gradients | update_JxW_values);
      const unsigned int dofs_per_cell = fe->n_dofs_per_cell();
      FullMatrix<double> cell_matrix(dofs_per_cell, dofs_per_cell);
      Vector<double>     cell_rhs(dofs_per_cell);
      std::vector<types::global_dof_index> dofs(dofs_per_cell);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          fe_values.reinit(cell);
          cell_matrix = 0;
          cell_rhs    = 0;
          for (const unsigned int q : fe_values.quadrature_point_indices())
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              {
                const unsigned int ci = fe->system_to_component_index(i).first;
                for (unsigned int j = 0; j < dofs_per_cell; ++j)
                  if (fe->system_to_component_index(j).first == ci)
                    cell_matrix(i, j) += fe_values.shape_grad(i, q) *
                                         fe_values.shape_grad(j, q) *
                                         fe_values.JxW(q);
                cell_rhs(i) += fe_values.shape_value(i, q) * fe_values.JxW(q);
              }
          cell->get_dof_indices(dofs);
          constraints.distribute_local_to_global(
            cell_matrix, cell_rhs, dofs, matrix, rhs);
        }
      t_assembly = timer.wall_time();
      timer.restart();
      SparseDirectUMFPACK direct;
      direct.initialize(matrix);
      direct.vmult(x, rhs);
      t_solve = timer.wall_time();
      n_dofs  = dof_handler.n_dofs();
    }
  std::cout << kind << ',' << degree << ',' << n << ',' << cells << ','
            << n_dofs << ',' << t_setup << ',' << t_assembly << ',' << t_solve
            << ',' << peak_rss_mib() << std::endl;
  return 0;
}
