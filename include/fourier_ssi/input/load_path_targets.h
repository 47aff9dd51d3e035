/**
 * Load path/Targets and Cycles: the turning points of a cyclic load path
 * (doc/cyclic-loading.md). A list of targets is a path that reverses at
 * every target; Cycles repeats a pair of them.
 */
#ifndef fourier_ssi_load_path_targets_h
#define fourier_ssi_load_path_targets_h

#include <string>
#include <vector>

namespace FourierSSI
{
  /**
   * The targets of `targets_text` ("0.01, -0.01, 0.01"), or with `cycles`
   * > 0 the two given t1, t2 expanded to t1, t2, t1, ... (`cycles` loops,
   * 2 cycles + 1 targets); empty for an empty text. Throws one line naming
   * the entry: a value that is not a number, a list of one value (a path
   * without reversal is Target's), Cycles without exactly two targets, two
   * equal neighbours or a first target of 0 (zero amplitude), and a target
   * that continues its predecessor's direction (no reversal). `target` is
   * Load path/Target, which must then be left 0.
   */
  std::vector<double>
  parse_load_path_targets(const std::string &targets_text,
                          const unsigned int cycles,
                          const double       target);
} // namespace FourierSSI

#endif
