/**
 * Subsection "Soil plasticity" of the .prm file: the perfectly plastic law
 * of each material id (Tresca with s_u(depth), or Mohr-Coulomb with c',
 * phi', psi) and what the coupled iteration re-solves with. The return
 * mapping of these laws is SoilReturnMapping (coupled/soil_law.h).
 */
#ifndef fourier_ssi_soil_plasticity_parameters_h
#define fourier_ssi_soil_plasticity_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace FourierSSI
{
  using namespace dealii;

  /** The data of one plastic law, as Soil plasticity/Laws gives it. */
  struct SoilLaw
  {
    enum class Kind
    {
      tresca,
      mohr_coulomb,
      /** Multi-surface kinematic hardening clay (multi_surface_clay.h). */
      iwan,
      /** Multi-surface drained sand (multi_surface_sand.h). */
      iwan_sand
    };
    Kind kind = Kind::tresca;
    /** Tresca and iwan: s_u = su0 + su_gradient depth [kPa, kPa/m]. */
    double su0         = 0.;
    double su_gradient = 0.;
    /** Mohr-Coulomb and iwan-sand: c' [kPa], phi', psi [rad]. */
    double cohesion = 0., friction = 0., dilation = 0.;
    /**
     * iwan: the reference shear strain gamma_ref of the hyperbolic backbone
     * (G / G0 = 1/2 at gamma_ref) and the number of sub-elements.
     */
    double       reference_strain = 0.;
    unsigned int n_surfaces       = 20;
    /**
     * iwan: a measured degradation curve instead of the hyperbola, pairs
     * (gamma, G/G0) with gamma increasing and G/G0 = 1 at the first
     * (MultiSurfaceBackbone); empty: the hyperbola of reference_strain.
     * n_surfaces is then its length: its kinks below s_u, at most one per
     * point (the last point's slope goes on), are the elements.
     */
    std::vector<std::pair<double, double>> degradation;
    /**
     * iwan-sand: the Duncan-Chang failure ratio R_f of its hyperbola (S3),
     * 0 < R_f < 1: G / G0 = 1/2 where the elastic stress is q_f / R_f.
     */
    double failure_ratio = 0.9;
    /** The largest number of iwan sub-elements (memory per soil point). */
    static constexpr unsigned int max_surfaces = 100;

    /** A frictional law in effective stress (mohr-coulomb, iwan-sand). */
    bool
    frictional() const
    {
      return kind == Kind::mohr_coulomb || kind == Kind::iwan_sand;
    }

    /**
     * A multi-surface law: hysteresis below failure, a plastic state of
     * n_surfaces elements per point.
     */
    bool
    hardening() const
    {
      return kind == Kind::iwan || kind == Kind::iwan_sand;
    }

    /** Undrained strength s_u at a depth [kPa] (Tresca, iwan). */
    double
    undrained_strength(const double depth) const
    {
      return su0 + su_gradient * depth;
    }
  };

  /**
   * Subsection "Soil plasticity": the plastic laws per material id; a
   * material without a law stays linear elastic.
   */
  struct SoilPlasticityParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * "id: tresca, su=..., k=...; id: mohr-coulomb, c=..., phi=...,
     * psi=...; id: iwan, su=..., k=..., gref=..., surfaces=...; id:
     * iwan-sand, c=..., phi=..., psi=..., rf=..., surfaces=..."; throws one
     * line naming the entry and the offending text.
     */
    void
    parse_law_list(const std::string &text);

    bool
    any() const
    {
      return !laws.empty();
    }

    std::map<types::material_id, SoilLaw> laws;

    /**
     * What the coupled iteration re-solves with (doc/soil-plasticity.md
     * section 3): the kept elastic factorizations only (initial stiffness),
     * or the tangent of all harmonics coupled (Newton; coupled_tangent.h).
     */
    bool tangent = true;
  };
} // namespace FourierSSI

#endif
