#include <cmath>
#include <deal.II/base/exceptions.h>
#include <fourier_ssi/coupled/anderson_acceleration.h>

namespace FourierSSI
{
  namespace
  {
    using Blocks = AndersonAcceleration::Blocks;

    double
    dot(const Blocks &a, const Blocks &b)
    {
      double sum = 0.;
      for (unsigned int i = 0; i < a.size(); ++i)
        sum += a[i] * b[i];
      return sum;
    }

    /** a += s b, blockwise. */
    void
    add(Blocks &a, const double s, const Blocks &b)
    {
      for (unsigned int i = 0; i < a.size(); ++i)
        a[i].add(s, b[i]);
    }

    Blocks
    difference(const Blocks &a, const Blocks &b)
    {
      Blocks d = a;
      add(d, -1., b);
      return d;
    }

    /**
     * A column whose part orthogonal to the newer columns is below this
     * fraction of its norm is dropped: the least-squares problem would
     * amplify round-off by the inverse (Walker & Ni's conditioning control).
     */
    constexpr double dependence_threshold = 1e-10;
  } // namespace

  AndersonAcceleration::AndersonAcceleration(const unsigned int depth,
                                             const double       mixing)
    : depth(depth)
    , mixing(mixing)
  {
    AssertThrow(depth >= 1,
                ExcMessage("Load path/Anderson depth: must be at "
                           "least 1"));
  }

  void
  AndersonAcceleration::reset()
  {
    previous_x.clear();
    previous_f.clear();
    dx.clear();
    df.clear();
  }

  std::vector<double>
  AndersonAcceleration::least_squares(const Blocks &f)
  {
    // Modified Gram-Schmidt on the columns, newest first, so that a column
    // dependent on newer ones is the one dropped (the oldest information).
    const unsigned int               m = df.size();
    std::vector<Blocks>              q;
    std::vector<unsigned int>        kept;
    std::vector<std::vector<double>> r; // r[j][i]: R(i, j) for kept i <= j
    for (int c = int(m) - 1; c >= 0; --c)
      {
        Blocks              v     = df[c];
        const double        norm0 = std::sqrt(dot(v, v));
        std::vector<double> column(q.size() + 1, 0.);
        for (unsigned int i = 0; i < q.size(); ++i)
          {
            column[i] = dot(q[i], v);
            add(v, -column[i], q[i]);
          }
        const double norm = std::sqrt(dot(v, v));
        if (norm0 == 0. || norm <= dependence_threshold * norm0)
          continue;
        column.back() = norm;
        for (Vector<double> &block : v)
          block /= norm;
        q.push_back(v);
        r.push_back(column);
        kept.push_back(c);
      }
    // R gamma_kept = Q^T f by back substitution.
    const unsigned int  k = q.size();
    std::vector<double> rhs(k), gamma_kept(k), gamma(m, 0.);
    for (unsigned int i = 0; i < k; ++i)
      rhs[i] = dot(q[i], f);
    for (int i = int(k) - 1; i >= 0; --i)
      {
        double s = rhs[i];
        for (unsigned int j = i + 1; j < k; ++j)
          s -= r[j][i] * gamma_kept[j];
        gamma_kept[i] = s / r[i][i];
      }
    for (unsigned int i = 0; i < k; ++i)
      gamma[kept[i]] = gamma_kept[i];
    return gamma;
  }

  AndersonAcceleration::Blocks
  AndersonAcceleration::increment(const Blocks &x, const Blocks &f)
  {
    // 0. Safeguard: a residual that grew well above the smallest of the
    //    history means the secant model failed (the law switched state at
    //    many points); restart from this iterate with a plain step.
    const double norm = std::sqrt(dot(f, f));
    if (!previous_x.empty() && norm > restart_factor * smallest_norm)
      {
        dx.clear();
        df.clear();
        previous_x.clear();
      }
    smallest_norm =
      dx.empty() && previous_x.empty() ? norm : std::min(smallest_norm, norm);
    // 1. the newest differences enter the history (at most `depth`).
    if (!previous_x.empty())
      {
        dx.push_back(difference(x, previous_x));
        df.push_back(difference(f, previous_f));
        if (dx.size() > depth)
          {
            dx.pop_front();
            df.pop_front();
          }
      }
    previous_x = x;
    previous_f = f;
    // 2. x_{k+1} - x_k = beta f - (dX + beta dF) gamma.
    Blocks step = f;
    for (Vector<double> &block : step)
      block *= mixing;
    if (df.empty())
      return step;
    const std::vector<double> gamma = least_squares(f);
    for (unsigned int c = 0; c < df.size(); ++c)
      if (gamma[c] != 0.)
        {
          add(step, -gamma[c], dx[c]);
          add(step, -mixing * gamma[c], df[c]);
        }
    return step;
  }
} // namespace FourierSSI
