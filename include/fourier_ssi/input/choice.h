/**
 * The choices of an enumerated .prm value (a Patterns::Selection entry, or a
 * word inside a list such as a law's name): one table of {name, value}
 * pairs, in the order the entry documents them, from which the value of a
 * name, the name of a value, the Patterns::Selection text and the list that
 * an error line quotes all follow. One table per choice, so that the parser,
 * the log and the parameter reference cannot come to disagree.
 */
#ifndef fourier_ssi_choice_h
#define fourier_ssi_choice_h

#include <deal.II/base/exceptions.h>
#include <initializer_list>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace FourierSSI
{
  template <typename Value>
  class Choices
  {
  public:
    /**
     * The names and their values; `aliases` are further names that are
     * read but not listed (e.g. "sym" for "symmetric").
     */
    Choices(std::initializer_list<std::pair<std::string, Value>> names,
            std::initializer_list<std::pair<std::string, Value>> aliases = {})
      : names(names)
      , aliases(aliases)
    {}

    /** The value named `name` (a name or an alias), or none. */
    std::optional<Value>
    find(const std::string &name) const
    {
      for (const auto *table : {&names, &aliases})
        for (const auto &[n, value] : *table)
          if (n == name)
            return value;
      return std::nullopt;
    }

    /**
     * The value of `name`, read from an `entry` whose Patterns::Selection
     * (selection()) has checked it already; anything else is refused with
     * one line naming the entry and the choices.
     */
    Value
    value_of(const std::string &name, const std::string &entry) const
    {
      const std::optional<Value> value = find(name);
      AssertThrow(value.has_value(),
                  dealii::ExcMessage(entry + ": " + unknown("value", name)));
      return *value;
    }

    /** The (first) name of `value`. */
    const std::string &
    name_of(const Value &value) const
    {
      for (const auto &[name, v] : names)
        if (v == value)
          return name;
      AssertThrow(false, dealii::ExcInternalError());
      return names.front().first;
    }

    /** "a|b|c": the Patterns::Selection of the entry. */
    std::string
    selection() const
    {
      std::string text;
      for (const auto &[name, value] : names)
        text += (text.empty() ? "" : "|") + name;
      return text;
    }

    /**
     * "a, b or c": the names as an error line lists them, followed by the
     * `more` alternatives that are not names of this table.
     */
    std::string
    expected(const std::vector<std::string> &more = {}) const
    {
      std::vector<std::string> all;
      for (const auto &[name, value] : names)
        all.push_back(name);
      all.insert(all.end(), more.begin(), more.end());
      std::string text;
      for (unsigned int i = 0; i < all.size(); ++i)
        text += (i == 0 ? "" : i + 1 == all.size() ? " or " : ", ") + all[i];
      return text;
    }

    /** "unknown WHAT 'NAME' (expected a, b or c)": the one error text. */
    std::string
    unknown(const std::string              &what,
            const std::string              &name,
            const std::vector<std::string> &more = {}) const
    {
      return "unknown " + what + " '" + name + "' (expected " + expected(more) +
             ")";
    }

  private:
    std::vector<std::pair<std::string, Value>> names;
    std::vector<std::pair<std::string, Value>> aliases;
  };
} // namespace FourierSSI

#endif
