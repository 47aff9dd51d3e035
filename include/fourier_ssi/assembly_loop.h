/**
 * The one assembly loop of a harmonic's system, for the serial and the
 * distributed path alike (step-40's is_locally_owned() habit): the cells
 * and interface pairs this process owns go through the constraints into the
 * matrix and the load. Serially a process owns everything; distributed, a
 * cell belongs to its METIS partition and an interface pair to the owner of
 * its side-A cell, so a pair straddling two ranks is assembled once.
 */
#ifndef fourier_ssi_assembly_loop_h
#define fourier_ssi_assembly_loop_h

#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/interface_integrator.h>
#include <functional>

namespace FourierSSI
{
  using namespace dealii;

  /** The cell matrix (and, if rhs != nullptr, cell load) of one cell. */
  using LocalMatrix =
    std::function<void(const DoFHandler<2>::active_cell_iterator &,
                       FullMatrix<double> &,
                       Vector<double> *)>;

  /**
   * Add the owned cells' matrices and loads, then the owned interface
   * pairs' closed-form matrices. Returns the wall time spent on the
   * interface pairs [s].
   */
  template <typename MatrixType>
  double
  assemble_owned(const DoFHandler<2>                           &dof_handler,
                 const AffineConstraints<double>               &constraints,
                 const InterfaceIntegrator                     *interfaces,
                 const std::function<bool(const unsigned int)> &owns_cell,
                 const LocalMatrix                             &local_matrix,
                 MatrixType                                    &matrix,
                 Vector<double>                                &rhs)
  {
    FullMatrix<double>                   cell_matrix;
    Vector<double>                       cell_rhs;
    std::vector<types::global_dof_index> dof_indices(
      dof_handler.get_fe().n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (owns_cell(cell->active_cell_index()))
        {
          local_matrix(cell, cell_matrix, &cell_rhs);
          cell->get_dof_indices(dof_indices);
          constraints.distribute_local_to_global(
            cell_matrix, cell_rhs, dof_indices, matrix, rhs);
        }
    Timer timer;
    if (interfaces)
      {
        FullMatrix<double>                   merged;
        std::vector<types::global_dof_index> unique_dofs;
        const auto                          &pairs = interfaces->get_pairs();
        for (unsigned int i = 0; i < pairs.size(); ++i)
          if (owns_cell(pairs[i].cells[0]))
            {
              interfaces->merged_matrix(i, merged, unique_dofs);
              Vector<double> pair_rhs(unique_dofs.size());
              constraints.distribute_local_to_global(
                merged, pair_rhs, unique_dofs, matrix, rhs);
            }
      }
    return timer.wall_time();
  }
} // namespace FourierSSI

#endif
