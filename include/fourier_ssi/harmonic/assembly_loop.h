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
#include <fourier_ssi/interfaces/interface_integrator.h>
#include <fourier_ssi/linear_algebra/thread_ranges.h>
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
   * Makes a LocalMatrix with scratch objects of its own (FEValues): one per
   * chunk of cells, so that threads never share them.
   */
  using LocalMatrixFactory = std::function<LocalMatrix()>;

  namespace internal
  {
    /** One chunk's cell matrices, loads and DoFs, added in cell order. */
    struct ChunkCopy
    {
      std::vector<FullMatrix<double>>                   matrices;
      std::vector<Vector<double>>                       rhs;
      std::vector<std::vector<types::global_dof_index>> dof_indices;
    };
  } // namespace internal

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
                 const LocalMatrixFactory                      &local_matrix,
                 const unsigned int                             n_threads,
                 MatrixType                                    &matrix,
                 Vector<double>                                &rhs)
  {
    // The cell matrices in fixed chunks of consecutive cells, each on a
    // LocalMatrix (FEValues) of its own, computed n_threads at a time and
    // added in cell order. FEValues reuses the previous cell's data on a
    // translated cell (cell similarity), so a matrix depends on the cell
    // before it at round-off: with fixed chunks, every result is the same
    // bit for bit on any number of threads.
    constexpr unsigned int                           chunk_size = 32;
    std::vector<DoFHandler<2>::active_cell_iterator> cells;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (owns_cell(cell->active_cell_index()))
        cells.push_back(cell);
    const unsigned int n_chunks = (cells.size() + chunk_size - 1) / chunk_size;
    const unsigned int batch_size = 4 * std::max(1u, n_threads);
    std::vector<internal::ChunkCopy> batch(batch_size);
    for (unsigned int first = 0; first < n_chunks; first += batch_size)
      {
        const unsigned int last = std::min(first + batch_size, n_chunks);
        for_each_range(
          last - first,
          1,
          n_threads,
          [&](const unsigned int begin, const unsigned int end) {
            for (unsigned int b = begin; b < end; ++b)
              {
                internal::ChunkCopy &copy        = batch[b];
                const LocalMatrix    cell_matrix = local_matrix();
                const unsigned int   start       = (first + b) * chunk_size;
                const unsigned int   stop =
                  std::min<std::size_t>(start + chunk_size, cells.size());
                copy.matrices.resize(stop - start);
                copy.rhs.resize(stop - start);
                copy.dof_indices.resize(stop - start);
                for (unsigned int c = start; c < stop; ++c)
                  {
                    const unsigned int k = c - start;
                    cell_matrix(cells[c], copy.matrices[k], &copy.rhs[k]);
                    copy.dof_indices[k].resize(
                      cells[c]->get_fe().n_dofs_per_cell());
                    cells[c]->get_dof_indices(copy.dof_indices[k]);
                  }
              }
          });
        for (unsigned int b = 0; b < last - first; ++b)
          for (unsigned int k = 0; k < batch[b].matrices.size(); ++k)
            constraints.distribute_local_to_global(batch[b].matrices[k],
                                                   batch[b].rhs[k],
                                                   batch[b].dof_indices[k],
                                                   matrix,
                                                   rhs);
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
