/**
 * Stress amplitudes (sigma_r, sigma_z, sigma_theta, tau_rz, tau_ztheta,
 * tau_rtheta) of one harmonic, sigma = D B u (thesis eq. 3.3 with Hooke's
 * law), evaluated at the output points of each cell: the "nodal" values of
 * the VTU output. They carry the trig factors of their strains (doc/theory.md).
 */
#ifndef fourier_ssi_stress_postprocessor_h
#define fourier_ssi_stress_postprocessor_h

#include <array>
#include <cmath>
#include <deal.II/base/point.h>
#include <deal.II/numerics/data_postprocessor.h>
#include <fourier_ssi/fourier/harmonic_operator.h>
#include <fourier_ssi/harmonic/bbar_projection.h>
#include <fourier_ssi/input/material.h>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /** sigma = D epsilon for an isotropic material (engineering shears). */
  StrainVector
  hooke_stress(const StrainVector &strain,
               const double        lambda,
               const double        mu);

  /**
   * epsilon = D^-1 sigma, the inverse of hooke_stress: tr eps = tr sigma /
   * (3 lambda + 2 mu), eps_k = (sigma_k - lambda tr eps) / (2 mu), the
   * engineering shears tau / mu.
   */
  StrainVector
  compliance_strain(const StrainVector &stress,
                    const double        lambda,
                    const double        mu);

  class StressPostprocessor : public DataPostprocessor<2>
  {
  public:
    /**
     * `dilatation`: per active cell, the B-bar dilatation of the solution
     * (empty: the strains of the displacement field as they are).
     */
    StressPostprocessor(
      const HarmonicOperator                  &harmonic_operator,
      const MaterialLibrary                   &materials,
      const std::vector<DilatationProjection> &dilatation = {});

    void
    evaluate_vector_field(
      const DataPostprocessorInputs::Vector<2> &inputs,
      std::vector<Vector<double>> &computed_quantities) const override;

    std::vector<std::string>
    get_names() const override;

    UpdateFlags
    get_needed_update_flags() const override;

  private:
    const HarmonicOperator                  &harmonic_operator;
    const MaterialLibrary                   &materials;
    const std::vector<DilatationProjection> &dilatation;
  };
} // namespace FourierSSI

#endif
