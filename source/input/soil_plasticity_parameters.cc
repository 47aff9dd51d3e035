#include <deal.II/base/numbers.h>
#include <deal.II/base/utilities.h>
#include <fourier_ssi/input/choice.h>
#include <fourier_ssi/input/prm_values.h>
#include <fourier_ssi/input/soil_plasticity_parameters.h>
#include <optional>
#include <set>
#include <sstream>

namespace FourierSSI
{
  namespace
  {
    const std::string entry = "Soil plasticity/Laws";

    const Choices<SoilLaw::Kind> &
    law_kinds()
    {
      static const Choices<SoilLaw::Kind> choices{
        {"tresca", SoilLaw::Kind::tresca},
        {"mohr-coulomb", SoilLaw::Kind::mohr_coulomb}};
      return choices;
    }

    /** Soil plasticity/Stiffness: Newton on the tangent (true) or elastic. */
    const Choices<bool> &
    stiffnesses()
    {
      static const Choices<bool> choices{{"elastic", false}, {"tangent", true}};
      return choices;
    }
  } // namespace

  void
  SoilPlasticityParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Soil plasticity");
    prm.declare_entry(
      "Laws",
      "",
      Patterns::Anything(),
      "Perfectly plastic laws by material id, separated by ';' (a material "
      "without a law stays linear elastic): 'id: tresca, su=S[, k=K]' with "
      "the undrained strength s_u = S + K depth [kPa, kPa/m], or "
      "'id: mohr-coulomb, c=C, phi=PHI[, psi=PSI]' with c' [kPa], phi' and "
      "the dilation angle psi [degrees, 0 < phi < 90, 0 <= psi <= phi]. "
      "The loading and the iteration are set in 'Load path'.");
    prm.declare_entry(
      "Stiffness",
      "tangent",
      Patterns::Selection(stiffnesses().selection()),
      "What the out-of-balance iteration solves with. elastic: the kept "
      "elastic factorization of every harmonic (initial stiffness, hundreds "
      "of iterations per step near the limit load); tangent: Newton on all "
      "harmonics together, their coupling through the plastic points "
      "included (the tangent of the return mapping, theta-integrated for "
      "every pair of harmonics, refactorized at every update; "
      "benchmarks/soil-plasticity). Under mpirun only elastic: the "
      "harmonics and the soil points are distributed over the ranks "
      "(doc/soil-plasticity.md 3c).");
    prm.leave_subsection();
  }

  void
  SoilPlasticityParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Soil plasticity");
    parse_law_list(prm.get("Laws"));
    tangent =
      stiffnesses().value_of(prm.get("Stiffness"), "Soil plasticity/Stiffness");
    prm.leave_subsection();
  }

  void
  SoilPlasticityParameters::parse_law_list(const std::string &text)
  {
    laws.clear();
    const auto fail = [&](const std::string &what) {
      AssertThrow(false,
                  ExcMessage(entry + ": " + what + " in '" + text + "'"));
    };
    for (const std::string &item : Utilities::split_string_list(text, ';'))
      {
        const auto colon = item.find(':');
        if (colon == std::string::npos)
          fail("entry '" + item + "' lacks 'id:'");
        const types::material_id id =
          boundary_id_in_entry(item.substr(0, colon), entry);
        const std::vector<std::string> words =
          Utilities::split_string_list(item.substr(colon + 1), ',');
        const std::string where = "material " + std::to_string(id) + ": ";
        if (words.empty())
          fail(where + "no law");
        const std::optional<SoilLaw::Kind> kind = law_kinds().find(words[0]);
        if (!kind)
          fail(where + law_kinds().unknown("law", words[0]));
        SoilLaw law;
        law.kind                     = *kind;
        bool                  has_su = false, has_c = false, has_phi = false;
        std::set<std::string> keys_given;
        for (unsigned int w = 1; w < words.size(); ++w)
          {
            const auto eq = words[w].find('=');
            if (eq == std::string::npos)
              fail(where + "'" + words[w] + "' is not key=value");
            const std::string key = Utilities::trim(words[w].substr(0, eq));
            record_key_once(keys_given, key, entry, item);
            const double value =
              number_in_entry(words[w].substr(eq + 1), entry);
            const bool is_tresca = law.kind == SoilLaw::Kind::tresca;
            if (is_tresca && key == "su")
              law.su0 = value, has_su = true;
            else if (is_tresca && key == "k")
              law.su_gradient = value;
            else if (!is_tresca && key == "c")
              law.cohesion = value, has_c = true;
            else if (!is_tresca && key == "phi")
              law.friction = value * numbers::PI / 180., has_phi = true;
            else if (!is_tresca && key == "psi")
              law.dilation = value * numbers::PI / 180.;
            else
              fail(where + "unknown key '" + key + "' (expected " +
                   (is_tresca ? "su, k" : "c, phi, psi") + ")");
          }
        std::ostringstream values;
        if (law.kind == SoilLaw::Kind::tresca)
          {
            values << "su = " << law.su0 << " kPa";
            if (!has_su || !(law.su0 > 0.))
              fail(where + (has_su ? values.str() + " must be > 0" :
                                     std::string("su is missing")));
            if (!(law.su_gradient >= 0.))
              fail(where + "k must be >= 0 kPa/m");
          }
        else
          {
            const double phi = law.friction * 180. / numbers::PI,
                         psi = law.dilation * 180. / numbers::PI;
            values << "phi = " << phi << " degrees";
            if (!has_c || !(law.cohesion >= 0.))
              fail(where + (has_c ? "c must be >= 0 kPa" : "c is missing"));
            if (!has_phi || !(phi > 0. && phi < 90.))
              fail(where +
                   (has_phi ? values.str() + " must satisfy 0 < phi < 90" :
                              std::string("phi is missing")) +
                   " (phi = 0: use tresca)");
            if (!(psi >= 0. && psi <= phi))
              fail(where + "psi must satisfy 0 <= psi <= phi");
          }
        if (laws.count(id))
          fail(where + "defined twice");
        laws[id] = law;
      }
  }
} // namespace FourierSSI
