#include <cmath>
#include <deal.II/base/symmetric_tensor.h>
#include <fourier_ssi/coupled/multi_surface_clay.h>

namespace FourierSSI
{
  namespace
  {
    /** The (r, z, theta) index pairs of the StrainVector components. */
    constexpr unsigned int component[6][2] =
      {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}};

    /** The strain tensor of a strain vector with engineering shears. */
    SymmetricTensor<2, 3>
    strain_tensor(const StrainVector &v)
    {
      SymmetricTensor<2, 3> t;
      for (unsigned int a = 0; a < 6; ++a)
        t[component[a][0]][component[a][1]] = a < 3 ? v[a] : 0.5 * v[a];
      return t;
    }

    /** The strain vector (engineering shears) of a strain tensor. */
    StrainVector
    strain_vector(const SymmetricTensor<2, 3> &t)
    {
      StrainVector v;
      for (unsigned int a = 0; a < 6; ++a)
        v[a] = (a < 3 ? 1. : 2.) * t[component[a][0]][component[a][1]];
      return v;
    }

    /** The stress vector (shear stresses) of a stress tensor. */
    StrainVector
    stress_vector(const SymmetricTensor<2, 3> &t)
    {
      StrainVector v;
      for (unsigned int a = 0; a < 6; ++a)
        v[a] = t[component[a][0]][component[a][1]];
      return v;
    }

    /**
     * d sigma_a / d eps_b (engineering shears) of a fourth-order tensor:
     * with its minor symmetries the entry is C_ijkl itself, because a unit
     * engineering shear puts 1/2 on both kl and lk.
     */
    StressTangent
    tangent_matrix(const SymmetricTensor<4, 3> &c)
    {
      StressTangent d;
      for (unsigned int a = 0; a < 6; ++a)
        for (unsigned int b = 0; b < 6; ++b)
          d[a * 6 + b] = c[component[a][0]][component[a][1]][component[b][0]]
                          [component[b][1]];
      return d;
    }
  } // namespace

  MultiSurfaceClay::MultiSurfaceClay(const MultiSurfaceBackbone &backbone,
                                     const double                bulk_modulus)
    : backbone(backbone)
    , bulk_modulus(bulk_modulus)
  {}

  MultiSurfaceClay::MultiSurfaceClay(const SoilLaw &law,
                                     const double   shear_modulus,
                                     const double   bulk_modulus,
                                     const double   depth)
    : MultiSurfaceClay(MultiSurfaceBackbone(shear_modulus,
                                            law.undrained_strength(depth),
                                            law.reference_strain,
                                            law.n_surfaces),
                       bulk_modulus)
  {
    Assert(law.kind == SoilLaw::Kind::iwan, ExcInternalError());
  }

  MultiSurfaceState
  MultiSurfaceClay::initial_state() const
  {
    return MultiSurfaceState(n_surfaces(), StrainVector{});
  }

  MultiSurfaceReturn
  MultiSurfaceClay::return_map(const StrainVector      &strain,
                               const MultiSurfaceState &committed) const
  {
    return with_state(strain, committed, nullptr);
  }

  MultiSurfaceReturn
  MultiSurfaceClay::return_map_with_tangent(const StrainVector      &strain,
                                            const MultiSurfaceState &committed,
                                            StressTangent &tangent) const
  {
    return with_state(strain, committed, &tangent);
  }

  MultiSurfaceReturn
  MultiSurfaceClay::with_state(const StrainVector      &strain,
                               const MultiSurfaceState &committed,
                               StressTangent           *tangent) const
  {
    Assert(committed.size() == n_surfaces(),
           ExcDimensionMismatch(committed.size(), n_surfaces()));
    MultiSurfaceReturn result;
    result.plastic_strains.resize(n_surfaces());
    const MultiSurfaceStress r = return_map(strain,
                                            committed.data(),
                                            result.plastic_strains.data(),
                                            tangent);
    result.stress              = r.stress;
    result.n_yielding          = r.n_yielding;
    return result;
  }

  MultiSurfaceStress
  MultiSurfaceClay::return_map(const StrainVector &strain,
                               const StrainVector *committed,
                               StrainVector       *updated,
                               StressTangent      *tangent) const
  {
    const SymmetricTensor<2, 3> eps   = strain_tensor(strain);
    const SymmetricTensor<2, 3> e     = deviator(eps);
    const SymmetricTensor<4, 3> i_dev = deviator_tensor<3>();

    MultiSurfaceStress result;
    // (C1): the volumetric part is elastic.
    SymmetricTensor<2, 3> stress =
      bulk_modulus * trace(eps) * unit_symmetric_tensor<3>();
    SymmetricTensor<4, 3> c;
    if (tangent)
      c = bulk_modulus *
          outer_product(unit_symmetric_tensor<3>(), unit_symmetric_tensor<3>());
    for (unsigned int i = 0; i < n_surfaces(); ++i)
      {
        const double g                  = backbone.shear_modulus(i);
        const double radius             = std::sqrt(2.) * backbone.strength(i);
        const SymmetricTensor<2, 3> e_p = strain_tensor(committed[i]);
        // (C2) with e^p_i frozen: the trial deviator of element i.
        SymmetricTensor<2, 3> s    = 2. * g * (e - e_p);
        const double          size = s.norm();
        if (size <= radius)
          {
            if (updated)
              updated[i] = committed[i];
            if (tangent)
              c += 2. * g * i_dev;
          }
        else
          {
            // The radial return onto |s_i| = sqrt(2) tau_i; the plastic
            // strain is what the elastic part 2 G_i (e - e^p) leaves.
            const double                scale = radius / size;
            const SymmetricTensor<2, 3> n     = s / size;
            s *= scale;
            if (updated)
              updated[i] = strain_vector(e - s / (2. * g));
            ++result.n_yielding;
            if (tangent)
              c += 2. * g * scale * (i_dev - outer_product(n, n));
          }
        stress += s;
      }
    result.stress = stress_vector(stress);
    if (tangent)
      *tangent = tangent_matrix(c);
    return result;
  }
} // namespace FourierSSI
