/**
 * Numbers and boundary ids inside the free text of a .prm entry (lists such
 * as "5: r=1, z=-2..0"), read strictly: a bad token stops the run with one
 * line naming the entry.
 */
#ifndef fourier_ssi_prm_values_h
#define fourier_ssi_prm_values_h

#include <deal.II/base/types.h>
#include <set>
#include <string>

namespace FourierSSI
{
  /** The finite number `text` (blanks trimmed); throws naming `entry`. */
  double
  number_in_entry(const std::string &text, const std::string &entry);

  /** The boundary id `text`, an integer in [0, 254]; throws naming `entry`. */
  dealii::types::boundary_id
  boundary_id_in_entry(const std::string &text, const std::string &entry);

  /**
   * Record `key` as given in the list item `item` of `entry`, refusing a
   * key given twice in one item: "kn=1e4, kn=1e5" has no meaning (which
   * value won was an accident of the parser). Every key=value list of the
   * .prm (materials, laws, interfaces, boundary values) calls this for each
   * key it reads, so the rule and its message live here only.
   */
  void
  record_key_once(std::set<std::string> &keys_given,
                  const std::string     &key,
                  const std::string     &entry,
                  const std::string     &item);
} // namespace FourierSSI

#endif
