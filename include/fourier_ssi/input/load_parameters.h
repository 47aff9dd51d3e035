/**
 * Subsection "Loads" of the .prm file: surface tractions and prescribed
 * displacements as functions of (r, z, theta), the 3D loads that
 * fourier/load_decomposition.h decomposes into harmonics.
 */
#ifndef fourier_ssi_load_parameters_h
#define fourier_ssi_load_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>
#include <fourier_ssi/input/boundary_conditions.h>
#include <map>

namespace FourierSSI
{
  using namespace dealii;

  /** The .prm subsection "Loads": loads as expressions of (r, z, theta). */
  struct LoadParameters
  {
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /** Surface tractions [kPa]: 'id: r=expr, z=expr, theta=expr; ...'. */
    std::map<types::boundary_id, ComponentExpressions> traction;
    /** Prescribed displacements [m]: 'id: u=expr, v=expr, w=expr; ...'. */
    std::map<types::boundary_id, ComponentExpressions> displacement;
    /** Relative amplitude below which a harmonic is not solved. */
    double tolerance = 1e-6;
    /** Largest harmonic considered. */
    unsigned int max_harmonic = 32;

    bool
    any() const
    {
      return !traction.empty() || !displacement.empty();
    }
  };
} // namespace FourierSSI

#endif
