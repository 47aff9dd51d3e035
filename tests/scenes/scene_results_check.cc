// Checks the results.csv of a bundled scene against the references listed in
// a .checks file (tests/scenes/README.md describes the format). Standard C++
// only: it reads text, so it does not link deal.II.
//
// Usage: scene_results_check FILE.checks RESULTS.csv
#include "../support/check.h"

#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace
{
  /** (quantity, n, family) -> value per cycle, from the rows of results.csv. */
  using Series = std::map<std::tuple<std::string, unsigned int, std::string>,
                          std::map<unsigned int, double>>;

  Series
  read_results(const std::string &filename)
  {
    std::ifstream in(filename);
    if (!in)
      throw std::runtime_error("cannot read '" + filename + "'");
    Series      series;
    std::string line;
    std::getline(in, line); // header quantity,n,family,cycle,value,unit
    while (std::getline(in, line))
      {
        std::vector<std::string> field;
        std::istringstream       row(line);
        for (std::string f; std::getline(row, f, ',');)
          field.push_back(f);
        if (field.size() < 5)
          throw std::runtime_error("malformed row '" + line + "'");
        series[{field[0],
                static_cast<unsigned int>(std::stoul(field[1])),
                field[2]}][static_cast<unsigned int>(std::stoul(field[3]))] =
          std::stod(field[4]);
      }
    return series;
  }

  /**
   * The value named by "quantity[*factor] n family cycle" ("last": the
   * highest cycle of that quantity).
   */
  double
  lookup(const Series      &series,
         const std::string &quantity_and_factor,
         const unsigned int n,
         const std::string &family,
         const std::string &cycle)
  {
    const auto   star     = quantity_and_factor.find('*');
    const auto   quantity = quantity_and_factor.substr(0, star);
    const double factor   = star == std::string::npos ?
                              1. :
                              std::stod(quantity_and_factor.substr(star + 1));
    const auto   s        = series.find({quantity, n, family});
    if (s == series.end() || s->second.empty())
      throw std::runtime_error("no row " + quantity +
                               " n=" + std::to_string(n) + " " + family);
    if (cycle == "last")
      return factor * s->second.rbegin()->second;
    const auto c = s->second.find(std::stoul(cycle));
    if (c == s->second.end())
      throw std::runtime_error("no row " + quantity +
                               " n=" + std::to_string(n) + " " + family +
                               " cycle " + cycle);
    return factor * c->second;
  }

  /** The n of the harmonics of one family that have a row of `quantity`. */
  std::set<unsigned int>
  harmonics_with(const Series      &series,
                 const std::string &quantity,
                 const std::string &family)
  {
    std::set<unsigned int> ns;
    for (const auto &[key, values] : series)
      if (std::get<0>(key) == quantity && std::get<2>(key) == family)
        ns.insert(std::get<1>(key));
    return ns;
  }

  std::string
  to_text(const std::set<unsigned int> &ns)
  {
    std::string text;
    for (const unsigned int n : ns)
      text += (text.empty() ? "" : ",") + std::to_string(n);
    return text.empty() ? "none" : text;
  }

  /**
   * Richardson extrapolation from the last three cycles of a sequence of
   * uniformly refined meshes (h halved per cycle): the observed order p from
   * the ratio of consecutive increments, and the limit v2 + (v2 - v1) /
   * (2^p - 1).
   */
  std::pair<double, double>
  richardson(const std::map<unsigned int, double> &cycles)
  {
    if (cycles.size() < 3)
      throw std::runtime_error("Richardson extrapolation needs 3 cycles");
    auto         last = cycles.rbegin();
    const double v2 = (last++)->second, v1 = (last++)->second,
                 v0    = last->second;
    const double ratio = (v1 - v0) / (v2 - v1);
    return {std::log2(ratio), v2 + (v2 - v1) / (ratio - 1.)};
  }
} // namespace

int
main(int argc, char **argv)
{
  if (argc != 3)
    {
      std::cerr << "usage: scene_results_check FILE.checks RESULTS.csv\n";
      return 2;
    }
  try
    {
      const Series  series = read_results(argv[2]);
      std::ifstream checks(argv[1]);
      if (!checks)
        throw std::runtime_error(std::string("cannot read '") + argv[1] + "'");
      std::string line;
      while (std::getline(checks, line))
        {
          const auto         hash = line.find('#');
          std::istringstream words(line.substr(0, hash));
          std::string        kind;
          if (!(words >> kind))
            continue;
          if (kind == "harmonics")
            {
              // harmonics QUANTITY FAMILY n1,n2,... (or none): exactly these
              std::string quantity, family, list;
              words >> quantity >> family >> list;
              std::set<unsigned int> expected;
              std::istringstream     items(list == "none" ? "" : list);
              for (std::string n; std::getline(items, n, ',');)
                expected.insert(std::stoul(n));
              const auto found = harmonics_with(series, quantity, family);
              check::that(family + " harmonics with a row " + quantity + ": " +
                            to_text(found) + ", expected " + to_text(expected),
                          found == expected);
              continue;
            }
          if (kind == "equal")
            {
              // equal QUANTITY_A QUANTITY_B N FAMILY CYCLE TOL: two results of
              // the same run agree (a symmetry or a balance)
              std::string  a, b, family, cycle;
              unsigned int n         = 0;
              double       tolerance = 0.;
              if (!(words >> a >> b >> n >> family >> cycle >> tolerance))
                throw std::runtime_error("malformed check '" + line + "'");
              check::relative(a + " vs " + b + " n=" + std::to_string(n) + " " +
                                family + " cycle " + cycle,
                              lookup(series, a, n, family, cycle),
                              lookup(series, b, n, family, cycle),
                              tolerance);
              continue;
            }
          if (kind == "richardson")
            {
              // richardson QUANTITY[*f] N FAMILY REFERENCE TOL P_MIN P_MAX
              std::string  quantity, family;
              unsigned int n   = 0;
              double reference = 0., tolerance = 0., p_min = 0., p_max = 0.;
              if (!(words >> quantity >> n >> family >> reference >>
                    tolerance >> p_min >> p_max))
                throw std::runtime_error("malformed check '" + line + "'");
              const auto star = quantity.find('*');
              const auto key =
                std::make_tuple(quantity.substr(0, star), n, family);
              const auto cycles = series.find(key);
              if (cycles == series.end())
                throw std::runtime_error("no row " + quantity);
              const double factor       = star == std::string::npos ?
                                            1. :
                                            std::stod(quantity.substr(star + 1));
              const auto [order, limit] = richardson(cycles->second);
              const std::string what =
                quantity + " n=" + std::to_string(n) + " " + family;
              check::in_range(what + " observed order", order, p_min, p_max);
              check::relative(what + " extrapolated",
                              factor * limit,
                              reference,
                              tolerance);
              continue;
            }
          if (kind == "effectivity")
            {
              // effectivity QUANTITY N FAMILY CYCLE REFERENCE MIN MAX: the
              // run's estimate QUANTITY_error (relative) over the true
              // relative error |value - reference| / |reference|
              std::string  quantity, family, cycle;
              unsigned int n         = 0;
              double       reference = 0., low = 0., high = 0.;
              if (!(words >> quantity >> n >> family >> cycle >> reference >>
                    low >> high))
                throw std::runtime_error("malformed check '" + line + "'");
              const double value = lookup(series, quantity, n, family, cycle);
              const double estimate =
                lookup(series, quantity + "_error", n, family, cycle);
              const double error =
                std::abs(value - reference) / std::abs(reference);
              check::in_range(quantity + " n=" + std::to_string(n) + " " +
                                family + " cycle " + cycle +
                                " effectivity (estimate " +
                                std::to_string(estimate) + ", error " +
                                std::to_string(error) + ")",
                              estimate / error,
                              low,
                              high);
              continue;
            }
          if (kind == "within")
            {
              // within QUANTITY N FAMILY CYCLE REFERENCE MODEL_TOL: the value
              // lies within its own error bar (the row QUANTITY_error, in the
              // value's unit) plus MODEL_TOL |REFERENCE| of the reference
              std::string  quantity, family, cycle;
              unsigned int n         = 0;
              double       reference = 0., model_tolerance = 0.;
              if (!(words >> quantity >> n >> family >> cycle >> reference >>
                    model_tolerance))
                throw std::runtime_error("malformed check '" + line + "'");
              const double value = lookup(series, quantity, n, family, cycle);
              const double bar =
                lookup(series, quantity + "_error", n, family, cycle);
              const double allowed =
                std::abs(bar) + model_tolerance * std::abs(reference);
              check::in_range(quantity + " n=" + std::to_string(n) + " " +
                                family + " cycle " + cycle + " (bar " +
                                std::to_string(bar) + " + model " +
                                std::to_string(model_tolerance) + ")",
                              value,
                              reference - allowed,
                              reference + allowed);
              continue;
            }
          std::string  quantity, family, cycle;
          unsigned int n = 0;
          double       a = 0., b = 0.;
          if (!(words >> quantity >> n >> family >> cycle >> a >> b))
            throw std::runtime_error("malformed check '" + line + "'");
          const double      value = lookup(series, quantity, n, family, cycle);
          const std::string what  = quantity + " n=" + std::to_string(n) + " " +
                                   family + " cycle " + cycle;
          if (kind == "relative")
            check::relative(what, value, a, b);
          else if (kind == "absolute")
            check::in_range(what, value, a - b, a + b);
          else if (kind == "range")
            check::in_range(what, value, a, b);
          else
            throw std::runtime_error("unknown check '" + kind + "'");
        }
    }
  catch (const std::exception &e)
    {
      std::cout << "  FAIL " << e.what() << std::endl;
      check::n_failed()++;
    }
  // A scene test without a single check would pass whatever the scene gives.
  check::that("at least one number checked",
              check::n_passed() + check::n_failed() > 0);
  return check::summary();
}
