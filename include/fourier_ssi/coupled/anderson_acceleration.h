/**
 * Anderson acceleration (Anderson 1965; Walker & Ni 2011, "Anderson
 * acceleration for fixed-point iterations", SIAM J. Numer. Anal. 49) of a
 * fixed point x = g(x) whose unknown is split in blocks (one vector per
 * harmonic). With the residual f = g(x) - x and the differences of the last
 * m iterates and residuals,
 *   dX = [x_{k-m+1} - x_{k-m}, ..., x_k - x_{k-1}],   dF likewise,
 * the step is
 *   gamma = argmin |f_k - dF gamma|_2,
 *   x_{k+1} = x_k + beta f_k - (dX + beta dF) gamma,
 * a secant (multisecant quasi-Newton) update that reuses m previous
 * residuals, where Aitken's Delta^2 rule reuses one. The least-squares
 * problem is solved by a QR factorization of dF (modified Gram-Schmidt);
 * columns that are nearly dependent on the newer ones are dropped, oldest
 * first, which keeps the update bounded when the residuals stagnate. A
 * residual that grows above 10 times the smallest since the last restart
 * clears the history (a plain step from there): the secant model no longer
 * describes the map (a nonsmooth law that changed state at many points).
 */
#ifndef fourier_ssi_anderson_acceleration_h
#define fourier_ssi_anderson_acceleration_h

#include <deal.II/lac/vector.h>
#include <deque>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  class AndersonAcceleration
  {
  public:
    /** One vector per block (harmonic). */
    using Blocks = std::vector<Vector<double>>;

    /** depth m >= 1; mixing beta in (0, 1]. */
    AndersonAcceleration(const unsigned int depth, const double mixing = 1.);

    /** Forget the history (a new load step). */
    void
    reset();

    /**
     * The increment x_{k+1} - x_k from the current iterate x_k and its
     * residual f_k = g(x_k) - x_k; the first call after reset() returns
     * beta f_k (a plain fixed-point step).
     */
    Blocks
    increment(const Blocks &x, const Blocks &f);

  private:
    /** gamma = argmin |f - dF gamma| over the kept columns. */
    std::vector<double>
    least_squares(const Blocks &f);

    unsigned int       depth;
    double             mixing;
    Blocks             previous_x, previous_f;
    std::deque<Blocks> dx, df;
    /** Smallest |f| since the last restart. */
    double smallest_norm = 0.;
    /**
     * |f| above this factor times the smallest since the last restart
     * clears the history (the iterate is kept).
     */
    static constexpr double restart_factor = 10.;
  };
} // namespace FourierSSI

#endif
