/**
 * The Gauss points of the nonlinear (coulomb) interfaces of a set of
 * harmonics and what a coupled iteration does there
 * (doc/nonlinear-interfaces.md section 5): the relative displacement of
 * fields given per harmonic, summed at the theta samples; the return
 * mapping from a committed plastic state; the out-of-balance load
 *   G_h = int int B_h^T D d_p r ds dtheta
 * of a plastic relative displacement d_p (theta by the trapezoidal rule,
 * s by Gauss p + 1 points through the element's own shape functions); and
 * the tangent's interface part
 *   -int B_h^T [int factor_h (D - D_t) factor_g dtheta] B_g r ds
 * (D_t the tangent of the return mapping). The interface solver
 * (coupled_interface_solver.h) and the plastic-soil solver with coulomb
 * interfaces (coupled_soil_solver.h) both iterate on it.
 */
#ifndef fourier_ssi_nonlinear_interface_points_h
#define fourier_ssi_nonlinear_interface_points_h

#include <array>
#include <deal.II/base/point.h>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/coupled/coupled_tangent.h>
#include <fourier_ssi/fourier/theta_sampling.h>
#include <fourier_ssi/harmonic/harmonic_set.h>
#include <fourier_ssi/input/parameters.h>
#include <fourier_ssi/interfaces/interface_law.h>
#include <fourier_ssi/interfaces/interface_pairing.h>
#include <functional>
#include <string>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /** One Gauss point of a nonlinear interface pair. */
  struct InterfacePoint
  {
    /** Index of the pair (InterfaceIntegrator::get_pairs()). */
    unsigned int pair = 0;
    /** w_q l r(xi_q): area per radian of theta [m^2]. */
    double              area_per_radian = 0.;
    std::vector<double> shape;
    Point<2>            position;
    /** t0 of the Initial stress, local (s, n, theta) [kPa]. */
    LocalVector initial_traction = {{0., 0., 0.}};
    /** Index into the laws. */
    unsigned int law = 0;
  };

  /**
   * The interface at every (point, theta sample) of one converged step,
   * index i * N + j for point i and angle theta_j.
   */
  struct InterfaceSnapshot
  {
    /** Relative displacement d = u_B - u_A, local (s, n, theta) [m]. */
    std::vector<LocalVector> relative;
    /** Traction t (total, initial stress included), (s, n, theta) [kPa]. */
    std::vector<LocalVector>  traction;
    std::vector<ContactState> state;
  };

  /** Counts of (point, theta) samples sticking, slipping, open. */
  using ContactCounts = std::array<unsigned int, 3>;

  class NonlinearInterfacePoints
  {
  public:
    /**
     * The Gauss points of every pair whose boundary id has a coulomb law;
     * one line if there is none. `set` may grow later (harmonics added):
     * every call reads its current harmonics.
     */
    NonlinearInterfacePoints(const HarmonicSet   &set,
                             const AllParameters &parameters);

    const std::vector<InterfacePoint> &
    get_points() const
    {
      return points;
    }

    unsigned int
    size() const
    {
      return points.size();
    }

    /** The pair of point i (in harmonic 0's numbering). */
    const InterfacePair &
    pair_of(const InterfacePoint &point) const;

    /** Some coulomb law has c = 0 and there is no Initial stress. */
    bool
    without_strength() const
    {
      return strengthless;
    }

    /**
     * Relative displacement d = u_B - u_A, local (s, n, theta), at every
     * (point i, sample j), index i * N + j, of fields given per harmonic:
     * the amplitudes of the harmonics this rank owns, summed over the
     * ranks (a collective), then sampled in theta.
     */
    std::vector<LocalVector>
    relative_displacements(const std::vector<Vector<double>> &fields,
                           const ThetaSampling               &sampling) const;

    /**
     * The return mapping at every sample from the committed plastic
     * relative displacements; fills plastic, traction (total, t0
     * included) and state; returns the counts.
     */
    ContactCounts
    return_map(const std::vector<LocalVector> &relative,
               const std::vector<LocalVector> &committed_plastic,
               std::vector<LocalVector>       &plastic,
               std::vector<LocalVector>       &traction,
               std::vector<ContactState>      &state) const;

    /**
     * At every sample, dd_p/dd = I - D^-1 D_t (row-major) of the return
     * from committed_plastic: how the plastic part follows a change of the
     * relative displacement (0 where it sticks, I where it is open), D_t
     * the consistent tangent (interface_law.h). load_of() of the plastic
     * change dd_p is then the exact change of G (Newton).
     */
    std::vector<LocalTangent>
    plastic_tangents(const std::vector<LocalVector> &relative,
                     const std::vector<LocalVector> &committed_plastic) const;

    /**
     * The largest f(t) = tau + t_n tan(phi) - c over the samples given
     * (index i * N + j) [kPa]: <= 0 where every traction is admissible.
     */
    double
    largest_yield_value(const std::vector<LocalVector> &traction) const;

    /**
     * G_h = int int B_h^T D d_p of the plastic samples, every harmonic,
     * with the homogeneous constraints of each harmonic applied
     * (distribute_local_to_global). Points without plastic part cost
     * nothing.
     */
    std::vector<Vector<double>>
    load_of(const std::vector<LocalVector> &plastic,
            const ThetaSampling            &sampling) const;

    /**
     * CSV of the interface state at every (point, theta sample) of every
     * converged step (snapshots[s] of step s + 1): position, angle,
     * stick/slip/open, traction and relative displacement with their units
     * in the header.
     */
    void
    write_state_csv(const std::string                    &filename,
                    const std::vector<InterfaceSnapshot> &snapshots,
                    const ThetaSampling                  &sampling) const;

    /**
     * The DoFs [pair][h] of every pair with a coulomb law: the couplings
     * between harmonics the tangent's interface part adds.
     */
    std::vector<std::vector<std::vector<types::global_dof_index>>>
    pair_dofs() const;

    /**
     * Adds the interface part of the coupled tangent at the relative
     * displacements given (return mapping from committed_plastic) to every
     * block (h, g) of `tangent`; D - D_t with D_t the closed-form
     * consistent tangent of the return mapping (interface_law.h).
     * Returns the number of samples that slip or open.
     */
    unsigned int
    add_softening(const std::vector<LocalVector> &relative,
                  const std::vector<LocalVector> &committed_plastic,
                  const ThetaSampling            &sampling,
                  CoupledTangent                 &tangent) const;

  private:
    /**
     * The return mapping at every (point i, theta sample) k = i N + j from
     * its committed plastic relative displacement, handed to use(k, i, r).
     */
    void
    for_each_return(
      const std::vector<LocalVector>                         &relative,
      const std::vector<LocalVector>                         &committed_plastic,
      const std::function<void(const unsigned int,
                               const unsigned int,
                               const ReturnMappingResult &)> &use) const;
    /** D - D_t at one sample (row-major 3 x 3); false where it sticks. */
    bool
    softening_at(const InterfacePoint  &point,
                 const LocalVector     &relative,
                 const LocalVector     &committed_plastic,
                 std::array<double, 9> &softening) const;

    /**
     * B of harmonic h's pair: row a (s, n, theta) of the relative
     * displacement at point, column i of pair.dof_indices.
     */
    void
    relative_displacement_operator(const InterfacePoint &point,
                                   const InterfacePair  &pair,
                                   FullMatrix<double>   &B) const;

    const HarmonicSet                &set;
    std::vector<MohrCoulombInterface> laws;
    /** (ks, kn, ks) per law [kPa/m]. */
    std::vector<LocalVector>    stiffness;
    std::vector<InterfacePoint> points;
    /** The pairs with a coulomb law (indices into get_pairs()). */
    std::vector<unsigned int> nonlinear_pairs;
    bool                      strengthless = false;
  };
} // namespace FourierSSI

#endif
