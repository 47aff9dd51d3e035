#include <algorithm>
#include <cmath>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/utilities.h>
#include <fourier_ssi/input/choice.h>
#include <fourier_ssi/input/interface_parameters.h>
#include <fourier_ssi/input/prm_values.h>
#include <limits>
#include <optional>
#include <set>
#include <utility>

namespace FourierSSI
{
  namespace
  {
    /**
     * The coulomb law's admissible data: kn, ks > 0 (the elastic part and
     * the iteration matrix), 0 <= psi <= phi < 90 degrees, and a cut-off
     * no higher than the apex c / tan(phi) of the slip cone (above it a
     * tensile t_n would have no admissible shear).
     */
    void
    check_coulomb(const InterfaceLaw &law,
                  const bool          complete,
                  const std::string  &entry,
                  const std::string  &where)
    {
      AssertThrow(complete,
                  ExcMessage(entry + " coulomb needs kn, ks and phi" + where));
      AssertThrow((law.normal > 0. || law.automatic_normal) &&
                    (law.shear > 0. || law.automatic_shear),
                  ExcMessage(entry + " coulomb needs kn > 0 and ks > 0" +
                             where));
      AssertThrow(law.friction_angle < 90.,
                  ExcMessage(entry + " phi must be below 90 degrees" + where));
      AssertThrow(law.dilation_angle <= law.friction_angle,
                  ExcMessage(entry + " psi must not exceed phi" + where));
      const double apex =
        law.friction_angle > 0. ?
          law.cohesion / std::tan(law.friction_angle * numbers::PI / 180.) :
          std::numeric_limits<double>::infinity();
      AssertThrow(!std::isfinite(law.tension_cutoff) ||
                    law.tension_cutoff <= apex,
                  ExcMessage(entry +
                             " sigma_t must not exceed the apex c/tan(phi) "
                             "of the slip surface" +
                             where));
      AssertThrow(std::isfinite(law.tension_cutoff) || law.friction_angle == 0.,
                  ExcMessage(entry +
                             " sigma_t=none needs phi=0 (a cone with "
                             "friction has its apex as cut-off)" +
                             where));
    }

    /**
     * The contact law's admissible data: phi given, 0 <= phi < 90 degrees,
     * c >= 0; no springs (non-penetration is exact), no dilation and no
     * tension (a contact transmits none).
     */
    void
    check_contact(const InterfaceLaw          &law,
                  const bool                   springs_given,
                  const std::set<std::string> &keys,
                  const std::string           &entry,
                  const std::string           &where)
    {
      AssertThrow(!springs_given,
                  ExcMessage(entry +
                             ": contact takes no kn or ks (non-penetration "
                             "is exact; use coulomb for springs)" +
                             where));
      AssertThrow(keys.count("phi") == 1,
                  ExcMessage(entry + ": contact needs phi" + where));
      AssertThrow(law.friction_angle < 90.,
                  ExcMessage(entry + ": contact phi must be below 90 degrees" +
                             where));
      AssertThrow(keys.count("psi") == 0 && keys.count("sigma_t") == 0,
                  ExcMessage(entry +
                             ": contact takes no psi or sigma_t (no "
                             "dilation, no tension)" +
                             where));
      AssertThrow(keys.count("mu") == 0 && keys.count("material") == 0,
                  ExcMessage(entry +
                             ": mu and material belong to the vermeer law" +
                             where));
    }
  } // namespace

  namespace
  {
    /** Interfaces/Nonlinear integration: nodal (true) or Gauss points. */
    const Choices<bool> &
    integration_choices()
    {
      static const Choices<bool> choices{{"gauss", false}, {"nodal", true}};
      return choices;
    }
  } // namespace

  void
  InterfaceParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Interfaces");
    prm.declare_entry(
      "Interfaces",
      "",
      Patterns::Anything(),
      "Zero-thickness interfaces by boundary id (the id carried by the faces "
      "on both sides of a double-node line), separated by ';': 'id: rough' "
      "(kn = ks = 1e10 kPa/m), 'id: smooth' (kn = 1e10, ks = 0), "
      "'id: kn=1e8, ks=0', or 'id: vermeer, mu=50[, material=m]' (Van Langen "
      "& Vermeer 1991: ks = mu G/l, kn = mu G/((1-2nu) l), G and nu of "
      "material m or of the side with the lower G, l the mean face length). "
      "Exact limits without penalty (constraints, no conditioning cost): "
      "'id: tied' (kn = ks = infinity) and 'id: tied-normal' (kn = infinity, "
      "ks = 0). Nonlinear Mohr-Coulomb slip with a tension cut-off: "
      "'id: coulomb, kn=1e6, ks=1e6, c=0, phi=25[, psi=0][, sigma_t=0]' "
      "(kn, ks > 0 [kPa/m] elastic, or 'auto': 1e3 G/l with G of the softer "
      "side and l the mean face length, within about 0.1 % of rigid "
      "contact, the rule printed in the log; c [kPa] cohesion; phi, psi [degrees] "
      "friction and dilation angles, 0 <= psi <= phi < 90; sigma_t [kPa] "
      "largest tension, 0 = tensionless (default), 'none' = no cut-off; "
      "doc/nonlinear-interfaces.md). Exact non-penetration with Coulomb "
      "friction, no springs to choose: 'id: contact, phi=25[, c=0]' "
      "(tensionless, augmented Lagrangian at the theta samples). Empty: no "
      "interface.");
    prm.declare_entry(
      "Nonlinear integration",
      "gauss",
      Patterns::Selection(integration_choices().selection()),
      "Where the coulomb and contact interfaces are sampled along each face "
      "(and their matrices integrated): gauss (p + 1 Gauss points, the "
      "exact closed-form matrix) or nodal (Gauss-Lobatto at the p + 1 "
      "nodes, a lumped matrix; Schellekens & de Borst 1993). With gauss a "
      "quadratic face has 3 samples for 2 new nodes, so exact contact asks "
      "more than the displacements can give and keeps a small penetration "
      "(3.5e-5 of the largest relative displacement on the free-head pile); "
      "nodal holds it to the force test (1e-7 there) "
      "(doc/nonlinear-interfaces.md 5e).");
    prm.declare_entry("Pairing tolerance",
                      "1e-8",
                      Patterns::Double(0.),
                      "Twin faces and nodes must coincide within this "
                      "fraction of the face length.");
    prm.leave_subsection();
  }

  void
  InterfaceParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Interfaces");
    laws              = parse_list(prm.get("Interfaces"));
    pairing_tolerance = prm.get_double("Pairing tolerance");
    nodal_integration =
      integration_choices().value_of(prm.get("Nonlinear integration"),
                                     "Interfaces/Nonlinear integration");
    prm.leave_subsection();
  }

  namespace
  {
    const std::string interfaces_entry = "Interfaces/Interfaces";

    /** A law named by a word: its kind and, for a preset, its kn, ks. */
    struct NamedLaw
    {
      InterfaceLaw::Kind                       kind;
      std::optional<std::pair<double, double>> springs;
    };

    /** The words of the law names, in the order the messages list them. */
    const Choices<NamedLaw> &
    named_laws()
    {
      using Kind = InterfaceLaw::Kind;
      static const Choices<NamedLaw> choices{
        {"rough", {Kind::springs, std::pair{1e10, 1e10}}},
        {"smooth", {Kind::springs, std::pair{1e10, 0.}}},
        {"tied", {Kind::tied, std::nullopt}},
        {"tied-normal", {Kind::tied_normal, std::nullopt}},
        {"vermeer", {Kind::vermeer, std::nullopt}},
        {"coulomb", {Kind::coulomb, std::nullopt}},
        {"contact", {Kind::contact, std::nullopt}}};
      return choices;
    }

    /** Which parts of a law an item of the list gave. */
    struct GivenParts
    {
      bool preset = false, has_kn = false, has_ks = false, has_mu = false,
           has_material = false, has_strength = false, has_phi = false;
      std::set<std::string> keys_given;
    };

    /** A token without '=': one of the named laws. */
    void
    apply_named_law(InterfaceLaw            &law,
                    GivenParts              &given,
                    const std::string       &token,
                    const types::boundary_id id)
    {
      const std::string &entry = interfaces_entry;
      AssertThrow(!given.preset,
                  ExcMessage(entry + ": two laws for boundary id " +
                             std::to_string(id)));
      given.preset                        = true;
      const std::optional<NamedLaw> named = named_laws().find(token);
      AssertThrow(named.has_value(),
                  ExcMessage(
                    entry + ": " +
                    named_laws().unknown("law", token, {"kn=..., ks=..."})));
      law.kind = named->kind;
      if (named->springs)
        std::tie(law.normal, law.shear) = *named->springs;
    }

    /** A token 'key=value' of item. */
    void
    apply_key_value(InterfaceLaw      &law,
                    GivenParts        &given,
                    const std::string &token,
                    const std::string &item)
    {
      const std::string &entry = interfaces_entry;
      const auto         eq    = token.find('=');
      const std::string  key   = Utilities::trim(token.substr(0, eq));
      record_key_once(given.keys_given, key, entry, item);
      if (key == "sigma_t" && Utilities::trim(token.substr(eq + 1)) == "none")
        {
          law.tension_cutoff = std::numeric_limits<double>::infinity();
          given.has_strength = true;
          return;
        }
      if ((key == "kn" || key == "ks") &&
          Utilities::trim(token.substr(eq + 1)) == "auto")
        {
          // automatic_interface_stiffness G / l, per face.
          (key == "kn" ? law.automatic_normal : law.automatic_shear) = true;
          (key == "kn" ? given.has_kn : given.has_ks)                = true;
          return;
        }
      const double value = number_in_entry(token.substr(eq + 1), entry);
      AssertThrow(value >= 0.,
                  ExcMessage(entry + ": " + key + " must be >= 0 in '" + item +
                             "'"));
      if (key == "kn")
        law.normal = value, given.has_kn = true;
      else if (key == "ks")
        law.shear = value, given.has_ks = true;
      else if (key == "mu")
        law.mu = value, given.has_mu = true;
      else if (key == "material")
        law.material = static_cast<int>(value), given.has_material = true;
      else if (key == "c")
        law.cohesion = value, given.has_strength = true;
      else if (key == "phi")
        law.friction_angle = value, given.has_strength = given.has_phi = true;
      else if (key == "psi")
        law.dilation_angle = value, given.has_strength = true;
      else if (key == "sigma_t")
        law.tension_cutoff = value, given.has_strength = true;
      else
        AssertThrow(false,
                    ExcMessage(entry + ": unknown key '" + key +
                               "' (expected kn, ks, mu, material, c, "
                               "phi, psi or sigma_t)"));
    }

    /** Each law takes its own parts and no others. */
    void
    check_law_parts(const InterfaceLaw      &law,
                    const GivenParts        &given,
                    const types::boundary_id id)
    {
      const std::string &entry = interfaces_entry;
      const std::string  where = " for boundary id " + std::to_string(id);
      AssertThrow(law.is_nonlinear() || !given.has_strength,
                  ExcMessage(entry +
                             ": c, phi, psi and sigma_t belong to the "
                             "coulomb and contact laws" +
                             where));
      AssertThrow(law.is_nonlinear() ||
                    !(law.automatic_normal || law.automatic_shear),
                  ExcMessage(entry +
                             ": kn=auto, ks=auto belong to the "
                             "coulomb law" +
                             where));
      if (law.kind == InterfaceLaw::Kind::contact)
        check_contact(
          law, given.has_kn || given.has_ks, given.keys_given, entry, where);
      else if (law.kind == InterfaceLaw::Kind::coulomb)
        {
          AssertThrow(!given.has_mu && !given.has_material,
                      ExcMessage(entry +
                                 ": mu and material belong to the vermeer "
                                 "law, not to coulomb (give kn and ks)" +
                                 where));
          check_coulomb(law,
                        given.has_kn && given.has_ks && given.has_phi,
                        entry + ":",
                        where);
        }
      else if (law.kind == InterfaceLaw::Kind::vermeer)
        {
          AssertThrow(
            given.has_mu && law.mu > 0. && !given.has_kn && !given.has_ks,
            ExcMessage(entry + ": vermeer needs mu > 0 and no kn/ks" + where));
        }
      else if (given.preset)
        {
          AssertThrow(!given.has_kn && !given.has_ks && !given.has_mu &&
                        !given.has_material,
                      ExcMessage(entry + ": a preset takes no kn/ks/mu" +
                                 where));
        }
      else
        {
          AssertThrow(given.has_kn && given.has_ks && !given.has_mu &&
                        !given.has_material,
                      ExcMessage(entry +
                                 ": give both kn and ks (or rough, "
                                 "smooth, vermeer)" +
                                 where));
        }
    }

    /** The law of one item 'id: token, token, ...' (tokens after colon). */
    InterfaceLaw
    parse_law(const std::string       &item,
              const std::size_t        colon,
              const types::boundary_id id)
    {
      InterfaceLaw law;
      GivenParts   given;
      for (const std::string &token :
           Utilities::split_string_list(item.substr(colon + 1), ','))
        if (token.find('=') == std::string::npos)
          apply_named_law(law, given, token, id);
        else
          apply_key_value(law, given, token, item);
      check_law_parts(law, given, id);
      return law;
    }
  } // namespace

  std::map<types::boundary_id, InterfaceLaw>
  InterfaceParameters::parse_list(const std::string &text)
  {
    const std::string                         &entry = interfaces_entry;
    std::map<types::boundary_id, InterfaceLaw> result;
    for (const std::string &item : Utilities::split_string_list(text, ';'))
      {
        const auto colon = item.find(':');
        AssertThrow(colon != std::string::npos,
                    ExcMessage(entry + ": '" + item + "' lacks 'id:'"));
        const types::boundary_id id =
          boundary_id_in_entry(item.substr(0, colon), entry);
        AssertThrow(result.count(id) == 0,
                    ExcMessage(entry + ": boundary id " + std::to_string(id) +
                               " given twice"));
        result[id] = parse_law(item, colon, id);
      }
    return result;
  }

  bool
  InterfaceParameters::any_nonlinear() const
  {
    return std::any_of(laws.begin(), laws.end(), [](const auto &entry) {
      return entry.second.is_nonlinear();
    });
  }

  bool
  InterfaceParameters::any_contact() const
  {
    return std::any_of(laws.begin(), laws.end(), [](const auto &entry) {
      return entry.second.kind == InterfaceLaw::Kind::contact;
    });
  }

  bool
  InterfaceParameters::is_stiff() const
  {
    AssertThrow(penalty_ratio.has_value(),
                ExcMessage("internal: the interfaces' penalty ratio is "
                           "measured on the mesh "
                           "(choose_interface_linearisation) before a "
                           "coupled solve asks for it"));
    return any_contact() || *penalty_ratio >= stiff_penalty_ratio;
  }
} // namespace FourierSSI
