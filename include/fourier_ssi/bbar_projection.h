/**
 * B-bar for FE_Q(2) (Hughes 1980; Volumetric strain = bbar): the dilatation
 * e_r + e_z + e_theta of the strain is replaced by its L2 projection onto
 * the cell's linear polynomials (the pressure space of Q2-P1disc), in the
 * stiffness (every shape function) and in the output stresses (the
 * solution), so both use the strain the equations were solved with. The
 * HarmonicProblem members that build the projections are in
 * source/bbar_projection.cc with these functions.
 */
#ifndef fourier_ssi_bbar_projection_h
#define fourier_ssi_bbar_projection_h

#include <array>
#include <cmath>
#include <deal.II/base/point.h>
#include <fourier_ssi/harmonic_operator.h>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /**
   * One cell's B-bar dilatation (source/bbar_projection.cc):
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
