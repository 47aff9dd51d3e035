#include <cmath>
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
        {"mohr-coulomb", SoilLaw::Kind::mohr_coulomb},
        {"iwan", SoilLaw::Kind::iwan}};
      return choices;
    }

    /** Soil plasticity/Stiffness: Newton on the tangent (true) or elastic. */
    const Choices<bool> &
    stiffnesses()
    {
      static const Choices<bool> choices{{"elastic", false}, {"tangent", true}};
      return choices;
    }

    /** The keys a law of this kind takes, for the error text. */
    std::string
    keys_of(const SoilLaw::Kind kind)
    {
      switch (kind)
        {
          case SoilLaw::Kind::tresca:
            return "su, k";
          case SoilLaw::Kind::mohr_coulomb:
            return "c, phi, psi";
          case SoilLaw::Kind::iwan:
            return "su, k, gref, surfaces";
        }
      return "";
    }

    /** Stores key = value in the law; false if the kind has no such key. */
    bool
    set_key(SoilLaw &law, const std::string &key, const double value)
    {
      const bool undrained = law.kind != SoilLaw::Kind::mohr_coulomb;
      const bool iwan      = law.kind == SoilLaw::Kind::iwan;
      if (undrained && key == "su")
        law.su0 = value;
      else if (undrained && key == "k")
        law.su_gradient = value;
      else if (iwan && key == "gref")
        law.reference_strain = value;
      else if (iwan && key == "surfaces")
        {
          // Checked as a real number first: 2.5 or 1e9 must not be cut to
          // an integer that passes.
          const bool whole = value == std::floor(value);
          law.n_surfaces =
            whole && value >= 1. && value <= SoilLaw::max_surfaces ?
              static_cast<unsigned int>(value) :
              0;
        }
      else if (!undrained && key == "c")
        law.cohesion = value;
      else if (!undrained && key == "phi")
        law.friction = value * numbers::PI / 180.;
      else if (!undrained && key == "psi")
        law.dilation = value * numbers::PI / 180.;
      else
        return false;
      return true;
    }

    /** What is wrong with an undrained law (tresca, iwan), or "". */
    std::string
    undrained_problem(const SoilLaw &law, const std::set<std::string> &given)
    {
      std::ostringstream text;
      if (!given.count("su"))
        return "su is missing";
      if (!(law.su0 > 0.))
        {
          text << "su = " << law.su0 << " kPa must be > 0";
          return text.str();
        }
      if (!(law.su_gradient >= 0.))
        return "k must be >= 0 kPa/m";
      if (law.kind != SoilLaw::Kind::iwan)
        return "";
      if (!given.count("gref"))
        return "gref is missing (the reference shear strain, G/G0 = 1/2)";
      // gamma_ref is a strain: above 1 it is a typing error (a percentage).
      if (!(law.reference_strain > 0. && law.reference_strain < 1.))
        {
          text << "gref = " << law.reference_strain
               << " must satisfy 0 < gref < 1 (a strain, not a percentage)";
          return text.str();
        }
      if (law.n_surfaces == 0)
        return "surfaces must be a whole number from 1 to " +
               std::to_string(SoilLaw::max_surfaces);
      return "";
    }

    /** What is wrong with a Mohr-Coulomb law, or "". */
    std::string
    mohr_coulomb_problem(const SoilLaw &law, const std::set<std::string> &given)
    {
      const double phi = law.friction * 180. / numbers::PI,
                   psi = law.dilation * 180. / numbers::PI;
      std::ostringstream values;
      values << "phi = " << phi << " degrees";
      if (!given.count("c") || !(law.cohesion >= 0.))
        return given.count("c") ? "c must be >= 0 kPa" : "c is missing";
      if (!given.count("phi") || !(phi > 0. && phi < 90.))
        return (given.count("phi") ?
                  values.str() + " must satisfy 0 < phi < 90" :
                  std::string("phi is missing")) +
               " (phi = 0: use tresca)";
      if (!(psi >= 0. && psi <= phi))
        return "psi must satisfy 0 <= psi <= phi";
      return "";
    }

    /** What is wrong with a law as given, or "". */
    std::string
    problem_of(const SoilLaw &law, const std::set<std::string> &given)
    {
      return law.kind == SoilLaw::Kind::mohr_coulomb ?
               mohr_coulomb_problem(law, given) :
               undrained_problem(law, given);
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
      "the dilation angle psi [degrees, 0 < phi < 90, 0 <= psi <= phi], or "
      "'id: iwan, su=S[, k=K], gref=G[, surfaces=N]': multi-surface "
      "kinematic hardening clay (undrained, total stress) on the hyperbolic "
      "backbone G/G0 = 1/(1 + gamma/gref) capped at s_u, G0 from the "
      "material, N = 1..100 von Mises sub-elements (default 20; "
      "doc/soil-plasticity.md section 10). The loading and the iteration are set in 'Load path'.");
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
        law.kind = *kind;
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
            if (!set_key(law, key, value))
              fail(where + "unknown key '" + key + "' (expected " +
                   keys_of(law.kind) + ")");
          }
        const std::string problem = problem_of(law, keys_given);
        if (!problem.empty())
          fail(where + problem);
        if (laws.count(id))
          fail(where + "defined twice");
        laws[id] = law;
      }
  }
} // namespace FourierSSI
