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
        {"iwan", SoilLaw::Kind::iwan},
        {"iwan-sand", SoilLaw::Kind::iwan_sand}};
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
            return "su, k, gref, surfaces, table";
          case SoilLaw::Kind::iwan_sand:
            return "c, phi, psi, rf, surfaces";
        }
      return "";
    }

    /** Stores key = value in the law; false if the kind has no such key. */
    bool
    set_key(SoilLaw &law, const std::string &key, const double value)
    {
      const bool undrained = !law.frictional();
      const bool iwan      = law.kind == SoilLaw::Kind::iwan;
      const bool sand      = law.kind == SoilLaw::Kind::iwan_sand;
      if (undrained && key == "su")
        law.su0 = value;
      else if (undrained && key == "k")
        law.su_gradient = value;
      else if (iwan && key == "gref")
        law.reference_strain = value;
      else if (sand && key == "rf")
        law.failure_ratio = value;
      else if (law.hardening() && key == "surfaces")
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

    /**
     * iwan's `table=g1:r1 g2:r2 ...`: pairs of a shear strain and G/G0,
     * separated by blanks.
     */
    std::vector<std::pair<double, double>>
    degradation_table(const std::string &text, const std::string &where)
    {
      std::vector<std::pair<double, double>> table;
      for (const std::string &pair : Utilities::split_string_list(text, ' '))
        {
          if (pair.empty())
            continue; // several blanks
          const auto colon = pair.find(':');
          AssertThrow(colon != std::string::npos,
                      ExcMessage(entry + ": " + where + "iwan table: '" + pair +
                                 "' is not gamma:G/G0"));
          table.emplace_back(number_in_entry(pair.substr(0, colon), entry),
                             number_in_entry(pair.substr(colon + 1), entry));
        }
      return table;
    }

    /**
     * What is wrong with a degradation table, or "": strains increasing
     * in (0, 1), G/G0 in (0, 1] falling from 1, and tau = G0 gamma G/G0 a
     * concave polygon that does not fall (its slopes are the sums of the
     * sub-elements' moduli, which must be >= 0; derivation section 7).
     */
    std::string
    table_problem(const std::vector<std::pair<double, double>> &table)
    {
      if (table.size() < 2 || table.size() > SoilLaw::max_surfaces)
        return "the table needs 2 to " + std::to_string(SoilLaw::max_surfaces) +
               " points (has " + std::to_string(table.size()) + ")";
      if (table[0].second != 1.)
        return "table must start at G/G0 = 1 (the small-strain modulus)";
      double last_slope = 1.;
      for (unsigned int k = 0; k < table.size(); ++k)
        {
          const auto [gamma, ratio] = table[k];
          std::ostringstream point;
          point << "table point " << k + 1 << " (" << gamma << ":" << ratio
                << "): ";
          const std::string at = point.str();
          if (!(gamma > 0. && gamma < 1.))
            return at + "the strain must satisfy 0 < gamma < 1";
          if (!(ratio > 0. && ratio <= 1.))
            return at + "G/G0 must satisfy 0 < G/G0 <= 1";
          if (k == 0)
            continue;
          const auto [gamma_last, ratio_last] = table[k - 1];
          if (!(gamma > gamma_last))
            return at + "the strains must increase";
          if (ratio > ratio_last)
            return at + "G/G0 must not rise";
          const double slope =
            (gamma * ratio - gamma_last * ratio_last) / (gamma - gamma_last);
          if (slope < 0.)
            return at + "tau = G0 gamma G/G0 falls (a softening curve has "
                        "no iwan elements)";
          if (slope > last_slope * (1. + 1e-12))
            return at + "tau = G0 gamma G/G0 bends upward here (its slope "
                        "rises from the last segment's: no iwan elements fit "
                        "it)";
          last_slope = slope;
        }
      return "";
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
      if (given.count("table"))
        {
          if (given.count("gref"))
            return "give gref or table, not both";
          if (given.count("surfaces"))
            return "surfaces come from the table (its points are the "
                   "kinks): leave surfaces out";
          return table_problem(law.degradation);
        }
      if (!given.count("gref"))
        return "gref is missing (the reference shear strain, G/G0 = 1/2), "
               "or give table=gamma:G/G0 ...";
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

    /** What is wrong with an iwan-sand law, or "". */
    std::string
    sand_problem(const SoilLaw &law, const std::set<std::string> &given)
    {
      const std::string surface = mohr_coulomb_problem(law, given);
      if (!surface.empty())
        return surface;
      std::ostringstream text;
      // R_f = 1 is the hyperbola that reaches q_f only at infinite strain
      // (S3): no last element.
      if (!(law.failure_ratio > 0. && law.failure_ratio < 1.))
        {
          text << "rf = " << law.failure_ratio
               << " must satisfy 0 < rf < 1 (the failure ratio q_f / q_ult "
                  "of the hyperbola)";
          return text.str();
        }
      if (law.n_surfaces == 0)
        return "surfaces must be a whole number from 1 to " +
               std::to_string(SoilLaw::max_surfaces);
      return "";
    }

    /** What is wrong with a law as given, or "". */
    std::string
    problem_of(const SoilLaw &law, const std::set<std::string> &given)
    {
      switch (law.kind)
        {
          case SoilLaw::Kind::mohr_coulomb:
            return mohr_coulomb_problem(law, given);
          case SoilLaw::Kind::iwan_sand:
            return sand_problem(law, given);
          default:
            return undrained_problem(law, given);
        }
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
      "material, N = 1..100 von Mises sub-elements (default 20), or "
      "'id: iwan, su=S[, k=K], table=g1:r1 g2:r2 ...' on a measured "
      "degradation curve: shear strains g increasing with G/G0 = r, r = 1 "
      "at the first, tau = G0 g r linear between the points and beyond the "
      "last, capped at s_u (doc/soil-plasticity.md section 10), or "
      "'id: iwan-sand, c=C, phi=PHI[, psi=PSI][, rf=R][, surfaces=N]': "
      "multi-surface drained sand, N = 1..100 Mohr-Coulomb elements "
      "(default 20) staggered on the Duncan-Chang hyperbola "
      "q/q_f = x/(1 + R x), x = 3 G0 eps_q/q_f, failure ratio R "
      "(0 < R < 1, default 0.9), G0 from the material, Mohr-Coulomb with "
      "c', phi', psi at failure (doc/soil-plasticity.md section 11). The "
      "loading and the iteration are set in 'Load path'.");
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
      "benchmarks/soil-plasticity). Under mpirun the tangent is factorized "
      "on one rank, or over the ranks by MUMPS with Linear solver/"
      "Distributed = always (doc/soil-plasticity.md 3c).");
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
            if (law.kind == SoilLaw::Kind::iwan && key == "table")
              {
                law.degradation =
                  degradation_table(words[w].substr(eq + 1), where);
                law.n_surfaces = law.degradation.size();
                continue;
              }
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
