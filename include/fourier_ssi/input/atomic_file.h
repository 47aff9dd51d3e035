/**
 * A file that appears under its name only when it is complete.
 *
 * Every result file of a run (CSV tables, VTU pieces, the batch CSV) is
 * written through this class: the text goes to a temporary name in the
 * same folder (".NAME.partial", hidden and never a result's name) and
 * commit() renames it to NAME. A rename within one folder is atomic on
 * POSIX file systems, so a reader sees the earlier state or the complete
 * file, never a part of it. A run interrupted while writing (SIGTERM, a
 * crash, an exception before commit()) leaves at most the temporary file,
 * which the next run into the folder removes (ResultFiles::remove_stale).
 */
#ifndef fourier_ssi_atomic_file_h
#define fourier_ssi_atomic_file_h

#include <fstream>
#include <string>

namespace FourierSSI
{
  class AtomicFile
  {
  public:
    /** Opens the temporary file; throws "Output: cannot write 'NAME'". */
    explicit AtomicFile(const std::string &name);

    /** Without commit(): the temporary file is removed, NAME untouched. */
    ~AtomicFile();

    AtomicFile(const AtomicFile &) = delete;
    AtomicFile &
    operator=(const AtomicFile &) = delete;

    /** Where the writer puts the file's text. */
    std::ostream &
    stream()
    {
      return out;
    }

    /**
     * Flush, check that every byte was written, and rename the temporary
     * file to its name (replacing an earlier file of that name). Throws
     * "Output: cannot write 'NAME'" if anything failed; then the temporary
     * file is removed and NAME is as it was.
     */
    void
    commit();

    /** The temporary name of `name`: ".NAME.partial" in NAME's folder. */
    static std::string
    temporary_name(const std::string &name);

  private:
    const std::string name;
    const std::string temporary;
    std::ofstream     out;
    bool              committed = false;
  };
} // namespace FourierSSI

#endif
