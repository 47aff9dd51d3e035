/**
 * Numbers and boundary ids inside the free text of a .prm entry (lists such
 * as "5: r=1, z=-2..0"), read strictly: a bad token stops the run with one
 * line naming the entry.
 */
#ifndef fourier_ssi_prm_values_h
#define fourier_ssi_prm_values_h

#include <deal.II/base/types.h>
#include <string>

namespace FourierSSI
{
  /** The finite number `text` (blanks trimmed); throws naming `entry`. */
  double
  number_in_entry(const std::string &text, const std::string &entry);

  /** The boundary id `text`, an integer in [0, 254]; throws naming `entry`. */
  dealii::types::boundary_id
  boundary_id_in_entry(const std::string &text, const std::string &entry);
} // namespace FourierSSI

#endif
