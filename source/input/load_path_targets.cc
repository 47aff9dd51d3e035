#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <fourier_ssi/input/load_path_targets.h>
#include <fourier_ssi/input/prm_values.h>
#include <sstream>

namespace FourierSSI
{
  namespace
  {
    const std::string entry = "Load path/Targets";

    std::vector<double>
    numbers_of(const std::string &text)
    {
      std::vector<double> values;
      for (const std::string &word : dealii::Utilities::split_string_list(text))
        values.push_back(number_in_entry(word, entry));
      return values;
    }

    /** The pair t1, t2 as `cycles` loops: t1, t2, t1, ..., t1. */
    std::vector<double>
    repeated(const std::vector<double> &pair, const unsigned int cycles)
    {
      AssertThrow(pair.size() == 2,
                  dealii::ExcMessage(
                    "Load path/Cycles: " + std::to_string(cycles) +
                    " cycles need Targets of exactly two values, the turning "
                    "points each cycle goes between (" +
                    std::to_string(pair.size()) + " given)"));
      std::vector<double> targets = {pair[0]};
      for (unsigned int c = 0; c < cycles; ++c)
        {
          targets.push_back(pair[1]);
          targets.push_back(pair[0]);
        }
      return targets;
    }

    /** Each segment reverses the one before and has a length. */
    void
    check_reversals(const std::vector<double> &targets)
    {
      AssertThrow(targets.size() >= 2,
                  dealii::ExcMessage(
                    entry +
                    ": one value is a path without reversal: give it as "
                    "Load path/Target (a cyclic path lists two or more "
                    "turning points)"));
      AssertThrow(targets[0] != 0.,
                  dealii::ExcMessage(entry +
                                     ": the first target is 0, where the "
                                     "path starts: zero amplitude"));
      for (unsigned int k = 1; k < targets.size(); ++k)
        {
          std::ostringstream pair;
          pair << targets[k - 1] << " to " << targets[k];
          AssertThrow(targets[k] != targets[k - 1],
                      dealii::ExcMessage(entry + ": " + pair.str() +
                                         " is a segment of zero amplitude"));
          const double before = targets[k - 1] - (k > 1 ? targets[k - 2] : 0.);
          const double now    = targets[k] - targets[k - 1];
          AssertThrow(before * now < 0.,
                      dealii::ExcMessage(
                        entry + ": " + pair.str() +
                        " goes on in the direction of the segment before: "
                        "a list of targets must reverse at every target"));
        }
    }
  } // namespace

  std::vector<double>
  parse_load_path_targets(const std::string &targets_text,
                          const unsigned int cycles,
                          const double       target)
  {
    const std::vector<double> given = numbers_of(targets_text);
    if (given.empty())
      {
        AssertThrow(cycles == 0,
                    dealii::ExcMessage(
                      "Load path/Cycles: " + std::to_string(cycles) +
                      " cycles need Load path/Targets, the two turning "
                      "points each cycle goes between"));
        return given;
      }
    AssertThrow(target == 0.,
                dealii::ExcMessage(
                  "Load path/Targets: give either Target (one monotonic "
                  "path) or Targets (a cyclic path), not both"));
    const std::vector<double> targets =
      cycles > 0 ? repeated(given, cycles) : given;
    check_reversals(targets);
    return targets;
  }
} // namespace FourierSSI
