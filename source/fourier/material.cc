#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <fourier_ssi/fourier/material.h>
#include <fourier_ssi/input/prm_values.h>
#include <set>
#include <sstream>

namespace FourierSSI
{
  double
  ElasticMaterial::shear_modulus(const double depth) const
  {
    if (alpha == 0.)
      return shear_modulus_ref;
    return shear_modulus_ref * std::pow(depth / depth_ref, alpha);
  }

  double
  ElasticMaterial::lambda(const double depth) const
  {
    return 2. * shear_modulus(depth) * poisson_ratio /
           (1. - 2. * poisson_ratio);
  }

  void
  MaterialLibrary::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Materials");
    prm.declare_entry(
      "Materials",
      "0: E=1e5, nu=0.3",
      Patterns::Anything(),
      "Elastic materials by material id, separated by ';'. Each is "
      "'id: key=value, ...' with keys E or G [kPa] (modulus at depth_ref), "
      "nu (-1 < nu < 0.5), alpha (power-law exponent of G with depth, "
      "thesis eq. 4.3; default 0 = homogeneous, 1 = Gibson) and depth_ref [m] "
      "(depth where G equals the given value; default 1).");
    prm.declare_entry("Ground surface elevation",
                      "0",
                      Patterns::Double(),
                      "Elevation z [m] of the ground surface; depth = "
                      "surface elevation - z enters G(depth).");
    prm.leave_subsection();
  }

  void
  MaterialLibrary::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Materials");
    surface_elevation = prm.get_double("Ground surface elevation");
    parse_material_list(prm.get("Materials"));
    prm.leave_subsection();
  }

  void
  MaterialLibrary::parse_material_list(const std::string &text)
  {
    materials.clear();
    const auto fail = [&](const std::string &what) {
      AssertThrow(false,
                  ExcMessage("Materials/Materials: " + what + " in '" + text +
                             "'"));
    };

    for (const std::string &entry : Utilities::split_string_list(text, ';'))
      {
        const auto colon = entry.find(':');
        if (colon == std::string::npos)
          fail("entry '" + entry + "' lacks 'id:'");
        int id = -1;
        try
          {
            id =
              Utilities::string_to_int(Utilities::trim(entry.substr(0, colon)));
          }
        catch (...)
          {
            fail("material id '" + entry.substr(0, colon) +
                 "' is not an integer");
          }
        if (id < 0 || id >= 255)
          fail("material id " + std::to_string(id) + " out of range [0,254]");

        ElasticMaterial       material;
        double                E = -1., G = -1.;
        bool                  has_nu = false;
        std::set<std::string> keys_given;
        for (const std::string &pair :
             Utilities::split_string_list(entry.substr(colon + 1), ','))
          {
            const auto eq = pair.find('=');
            if (eq == std::string::npos)
              fail("'" + pair + "' is not key=value");
            const std::string key = Utilities::trim(pair.substr(0, eq));
            record_key_once(keys_given, key, "Materials/Materials", entry);
            double value;
            try
              {
                value = Utilities::string_to_double(
                  Utilities::trim(pair.substr(eq + 1)));
              }
            catch (...)
              {
                fail("value of '" + key + "' is not a number");
              }
            if (!std::isfinite(value))
              fail("value of '" + key + "' is not finite");
            if (key == "E")
              E = value;
            else if (key == "G")
              G = value;
            else if (key == "nu")
              {
                material.poisson_ratio = value;
                has_nu                 = true;
              }
            else if (key == "alpha")
              material.alpha = value;
            else if (key == "depth_ref")
              material.depth_ref = value;
            else
              fail("unknown key '" + key +
                   "' (expected E, G, nu, alpha, depth_ref)");
          }
        const std::string where = "material " + std::to_string(id) + ": ";
        if (!has_nu)
          fail(where + "nu is missing");
        if (!(material.poisson_ratio > -1. && material.poisson_ratio < 0.5))
          {
            std::ostringstream nu;
            nu << material.poisson_ratio;
            fail(where + "nu = " + nu.str() + " must satisfy -1 < nu < 0.5");
          }
        if ((E > 0.) == (G > 0.) && !(E == -1. && G == -1.))
          {
            if (E != -1. && G != -1.)
              fail(where + "give E or G, not both");
          }
        if (E == -1. && G == -1.)
          fail(where + "E or G is missing");
        if ((E != -1. && !(E > 0.)) || (G != -1. && !(G > 0.)))
          fail(where + "the modulus must be positive");
        material.shear_modulus_ref =
          G > 0. ? G : E / (2. * (1. + material.poisson_ratio));
        if (!(material.alpha >= 0.))
          fail(where + "alpha must be >= 0");
        if (!(material.depth_ref > 0.))
          fail(where + "depth_ref must be > 0");
        if (materials.count(id))
          fail(where + "defined twice");
        materials[id] = material;
      }
    if (materials.empty())
      fail("no material given");
  }

  const ElasticMaterial &
  MaterialLibrary::get(const types::material_id id) const
  {
    const auto it = materials.find(id);
    AssertThrow(it != materials.end(),
                ExcMessage("the mesh has material id " + std::to_string(id) +
                           " but Materials/Materials does not define it"));
    return it->second;
  }

  double
  largest_poisson_ratio(const MaterialLibrary &materials)
  {
    double nu = -1.;
    for (const auto &[id, material] : materials.all())
      nu = std::max(nu, material.poisson_ratio);
    return nu;
  }
} // namespace FourierSSI
