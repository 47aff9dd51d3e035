// Static condensation of the cell interiors in front of CHOLMOD
// (static_condensation.h) is exact elimination: on an FE_Q(4) vector
// problem with hanging nodes and Dirichlet constraints (a vector Laplacian
// plus a div-div and a mass term: symmetric positive definite), the
// solution with the cell interiors condensed equals the one without. Both
// are backward-stable Cholesky solves of the same matrix; the two differ by
// round-off amplified by the condition number, which the bound 1e-10
// covers with margin (cond ~ 1e4 here: measured differences ~1e-13).
// Checked too: every interior block eliminated (n_kept), several
// right-hand sides in one sweep, hints that overlap or couple to each
// other kept whole, and a matrix whose interior block is indefinite (the
// condensation switches off and the LU fallback answers).
#include "check.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/numerics/vector_tools.h>
#include <fourier_ssi/linear_algebra/sparse_direct.h>
#include <fourier_ssi/linear_algebra/static_condensation.h>

using namespace FourierSSI;

namespace
{
  struct System
  {
    Triangulation<2>          triangulation;
    FESystem<2>               fe{FE_Q<2>(4), 2};
    DoFHandler<2>             dof_handler;
    AffineConstraints<double> constraints;
    SparsityPattern           sparsity;
    SparseMatrix<double>      matrix;
    Vector<double>            rhs;

    System()
    {
      GridGenerator::hyper_cube(triangulation, 0., 1., true);
      triangulation.refine_global(2);
      triangulation.begin_active()->set_refine_flag();
      triangulation.execute_coarsening_and_refinement(); // hanging nodes
      dof_handler.reinit(triangulation);
      dof_handler.distribute_dofs(fe);
      DoFTools::make_hanging_node_constraints(dof_handler, constraints);
      VectorTools::interpolate_boundary_values(dof_handler,
                                               0,
                                               Functions::ZeroFunction<2>(2),
                                               constraints);
      constraints.close();
      DynamicSparsityPattern dsp(dof_handler.n_dofs());
      DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
      sparsity.copy_from(dsp);
      matrix.reinit(sparsity);
      rhs.reinit(dof_handler.n_dofs());
      assemble();
    }

    void
    assemble()
    {
      const QGauss<2>                      quadrature(5);
      FEValues<2>                          fe_values(fe,
                            quadrature,
                            update_values | update_gradients |
                              update_quadrature_points | update_JxW_values);
      const unsigned int                   n = fe.n_dofs_per_cell();
      FullMatrix<double>                   cell_matrix(n, n);
      Vector<double>                       cell_rhs(n);
      std::vector<types::global_dof_index> dofs(n);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          fe_values.reinit(cell);
          cell_matrix = 0.;
          cell_rhs    = 0.;
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const Point<2> x = fe_values.quadrature_point(q);
              for (unsigned int i = 0; i < n; ++i)
                {
                  const unsigned int ci = fe.system_to_component_index(i).first;
                  for (unsigned int j = 0; j < n; ++j)
                    {
                      const unsigned int cj =
                        fe.system_to_component_index(j).first;
                      double a = fe_values.shape_grad_component(i, q, ci)[ci] *
                                 fe_values.shape_grad_component(j, q, cj)[cj];
                      if (ci == cj)
                        a += fe_values.shape_grad(i, q) *
                               fe_values.shape_grad(j, q) +
                             fe_values.shape_value(i, q) *
                               fe_values.shape_value(j, q);
                      cell_matrix(i, j) += a * fe_values.JxW(q);
                    }
                  cell_rhs(i) += (ci == 0 ? 1. : x[0] * x[1]) *
                                 fe_values.shape_value(i, q) * fe_values.JxW(q);
                }
            }
          cell->get_dof_indices(dofs);
          constraints.distribute_local_to_global(
            cell_matrix, cell_rhs, dofs, matrix, rhs);
        }
    }
  };

  Vector<double>
  solve(const SparseMatrix<double>                              &A,
        const Vector<double>                                    &b,
        const std::vector<std::vector<types::global_dof_index>> &blocks)
  {
    SparseDirect direct;
    direct.initialize(A, blocks);
    Vector<double> x(b);
    direct.solve(x);
    return x;
  }

  double
  difference(const Vector<double> &x, const Vector<double> &reference)
  {
    Vector<double> d(x);
    d -= reference;
    return d.l2_norm() / reference.l2_norm();
  }

  std::size_t
  kept_size(const SparseMatrix<double>                              &A,
            const std::vector<std::vector<types::global_dof_index>> &blocks,
            bool                                                    &active)
  {
    StaticCondensation              condensation;
    StaticCondensation::UpperMatrix kept;
    active = condensation.initialize(A, blocks, kept);
    return condensation.n_kept();
  }
} // namespace

int
main()
{
  System      s;
  const auto  blocks = cell_interior_dofs(s.dof_handler);
  const auto  n      = s.dof_handler.n_dofs();
  const auto  plain  = solve(s.matrix, s.rhs, {});
  const auto &cells  = s.triangulation;
  std::cout << n << " DoFs, " << cells.n_active_cells() << " cells"
            << std::endl;

  // Every cell interior (9 nodes x 2 components) eliminated.
  bool active = false;
  check::equal("kept DoFs, every interior condensed",
               kept_size(s.matrix, blocks, active),
               n - 18 * cells.n_active_cells());
  check::that("condensation active", active);
  check::small("condensed vs plain Cholesky",
               difference(solve(s.matrix, s.rhs, blocks), plain),
               1e-10);

  // Several right-hand sides in one sweep: the second is x * rhs.
  {
    SparseDirect direct;
    direct.initialize(s.matrix, blocks);
    std::vector<Vector<double>> x(2, s.rhs);
    x[1] *= 3.;
    direct.solve(x);
    Vector<double> thrice(plain);
    thrice *= 3.;
    check::small("two right-hand sides: first", difference(x[0], plain), 1e-10);
    check::small("two right-hand sides: second",
                 difference(x[1], thrice),
                 1e-10);
  }

  // Hints that overlap (blocks 0 and 1 share a DoF) or couple to another
  // hint (the DoFs inside a boundary edge of a cell away from the hanging
  // nodes, coupled to that cell's interior): those interiors stay whole,
  // the rest is condensed, the solution is unchanged.
  {
    auto hints = blocks;
    hints[1].push_back(hints[0][0]);
    unsigned int coupled_cell = 0;
    for (const auto &cell : s.dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (coupled_cell == 0 && cell->face(f)->at_boundary() &&
            cell->face(f)->boundary_id() == 1)
          {
            std::vector<types::global_dof_index> face_dofs(
              s.fe.n_dofs_per_face());
            cell->face(f)->get_dof_indices(face_dofs);
            hints.emplace_back(face_dofs.begin() + 2 * s.fe.n_dofs_per_vertex(),
                               face_dofs.end());
            coupled_cell = cell->active_cell_index();
          }
    check::that("a cell on x = 1 found", coupled_cell > 1);
    check::equal("kept DoFs, three interiors kept whole",
                 kept_size(s.matrix, hints, active),
                 n - 18 * cells.n_active_cells() + 3 * 18);
    check::small("condensed with bad hints vs plain",
                 difference(solve(s.matrix, s.rhs, hints), plain),
                 1e-10);
  }

  // An indefinite interior block: the condensation switches off, CHOLMOD
  // finds the matrix not positive definite, UMFPACK answers.
  {
    SparseMatrix<double> indefinite(s.sparsity);
    indefinite.copy_from(s.matrix);
    for (const types::global_dof_index i : blocks[5])
      indefinite.diag_element(i) -= 1e3;
    check::equal("kept DoFs, indefinite block",
                 kept_size(indefinite, blocks, active),
                 n);
    check::that("condensation switched off", !active);
    SparseDirectUMFPACK lu;
    lu.initialize(indefinite);
    Vector<double> reference(s.rhs);
    lu.solve(reference);
    check::small("indefinite: fallback vs UMFPACK",
                 difference(solve(indefinite, s.rhs, blocks), reference),
                 1e-10);
  }
  return check::summary();
}
