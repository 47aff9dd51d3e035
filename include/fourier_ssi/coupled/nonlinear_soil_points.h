/**
 * The quadrature points of the plastic soil (Soil plasticity/Laws) of a set
 * of harmonics and what a coupled iteration does there
 * (doc/soil-plasticity.md section 3): the nonlinear source of the soil, as
 * NonlinearInterfacePoints is that of the interfaces. At every
 * (point, theta sample):
 *   - the strain of fields given per harmonic (B-bar where the dilatation
 *     is projected), summed at the theta samples;
 *   - the return mapping from the committed plastic stress
 *     s_p = D eps_p (soil_law.h), or, for the multi-surface clay (iwan),
 *     from the committed plastic strains of its elements, the sample's
 *     hardening history (multi_surface_clay.h), with s_p = D eps -
 *     (sigma - sigma_0) the same correction;
 * and over the soil cells:
 *   - the out-of-balance load G_h = int Bbar_h^T [int factor_h s_p dtheta]
 *     r dr dz;
 *   - the tangent's soil part -int Bbar_h^T [int factor_h (D_e - D_ep)
 *     factor_g dtheta] Bbar_g r dr dz (D_ep the closed-form algorithmic
 *     tangent), added to a CoupledTangent.
 * The coupled load path (coupled_solver.h) iterates on it.
 *
 * Under mpirun the harmonics are distributed over the ranks: strain
 * amplitudes are computed by each harmonic's owner and summed over the
 * ranks; point p is return-mapped by rank p mod P only (owns_point), and
 * its theta integrals and softening reach every rank by a sum in which each
 * entry is non-zero on one rank: exact, the serial run's bits
 * (doc/soil-plasticity.md section 3c).
 */
#ifndef fourier_ssi_nonlinear_soil_points_h
#define fourier_ssi_nonlinear_soil_points_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>
#include <fourier_ssi/coupled/coupled_tangent.h>
#include <fourier_ssi/coupled/multi_surface_clay.h>
#include <fourier_ssi/coupled/multi_surface_sand.h>
#include <fourier_ssi/coupled/soil_law.h>
#include <fourier_ssi/fourier/harmonic_operator.h>
#include <fourier_ssi/fourier/theta_sampling.h>
#include <fourier_ssi/harmonic/bbar_projection.h>
#include <fourier_ssi/harmonic/harmonic_set.h>
#include <fourier_ssi/input/parameters.h>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /**
   * Strain amplitudes of a field given per harmonic, [point][harmonic]:
   * what every (point, theta) strain is sampled from.
   */
  using StrainAmplitudes = std::vector<std::vector<StrainVector>>;

  /**
   * The theta factor of stress and strain component k (order r, z, theta,
   * rz, z theta, r theta): 0..3 that of (u, v), 4, 5 that of w
   * (harmonic_operator.h).
   */
  inline ThetaFactor
  strain_theta_factor(const unsigned int k)
  {
    return k < 4 ? ThetaFactor::in_plane : ThetaFactor::circumferential;
  }

  /** The soil's state over its (point, theta) samples. */
  struct SoilYieldCounts
  {
    /** Samples elastic and plastic. */
    unsigned int n_elastic = 0, n_plastic = 0;
    /** Largest f(sigma) [kPa] (<= 0 admissible). */
    double largest_yield_value = 0.;
  };

  /**
   * One (point, theta) sample of a converged state, as the plastic-field
   * output reads it (plastic_field_recorder.h).
   */
  struct SoilSample
  {
    /** sigma = sigma_0 + D eps - s_p (tension positive, shear stresses). */
    StrainVector stress = {{0., 0., 0., 0., 0., 0.}};
    /**
     * eps_p = D^-1 s_p and its change over the step (engineering shear
     * strains).
     */
    StrainVector plastic_strain           = {{0., 0., 0., 0., 0., 0.}};
    StrainVector plastic_strain_increment = {{0., 0., 0., 0., 0., 0.}};
    /** f(sigma) [kPa], <= 0 admissible. */
    double yield_value = 0.;
    /** The step's return mapping ended on the yield surface. */
    bool plastic = false;
  };

  /** Where a soil point lies and what it weighs, for output. */
  struct SoilPointPlace
  {
    /** (r, z) [m]. */
    Point<2> position;
    /** r JxW: its weight in int ... r dr dz. */
    double dV;
    /** The index of its plastic law (Soil plasticity/Laws, in order). */
    unsigned int law;
  };

  class NonlinearSoilPoints
  {
  public:
    /**
     * The points of every cell whose material id has a plastic law, with
     * the stiffness's own quadrature; `sampling` the theta samples of the
     * soil. One line if no cell has such a law, or if the geostatic stress
     * (Initial stress) lies outside a law.
     */
    NonlinearSoilPoints(const HarmonicSet   &set,
                        const AllParameters &parameters,
                        const ThetaSampling &sampling);

    unsigned int
    size() const
    {
      return points.size();
    }

    unsigned int
    n_theta_samples() const
    {
      return sampling.n_samples();
    }

    /** The soil cells (cells with a plastic law), in mesh order. */
    unsigned int
    n_cells() const
    {
      return cells.size();
    }

    /** The active cell index of soil cell c (DoFHandler order). */
    unsigned int
    active_cell_index(const unsigned int c) const
    {
      return cells[c].active_cell_index;
    }

    /** The points of soil cell c: [first_point(c), first_point(c + 1)). */
    unsigned int
    first_point(const unsigned int c) const
    {
      return c < cells.size() ? cells[c].first_point : points.size();
    }

    /**
     * The length of a hardening history: the element plastic strains of
     * every (iwan point, theta sample), [first of the point + j S + i] for
     * sample j and element i of S; 0 without iwan laws.
     */
    std::size_t
    history_size() const
    {
      return n_history;
    }

    /** Position, weight and law of point p. */
    SoilPointPlace
    place(const unsigned int p) const
    {
      return {points[p].position, points[p].dV, points[p].law};
    }

    /**
     * The samples [point * N + j] of a converged state at the points this
     * rank owns (default values at the others): its strain and s_p, and
     * s_p and the hardening history of the step before (empty: at rest),
     * from which the step's return mapping is repeated to tell plastic from
     * elastic samples (the same count as the step's record).
     */
    std::vector<SoilSample>
    samples_of(const std::vector<StrainVector> &strain,
               const std::vector<StrainVector> &previous_plastic,
               const std::vector<StrainVector> &previous_history,
               const std::vector<StrainVector> &plastic) const;

    /** The strains are B-bar's (the dilatation projected per cell). */
    bool
    projects_dilatation() const
    {
      return !cells.empty() && cells.front().projection != nullptr;
    }

    /**
     * Strain amplitudes of fields (one per harmonic): of the harmonics this
     * rank owns, summed over the ranks (a collective).
     */
    StrainAmplitudes
    strain_amplitudes(const std::vector<Vector<double>> &fields) const;

    /**
     * Total strain [point * N + j] of sum_t factor_t amplitudes_t at the
     * points this rank owns (owns_point; zero at the others): one affine
     * combination, as the solver writes its iterate u = v + lambda u_F +
     * rho u_held (+ mu u_V).
     */
    std::vector<StrainVector>
    strain_samples(
      const std::vector<std::pair<double, const StrainAmplitudes *>> &terms)
      const;

    /**
     * The return mapping at every (point, theta) of the points this rank
     * owns from the committed s_p and hardening history: fills `plastic`
     * (s_p = sigma_0 + D eps - sigma, so that int Bbar^T (sigma - sigma_0)
     * = K u - c) and `history` (the iwan elements' new plastic strains);
     * the counts are this rank's (count_over_ranks: all of them).
     */
    SoilYieldCounts
    return_map(const std::vector<StrainVector> &strain,
               const std::vector<StrainVector> &committed_plastic,
               const std::vector<StrainVector> &committed_history,
               std::vector<StrainVector>       &plastic,
               std::vector<StrainVector>       &history) const;

    /** The counts summed, and the largest f, over the ranks. */
    void
    count_over_ranks(SoilYieldCounts &counts) const;

    /**
     * G_h = int Bbar_h^T (theta integral of samples), every harmonic, the
     * homogeneous constraints applied (or at the DoFs as they are,
     * `condensed` false): the theta integrals at the points this rank owns,
     * summed over the ranks. Points whose samples are all zero cost nothing.
     */
    std::vector<Vector<double>>
    load_of(const std::vector<StrainVector> &samples,
            const bool                       condensed = true) const;

    /**
     * int Bbar_h^T D eps(fields) over the soil, theta by sampling: the soil
     * part of K u, through the same projection as the out-of-balance loads.
     */
    std::vector<Vector<double>>
    elastic_force(const std::vector<Vector<double>> &fields) const;

    /**
     * int Bbar_h^T (D eps - s_p) over the cells whose centre is `selected`,
     * every harmonic, at the DoFs as they are (not condensed): the stress
     * less the geostatic sigma_0 of the state given. Serial runs only.
     */
    std::vector<Vector<double>>
    nodal_force(const std::vector<StrainVector>             &strain,
                const std::vector<StrainVector>             &plastic,
                const std::function<bool(const Point<2> &)> &selected) const;

    /**
     * The DoFs [cell][h] of every soil cell: the couplings between harmonics
     * the tangent's soil part adds.
     */
    std::vector<std::vector<std::vector<types::global_dof_index>>>
    cell_dofs() const;

    /**
     * Adds the soil part of the coupled tangent at the strains given
     * (return mapping from committed_plastic) to the block rows of the
     * harmonics this rank owns:
     *   K_t,hg -= int Bbar_h^T S_hg Bbar_g,
     * S_hg the theta integral of factor_h (D_e - D_ep) factor_g over the
     * samples that yield (harmonic_pair_integral.h).
     */
    void
    add_softening(const std::vector<StrainVector> &strain,
                  const std::vector<StrainVector> &committed_plastic,
                  const std::vector<StrainVector> &committed_history,
                  CoupledTangent                  &tangent) const;

    /**
     * The set grew (HarmonicSet::add): the strain operators and cell DoFs
     * of the harmonics added; `grown` the same angles with the factors of
     * every harmonic. The points, their weights and the state kept at the
     * samples do not depend on the harmonics (nonlinear_soil_points_growth.cc).
     */
    void
    grow(const ThetaSampling &grown);

    /**
     * The theta spectrum of the stress change sigma - sigma_0 = D eps - s_p
     * at the samples of a converged state (`strain`, `plastic`): per
     * harmonic of `candidates` (the same angles), the sum over the points
     * and the six components of dV |a|^2, a the amplitude of that harmonic
     * (ThetaSampling::project with the component's factor); summed over
     * the ranks. The elastic part D eps is band-limited to the harmonics
     * solved, so a harmonic not solved shows only the plastic correction
     * (doc/soil-plasticity.md section 3e).
     */
    std::vector<double>
    stress_spectrum(const std::vector<StrainVector> &strain,
                    const std::vector<StrainVector> &plastic,
                    const ThetaSampling             &candidates) const;

  private:
    /** A soil quadrature point: its weight and elastic constants. */
    struct SoilPoint
    {
      Point<2>     position;
      double       dV, depth, shear_modulus, lambda;
      unsigned int law;
      /** The geostatic stress sigma_0 (Initial stress; zero without). */
      StrainVector initial_stress;
      /**
       * An iwan point: its elements (index into clays); invalid_unsigned_int
       * otherwise.
       */
      unsigned int clay = numbers::invalid_unsigned_int;
      /**
       * A multi-surface point (iwan, iwan-sand): its elements per sample
       * and the first entry of its samples' histories; 0 otherwise.
       */
      unsigned int n_elements    = 0;
      std::size_t  first_history = 0;
    };

    /**
     * The committed state one sample's return mapping starts from: s_p,
     * and the iwan elements' plastic strains (null for other laws).
     */
    struct SampleHistory
    {
      const StrainVector *plastic;
      const StrainVector *elements;
    };

    /** A cell of plastic soil: shape data at its quadrature points. */
    struct SoilCell
    {
      /** Local DoF indices per harmonic. */
      std::vector<std::vector<types::global_dof_index>> dof_indices;
      /** shape_value[q][i], shape_grad[q][i]. */
      std::vector<std::vector<double>>       shape_value;
      std::vector<std::vector<Tensor<1, 2>>> shape_grad;
      std::vector<double>                    radius;
      /** B-bar projection of the cell (null: standard strains). */
      std::shared_ptr<LinearProjection> projection;
      unsigned int                      first_point;
      /**
       * Its active cell index: the DoFs of harmonics added later, the
       * plastic fields' cells.
       */
      unsigned int active_cell_index;
      Point<2>     centre;
    };

    void
    make_points(const AllParameters &parameters);

    /** An iwan law: the point's elements and its place in the history. */
    void
    add_hardening_elements(const SoilLaw &law, SoilPoint &point);

    /** One line if the geostatic stress lies outside a soil law. */
    void
    check_initial_stress(const AllParameters &parameters) const;

    /**
     * sigma_0 + D eps at a point: its stress if it had stayed elastic from
     * the initial (geostatic) state.
     */
    StrainVector
    elastic_stress(const SoilPoint &point, const StrainVector &eps) const;

    /**
     * The return mapping at sample j of a point from its committed state:
     * trial = sigma_0 + D eps - s_p,committed for a perfectly plastic law;
     * sigma_0 plus the elements' stress at eps for an iwan law, their new
     * plastic strains written to `updated` (if not null). With the tangent
     * D_ep if asked.
     */
    SoilReturn
    return_from(const SoilPoint     &point,
                const StrainVector  &strain,
                const SampleHistory &committed,
                StrainVector        *updated,
                StressTangent       *tangent = nullptr) const;

    /** The first history entry of sample j of an iwan point. */
    std::size_t
    history_index(const SoilPoint &point, const unsigned int j) const
    {
      return point.first_history + j * point.n_elements;
    }

    /** The committed state of sample k = p N + j of point p. */
    SampleHistory
    history_of(const unsigned int               p,
               const unsigned int               k,
               const std::vector<StrainVector> &plastic,
               const std::vector<StrainVector> &history) const;

    /**
     * f(sigma) [kPa] at a point, <= 0 admissible: the law's yield function;
     * for iwan sqrt(J2(sigma - sigma_0)) - s_u, the outer surface of its
     * elements about the geostatic stress they start from.
     */
    double
    yield_value(const SoilPoint &point, const StrainVector &stress) const;

    /**
     * D_e - D_ep at one sample (row-major 6 x 6); false where the return
     * is elastic (no softening).
     */
    bool
    softening_at(const SoilPoint        &point,
                 const StrainVector     &strain,
                 const SampleHistory    &committed,
                 std::array<double, 36> &softening) const;

    /**
     * Per point, the theta integrals S_hg of factor_h (D_e - D_ep) factor_g
     * over the samples that yield, [(a * 6 + b) * H^2 + h * H + g] (empty:
     * elastic at every theta), on every rank (softening_over_ranks).
     */
    std::vector<std::vector<double>>
    softening_integrals(const std::vector<StrainVector> &strain,
                        const std::vector<StrainVector> &committed,
                        const std::vector<StrainVector> &history) const;

    /**
     * Under MPI: every point's softening integrals on every rank (each
     * computed by the rank that return-maps the point), exactly; the
     * yielding points only, so the sum stays small while few yield.
     */
    void
    softening_over_ranks(std::vector<std::vector<double>> &softening) const;

    /** The cells with a point that yields. */
    std::vector<unsigned int>
    yielding_cells(const std::vector<std::vector<double>> &softening) const;

    /**
     * Bbar strains of a cell's shape functions, flat: component a of shape
     * function i at quadrature point q is at (i n_q + q) 6 + a.
     */
    using ShapeStrains = std::vector<double>;

    /** Work space of add_cell_softening, kept between its calls. */
    struct SofteningScratch
    {
      std::vector<unsigned int> yielding;
      std::vector<double>       rows, columns, row_sum;
    };

    /** [yielding cell][h]: the shape strains of every harmonic. */
    std::vector<std::vector<ShapeStrains>>
    shape_strains(const std::vector<unsigned int> &yielding) const;

    /**
     * The softening of every yielding cell into the tangent, each block row
     * on its harmonic's thread (as many harmonics as cores, or more).
     */
    void
    add_softening_by_harmonics(
      const std::vector<unsigned int>              &yielding,
      const std::vector<std::vector<double>>       &softening,
      const std::vector<std::vector<ShapeStrains>> &strains,
      CoupledTangent                               &tangent) const;

    /**
     * The same with the cells on the cores (fewer harmonics than cores),
     * the matrices added afterwards on one thread.
     */
    void
    add_softening_by_cells(
      const std::vector<unsigned int>              &yielding,
      const std::vector<std::vector<double>>       &softening,
      const std::vector<std::vector<ShapeStrains>> &strains,
      CoupledTangent                               &tangent) const;

    /** local = -int Bbar_h^T S_hg Bbar_g over one yielding cell. */
    void
    add_cell_softening(const SoilCell                         &cell,
                       const unsigned int                      h,
                       const unsigned int                      g,
                       const std::vector<std::vector<double>> &softening,
                       const ShapeStrains                     &row_strain,
                       const ShapeStrains                     &column_strain,
                       SofteningScratch                       &scratch,
                       FullMatrix<double>                     &local) const;

    /**
     * int Bbar_h^T field dV over one cell (its local vector): `field` is
     * the theta integrals per quadrature point (B-bar applied in place).
     */
    Vector<double>
    cell_load(const SoilCell            &cell,
              const unsigned int         h,
              std::vector<StrainVector> &field) const;

    /**
     * Several ranks: point p is return-mapped by rank p mod P only (the
     * return mapping is most of an iteration, doc/soil-plasticity.md 3c).
     */
    bool
    owns_point(const unsigned int p) const
    {
      return p % point_stride == point_rank;
    }

    const HarmonicSet             &set;
    std::vector<Harmonic>          harmonics;
    std::vector<HarmonicOperator>  operators;
    ThetaSampling                  sampling;
    std::vector<SoilReturnMapping> laws;
    /** The elements of every iwan point (SoilPoint::clay). */
    std::vector<MultiSurfaceClay> clays;
    /**
     * Per law: the elements of an iwan-sand law (the same at every point:
     * G0, K and sigma_0 scale them there); null for the other laws.
     */
    std::vector<std::shared_ptr<const MultiSurfaceSand>> sands;
    /** history_size(). */
    std::size_t            n_history = 0;
    std::vector<SoilCell>  cells;
    std::vector<SoilPoint> points;
    /** The vector component of each local DoF of a cell. */
    std::vector<unsigned int> component;
    /** owns_point(): the ranks and this rank (1, 0: every point). */
    unsigned int point_stride = 1, point_rank = 0;
  };
} // namespace FourierSSI

#endif
