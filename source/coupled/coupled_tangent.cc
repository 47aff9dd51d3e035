#include <algorithm>
#include <deal.II/lac/affine_constraints.templates.h>
#include <deal.II/lac/block_vector.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <fourier_ssi/coupled/coupled_tangent.h>
#include <fourier_ssi/input/messages.h>
#include <numeric>

namespace FourierSSI
{
  namespace
  {
    const std::string what_is_factorized =
      "Soil plasticity: the coupled Newton tangent";

    /**
     * The distinct indices of `dofs`, sorted. deal.II's pattern and matrix
     * insertion (add_entries_local_to_global, distribute_local_to_global)
     * take each index once: a repeated one becomes a repeated column of the
     * pattern (UMFPACK status -8) and a value written to one copy only. An
     * interface pair repeats indices where its line ends inside the body:
     * the end node is one node of both faces.
     */
    std::vector<types::global_dof_index>
    distinct(const std::vector<types::global_dof_index> &dofs)
    {
      std::vector<types::global_dof_index> result(dofs);
      std::sort(result.begin(), result.end());
      result.erase(std::unique(result.begin(), result.end()), result.end());
      return result;
    }

    /** Where each entry of `dofs` is among `distinct_dofs`. */
    std::vector<unsigned int>
    positions_among(const std::vector<types::global_dof_index> &dofs,
                    const std::vector<types::global_dof_index> &distinct_dofs)
    {
      std::vector<unsigned int> position(dofs.size());
      for (unsigned int k = 0; k < dofs.size(); ++k)
        position[k] = std::lower_bound(distinct_dofs.begin(),
                                       distinct_dofs.end(),
                                       dofs[k]) -
                      distinct_dofs.begin();
      return position;
    }
  } // namespace

  CoupledTangent::CoupledTangent(
    const HarmonicSet &set,
    const std::vector<std::vector<std::vector<types::global_dof_index>>>
              &cell_dofs,
    const bool over_ranks)
    : set(set)
    , over_ranks(over_ranks)
    , lu(what_is_factorized)
  {
    const unsigned int          H = set.size();
    BlockDynamicSparsityPattern dsp(H, H);
    for (unsigned int h = 0; h < H; ++h)
      for (unsigned int g = 0; g < H; ++g)
        dsp.block(h, g).reinit(set.problem(h).get_dof_handler().n_dofs(),
                               set.problem(g).get_dof_handler().n_dofs());
    dsp.collect_sizes();
    number_rows();
    for (const unsigned int h : held)
      {
        // The elastic couplings (the interfaces, the rigid foundation's
        // constraints and the elastic materials included).
        const SparseMatrix<double> &elastic =
          set.problem(h).get_system_matrix();
        for (unsigned int row = 0; row < elastic.m(); ++row)
          for (auto entry = elastic.begin(row); entry != elastic.end(row);
               ++entry)
            dsp.block(h, h).add(row, entry->column());
        const auto &rows = set.problem(h).get_homogeneous_constraints();
        for (const auto &dofs : cell_dofs)
          for (unsigned int g = 0; g < H; ++g)
            rows.add_entries_local_to_global(
              distinct(dofs[h]),
              set.problem(g).get_homogeneous_constraints(),
              distinct(dofs[g]),
              dsp.block(h, g),
              false);
      }
    pattern.copy_from(dsp);
    matrix.reinit(pattern);
    make_lu_pattern();
  }

  void
  CoupledTangent::number_rows()
  {
    const unsigned int H = set.size();
    // Over the ranks the rows go rank by rank, so that each rank's are one
    // contiguous range (what the distributed matrix wants).
    std::vector<unsigned int> order(H);
    std::iota(order.begin(), order.end(), 0u);
    if (over_ranks)
      std::stable_sort(order.begin(),
                       order.end(),
                       [&](const unsigned int a, const unsigned int b) {
                         return set.owner(a) < set.owner(b);
                       });
    offset.assign(H, 0);
    held.clear();
    unsigned int next_row = 0;
    for (const unsigned int h : order)
      {
        offset[h] = next_row;
        if (!over_ranks || set.owns(h))
          {
            if (held.empty())
              first_held_row = next_row;
            held.push_back(h);
          }
        next_row += set.problem(h).get_dof_handler().n_dofs();
      }
    n_rows = next_row;
  }

  void
  CoupledTangent::make_lu_pattern()
  {
    unsigned int n_held_rows = 0;
    for (const unsigned int h : held)
      n_held_rows += pattern.block(h, h).n_rows();
    // Each held row: (column, sweep index) over its blocks, sorted by
    // column (UMFPACK and MUMPS want sorted indices).
    std::vector<std::vector<std::pair<long, unsigned int>>> rows(n_held_rows);
    unsigned int                                            sweep = 0;
    for (const unsigned int h : held)
      for (unsigned int g = 0; g < set.size(); ++g)
        {
          const SparsityPattern &block = pattern.block(h, g);
          const unsigned int     first = offset[h] - first_held_row;
          for (unsigned int row = 0; row < block.n_rows(); ++row)
            for (auto entry = block.begin(row); entry != block.end(row);
                 ++entry)
              rows[first + row].emplace_back(offset[g] + entry->column(),
                                             sweep++);
        }
    std::vector<long> row_start(1, 0), columns;
    position.resize(sweep);
    for (auto &row : rows)
      {
        std::sort(row.begin(), row.end());
        for (const auto &[column, index] : row)
          {
            position[index] = columns.size();
            columns.push_back(column);
          }
        row_start.push_back(columns.size());
      }
    if (!over_ranks)
      {
        lu.set_pattern(std::move(row_start), std::move(columns));
        return;
      }
    distributed_lu = std::make_unique<DistributedSparseLU>(what_is_factorized,
                                                           set.get_ranks());
    distributed_lu->set_pattern(n_rows,
                                first_held_row,
                                std::move(row_start),
                                std::move(columns));
  }

  std::vector<double> &
  CoupledTangent::held_values()
  {
    return over_ranks ? distributed_lu->values() : lu.values();
  }

  void
  CoupledTangent::copy_to_lu()
  {
    std::vector<double> &values = held_values();
    unsigned int         sweep  = 0;
    for (const unsigned int h : held)
      for (unsigned int g = 0; g < set.size(); ++g)
        {
          const SparseMatrix<double> &block = matrix.block(h, g);
          for (unsigned int row = 0; row < block.m(); ++row)
            for (auto entry = block.begin(row); entry != block.end(row);
                 ++entry)
              values[position[sweep++]] = entry->value();
        }
  }

  void
  CoupledTangent::reset_to_elastic()
  {
    matrix = 0.;
    set.for_each([&](const unsigned int h) {
      if (!set.owns(h))
        return; // its block row comes from its owner (the class comment)
      const SparseMatrix<double> &elastic = set.problem(h).get_system_matrix();
      SparseMatrix<double>       &block   = matrix.block(h, h);
      for (unsigned int row = 0; row < elastic.m(); ++row)
        for (auto entry = elastic.begin(row); entry != elastic.end(row);
             ++entry)
          block.set(row, entry->column(), entry->value());
    });
  }

  void
  CoupledTangent::add(const unsigned int                          h,
                      const unsigned int                          g,
                      const FullMatrix<double>                   &local,
                      const std::vector<types::global_dof_index> &row_dofs,
                      const std::vector<types::global_dof_index> &column_dofs)
  {
    if (!set.owns(h))
      return; // its block row comes from its owner (the class comment)
    const auto &row_constraints = set.problem(h).get_homogeneous_constraints();
    const auto &column_constraints =
      set.problem(g).get_homogeneous_constraints();
    const std::vector<types::global_dof_index> rows    = distinct(row_dofs),
                                               columns = distinct(column_dofs);
    if (rows.size() == row_dofs.size() && columns.size() == column_dofs.size())
      {
        row_constraints.distribute_local_to_global(
          local, row_dofs, column_constraints, column_dofs, matrix.block(h, g));
        return;
      }
    // Repeated indices: the entries of one DoF summed first (the virtual
    // work of a shared node is that of both faces).
    const std::vector<unsigned int> row_at = positions_among(row_dofs, rows),
                                    column_at =
                                      positions_among(column_dofs, columns);
    FullMatrix<double> merged(rows.size(), columns.size());
    for (unsigned int i = 0; i < row_dofs.size(); ++i)
      for (unsigned int j = 0; j < column_dofs.size(); ++j)
        merged(row_at[i], column_at[j]) += local(i, j);
    row_constraints.distribute_local_to_global(
      merged, rows, column_constraints, columns, matrix.block(h, g));
  }

  void
  CoupledTangent::factorize()
  {
    copy_to_lu();
    ++factorizations;
    if (over_ranks)
      {
        distributed_lu->factorize();
        return;
      }
    // The block rows of every rank's harmonics (zero elsewhere): exact.
    set.sum_over_ranks(lu.values());
    if (set.n_owning_ranks() == 1)
      {
        lu.factorize();
        return;
      }
    // One rank factorizes; a singular matrix stops every rank with its
    // message instead of leaving the others waiting in solve().
    std::string failure;
    if (set.owns(solving_harmonic))
      try
        {
          lu.factorize();
        }
      catch (const std::exception &e)
        {
          failure = one_line_message(e);
        }
    failure = Utilities::MPI::broadcast(set.get_ranks(),
                                        failure,
                                        set.owner(solving_harmonic));
    AssertThrow(failure.empty(), ExcMessage(failure));
  }

  void
  CoupledTangent::vmult(std::vector<Vector<double>>       &y,
                        const std::vector<Vector<double>> &x) const
  {
    BlockVector<double> in(pattern.get_row_indices()),
      out(pattern.get_row_indices());
    for (unsigned int h = 0; h < x.size(); ++h)
      in.block(h) = x[h];
    matrix.vmult(out, in);
    y.resize(x.size());
    for (unsigned int h = 0; h < x.size(); ++h)
      y[h] = out.block(h);
  }

  void
  CoupledTangent::solve(std::vector<Vector<double>> &b_to_x) const
  {
    if (over_ranks)
      solve_over_ranks(b_to_x);
    else
      solve_on_one_rank(b_to_x);
    for (unsigned int h = 0; h < b_to_x.size(); ++h)
      set.problem(h).get_homogeneous_constraints().distribute(b_to_x[h]);
  }

  void
  CoupledTangent::solve_on_one_rank(std::vector<Vector<double>> &b_to_x) const
  {
    std::vector<double> b(n_rows), x(n_rows);
    for (unsigned int h = 0; h < b_to_x.size(); ++h)
      std::copy(b_to_x[h].begin(), b_to_x[h].end(), b.begin() + offset[h]);
    // The factorizing rank solves, the others receive its bits.
    if (set.owns(solving_harmonic))
      lu.solve(b, x);
    set.broadcast_from_owner(solving_harmonic, x.data(), x.size());
    for (unsigned int h = 0; h < b_to_x.size(); ++h)
      std::copy(x.begin() + offset[h],
                x.begin() + offset[h] + b_to_x[h].size(),
                b_to_x[h].begin());
  }

  void
  CoupledTangent::solve_over_ranks(std::vector<Vector<double>> &b_to_x) const
  {
    std::vector<double> b(distributed_lu->n_rows()), x;
    for (const unsigned int h : held)
      std::copy(b_to_x[h].begin(),
                b_to_x[h].end(),
                b.begin() + (offset[h] - first_held_row));
    distributed_lu->solve(b, x);
    for (const unsigned int h : held)
      std::copy(x.begin() + (offset[h] - first_held_row),
                x.begin() + (offset[h] - first_held_row) + b_to_x[h].size(),
                b_to_x[h].begin());
    // Each harmonic's increments from the rank that holds its rows.
    for (unsigned int h = 0; h < b_to_x.size(); ++h)
      set.broadcast_from_owner(h, b_to_x[h].data(), b_to_x[h].size());
  }
} // namespace FourierSSI
