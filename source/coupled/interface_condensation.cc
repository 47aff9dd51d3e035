#include <deal.II/lac/lapack_full_matrix.h>
#include <fourier_ssi/coupled/interface_condensation.h>
#include <set>

namespace FourierSSI
{
  namespace
  {
    /**
     * The whole matrix on every rank from the columns each rank filled
     * (zero elsewhere): one sum over the ranks the harmonics are
     * distributed over, exact since every column comes from one rank.
     */
    void
    sum_columns_over_ranks(const HarmonicSet &set, FullMatrix<double> &matrix)
    {
      if (set.n_owning_ranks() == 1 || matrix.m() == 0)
        return;
      double *const       first = &matrix(0, 0);
      const std::size_t   n     = matrix.m() * matrix.n();
      std::vector<double> entries(first, first + n);
      set.sum_over_ranks(entries);
      std::copy(entries.begin(), entries.end(), first);
    }

    unsigned int
    n_dofs_of(const HarmonicSet &set, const unsigned int h)
    {
      return set.problem(h).get_dof_handler().n_dofs();
    }
  } // namespace

  InterfaceCondensation::InterfaceCondensation(
    const HarmonicSet                                   &set,
    const NonlinearInterfacePoints                      &interface,
    const unsigned int                                   carrier,
    const std::function<double(const Vector<double> &)> &controlled_motion)
    : set(set)
    , interface(interface)
    , carrier(carrier)
    , controlled_motion_of(controlled_motion)
  {
    condense(0);
  }

  void
  InterfaceCondensation::condense(const unsigned int first)
  {
    blocks.resize(set.size());
    // 1. Per harmonic, the DoFs c reaches (write) and the DoFs the relative
    //    displacements read, from the nonlinear pairs.
    std::set<unsigned int> nonlinear_pairs;
    for (const InterfacePoint &point : interface.get_points())
      nonlinear_pairs.insert(point.pair);
    for (unsigned int h = first; h < set.size(); ++h)
      {
        const AffineConstraints<double> &constraints =
          set.problem(h).get_homogeneous_constraints();
        const auto &pairs = set.problem(h).get_interfaces()->get_pairs();
        std::set<types::global_dof_index> write, read;
        for (const unsigned int i : nonlinear_pairs)
          for (const types::global_dof_index d : pairs[i].dof_indices)
            {
              read.insert(d);
              if (!constraints.is_constrained(d))
                write.insert(d);
              else if (const auto *entries =
                         constraints.get_constraint_entries(d))
                for (const auto &entry : *entries)
                  write.insert(entry.first);
            }
        blocks[h].write.assign(write.begin(), write.end());
        blocks[h].read.assign(read.begin(), read.end());
        if (set.owns(h))
          blocks[h].flexibility.reinit(read.size(), write.size());
        blocks[h].controlled_motion.assign(write.size(), 0.);
      }
    // 2. K^-1 e_j for every write DoF j, in batches (memory), every
    //    harmonic this rank owns concurrently with the kept factorizations.
    //    The number of batches is the same on every rank (solve_increments
    //    is collective when the harmonics are distributed).
    std::size_t n_write = 0;
    for (unsigned int h = first; h < set.size(); ++h)
      n_write = std::max(n_write, blocks[h].write.size());
    const unsigned int batch = 64;
    for (unsigned int start = 0; start < n_write; start += batch)
      {
        std::vector<std::vector<Vector<double>>> x(set.size());
        for (unsigned int h = first; h < set.size(); ++h)
          if (set.owns(h))
            for (unsigned int j = start;
                 j <
                 std::min<std::size_t>(start + batch, blocks[h].write.size());
                 ++j)
              {
                x[h].emplace_back(n_dofs_of(set, h));
                x[h].back()(blocks[h].write[j]) = 1.;
              }
        set.solve_increments(x);
        for (unsigned int h = first; h < set.size(); ++h)
          for (unsigned int k = 0; k < x[h].size(); ++k)
            {
              Block &block = blocks[h];
              for (unsigned int i = 0; i < block.read.size(); ++i)
                block.flexibility(i, start + k) = x[h][k](block.read[i]);
              if (h == carrier)
                block.controlled_motion[start + k] =
                  controlled_motion_of(x[h][k]);
            }
      }
    // 3. The controlled motion of every column on every rank (the owner's,
    //    zeros elsewhere: an exact sum): the iteration updates the motion
    //    (and so lambda) redundantly.
    if (carrier >= first && carrier < set.size())
      set.sum_over_ranks(blocks[carrier].controlled_motion);
  }

  std::vector<Vector<double>>
  InterfaceCondensation::on_write_dofs(
    const std::vector<Vector<double>> &full) const
  {
    std::vector<Vector<double>> result(set.size());
    for (unsigned int h = 0; h < set.size(); ++h)
      {
        const Block &block = blocks[h];
        result[h].reinit(block.write.size());
        for (unsigned int j = 0; j < block.write.size(); ++j)
          result[h](j) = full[h](block.write[j]);
      }
    return result;
  }

  void
  InterfaceCondensation::add(const std::vector<Vector<double>> &dc_write,
                             std::vector<Vector<double>>       &correction_load,
                             std::vector<Vector<double>> &correction_solution,
                             double &controlled_motion) const
  {
    for (unsigned int h = 0; h < set.size(); ++h)
      {
        const Block &block = blocks[h];
        if (set.owns(h))
          {
            Vector<double> dv_read(block.read.size());
            block.flexibility.vmult(dv_read, dc_write[h]);
            for (unsigned int i = 0; i < block.read.size(); ++i)
              correction_solution[h](block.read[i]) += dv_read(i);
          }
        for (unsigned int j = 0; j < block.write.size(); ++j)
          {
            correction_load[h](block.write[j]) += dc_write[h](j);
            controlled_motion += block.controlled_motion[j] * dc_write[h](j);
          }
      }
  }

  void
  InterfaceCondensation::complete(
    const std::vector<Vector<double>> &correction_load,
    std::vector<Vector<double>>       &correction_solution) const
  {
    std::vector<std::vector<Vector<double>>> x(set.size());
    for (unsigned int h = 0; h < set.size(); ++h)
      if (set.owns(h))
        x[h] = {correction_load[h]};
    set.solve_increments(x);
    for (unsigned int h = 0; h < set.size(); ++h)
      if (set.owns(h))
        correction_solution[h] = x[h][0];
  }

  FullMatrix<double>
  InterfaceCondensation::out_of_balance_jacobian(
    const std::vector<LocalVector> &relative,
    const std::vector<LocalVector> &origin,
    const ThetaSampling            &sampling,
    const bool                      load_factor_follows,
    const double                    pattern_motion,
    const std::vector<LocalVector> &pattern_relative) const
  {
    const std::vector<LocalTangent> follow =
      interface.plastic_tangents(relative, origin);
    std::vector<unsigned int> offset(set.size() + 1, 0);
    for (unsigned int h = 0; h < set.size(); ++h)
      offset[h + 1] = offset[h] + blocks[h].write.size();
    FullMatrix<double>          jacobian(offset.back(), offset.back());
    std::vector<Vector<double>> unit(set.size());
    for (unsigned int h = 0; h < set.size(); ++h)
      unit[h].reinit(n_dofs_of(set, h));
    std::vector<LocalVector> plastic_change(relative.size());
    for (unsigned int g = 0; g < set.size(); ++g)
      {
        // Only g's owner holds its flexibility block (file comment).
        if (!set.owns(g))
          continue;
        const Block &column = blocks[g];
        for (unsigned int j = 0; j < column.write.size(); ++j)
          {
            // 1. dd of c = e_j at every sample: K^-1 e_j at the read DoFs
            //    (the flexibility column), and lambda's change.
            for (unsigned int i = 0; i < column.read.size(); ++i)
              unit[g](column.read[i]) = column.flexibility(i, j);
            std::vector<LocalVector> change =
              interface.owned_relative_displacements(unit, sampling);
            unit[g] = 0.;
            const double load_factor_change =
              load_factor_follows ?
                -column.controlled_motion[j] / pattern_motion :
                0.;
            // 2. dd_p = (I - D^-1 D_t) dd, and dG = load_of(dd_p).
            for (unsigned int k = 0; k < change.size(); ++k)
              for (unsigned int a = 0; a < 3; ++a)
                {
                  plastic_change[k][a] = 0.;
                  for (unsigned int b = 0; b < 3; ++b)
                    plastic_change[k][a] +=
                      follow[k][a * 3 + b] *
                      (change[k][b] +
                       load_factor_change * pattern_relative[k][b]);
                }
            const std::vector<Vector<double>> load_change =
              on_write_dofs(interface.load_of(plastic_change, sampling));
            for (unsigned int h = 0; h < set.size(); ++h)
              for (unsigned int i = 0; i < load_change[h].size(); ++i)
                jacobian(offset[h] + i, offset[g] + j) = load_change[h](i);
          }
      }
    sum_columns_over_ranks(set, jacobian);
    return jacobian;
  }

  std::vector<Vector<double>>
  InterfaceCondensation::newton_update(
    const std::vector<LocalVector>    &relative,
    const std::vector<LocalVector>    &origin,
    const std::vector<Vector<double>> &residual,
    const ThetaSampling               &sampling,
    const bool                         load_factor_follows,
    const double                       pattern_motion,
    const std::vector<LocalVector>    &pattern_relative) const
  {
    const FullMatrix<double>          dG = out_of_balance_jacobian(relative,
                                                          origin,
                                                          sampling,
                                                          load_factor_follows,
                                                          pattern_motion,
                                                          pattern_relative);
    const unsigned int                n  = dG.m();
    LAPACKFullMatrix<double>          system(n, n);
    Vector<double>                    dc(n);
    const std::vector<Vector<double>> on_write = on_write_dofs(residual);
    for (unsigned int r = 0, h = 0; h < set.size(); ++h)
      for (unsigned int i = 0; i < on_write[h].size(); ++i, ++r)
        dc(r) = on_write[h](i);
    // One rank solves, the others receive its dc (the same bits on every
    // rank whatever the BLAS does; on one rank the broadcast is nothing).
    if (set.owns(0))
      {
        for (unsigned int r = 0; r < n; ++r)
          for (unsigned int c = 0; c < n; ++c)
            system(r, c) = (r == c ? 1. : 0.) - dG(r, c);
        system.compute_lu_factorization();
        system.solve(dc);
      }
    set.broadcast_from_owner(0, dc.begin(), n);
    std::vector<Vector<double>> update(set.size());
    for (unsigned int r = 0, h = 0; h < set.size(); ++h)
      {
        update[h].reinit(blocks[h].write.size());
        for (unsigned int i = 0; i < update[h].size(); ++i, ++r)
          update[h](i) = dc(r);
      }
    return update;
  }
} // namespace FourierSSI
