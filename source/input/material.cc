#include <algorithm>
#include <cmath>
#include <deal.II/base/utilities.h>
#include <fourier_ssi/input/material.h>
#include <fourier_ssi/input/prm_values.h>
#include <optional>
#include <set>
#include <sstream>

namespace FourierSSI
{
  double
  ElasticMaterial::shear_modulus(const double depth) const
  {
    if (hardin())
      return shear_modulus_ref *
             std::pow((mean_at_surface + mean_gradient * depth) /
                        hardin_reference_stress,
                      hardin_exponent);
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
      "(depth where G equals the given value; default 1); or, instead of "
      "alpha and depth_ref, Hardin's pref [kPa] and m (default 0.5): "
      "G0 = G (p'0/pref)^m with p'0 = (1 + 2 K0) sigma'_v / 3 the "
      "geostatic mean effective stress of Initial stress.");
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

  namespace
  {
    /** The moduli [kPa] a material may have. */
    constexpr double smallest_modulus = 1e-3;
    constexpr double largest_modulus  = 1e12;

    std::string
    number_text(const double value)
    {
      std::ostringstream out;
      out << value;
      return out.str();
    }

    /** The one-line error of Materials/Materials, quoting the whole text. */
    void
    refuse_materials(const std::string &text, const std::string &what)
    {
      AssertThrow(false,
                  ExcMessage("Materials/Materials: " + what + " in '" + text +
                             "'"));
    }

    /** The id before the colon of one entry, 0..254. */
    int
    material_id_of(const std::string &entry,
                   const std::size_t  colon,
                   const std::string &text)
    {
      int id = -1;
      try
        {
          id =
            Utilities::string_to_int(Utilities::trim(entry.substr(0, colon)));
        }
      catch (...)
        {
          refuse_materials(text,
                           "material id '" + entry.substr(0, colon) +
                             "' is not an integer");
        }
      if (id < 0 || id >= 255)
        refuse_materials(text,
                         "material id " + std::to_string(id) +
                           " out of range [0,254]");
      return id;
    }

    /** The moduli as given (empty: not given) and whether nu was. */
    struct GivenModuli
    {
      std::optional<double> E, G;
      bool                  has_nu = false;
      std::set<std::string> keys;
    };

    /** The key=value pairs after the colon of one entry. */
    GivenModuli
    read_material_keys(const std::string &entry,
                       const std::size_t  colon,
                       const std::string &text,
                       ElasticMaterial   &material)
    {
      GivenModuli            given;
      std::set<std::string> &keys_given = given.keys;
      for (const std::string &pair :
           Utilities::split_string_list(entry.substr(colon + 1), ','))
        {
          const auto eq = pair.find('=');
          if (eq == std::string::npos)
            refuse_materials(text, "'" + pair + "' is not key=value");
          const std::string key = Utilities::trim(pair.substr(0, eq));
          record_key_once(keys_given, key, "Materials/Materials", entry);
          const double value =
            number_in_entry(pair.substr(eq + 1),
                            "Materials/Materials: material '" +
                              Utilities::trim(entry.substr(0, colon)) +
                              "': " + key);
          if (key == "E")
            given.E = value;
          else if (key == "G")
            given.G = value;
          else if (key == "nu")
            {
              material.poisson_ratio = value;
              given.has_nu           = true;
            }
          else if (key == "alpha")
            material.alpha = value;
          else if (key == "depth_ref")
            material.depth_ref = value;
          else if (key == "pref")
            material.hardin_reference_stress = value;
          else if (key == "m")
            material.hardin_exponent = value;
          else
            refuse_materials(text,
                             "unknown key '" + key +
                               "' (expected E, G, nu, alpha, depth_ref, "
                               "pref, m)");
        }
      return given;
    }

    /** A modulus [kPa] named `what`: positive and within the bounds. */
    void
    check_modulus(const std::string &text,
                  const std::string &what,
                  const double       modulus)
    {
      if (!(modulus > 0.))
        refuse_materials(text,
                         what + " = " + number_text(modulus) +
                           ": the modulus must be positive");
      // Outside these bounds the stiffness and the penalty ties lose every
      // digit (G = 1e-300 gave a negative K_V, 1e300 an inf): no soil or
      // structure in kPa lies there.
      if (modulus < smallest_modulus || modulus > largest_modulus)
        refuse_materials(text,
                         what + " = " + number_text(modulus) +
                           " kPa is outside " + number_text(smallest_modulus) +
                           " ... " + number_text(largest_modulus) +
                           " kPa (units: kN, m, kPa)");
    }

    /** Hardin's keys: pref > 0, 0 <= m <= 1, not with the depth law. */
    void
    check_hardin(const ElasticMaterial &material,
                 const GivenModuli     &given,
                 const std::string     &where,
                 const std::string     &text)
    {
      const bool hardin = given.keys.count("pref") > 0;
      if (given.keys.count("m") && !hardin)
        refuse_materials(text,
                         where + "m without pref (Hardin's G0 = G "
                                 "(p'0/pref)^m needs both)");
      if (!hardin)
        return;
      if (given.keys.count("alpha") || given.keys.count("depth_ref"))
        refuse_materials(text,
                         where + "give alpha and depth_ref (G with depth) "
                                 "or pref and m (G with p'0), not both");
      if (!(material.hardin_reference_stress > 0.))
        refuse_materials(text, where + "pref must be > 0 kPa");
      if (!(material.hardin_exponent >= 0. && material.hardin_exponent <= 1.))
        refuse_materials(text, where + "m must satisfy 0 <= m <= 1");
    }

    /** Check the given data and set the shear modulus (from E or G). */
    void
    finish_material(ElasticMaterial   &material,
                    const GivenModuli &given,
                    const std::string &where,
                    const std::string &text)
    {
      if (!given.has_nu)
        refuse_materials(text, where + "nu is missing");
      if (!(material.poisson_ratio > -1. && material.poisson_ratio < 0.5))
        refuse_materials(text,
                         where + "nu = " + number_text(material.poisson_ratio) +
                           " must satisfy -1 < nu < 0.5");
      // Each modulus given is checked before the pair: a negative one is
      // the mistake to name, not that both were given.
      for (const auto &[name, value] :
           {std::pair{"E", given.E}, std::pair{"G", given.G}})
        if (value)
          check_modulus(text, where + name, *value);
      if (given.E && given.G)
        refuse_materials(text, where + "give E or G, not both");
      if (!given.E && !given.G)
        refuse_materials(text, where + "E or G is missing");
      material.shear_modulus_ref =
        given.G ? *given.G : *given.E / (2. * (1. + material.poisson_ratio));
      if (!(material.alpha >= 0.))
        refuse_materials(text, where + "alpha must be >= 0");
      if (!(material.depth_ref > 0.))
        refuse_materials(text, where + "depth_ref must be > 0");
      check_hardin(material, given, where, text);
    }
  } // namespace

  void
  MaterialLibrary::parse_material_list(const std::string &text)
  {
    materials.clear();
    for (const std::string &entry : Utilities::split_string_list(text, ';'))
      {
        const auto colon = entry.find(':');
        if (colon == std::string::npos)
          refuse_materials(text, "entry '" + entry + "' lacks 'id:'");
        const int         id = material_id_of(entry, colon, text);
        ElasticMaterial   material;
        const GivenModuli given =
          read_material_keys(entry, colon, text, material);
        const std::string where = "material " + std::to_string(id) + ": ";
        finish_material(material, given, where, text);
        if (materials.count(id))
          refuse_materials(text, where + "defined twice");
        materials[id] = material;
      }
    if (materials.empty())
      refuse_materials(text, "no material given");
  }

  void
  MaterialLibrary::use_geostatic_stress(
    const InitialStressParameters &initial_stress)
  {
    // p'0 = (sigma'_v + 2 K0 sigma'_v) / 3, sigma'_v = q + gamma' depth.
    const double mean =
      (1. + 2. * initial_stress.earth_pressure_coefficient) / 3.;
    for (auto &[id, material] : materials)
      {
        if (!material.hardin())
          continue;
        AssertThrow(initial_stress.enabled(),
                    ExcMessage("Materials/Materials: material " +
                               std::to_string(id) +
                               ": pref (Hardin's G0 from the mean effective "
                               "stress) needs Initial stress (Effective unit "
                               "weight or Surcharge, K0)"));
        material.mean_at_surface = mean * initial_stress.surcharge;
        material.mean_gradient   = mean * initial_stress.unit_weight;
      }
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
