// AndersonAcceleration (include/fourier_ssi/coupled/anderson_acceleration.h) on
// an affine fixed point x = A x + b split in two blocks, against properties
// that hold independently of the implementation:
//  * on an affine map, Anderson with depth m >= n (the dimension) and
//    beta = 1 is equivalent to GMRES on (I - A) x = b (Walker & Ni 2011,
//    Theorem 2.2), so it reaches the exact fixed point x* = (I - A)^-1 b
//    after at most n + 1 residuals; checked: |x - x*| <= 1e-10 |x*| after
//    n + 2 updates (round-off of a 6 x 6 solve with condition < 1e3);
//  * plain iteration (the first update, and m unused) contracts only by
//    the spectral radius of A (here 0.95), so it is still far after as many
//    steps: |x - x*| > 0.1 |x*| (it must be, else the map is too easy to
//    show anything);
//  * the first update after reset() is beta f exactly.
#include "check.h"

#include <deal.II/lac/full_matrix.h>
#include <fourier_ssi/coupled/anderson_acceleration.h>
#include <random>

using namespace FourierSSI;

namespace
{
  using Blocks = AndersonAcceleration::Blocks;

  constexpr unsigned int n = 6;

  /** A with eigenvalues 0.95, -0.9, 0.5, ... in a random orthogonal basis. */
  FullMatrix<double>
  contraction()
  {
    std::mt19937                           random(7);
    std::uniform_real_distribution<double> u(-1., 1.);
    FullMatrix<double>                     q(n, n), d(n, n), a(n, n), t(n, n);
    // Gram-Schmidt on random columns: an orthogonal Q.
    for (unsigned int j = 0; j < n; ++j)
      {
        std::vector<double> v(n);
        for (double &x : v)
          x = u(random);
        for (unsigned int k = 0; k < j; ++k)
          {
            double s = 0.;
            for (unsigned int i = 0; i < n; ++i)
              s += q(i, k) * v[i];
            for (unsigned int i = 0; i < n; ++i)
              v[i] -= s * q(i, k);
          }
        double norm = 0.;
        for (const double x : v)
          norm += x * x;
        for (unsigned int i = 0; i < n; ++i)
          q(i, j) = v[i] / std::sqrt(norm);
      }
    const double eigenvalues[n] = {0.95, -0.9, 0.5, 0.3, -0.2, 0.1};
    for (unsigned int i = 0; i < n; ++i)
      d(i, i) = eigenvalues[i];
    q.mmult(t, d);
    t.mTmult(a, q);
    return a;
  }

  Blocks
  split(const Vector<double> &x)
  {
    Blocks b = {Vector<double>(2), Vector<double>(n - 2)};
    for (unsigned int i = 0; i < n; ++i)
      (i < 2 ? b[0](i) : b[1](i - 2)) = x(i);
    return b;
  }

  Vector<double>
  join(const Blocks &b)
  {
    Vector<double> x(n);
    for (unsigned int i = 0; i < n; ++i)
      x(i) = i < 2 ? b[0](i) : b[1](i - 2);
    return x;
  }

  /** |x_k - x*| / |x*| after `updates` updates from x = 0. */
  double
  error_after(const unsigned int depth,
              const unsigned int updates,
              const bool         accelerate)
  {
    const FullMatrix<double> a = contraction();
    Vector<double>           b(n), x(n), ax(n), exact(n);
    for (unsigned int i = 0; i < n; ++i)
      b(i) = 1. + i;
    // x* = (I - A)^-1 b.
    FullMatrix<double> i_minus_a{IdentityMatrix(n)};
    i_minus_a.add(-1., a);
    i_minus_a.gauss_jordan();
    i_minus_a.vmult(exact, b);
    AndersonAcceleration anderson(depth);
    for (unsigned int k = 0; k < updates; ++k)
      {
        a.vmult(ax, x);
        Vector<double> f = ax;
        f += b;
        f -= x;
        if (accelerate)
          x += join(anderson.increment(split(x), split(f)));
        else
          x += f;
      }
    x -= exact;
    return x.l2_norm() / exact.l2_norm();
  }
} // namespace

int
main()
{
  const double accelerated = error_after(n, n + 2, true);
  const double plain       = error_after(n, n + 2, false);
  std::cout << "  after " << n + 2 << " updates: Anderson m = " << n << " "
            << accelerated << ", plain " << plain << std::endl;
  check::small("Anderson m = n on an affine map: exact after n + 2 updates",
               accelerated,
               1e-10);
  check::in_range("plain iteration still far (the map is not trivial)",
                  plain,
                  0.1,
                  10.);

  AndersonAcceleration anderson(3, 0.5);
  const Blocks         x = {Vector<double>(2), Vector<double>(1)};
  Blocks               f = x;
  f[0](0)                = 2.;
  f[1](0)                = -4.;
  const Blocks step      = anderson.increment(x, f);
  check::small("first update is beta f", step[0](0) - 1., 1e-15);
  check::small("first update is beta f (second block)", step[1](0) + 2., 1e-15);
  return check::summary();
}
