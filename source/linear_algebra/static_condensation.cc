#include <algorithm>
#include <deal.II/lac/lapack_templates.h>
#include <fourier_ssi/linear_algebra/static_condensation.h>

namespace FourierSSI
{
  std::vector<std::vector<types::global_dof_index>>
  cell_interior_dofs(const DoFHandler<2> &dof_handler)
  {
    const FiniteElement<2> &fe         = dof_handler.get_fe();
    const unsigned int      n_interior = fe.n_dofs_per_quad();
    const unsigned int      first      = fe.get_first_quad_index();
    std::vector<std::vector<types::global_dof_index>> blocks;
    if (n_interior == 0)
      return blocks;
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    blocks.reserve(dof_handler.get_triangulation().n_active_cells());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        blocks.emplace_back(dofs.begin() + first,
                            dofs.begin() + first + n_interior);
      }
    return blocks;
  }

  void
  StaticCondensation::reset(const types::global_dof_index n_dofs)
  {
    kept_index.resize(n_dofs);
    kept_dofs.resize(n_dofs);
    for (types::global_dof_index i = 0; i < n_dofs; ++i)
      {
        kept_index[i] = i;
        kept_dofs[i]  = i;
      }
    eliminated.clear();
    interior.clear();
    coupling.clear();
    factors.clear();
    w.clear();
  }

  std::size_t
  StaticCondensation::n_kept() const
  {
    return kept_dofs.size();
  }

  bool
  StaticCondensation::initialize(
    const SparseMatrix<double>                              &A,
    const std::vector<std::vector<types::global_dof_index>> &blocks,
    UpperMatrix                                             &kept)
  {
    const types::global_dof_index n = A.m();
    reset(n);
    const std::vector<int> block_of = condensed_block_of(A, blocks);
    number_kept_dofs(block_of);
    copy_kept_part(A, kept);
    plan_blocks(A, blocks, block_of);
    if (!eliminate_blocks(A, kept))
      {
        reset(n);
        copy_kept_part(A, kept);
        return false;
      }
    return true;
  }

  std::vector<int>
  StaticCondensation::condensed_block_of(
    const SparseMatrix<double>                              &A,
    const std::vector<std::vector<types::global_dof_index>> &blocks) const
  {
    // A block that shares a DoF with another block, or couples to one,
    // stays whole, and so does the other.
    std::vector<int>  block_of(A.m(), -1);
    std::vector<bool> whole(blocks.size(), false);
    for (unsigned int b = 0; b < blocks.size(); ++b)
      for (const types::global_dof_index i : blocks[b])
        {
          if (block_of[i] >= 0)
            whole[b] = whole[block_of[i]] = true;
          block_of[i] = b;
        }
    for (unsigned int b = 0; b < blocks.size(); ++b)
      for (const types::global_dof_index i : blocks[b])
        for (auto entry = A.begin(i); entry != A.end(i); ++entry)
          {
            const int other = block_of[entry->column()];
            if (other >= 0 && other != static_cast<int>(b))
              whole[b] = whole[other] = true;
          }
    for (int &b : block_of)
      if (b >= 0 && whole[b])
        b = -1;
    return block_of;
  }

  void
  StaticCondensation::number_kept_dofs(const std::vector<int> &block_of)
  {
    kept_dofs.clear();
    for (types::global_dof_index i = 0; i < block_of.size(); ++i)
      if (block_of[i] >= 0)
        kept_index[i] = -1;
      else
        {
          kept_index[i] = kept_dofs.size();
          kept_dofs.push_back(i);
        }
  }

  void
  StaticCondensation::plan_blocks(
    const SparseMatrix<double>                              &A,
    const std::vector<std::vector<types::global_dof_index>> &blocks,
    const std::vector<int>                                  &block_of)
  {
    // Each condensed block's coupling set C (the columns of its rows outside
    // it), then the storage of all L and W at once, sized exactly.
    std::size_t n_factor = 0, n_w = 0;
    for (unsigned int b = 0; b < blocks.size(); ++b)
      if (!blocks[b].empty() && block_of[blocks[b][0]] == static_cast<int>(b))
        {
          Block block;
          block.interior_start = interior.size();
          block.coupling_start = coupling.size();
          block.factor_start   = n_factor;
          block.w_start        = n_w;
          interior.insert(interior.end(), blocks[b].begin(), blocks[b].end());
          for (const types::global_dof_index i : blocks[b])
            for (auto entry = A.begin(i); entry != A.end(i); ++entry)
              if (block_of[entry->column()] != static_cast<int>(b))
                coupling.push_back(entry->column());
          const auto first = coupling.begin() + block.coupling_start;
          std::sort(first, coupling.end());
          coupling.erase(std::unique(first, coupling.end()), coupling.end());
          block.n_interior = blocks[b].size();
          block.n_coupling = coupling.size() - block.coupling_start;
          n_factor += block.n_interior * block.n_interior;
          n_w += block.n_interior * block.n_coupling;
          eliminated.push_back(block);
        }
    factors.resize(n_factor);
    w.resize(n_w);
  }

  bool
  StaticCondensation::eliminate_blocks(const SparseMatrix<double> &A,
                                       UpperMatrix                &kept)
  {
    Workspace work;
    work.local_position.assign(A.m(), -1);
    for (const Block &block : eliminated)
      if (!eliminate_block(A, block, work, kept))
        return false;
    return true;
  }

  void
  StaticCondensation::copy_kept_part(const SparseMatrix<double> &A,
                                     UpperMatrix                &kept) const
  {
    // deal.II stores rows with the diagonal first, then the other columns
    // ascending. The lower triangle of row j (columns i <= j) is column j of
    // the upper triangle (A is symmetric), written with the diagonal last.
    kept.column_start.assign(1, 0);
    kept.row_index.clear();
    kept.value.clear();
    kept.row_index.reserve(A.n_nonzero_elements() / 2 + A.m());
    kept.value.reserve(A.n_nonzero_elements() / 2 + A.m());
    for (const types::global_dof_index j : kept_dofs)
      {
        double diagonal     = 0.;
        bool   has_diagonal = false;
        for (auto entry = A.begin(j); entry != A.end(j); ++entry)
          if (entry->column() < j && kept_index[entry->column()] >= 0)
            {
              kept.row_index.push_back(kept_index[entry->column()]);
              kept.value.push_back(entry->value());
            }
          else if (entry->column() == j)
            {
              diagonal     = entry->value();
              has_diagonal = true;
            }
        if (has_diagonal)
          {
            kept.row_index.push_back(kept_index[j]);
            kept.value.push_back(diagonal);
          }
        kept.column_start.push_back(kept.row_index.size());
      }
  }

  bool
  StaticCondensation::eliminate_block(const SparseMatrix<double> &A,
                                      const Block                &block,
                                      Workspace                  &work,
                                      UpperMatrix                &kept)
  {
    std::vector<int>     &local_position = work.local_position;
    const types::blas_int p = block.n_interior, m = block.n_coupling;
    const auto           *i  = &interior[block.interior_start];
    const auto           *c  = &coupling[block.coupling_start];
    double               *l  = &factors[block.factor_start];
    double               *wb = &w[block.w_start];

    // A_II into l, A_IC into wb, by columns (block first, then C).
    for (types::blas_int a = 0; a < p; ++a)
      local_position[i[a]] = a;
    for (types::blas_int r = 0; r < m; ++r)
      local_position[c[r]] = p + r;
    for (types::blas_int a = 0; a < p; ++a)
      for (auto entry = A.begin(i[a]); entry != A.end(i[a]); ++entry)
        {
          const int k = local_position[entry->column()];
          if (k < p)
            l[a + k * p] = entry->value();
          else
            wb[a + (k - p) * p] = entry->value();
        }
    for (types::blas_int a = 0; a < p; ++a)
      local_position[i[a]] = -1;
    for (types::blas_int r = 0; r < m; ++r)
      local_position[c[r]] = -1;

    // L L^T = A_II, W = L^-1 A_IC, U = W^T W (upper triangle).
    types::blas_int info = 0;
    potrf("L", &p, l, &p, &info);
    if (info != 0)
      return false;
    if (m > 0)
      trtrs("L", "N", "N", &p, &m, l, &p, wb, &p, &info);
    if (info != 0)
      return false;
    std::vector<double> &u = work.update;
    u.resize(m * m);
    const double one = 1., zero = 0.;
    if (m > 0)
      syrk("U", "T", &m, &p, &one, wb, &p, &zero, u.data(), &m);

    // S_CC -= U. C ascending and the kept numbering monotone, so the rows
    // of column c of U are found by one walk down the kept column.
    for (types::blas_int col = 0; col < m; ++col)
      {
        const std::int64_t kc  = kept_index[c[col]];
        std::int64_t       pos = kept.column_start[kc];
        const std::int64_t end = kept.column_start[kc + 1];
        for (types::blas_int row = 0; row <= col; ++row)
          {
            const std::int64_t kr = kept_index[c[row]];
            while (pos < end && kept.row_index[pos] < kr)
              ++pos;
            if (pos == end || kept.row_index[pos] != kr)
              return false; // not in A's sparsity pattern
            kept.value[pos] -= u[row + col * m];
          }
      }
    return true;
  }

  namespace
  {
    /** dense (rows x k, by columns) = the entries `rows` of each x[j]. */
    void
    gather(const std::vector<Vector<double>> &x,
           const types::global_dof_index     *rows,
           const types::blas_int              n_rows,
           std::vector<double>               &dense)
    {
      dense.resize(n_rows * x.size());
      for (std::size_t j = 0; j < x.size(); ++j)
        for (types::blas_int a = 0; a < n_rows; ++a)
          dense[a + j * n_rows] = x[j][rows[a]];
    }

    /** The entries `rows` of each x[j] = (or +=) dense. */
    void
    scatter(const std::vector<double>     &dense,
            const types::global_dof_index *rows,
            const types::blas_int          n_rows,
            const bool                     add,
            std::vector<Vector<double>>   &x)
    {
      for (std::size_t j = 0; j < x.size(); ++j)
        for (types::blas_int a = 0; a < n_rows; ++a)
          x[j][rows[a]] = (add ? x[j][rows[a]] : 0.) + dense[a + j * n_rows];
    }

    /** y := L^-1 y ("N") or L^-T y ("T"), L lower (p x p), k columns. */
    void
    triangular_solve(const char           *transpose,
                     const double         *l,
                     const types::blas_int p,
                     const types::blas_int k,
                     std::vector<double>  &y)
    {
      types::blas_int info = 0;
      trtrs("L", transpose, "N", &p, &k, l, &p, y.data(), &p, &info);
    }
  } // namespace

  void
  StaticCondensation::condense(std::vector<Vector<double>> &b,
                               double                      *kept_rhs) const
  {
    const types::blas_int k = b.size();
    std::vector<double>   y, t;
    for (const Block &block : eliminated)
      {
        const types::blas_int p = block.n_interior, m = block.n_coupling;
        const auto           *i = &interior[block.interior_start];
        const auto           *c = &coupling[block.coupling_start];
        // y = L^-1 b_I, kept in b_I for expand(); b_C -= W^T y.
        gather(b, i, p, y);
        triangular_solve("N", &factors[block.factor_start], p, k, y);
        scatter(y, i, p, false, b);
        if (m == 0)
          continue;
        t.resize(m * k);
        const double minus_one = -1., zero = 0.;
        gemm("T",
             "N",
             &m,
             &k,
             &p,
             &minus_one,
             &w[block.w_start],
             &p,
             y.data(),
             &p,
             &zero,
             t.data(),
             &m);
        scatter(t, c, m, true, b);
      }
    const std::size_t n = kept_dofs.size();
    for (std::size_t j = 0; j < b.size(); ++j)
      for (std::size_t r = 0; r < n; ++r)
        kept_rhs[r + j * n] = b[j][kept_dofs[r]];
  }

  void
  StaticCondensation::expand(const double                *kept_solution,
                             std::vector<Vector<double>> &x) const
  {
    const std::size_t n = kept_dofs.size();
    for (std::size_t j = 0; j < x.size(); ++j)
      for (std::size_t r = 0; r < n; ++r)
        x[j][kept_dofs[r]] = kept_solution[r + j * n];
    const types::blas_int k = x.size();
    std::vector<double>   y, xc;
    for (const Block &block : eliminated)
      {
        const types::blas_int p = block.n_interior, m = block.n_coupling;
        const auto           *i = &interior[block.interior_start];
        const auto           *c = &coupling[block.coupling_start];
        // x_I = L^-T (y - W x_C), y = L^-1 b_I left by condense().
        gather(x, i, p, y);
        if (m > 0)
          {
            gather(x, c, m, xc);
            const double minus_one = -1., one = 1.;
            gemm("N",
                 "N",
                 &p,
                 &k,
                 &m,
                 &minus_one,
                 &w[block.w_start],
                 &p,
                 xc.data(),
                 &m,
                 &one,
                 y.data(),
                 &p);
          }
        triangular_solve("T", &factors[block.factor_start], p, k, y);
        scatter(y, i, p, false, x);
      }
  }
} // namespace FourierSSI
