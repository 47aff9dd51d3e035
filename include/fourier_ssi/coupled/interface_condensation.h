/**
 * The coupled load path's linearisation for scenes whose only nonlinear
 * source is the interfaces (doc/nonlinear-interfaces.md section 5): the
 * correction load c is non-zero only at the DoFs its assembly reaches
 * ("write": the interface DoFs, or their masters where constrained), and an
 * iteration reads K^-1 c only at the interface DoFs ("read") and in the
 * controlled motion. So the flexibility block F = K^-1 restricted to read x
 * write (one solve per write DoF, once per harmonic, with the kept
 * factorizations) gives the iterate exactly: a dense product per iteration
 * instead of a sparse re-solve, the full K^-1 c solved once per converged
 * step (complete()).
 *
 * Newton (Load path/Stiffness = tangent, section 5b) works on c at the
 * write DoFs: R(c) = G(c) - c,
 *   dG/dc = load_of( (I - D_K^-1 D_t) dd/dc ),  dd/dc = B F (+ dlambda/dc d_F),
 * D_K the springs assembled into K, D_t the closed-form consistent tangent of
 * the return mapping, and under displacement control dlambda/dc =
 * -m(K^-1 e_j) / m(u_F) (lambda keeps the controlled motion on its target).
 * The update solves (I - dG/dc) dc = R, dense (tens to a few thousand
 * unknowns).
 *
 * Under MPI harmonic g's flexibility block lives on its owner only: each rank
 * fills the columns of dG/dc of its harmonics, one exact sum over the ranks
 * completes the matrix (each column non-zero on one rank), and the owner of
 * the first harmonic solves and broadcasts dc, so every rank takes the same
 * step.
 */
#ifndef fourier_ssi_interface_condensation_h
#define fourier_ssi_interface_condensation_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/coupled/nonlinear_interface_points.h>
#include <fourier_ssi/fourier/theta_sampling.h>
#include <fourier_ssi/harmonic/harmonic_set.h>
#include <functional>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  class InterfaceCondensation
  {
  public:
    /**
     * `controlled_motion` is the controlled motion of a field of harmonic
     * `carrier` (displacement control; carrier >= set.size() without).
     */
    InterfaceCondensation(
      const HarmonicSet                                   &set,
      const NonlinearInterfacePoints                      &interface,
      const unsigned int                                   carrier,
      const std::function<double(const Vector<double> &)> &controlled_motion);

    /**
     * The blocks of harmonics first, first + 1, ... of the set (all at
     * construction; the added ones after the set grew).
     */
    void
    condense(const unsigned int first);

    /** The entries of (condensed) loads at the write DoFs, per harmonic. */
    std::vector<Vector<double>>
    on_write_dofs(const std::vector<Vector<double>> &full) const;

    /**
     * c += dc (given at the write DoFs) in `correction_load`, and K^-1 dc
     * added to `correction_solution` at the read DoFs (the owner's) and to
     * `controlled_motion`: the iterate's view, exact where it is read.
     */
    void
    add(const std::vector<Vector<double>> &dc_write,
        std::vector<Vector<double>>       &correction_load,
        std::vector<Vector<double>>       &correction_solution,
        double                            &controlled_motion) const;

    /**
     * The whole K^-1 c of `correction_load` (one solve per harmonic) into
     * `correction_solution`: a converged step's, the next step's view
     * restarting from the exact field (no round-off carried over steps).
     */
    void
    complete(const std::vector<Vector<double>> &correction_load,
             std::vector<Vector<double>>       &correction_solution) const;

    /**
     * The Newton update dc of (I - dG/dc) dc = R at an iterate with
     * relative displacements `relative` (origin the return's), split per
     * harmonic at its write DoFs. `load_factor_follows`: lambda keeps the
     * controlled motion (by the pattern `pattern_motion`, its relative
     * displacement `pattern_relative`).
     */
    std::vector<Vector<double>>
    newton_update(const std::vector<LocalVector>    &relative,
                  const std::vector<LocalVector>    &origin,
                  const std::vector<Vector<double>> &residual,
                  const ThetaSampling               &sampling,
                  const bool                         load_factor_follows,
                  const double                       pattern_motion,
                  const std::vector<LocalVector>    &pattern_relative) const;

  private:
    /** One harmonic's block. */
    struct Block
    {
      std::vector<types::global_dof_index> write, read;
      /** F(i, j) = (K^-1 e_write[j])(read[i]); on the owner only. */
      FullMatrix<double> flexibility;
      /** Controlled motion of K^-1 e_write[j] (0 if not its harmonic). */
      std::vector<double> controlled_motion;
    };

    /** dG/dc on the write DoFs of every harmonic, dense (column (h, j)). */
    FullMatrix<double>
    out_of_balance_jacobian(
      const std::vector<LocalVector> &relative,
      const std::vector<LocalVector> &origin,
      const ThetaSampling            &sampling,
      const bool                      load_factor_follows,
      const double                    pattern_motion,
      const std::vector<LocalVector> &pattern_relative) const;

    const HarmonicSet                                  &set;
    const NonlinearInterfacePoints                     &interface;
    const unsigned int                                  carrier;
    const std::function<double(const Vector<double> &)> controlled_motion_of;
    std::vector<Block>                                  blocks;
  };
} // namespace FourierSSI

#endif
