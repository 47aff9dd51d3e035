// Result files appear under their name only when complete (AtomicFile), and
// ResultFiles removes exactly the files a run may write:
// - a committed file holds every byte written, and no temporary is left;
// - while a file is written, its name still holds the earlier file (or
//   nothing): a reader never sees a part;
// - a write abandoned by an exception, or by the process dying from SIGTERM
//   before commit(), leaves the earlier file byte for byte (or no file)
//   under the name;
// - ResultFiles::remove_stale() removes every catalogued name (each template
//   filled in), their temporary files and the Results file, and keeps the
//   user's other files; claiming a name outside the catalogue throws.
// Exact checks: file existence and byte counts are integers.
#include "check.h"

#include <csignal>
#include <filesystem>
#include <fourier_ssi/driver/result_files.h>
#include <fourier_ssi/input/atomic_file.h>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

using namespace FourierSSI;
namespace fs = std::filesystem;

namespace
{
  std::string
  content_of(const fs::path &file)
  {
    std::ifstream      in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  void
  write_plain(const fs::path &file, const std::string &text)
  {
    std::ofstream(file, std::ios::binary) << text;
  }

  /** A text large enough to span many stream buffers (about 2 MB). */
  std::string
  large_text()
  {
    std::string text;
    for (unsigned int i = 0; i < 200000; ++i)
      text += "row," + std::to_string(i) + "\n";
    return text;
  }

  void
  committed_file_is_complete(const fs::path &folder)
  {
    const fs::path    name = folder / "complete.csv";
    const std::string text = large_text();
    {
      AtomicFile file(name.string());
      file.stream() << text;
      // Before commit() the name does not exist yet.
      check::equal("name absent while writing", fs::exists(name), 0);
      file.commit();
    }
    check::equal("bytes of the committed file",
                 content_of(name).size(),
                 text.size());
    check::equal("committed text equal", content_of(name) == text, 1);
    check::equal("no temporary left after commit",
                 fs::exists(AtomicFile::temporary_name(name.string())),
                 0);
  }

  void
  abandoned_write_keeps_earlier_file(const fs::path &folder)
  {
    const fs::path name = folder / "earlier.csv";
    write_plain(name, "earlier run\n");
    try
      {
        AtomicFile file(name.string());
        file.stream() << large_text();
        file.stream().flush();
        // A reader during the write sees the earlier file.
        check::equal("earlier file intact while writing",
                     content_of(name) == "earlier run\n",
                     1);
        throw std::runtime_error("writer failed");
      }
    catch (const std::runtime_error &)
      {}
    check::equal("earlier file intact after an abandoned write",
                 content_of(name) == "earlier run\n",
                 1);
    check::equal("no temporary left after an abandoned write",
                 fs::exists(AtomicFile::temporary_name(name.string())),
                 0);
  }

  /**
   * A child process writes 2 MB through AtomicFile, flushes them to the
   * temporary file and then receives SIGTERM before commit(): deterministic,
   * the signal comes at a known point of the write.
   */
  void
  terminated_write_leaves_no_result(const fs::path &folder)
  {
    const fs::path name = folder / "interface-state.csv";
    const pid_t    pid  = fork();
    if (pid == 0)
      {
        AtomicFile file(name.string());
        file.stream() << large_text();
        file.stream().flush();
        raise(SIGTERM);
        _exit(0); // not reached
      }
    int status = 0;
    waitpid(pid, &status, 0);
    check::equal("child ended by SIGTERM",
                 WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM,
                 1);
    check::equal("no file under the result's name", fs::exists(name), 0);
    // The part is under the temporary name, which the next run removes.
    const fs::path part = AtomicFile::temporary_name(name.string());
    check::equal("the part is under the temporary name", fs::exists(part), 1);
    OutputParameters output;
    output.directory = folder.string();
    ResultFiles(output).remove_stale();
    check::equal("the next run removes the part", fs::exists(part), 0);
  }

  void
  stale_files_removed_others_kept(const fs::path &folder)
  {
    OutputParameters output;
    output.directory              = folder.string();
    output.results_file           = "renamed.csv";
    std::vector<std::string> ours = {
      "renamed.csv",
      ".renamed.csv.partial",
      "solution-n12-antisymmetric-cycle3.rank7.vtu"};
    for (const std::string &file_template : ResultFiles::catalogue())
      {
        std::string name = ResultFiles::fill(file_template,
                                             Harmonic{3, Family::antisymmetric},
                                             2,
                                             5);
        // The fields fill() does not know: an MPI rank, a plastic field's
        // step and meridian angle.
        for (const auto &[field, value] :
             {std::pair<std::string, std::string>{"{rank}", "1"},
              {"{step}", "4"},
              {"{deg}", "90"}})
          if (const auto at = name.find(field); at != std::string::npos)
            name.replace(at, field.size(), value);
        ours.push_back(name);
        ours.push_back(fs::path(AtomicFile::temporary_name(name)).string());
      }
    const std::vector<std::string> theirs = {"notes.txt",
                                             "results.csv.bak",
                                             "my-results.csv",
                                             "solution-n1-symmetric.vtu",
                                             "load-displacement.csv.old"};
    for (const std::string &name : ours)
      write_plain(folder / name, "x");
    for (const std::string &name : theirs)
      write_plain(folder / name, "x");
    ResultFiles(output).remove_stale();
    unsigned int left = 0, lost = 0;
    for (const std::string &name : ours)
      if (fs::exists(folder / name))
        {
          ++left;
          std::cout << "  left: " << name << std::endl;
        }
    for (const std::string &name : theirs)
      lost += !fs::exists(folder / name);
    check::equal("result files left (of " + std::to_string(ours.size()) + ")",
                 left,
                 0);
    check::equal("other files removed (of " + std::to_string(theirs.size()) +
                   ")",
                 lost,
                 0);

    ResultFiles files(output);
    bool        refused = false;
    try
      {
        files.claim("my-results.csv");
      }
    catch (const std::exception &)
      {
        refused = true;
      }
    check::equal("a name outside the catalogue is refused", refused, 1);
    const std::string claimed = files.claim("interface-state-3d.vtu");
    write_plain(claimed, "x");
    files.remove_claimed();
    check::equal("claimed file removed on failure", fs::exists(claimed), 0);
  }
} // namespace

int
main()
{
  const fs::path folder = fs::current_path() / "atomic_result_file";
  fs::remove_all(folder);
  fs::create_directories(folder);
  committed_file_is_complete(folder);
  abandoned_write_keeps_earlier_file(folder);
  terminated_write_leaves_no_result(folder);
  stale_files_removed_others_kept(folder);
  return check::summary();
}
