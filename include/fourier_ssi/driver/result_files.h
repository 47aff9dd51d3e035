/**
 * The result files of a run: one list of what a run may write into its
 * output folder, the names the writers get from it, and their removal.
 *
 * A result left in the folder must be the result of the last run. So the
 * files an earlier run may have written are removed as soon as the folder
 * is known (remove_stale(), before the input is checked: a refused input
 * leaves no earlier results beside its error line), and the files this run
 * wrote are removed again if it fails (remove_claimed()). Both read the
 * one catalogue below, from which the writers also take their names
 * (claim()), so the list of removed files cannot drift from the writers:
 * claiming a name that is not in the catalogue is an internal error. The
 * files themselves are written through AtomicFile (complete or absent).
 * doc/output-files.md lists the files for the user.
 */
#ifndef fourier_ssi_result_files_h
#define fourier_ssi_result_files_h

#include <deal.II/base/types.h>
#include <fourier_ssi/input/harmonic.h>
#include <fourier_ssi/input/parameters.h>
#include <string>
#include <vector>

namespace FourierSSI
{
  class ResultFiles
  {
  public:
    /** No folder: writes nothing, removes nothing. */
    ResultFiles() = default;

    /** An interrupt after this no longer removes this run's files. */
    ~ResultFiles();

    ResultFiles(const ResultFiles &) = default;
    ResultFiles &
    operator=(const ResultFiles &) = default;

    /** The folder Output/Directory and the name Output/Results file. */
    explicit ResultFiles(const OutputParameters &output);

    /**
     * The catalogue: every name a run may write into its folder, as
     * templates with the fields {n} (harmonic number), {family}
     * (symmetric, antisymmetric), {cycle}, {rank} (MPI rank of a VTU
     * piece), {id} (interface boundary id), {step} (load step) and {deg}
     * (a meridian plane's angle). Output/Results file is
     * added to these by each object.
     */
    static const std::vector<std::string> &
    catalogue();

    /** The catalogue's template of a harmonic's VTU
     * (HarmonicProblem::write_vtu). */
    inline static const std::string harmonic_vtu =
      "solution-n{n}-{family}-cycle{cycle}.vtu";

    /** The catalogue's template of a linear interface's tractions. */
    inline static const std::string interface_tractions_csv =
      "interface-{id}-n{n}-{family}-cycle{cycle}.csv";

    /** A catalogue template with its fields filled in. */
    static std::string
    fill(const std::string &file_template,
         const Harmonic    &harmonic,
         const unsigned int cycle,
         const unsigned int id = 0);

    /** True if a run may write `file_name` (a name in the folder). */
    bool
    is_result_file(const std::string &file_name) const;

    /**
     * The path of `file_name` in the output folder, registered as written
     * by this run (removed by remove_claimed() and by an interrupt), once
     * however often it is claimed; thread-safe. Throws if the name is not
     * in the catalogue.
     */
    std::string
    claim(const std::string &file_name);

    /** The path of Output/Results file, claimed. */
    std::string
    claim_results_file();

    /**
     * The path of `file_name` without registering it: a record that stays
     * when the run fails (load-displacement-incomplete.csv). Throws if the
     * name is not in the catalogue.
     */
    std::string
    path_of(const std::string &file_name) const;

    /**
     * Register paths a writer made itself from a claimed name (the
     * .rankR.vtu pieces and .pvtu record of one harmonic's VTU); each must
     * be in the catalogue.
     */
    void
    claim_paths(const std::vector<std::string> &paths);

    /**
     * Remove every file of the folder that a run may write, and their
     * temporary files (AtomicFile): an earlier run's results and an
     * interrupted run's parts. Other files of the folder stay.
     */
    void
    remove_stale() const;

    /** Remove the files claimed by this run (it failed). */
    void
    remove_claimed() noexcept;

    /** The claimed paths, in order. */
    const std::vector<std::string> &
    claimed() const
    {
      return claimed_paths;
    }

  private:
    std::string              directory;
    std::string              results_file;
    std::vector<std::string> claimed_paths;
  };

  /**
   * Remove the result files of the output folder of the parameter file
   * `prm_file` (ResultFiles::remove_stale), reading only Output/Directory
   * and Output/Results file: called before the file is checked, so that
   * input refused later leaves no earlier results. A file that cannot be
   * read removes nothing.
   */
  void
  remove_stale_results_of(const std::string &prm_file);

  /**
   * SIGTERM, SIGINT and SIGHUP remove the files the running ResultFiles
   * has claimed, then end the process by the same signal: an interrupted
   * run leaves no set of complete-looking results without its results.csv
   * (each file is whole by the temporary-name rule, but together they are
   * a run that did not finish). Its `.partial` files are the next run's to
   * remove.
   */
  void
  remove_claimed_results_on_interrupt();
} // namespace FourierSSI

#endif
