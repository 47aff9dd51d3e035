/**
 * B-bar for FE_Q(2) (Hughes 1980; Volumetric strain = bbar): the dilatation
 * e_r + e_z + e_theta of the strain is replaced by its L2 projection onto
 * the cell's linear polynomials (the pressure space of Q2-P1disc), in the
 * stiffness (every shape function) and in the output stresses (the
 * solution), so both use the strain the equations were solved with. The
 * HarmonicProblem members that build the projections are in
 * source/harmonic/bbar_projection.cc with these functions.
 */
#ifndef fourier_ssi_bbar_projection_h
#define fourier_ssi_bbar_projection_h

#include <array>
#include <cmath>
#include <deal.II/base/point.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <fourier_ssi/fourier/harmonic_operator.h>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /**
   * One cell's B-bar dilatation (source/harmonic/bbar_projection.cc):
   * c0 + c1 (r - r_c) + c2 (z - z_c) about the cell's centroid.
   */
  struct DilatationProjection
  {
    Point<2>              center;
    std::array<double, 3> coefficients = {{std::nan(""), 0., 0.}};

    bool
    valid() const
    {
      return !std::isnan(coefficients[0]);
    }

    double
    value(const Point<2> &x) const
    {
      return coefficients[0] + coefficients[1] * (x[0] - center[0]) +
             coefficients[2] * (x[1] - center[1]);
    }
  };

  /**
   * The L2(r dr dz) projection of one cell onto the linear polynomials
   * {1, r - r_c, z - z_c} (r_c, z_c: the cell's r-weighted centroid), from
   * the cell's quadrature: the volumetric space of the stable Q2-P1disc
   * mixed element, used by B-bar (the stiffness, the output stresses and
   * the plastic soil's strains, doc/soil-plasticity.md).
   */
  struct LinearProjection
  {
    explicit LinearProjection(const FEValues<2> &fe_values);

    std::array<double, 3>
    basis(const Point<2> &x) const
    {
      const Tensor<1, 2> d = x - center;
      return {{1., d[0], d[1]}};
    }

    /** Coefficients of the projection of f, given at the quadrature points. */
    std::array<double, 3>
    project(const std::vector<double> &f) const;

    /** The projection of f evaluated at the quadrature points. */
    double
    value_at(const std::array<double, 3> &c, const unsigned int q) const
    {
      const auto p = basis(points[q]);
      return c[0] * p[0] + c[1] * p[1] + c[2] * p[2];
    }

    unsigned int          n_q;
    std::vector<double>   dV;
    std::vector<Point<2>> points;
    Point<2>              center;
    FullMatrix<double>    inverse;
    bool                  valid = false;
  };

  /**
   * The strain with its dilatation e_r + e_z + e_t replaced by `dilatation`
   * (the deviatoric part kept): the B-bar strain (Hughes 1980).
   */
  StrainVector
  with_dilatation(const StrainVector &strain, const double dilatation);

  /**
   * The output strain of a cell: `strain` with the cell's projected B-bar
   * dilatation at x, or `strain` unchanged without a projection (empty
   * `dilatation`, or a degenerate cell).
   */
  StrainVector
  bbar_strain(const StrainVector                      &strain,
              const std::vector<DilatationProjection> &dilatation,
              const unsigned int                       cell_index,
              const Point<2>                          &x);

} // namespace FourierSSI

#endif
