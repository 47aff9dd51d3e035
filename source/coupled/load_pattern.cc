#include <cmath>
#include <fourier_ssi/coupled/coupled_iteration.h>
#include <fourier_ssi/coupled/load_path.h>
#include <fourier_ssi/coupled/load_pattern.h>
#include <fourier_ssi/harmonic/rigid_foundation.h>

namespace FourierSSI
{
  namespace
  {
    /** K^-1 b per harmonic: the owner's, a zero vector on the others. */
    std::vector<Vector<double>>
    solutions(const HarmonicSet                        &set,
              std::vector<std::vector<Vector<double>>> &b)
    {
      set.solve_increments(b);
      std::vector<Vector<double>> x;
      for (unsigned int h = 0; h < set.size(); ++h)
        x.push_back(set.owns(h) ? b[h][0] :
                                  Vector<double>(
                                    set.problem(h).get_dof_handler().n_dofs()));
      return x;
    }
  } // namespace

  LoadPattern::LoadPattern(const HarmonicSet &set)
  {
    // |F|^2, |F_held|^2 and F . F_held per harmonic [h * 3 + 0, 1, 2], on
    // its owner.
    std::vector<std::vector<Vector<double>>> b(set.size()), b_held(set.size());
    std::vector<double>                      products(3 * set.size(), 0.);
    for (unsigned int h = 0; h < set.size(); ++h)
      {
        const unsigned int n_dofs = set.problem(h).get_dof_handler().n_dofs();
        load.push_back(set.owns(h) ? load_factor_pattern(set.problem(h)) :
                                     Vector<double>(n_dofs));
        if (!set.owns(h))
          continue;
        Vector<double> held = held_stage_load(set.problem(h));
        products[3 * h]     = load[h].norm_sqr();
        products[3 * h + 1] = held.norm_sqr();
        products[3 * h + 2] = held * load[h];
        b[h]                = {load[h]};
        b_held[h]           = {std::move(held)};
      }
    const std::vector<double> sums = sum_over_harmonics(set, products, 3);
    load_norm                      = std::sqrt(sums[0]);
    held_norm                      = std::sqrt(sums[1]);
    load_held_dot                  = sums[2];
    solution                       = solutions(set, b);
    // No held loads (the same answer on every rank): no held stage.
    if (held_norm != 0.)
      held_solution = solutions(set, b_held);
  }

  double
  LoadPattern::applied_norm(const double load_factor,
                            const double held_fraction) const
  {
    return combined_load_norm(
      load_factor, held_fraction, load_norm, load_held_dot, held_norm);
  }

  Vector<double>
  LoadPattern::total_displacement(const unsigned int    h,
                                  const double          load_factor,
                                  const Vector<double> &correction,
                                  const double          held_fraction,
                                  const double          swipe_force) const
  {
    Vector<double> u =
      FourierSSI::total_displacement(solution[h],
                                     load_factor,
                                     correction,
                                     held_solution.empty() ? nullptr :
                                                             &held_solution[h],
                                     held_fraction);
    if (!swipe_solution.empty())
      u.add(swipe_force, swipe_solution[h]);
    return u;
  }

  void
  LoadPattern::add_swipe_pattern(const HarmonicSet &set)
  {
    std::vector<std::vector<Vector<double>>> b(set.size());
    for (unsigned int h = 0; h < set.size(); ++h)
      {
        const unsigned int n_dofs = set.problem(h).get_dof_handler().n_dofs();
        const RigidFoundation *foundation = set.problem(h).get_foundation();
        const Harmonic        &harmonic   = set.harmonic(h);
        const bool carries_w = set.owns(h) && foundation != nullptr &&
                               harmonic.n == 0 &&
                               harmonic.family == Family::symmetric;
        swipe_load.push_back(carries_w ? foundation->unit_axial_load(n_dofs) :
                                         Vector<double>(n_dofs));
        if (set.owns(h))
          b[h] = {swipe_load[h]};
      }
    swipe_solution = solutions(set, b);
  }
} // namespace FourierSSI
