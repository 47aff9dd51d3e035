/**
 * Perfectly plastic soil laws per material id and their closed-form return
 * mapping in principal stresses (doc/soil-plasticity.md, section 2).
 *
 * Stresses are tension positive, in the order of StrainVector
 * (r, z, theta, rz, ztheta, rtheta) with the shear STRESSES (not doubled).
 * Principal stresses s1 >= s2 >= s3. Every yield surface used here is a
 * union of planes in principal space,
 *   Tresca:        f = s1 - s3 - 2 s_u(depth),   s_u = s_u0 + k depth,
 *   Mohr-Coulomb:  f = (s1 - s3) + (s1 + s3) sin phi - 2 c cos phi,
 *   potential      g = (s1 - s3) + (s1 + s3) sin psi,
 * so the return onto one plane, onto the edge where two planes meet
 * (s1 = s2 or s2 = s3) and, for Mohr-Coulomb, onto the apex
 * s1 = s2 = s3 = c cot phi, is a linear system of at most 2 x 2 equations
 * (de Souza Neto, Peric & Owen 2008, Computational Methods for Plasticity,
 * sections 8.2.1 and 8.2.2; checked in doc/derivations/soil_return_mapping.py).
 * The principal directions of the trial stress are kept (isotropy).
 */
#ifndef fourier_ssi_soil_law_h
#define fourier_ssi_soil_law_h

#include <array>
#include <fourier_ssi/fourier/harmonic_operator.h>
#include <fourier_ssi/input/soil_plasticity_parameters.h>

namespace FourierSSI
{
  using namespace dealii;

  /** Which surface the return mapping ended on. */
  enum class SoilState
  {
    elastic,
    plane,
    edge,
    apex
  };

  struct SoilReturn
  {
    /** The admissible stress (tension positive, shear stresses). */
    StrainVector stress = {{0., 0., 0., 0., 0., 0.}};
    SoilState    state  = SoilState::elastic;
  };

  /**
   * A 6 x 6 matrix in the order of StrainVector, row-major: entry (a, b) is
   * d stress_a / d strain_b with engineering shear strains (as
   * hooke_stress).
   */
  using StressTangent = std::array<double, 36>;

  /**
   * The closed-form return mapping of one SoilLaw (the file comment): its
   * yield function, the closest admissible stress and the consistent
   * tangent.
   */
  class SoilReturnMapping
  {
  public:
    explicit SoilReturnMapping(const SoilLaw &law);

    /** f(stress) [kPa]: <= 0 admissible. */
    double
    yield_function(const StrainVector &stress, const double depth) const;

    /**
     * The closest admissible stress (in the energy norm of the elastic law
     * G, K) to the elastic trial stress, at a point at `depth`.
     */
    SoilReturn
    return_map(const StrainVector &trial,
               const double        shear_modulus,
               const double        bulk_modulus,
               const double        depth) const;

    /**
     * The algorithmic (consistent) tangent D_ep = d sigma / d eps of the
     * return mapping at the trial stress sigma_tr(eps) = sigma_fixed +
     * D_e eps (doc/soil-plasticity.md section 3b; derivation in
     * doc/derivations/soil_consistent_tangent.md): the derivative of the
     * returned principal stresses times D_e on the principal axes, and
     * (sigma_i - sigma_j) / (s_i - s_j) G on the shears of the principal
     * frame (the rotation of the principal directions). D_e where the
     * trial is admissible, zero at the apex. Also returns the return.
     */
    SoilReturn
    return_map_with_tangent(const StrainVector &trial,
                            const double        shear_modulus,
                            const double        bulk_modulus,
                            const double        depth,
                            StressTangent      &tangent) const;

  private:
    SoilLaw law;
  };
} // namespace FourierSSI

#endif
