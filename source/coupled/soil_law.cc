#include <cmath>
#include <deal.II/base/symmetric_tensor.h>
#include <fourier_ssi/coupled/soil_law.h>
#include <optional>

namespace FourierSSI
{
  namespace
  {
    using Principal = std::array<double, 3>;

    /** (r, z, theta) tensor of a stress vector (shear stresses, not doubled).
     */
    SymmetricTensor<2, 3>
    to_tensor(const StrainVector &s)
    {
      SymmetricTensor<2, 3> t;
      t[0][0] = s[StrainIndex::rr];
      t[1][1] = s[StrainIndex::zz];
      t[2][2] = s[StrainIndex::tt];
      t[0][1] = s[StrainIndex::rz];
      t[1][2] = s[StrainIndex::zt];
      t[0][2] = s[StrainIndex::rt];
      return t;
    }

    /** Principal values (s1 >= s2 >= s3) and their directions. */
    using Principals = std::array<std::pair<double, Tensor<1, 3>>, 3>;

    /**
     * Jacobi: eigenvalues to round-off (the closed-form cubic of
     * eigenvalues() loses about 1e-9 relative).
     */
    Principals
    principals_of(const StrainVector &stress)
    {
      return eigenvectors(to_tensor(stress),
                          SymmetricTensorEigenvectorMethod::jacobi);
    }

    /** The yield function from s1 and s3 (tension positive). */
    double
    yield_of_principals(const SoilLaw &law,
                        const double   s1,
                        const double   s3,
                        const double   depth)
    {
      if (law.kind == SoilLaw::Kind::tresca)
        return s1 - s3 - 2. * law.undrained_strength(depth);
      return (s1 - s3) + (s1 + s3) * std::sin(law.friction) -
             2. * law.cohesion * std::cos(law.friction);
    }

    /**
     * Elastic without the eigenvalues: with the deviator's norm |d| (shears
     * counted twice), s1 - s3 <= sqrt(2) |d| and the middle deviatoric
     * value is at most |d| / sqrt(6), so s1 + s3 = 3 p - s2 <= 2 p + |d| /
     * sqrt(6); the yield function is at most the bound with these, and a
     * bound below zero (with a margin of 1e-12 for its own rounding) is a
     * stress the eigenvalues would find elastic too. Most samples of a
     * plastic run are elastic; this spares them the Jacobi sweeps.
     */
    bool
    certainly_elastic(const SoilLaw      &law,
                      const StrainVector &stress,
                      const double        depth)
    {
      const double mean = (stress[StrainIndex::rr] + stress[StrainIndex::zz] +
                           stress[StrainIndex::tt]) /
                          3.;
      double deviator = 0.;
      for (const unsigned int c :
           {StrainIndex::rr, StrainIndex::zz, StrainIndex::tt})
        deviator += (stress[c] - mean) * (stress[c] - mean);
      for (const unsigned int c :
           {StrainIndex::rz, StrainIndex::zt, StrainIndex::rt})
        deviator += 2. * stress[c] * stress[c];
      deviator               = std::sqrt(deviator);
      const double spread    = std::sqrt(2.) * deviator;
      const double outer_sum = 2. * mean + deviator / std::sqrt(6.);
      const double margin    = 1e-12 * (spread + std::abs(outer_sum));
      // The yield function of an s1, s3 with these difference and sum.
      return yield_of_principals(law,
                                 (outer_sum + spread) / 2.,
                                 (outer_sum - spread) / 2.,
                                 depth) +
               margin <
             0.;
    }

    /**
     * One plane of the yield surface in principal space, f = n . s - k, with
     * the gradient m of its plastic potential.
     */
    struct Plane
    {
      Principal n, m;
      double    k;
    };

    double
    dot(const Principal &a, const Principal &b)
    {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    /** D m with the principal elastic matrix (K - 2G/3) 1 1^T + 2 G I. */
    Principal
    elastic_times(const Principal &m, const double G, const double K)
    {
      const double volumetric = (K - 2. * G / 3.) * (m[0] + m[1] + m[2]);
      return {{volumetric + 2. * G * m[0],
               volumetric + 2. * G * m[1],
               volumetric + 2. * G * m[2]}};
    }

    /** d returned_i / d trial_j in principal space (row-major 3 x 3). */
    using PrincipalJacobian = std::array<Principal, 3>;

    /**
     * Return onto the planes given (one or two): s = s_tr - sum_a dgamma_a
     * D m_a with f_b(s) = 0 for every plane b, a linear system
     * sum_a (n_b . D m_a) dgamma_a = f_b(s_tr). Returns false if a
     * multiplier is negative (the trial is not in this return's region).
     * The system is linear in s_tr, so its derivative is
     * d s / d s_tr = I - sum_ab D m_a (A^-1)_ab n_b^T
     * (de Souza Neto et al. 2008, eq. 8.60 and box 8.4 in principal form).
     */
    bool
    return_to_planes(const Principal          &trial,
                     const std::vector<Plane> &planes,
                     const double              G,
                     const double              K,
                     Principal                &result,
                     PrincipalJacobian        &jacobian)
    {
      const unsigned int     n_planes = planes.size();
      std::vector<Principal> Dm(n_planes);
      double                 A[2][2], f[2], dgamma[2], inverse[2][2];
      for (unsigned int a = 0; a < n_planes; ++a)
        Dm[a] = elastic_times(planes[a].m, G, K);
      for (unsigned int b = 0; b < n_planes; ++b)
        {
          f[b] = dot(planes[b].n, trial) - planes[b].k;
          for (unsigned int a = 0; a < n_planes; ++a)
            A[b][a] = dot(planes[b].n, Dm[a]);
        }
      if (n_planes == 1)
        inverse[0][0] = 1. / A[0][0];
      else
        {
          const double det = A[0][0] * A[1][1] - A[0][1] * A[1][0];
          inverse[0][0]    = A[1][1] / det;
          inverse[0][1]    = -A[0][1] / det;
          inverse[1][0]    = -A[1][0] / det;
          inverse[1][1]    = A[0][0] / det;
        }
      // The multipliers as divisions by det (not by the inverse): the
      // returned stresses to the bit of the return without its tangent.
      if (n_planes == 1)
        dgamma[0] = f[0] / A[0][0];
      else
        {
          const double det = A[0][0] * A[1][1] - A[0][1] * A[1][0];
          dgamma[0]        = (A[1][1] * f[0] - A[0][1] * f[1]) / det;
          dgamma[1]        = (A[0][0] * f[1] - A[1][0] * f[0]) / det;
        }
      result = trial;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          jacobian[i][j] = i == j ? 1. : 0.;
      for (unsigned int a = 0; a < n_planes; ++a)
        {
          if (dgamma[a] < 0.)
            return false;
          for (unsigned int i = 0; i < 3; ++i)
            {
              result[i] -= dgamma[a] * Dm[a][i];
              for (unsigned int b = 0; b < n_planes; ++b)
                for (unsigned int j = 0; j < 3; ++j)
                  jacobian[i][j] -= Dm[a][i] * inverse[a][b] * planes[b].n[j];
            }
        }
      return true;
    }

    /**
     * s1 >= s2 >= s3 up to the round-off of a return from `trial` (the
     * returned stresses are differences of trial-sized numbers).
     */
    bool
    ordered(const Principal &s, const Principal &trial)
    {
      const double slack =
        1e-12 * (std::abs(trial[0]) + std::abs(trial[1]) + std::abs(trial[2]));
      return s[0] + slack >= s[1] && s[1] + slack >= s[2];
    }

    /**
     * The return of a yielding trial in its principal frame: the trial's
     * principal stresses s1 >= s2 >= s3 and directions, the returned
     * principal stresses and their derivative by the trial's.
     */
    struct PrincipalReturn
    {
      Principal                   trial, stress;
      std::array<Tensor<1, 3>, 3> directions;
      PrincipalJacobian           jacobian;
      SoilState                   state = SoilState::plane;
    };

    /**
     * Plane, edge or apex (doc/soil-plasticity.md section 2): the main
     * plane first; an edge if that return left the order s1 >= s2 >= s3;
     * the apex (Mohr-Coulomb) if the edge return is not admissible either.
     * Tresca is Mohr-Coulomb with phi = psi = 0 and 2 c cos phi = 2 s_u.
     */
    PrincipalReturn
    principal_return(const Principals &eigen,
                     const double      sin_friction,
                     const double      sin_dilation,
                     const double      strength,
                     const double      apex,
                     const bool        has_apex,
                     const double      G,
                     const double      K)
    {
      PrincipalReturn r;
      for (unsigned int i = 0; i < 3; ++i)
        {
          r.trial[i]      = eigen[i].first;
          r.directions[i] = eigen[i].second;
        }
      const double sf = sin_friction, sp = sin_dilation, k = strength;
      const Plane  main{{{1. + sf, 0., -(1. - sf)}},
                       {{1. + sp, 0., -(1. - sp)}},
                       k};
      // s1 = s2 (right edge): the plane of (s2, s3); s2 = s3 (left edge):
      // the plane of (s1, s2).
      const Plane right{{{0., 1. + sf, -(1. - sf)}},
                        {{0., 1. + sp, -(1. - sp)}},
                        k};
      const Plane left{{{1. + sf, -(1. - sf), 0.}},
                       {{1. + sp, -(1. - sp), 0.}},
                       k};
      if (return_to_planes(r.trial, {main}, G, K, r.stress, r.jacobian) &&
          ordered(r.stress, r.trial))
        return r;
      // The main-plane return crossed an edge: s2 overtook s1 (right
      // edge, s1 = s2) or fell below s3 (left edge, s2 = s3); on Tresca's
      // right edge dgamma_2 > 0 iff s2' > s1' [soil_return_mapping.py 3].
      const bool   to_right = r.stress[1] > r.stress[0];
      const Plane &second   = to_right ? right : left;
      r.state               = SoilState::edge;
      if (return_to_planes(
            r.trial, {main, second}, G, K, r.stress, r.jacobian) &&
          ordered(r.stress, r.trial))
        return r;
      // Only Mohr-Coulomb has an apex: the hydrostatic stress c cot phi
      // where all planes meet, the same for every trial near it (a zero
      // derivative: perfect plasticity).
      AssertThrow(has_apex,
                  ExcMessage("Tresca return mapping: no admissible "
                             "edge return (internal error)"));
      r.state  = SoilState::apex;
      r.stress = {{apex, apex, apex}};
      for (Principal &row : r.jacobian)
        row = {{0., 0., 0.}};
      return r;
    }

    /**
     * sym(a b^T) as a stress vector (shears not doubled): also the
     * component a . eps b of a strain given as a vector with engineering
     * shears, eps : sym(a b^T) = w . eps_vector.
     */
    StrainVector
    symmetric_product(const Tensor<1, 3> &a, const Tensor<1, 3> &b)
    {
      return {{a[0] * b[0],
               a[1] * b[1],
               a[2] * b[2],
               0.5 * (a[0] * b[1] + a[1] * b[0]),
               0.5 * (a[1] * b[2] + a[2] * b[1]),
               0.5 * (a[0] * b[2] + a[2] * b[0])}};
    }

    /** sum_i stress_i e_i e_i^T in (r, z, theta) as a stress vector. */
    StrainVector
    from_principal(const PrincipalReturn &r)
    {
      StrainVector stress{};
      for (unsigned int i = 0; i < 3; ++i)
        {
          const StrainVector w =
            symmetric_product(r.directions[i], r.directions[i]);
          for (unsigned int a = 0; a < 6; ++a)
            stress[a] += r.stress[i] * w[a];
        }
      return stress;
    }

    /**
     * The spin factor of the principal pair (i, j): d sigma'_ij / d
     * sigma_tr'_ij = (sigma_i - sigma_j) / (s_i - s_j) in the principal
     * frame (the derivative of the eigenprojections, de Souza Neto et al.
     * 2008, appendix A.5); for coinciding trial values its limit, the
     * derivative of sigma_i - sigma_j along s_i - s_j.
     */
    double
    spin_factor(const PrincipalReturn &r,
                const unsigned int     i,
                const unsigned int     j)
    {
      const double scale =
        std::abs(r.trial[0]) + std::abs(r.trial[1]) + std::abs(r.trial[2]);
      const double gap = r.trial[i] - r.trial[j];
      if (std::abs(gap) > 1e-10 * scale)
        return (r.stress[i] - r.stress[j]) / gap;
      const PrincipalJacobian &J = r.jacobian;
      return 0.5 * (J[i][i] - J[i][j] - J[j][i] + J[j][j]);
    }

    /** tangent += factor u v^T (6 x 6, row-major). */
    void
    add_outer(const double        factor,
              const StrainVector &u,
              const StrainVector &v,
              StressTangent      &tangent)
    {
      for (unsigned int a = 0; a < 6; ++a)
        for (unsigned int l = 0; l < 6; ++l)
          tangent[a * 6 + l] += factor * u[a] * v[l];
    }

    /**
     * D_ep = d sigma / d eps in the principal frame's projections w_ij =
     * sym(e_i e_j^T): a strain's principal-frame component is w_ij . eps,
     * the trial's normal change D_e eps' is 2 G w_mm . eps + lambda tr eps,
     * the principal Jacobian J maps it to the returned normal stresses and
     * the spin factors scale the shears, so
     *   D_ep = sum_i w_ii (sum_m J_im (2 G w_mm + lambda 1))^T
     *        + sum_{i < j} 4 G spin_ij w_ij w_ij^T
     * (each pair i != j counted for (i, j) and (j, i); the derivation in
     * doc/derivations/soil_consistent_tangent.md).
     */
    void
    tangent_of(const PrincipalReturn &r,
               const double           G,
               const double           K,
               StressTangent         &tangent)
    {
      const double lambda = K - 2. * G / 3.;
      tangent.fill(0.);
      std::array<StrainVector, 3> normal;
      for (unsigned int i = 0; i < 3; ++i)
        normal[i] = symmetric_product(r.directions[i], r.directions[i]);
      for (unsigned int i = 0; i < 3; ++i)
        {
          StrainVector change{};
          for (unsigned int m = 0; m < 3; ++m)
            for (unsigned int l = 0; l < 6; ++l)
              change[l] += r.jacobian[i][m] *
                           (2. * G * normal[m][l] + (l < 3 ? lambda : 0.));
          add_outer(1., normal[i], change, tangent);
        }
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = i + 1; j < 3; ++j)
          {
            const StrainVector w =
              symmetric_product(r.directions[i], r.directions[j]);
            add_outer(4. * G * spin_factor(r, i, j), w, w, tangent);
          }
    }

    /** D_e in the order of StrainVector (engineering shears). */
    void
    elastic_tangent(const double G, const double K, StressTangent &tangent)
    {
      const double lambda = K - 2. * G / 3.;
      tangent.fill(0.);
      for (unsigned int a = 0; a < 3; ++a)
        {
          for (unsigned int b = 0; b < 3; ++b)
            tangent[a * 6 + b] = lambda;
          tangent[a * 6 + a] += 2. * G;
          tangent[(a + 3) * 6 + a + 3] = G;
        }
    }
  } // namespace

  SoilReturnMapping::SoilReturnMapping(const SoilLaw &law)
    : law(law)
  {}

  double
  SoilReturnMapping::yield_function(const StrainVector &stress,
                                    const double        depth) const
  {
    const Principals eigen = principals_of(stress);
    return yield_of_principals(law, eigen[0].first, eigen[2].first, depth);
  }

  namespace
  {
    /**
     * The principal decomposition of a trial that yields; none for an
     * elastic one (the deviator's bound first, then the eigenvalues).
     */
    std::optional<Principals>
    yielding_principals(const SoilLaw      &law,
                        const StrainVector &trial,
                        const double        depth)
    {
      if (certainly_elastic(law, trial, depth))
        return std::nullopt;
      Principals eigen = principals_of(trial);
      if (yield_of_principals(law, eigen[0].first, eigen[2].first, depth) <= 0.)
        return std::nullopt;
      return eigen;
    }
  } // namespace

  SoilReturn
  SoilReturnMapping::return_map(const StrainVector &trial,
                                const double        G,
                                const double        K,
                                const double        depth) const
  {
    StressTangent unused;
    return return_map_with_tangent(trial, G, K, depth, unused);
  }

  SoilReturn
  SoilReturnMapping::return_map_with_tangent(const StrainVector &trial,
                                             const double        G,
                                             const double        K,
                                             const double        depth,
                                             StressTangent      &tangent) const
  {
    SoilReturn result;
    result.stress = trial;
    // One decomposition for the yield test and the return.
    const std::optional<Principals> eigen =
      yielding_principals(law, trial, depth);
    if (!eigen)
      {
        elastic_tangent(G, K, tangent);
        return result;
      }
    const bool            tresca = law.kind == SoilLaw::Kind::tresca;
    const PrincipalReturn r =
      principal_return(*eigen,
                       tresca ? 0. : std::sin(law.friction),
                       tresca ? 0. : std::sin(law.dilation),
                       tresca ? 2. * law.undrained_strength(depth) :
                                2. * law.cohesion * std::cos(law.friction),
                       tresca ? 0. : law.cohesion / std::tan(law.friction),
                       !tresca,
                       G,
                       K);
    result.state  = r.state;
    result.stress = from_principal(r);
    tangent_of(r, G, K, tangent);
    return result;
  }
} // namespace FourierSSI
