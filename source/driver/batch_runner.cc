#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <filesystem>
#include <fourier_ssi/driver/batch_runner.h>
#include <fourier_ssi/driver/case_queue.h>
#include <fourier_ssi/driver/result_files.h>
#include <fourier_ssi/driver/simulator.h>
#include <fourier_ssi/input/atomic_file.h>
#include <fourier_ssi/input/messages.h>
#include <fourier_ssi/input/parameters.h>
#include <fstream>
#include <iomanip>
#include <map>
#include <optional>
#include <sstream>

namespace FourierSSI
{
  std::vector<std::string>
  batch_cases(const std::vector<std::string> &arguments)
  {
    std::vector<std::string> cases;
    for (const std::string &argument : arguments)
      {
        if (argument.size() > 4 &&
            argument.substr(argument.size() - 4) == ".prm")
          {
            cases.push_back(argument);
            continue;
          }
        std::ifstream in(argument);
        AssertThrow(in,
                    ExcMessage("--batch: cannot read the case list '" +
                               argument + "'"));
        const std::filesystem::path directory =
          std::filesystem::path(argument).parent_path();
        std::string line;
        while (std::getline(in, line))
          {
            line = Utilities::trim(line.substr(0, line.find('#')));
            if (line.empty())
              continue;
            const std::filesystem::path path(line);
            cases.push_back(path.is_absolute() ? line :
                                                 (directory / path).string());
          }
      }
    AssertThrow(!cases.empty(),
                ExcMessage("--batch: no cases given (usage: fourier-ssi "
                           "--batch [--csv FILE] CASE.prm... | LIST...)"));
    return cases;
  }

  void
  check_batch_output_folders(const std::vector<std::string> &cases)
  {
    // Each run removes the stale results of its folder and claims its file
    // names there, so two cases in one folder would delete each other's.
    std::map<std::string, std::string> case_of_folder;
    for (const std::string &file : cases)
      {
        const std::optional<OutputParameters> output =
          OutputParameters::read_folder_of(file);
        if (!output)
          continue; // the case fails on its own with its one line
        std::error_code       ignored;
        std::filesystem::path folder =
          std::filesystem::weakly_canonical(output->directory, ignored)
            .lexically_normal();
        if (!folder.has_filename()) // "out/" names the folder "out"
          folder = folder.parent_path();
        const auto [entry, inserted] =
          case_of_folder.emplace(folder.string(), file);
        AssertThrow(inserted,
                    ExcMessage("--batch: " + entry->second + " and " + file +
                               " both write to Output/Directory '" +
                               output->directory +
                               "' (each run removes the other's results): "
                               "give each case its own folder"));
      }
  }

  namespace
  {
    /**
     * One case of the batch, serial (MPI_COMM_SELF), as `fourier-ssi CASE`
     * would run it: its status ("ok" or the one-line error, never empty),
     * log and batch-CSV rows.
     */
    void
    solve_case(const std::string &file,
               std::string       &status,
               std::string       &log_text,
               std::string       &rows)
    {
      std::ostringstream log;
      try
        {
          // As a single run: the case's earlier results go before its input
          // is checked.
          remove_stale_results_of(file);
          AllParameters parameters;
          parameters.read_file(file);
          log << "fourier-ssi: " << file << '\n';
          Simulator          simulator(parameters);
          const ResultsTable results = simulator.run(log);
          std::ostringstream csv;
          csv << std::setprecision(12);
          for (const ResultRow &row : results.rows())
            if (row.quantity.rfind("time_", 0) != 0)
              csv << file << ',' << row.quantity << ',' << row.harmonic.n << ','
                  << to_string(row.harmonic.family) << ',' << row.cycle << ','
                  << row.value << ',' << row.unit << '\n';
          rows   = csv.str();
          status = "ok";
          // A target not reached fails the case (its rows stay, marked),
          // as it fails a single run.
          if (!simulator.unmet_target().empty() &&
              !parameters.adaptivity.allow_unconverged)
            status = simulator.unmet_target();
        }
      catch (const std::exception &e)
        {
          status = one_line_message(e);
        }
      if (status.empty())
        status = "failed";
      log_text = log.str();
    }

    /** Every case's status, log and rows as each rank left them (rank 0). */
    struct GatheredCases
    {
      std::vector<std::vector<std::string>> status, logs, rows;
      unsigned int                          n_ranks;

      /** The rank that ran case c: the first with a non-empty status. */
      unsigned int
      owner(const unsigned int c) const
      {
        unsigned int r = 0;
        while (r + 1 < n_ranks && status[r][c].empty())
          ++r;
        return r;
      }
    };

    /**
     * Rank 0: the logs in case order, one error line per failed case;
     * returns the batch CSV text (header and the rows of every case).
     */
    std::string
    report_cases(const std::vector<std::string> &cases,
                 const GatheredCases            &gathered,
                 int                            &exit_code,
                 std::ostream                   &out,
                 std::ostream                   &err)
    {
      std::ostringstream csv;
      csv << "case,quantity,n,family,cycle,value,unit\n";
      for (unsigned int c = 0; c < cases.size(); ++c)
        {
          const unsigned int r = gathered.owner(c);
          out << gathered.logs[r][c];
          if (gathered.status[r][c] != "ok")
            {
              err << "fourier-ssi: error: " << cases[c] << ": "
                  << gathered.status[r][c] << std::endl;
              exit_code = 1;
            }
          csv << gathered.rows[r][c];
        }
      return csv.str();
    }

    /**
     * The succeeded cases' rows are written (a failed case has none);
     * the failed ones are listed on stderr and the exit code is 1. With
     * no case succeeded there is no file, not even an earlier one.
     */
    void
    write_batch_csv(const std::string &csv_file,
                    const std::string &csv,
                    const unsigned int n_ok,
                    const unsigned int n_cases,
                    const unsigned int n_ranks,
                    int               &exit_code,
                    std::ostream      &out,
                    std::ostream      &err)
    {
      std::filesystem::remove(csv_file);
      if (n_ok > 0)
        {
          bool written = false;
          try
            {
              AtomicFile file(csv_file);
              file.stream() << csv;
              file.commit();
              written = true;
            }
          catch (const std::exception &)
            {
              err << "fourier-ssi: error: --batch: cannot write '" << csv_file
                  << "'" << std::endl;
              exit_code = 1;
            }
          if (written)
            out << n_ok << " of " << n_cases << " cases succeeded on "
                << n_ranks << " ranks, their results written to " << csv_file
                << std::endl;
        }
      if (n_ok < n_cases)
        err << "fourier-ssi: error: --batch: " << n_cases - n_ok << " of "
            << n_cases << " cases failed (listed above)"
            << (n_ok > 0 ? "; " + csv_file + " holds the others" : "")
            << std::endl;
    }
  } // namespace

  int
  run_batch(const std::vector<std::string> &arguments,
            const MPI_Comm                  communicator,
            std::ostream                   &out,
            std::ostream                   &err)
  {
    const unsigned int rank    = Utilities::MPI::this_mpi_process(communicator);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(communicator);
    std::string        csv_file = "batch.csv";
    std::vector<std::string> rest;
    for (unsigned int i = 0; i < arguments.size(); ++i)
      if (arguments[i] == "--csv" && i + 1 < arguments.size())
        csv_file = arguments[++i];
      else
        rest.push_back(arguments[i]);
    // Every rank expands the list itself (same files, same result), so an
    // unreadable list fails on all ranks alike.
    const std::vector<std::string> cases = batch_cases(rest);
    check_batch_output_folders(cases);

    // Per case: status ("ok" or the error), log, CSV rows. Cases of other
    // ranks stay empty strings: a non-empty status marks the case's rank.
    std::vector<std::string> status(cases.size()), logs(cases.size()),
      rows(cases.size());
    {
      CaseQueue queue(communicator, cases.size());
      for (unsigned int c = queue.next(); c < cases.size(); c = queue.next())
        solve_case(cases[c], status[c], logs[c], rows[c]);
    }

    const GatheredCases gathered{Utilities::MPI::gather(communicator,
                                                        status,
                                                        0),
                                 Utilities::MPI::gather(communicator, logs, 0),
                                 Utilities::MPI::gather(communicator, rows, 0),
                                 n_ranks};
    int                 exit_code = 0;
    if (rank == 0)
      {
        const std::string csv =
          report_cases(cases, gathered, exit_code, out, err);
        unsigned int n_ok = 0;
        for (unsigned int c = 0; c < cases.size(); ++c)
          n_ok += gathered.status[gathered.owner(c)][c] == "ok";
        write_batch_csv(
          csv_file, csv, n_ok, cases.size(), n_ranks, exit_code, out, err);
      }
    return Utilities::MPI::broadcast(communicator, exit_code, 0);
  }
} // namespace FourierSSI
