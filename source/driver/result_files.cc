#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstring>
#include <deal.II/base/exceptions.h>
#include <filesystem>
#include <fourier_ssi/driver/result_files.h>
#include <fourier_ssi/input/atomic_file.h>
#include <map>
#include <mutex>
#include <regex>
#include <unistd.h>

namespace FourierSSI
{
  namespace
  {
    /**
     * What an interrupt signal removes: the paths the running ResultFiles
     * has claimed, as C strings (the handler may not allocate), and which
     * object published them. Each claim publishes a new array with one
     * atomic store; earlier arrays and strings are never freed, since the
     * handler may be reading one.
     */
    struct InterruptedRunFiles
    {
      const ResultFiles        *owner = nullptr;
      std::vector<const char *> paths;
    };
    std::atomic<const InterruptedRunFiles *> interrupted_run_files{nullptr};

    void
    publish_claimed(const ResultFiles              *owner,
                    const std::vector<std::string> &claimed)
    {
      auto *files  = new InterruptedRunFiles;
      files->owner = owner;
      for (const std::string &path : claimed)
        files->paths.push_back(strdup(path.c_str()));
      interrupted_run_files.store(files);
    }

    extern "C" void
    remove_claimed_and_stop(const int signal_number)
    {
      // unlink() is async-signal-safe; the array is not written after it
      // was published.
      if (const InterruptedRunFiles *files = interrupted_run_files.load())
        for (const char *path : files->paths)
          unlink(path);
      std::signal(signal_number, SIG_DFL);
      std::raise(signal_number);
    }

    /** The text of a field of the catalogue's templates. */
    const std::map<std::string, std::string> &
    field_patterns()
    {
      static const std::map<std::string, std::string> fields = {
        {"{n}", "[0-9]+"},
        {"{family}", "(symmetric|antisymmetric)"},
        {"{cycle}", "[0-9]+"},
        {"{rank}", "[0-9]+"},
        {"{id}", "[0-9]+"},
        {"{step}", "[0-9]+"},
        {"{deg}", "[0-9][0-9.e+-]*"}};
      return fields;
    }

    /** A regular expression that matches every name a template makes. */
    std::string
    pattern_of(const std::string &file_template)
    {
      std::string pattern;
      for (std::size_t i = 0; i < file_template.size();)
        {
          bool field = false;
          for (const auto &[name, text] : field_patterns())
            if (file_template.compare(i, name.size(), name) == 0)
              {
                pattern += text;
                i += name.size();
                field = true;
                break;
              }
          if (field)
            continue;
          const char c = file_template[i++];
          if (std::string(".+*?()[]{}|^$\\").find(c) != std::string::npos)
            pattern += '\\';
          pattern += c;
        }
      return pattern;
    }

    /** Names of the catalogue, and their temporary names (AtomicFile). */
    const std::regex &
    catalogue_names()
    {
      static const std::regex names = []() {
        std::string alternatives;
        for (const std::string &file_template : ResultFiles::catalogue())
          alternatives +=
            (alternatives.empty() ? "" : "|") + pattern_of(file_template);
        return std::regex("(" + alternatives + ")|\\.(" + alternatives +
                          ")\\.partial");
      }();
      return names;
    }

    void
    replace(std::string &text, const std::string &from, const std::string &to)
    {
      for (auto at = text.find(from); at != std::string::npos;
           at      = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
    }
  } // namespace

  const std::vector<std::string> &
  ResultFiles::catalogue()
  {
    // Every writer takes its name from here (claim(), path_of()).
    static const std::vector<std::string> names = {
      // Output/Results file as it is named by default: an earlier run's
      // results.csv must go when this run names its results otherwise.
      "results.csv",
      // Per harmonic and cycle: the displacement and stress amplitudes
      // (HarmonicProblem::write_vtu; one piece per rank and the .pvtu
      // record under mpirun) and the linear interfaces' tractions.
      harmonic_vtu,
      "solution-n{n}-{family}-cycle{cycle}.pvtu",
      "solution-n{n}-{family}-cycle{cycle}.rank{rank}.vtu",
      interface_tractions_csv,
      // The 3D reconstruction (FieldReconstruction).
      "lines-3d.csv",
      "solution-3d.vtu",
      // Coupled (nonlinear) runs: the load path, the record of a path that
      // stopped early, the coulomb interfaces' state.
      "load-displacement.csv",
      "load-displacement-incomplete.csv",
      "interface-state.csv",
      "interface-state-3d.vtu",
      // A cyclic path (Load path/Targets): one row per cycle.
      "load-cycles.csv",
      // Output/Interface state 3D: the interface state as a revolved
      // surface per step and its .pvd series (interface_state_surface.h).
      "interface-state-3d-step{step}.vtu",
      "interface-state-3d.pvd",
      // Refinement cycles and Target accuracy of a coupled run: each mesh
      // with the indicator that refined it.
      "mesh-cycle{cycle}.vtu",
      // Plastic soil: the plastic field per meridian plane and step, the
      // revolved soil per step, and their .pvd series (plastic_field_output.h).
      "plastic-field-theta{deg}-step{step}.vtu",
      "plastic-field-theta{deg}.pvd",
      "plastic-field-3d-step{step}.vtu",
      "plastic-field-3d.pvd",
      // Output/Soil reaction depths: the PISA curves of a plastic run.
      "soil-reaction-curves.csv",
      // Rigid foundation/Stiffness matrix: the 6x6 matrix, as CSV and as
      // OpenFAST SubDyn's SSI file.
      "foundation-stiffness.csv",
      "foundation-stiffness-subdyn.txt"};
    return names;
  }

  std::string
  ResultFiles::fill(const std::string &file_template,
                    const Harmonic    &harmonic,
                    const unsigned int cycle,
                    const unsigned int id)
  {
    std::string name = file_template;
    replace(name, "{n}", std::to_string(harmonic.n));
    replace(name, "{family}", to_string(harmonic.family));
    replace(name, "{cycle}", std::to_string(cycle));
    replace(name, "{id}", std::to_string(id));
    return name;
  }

  ResultFiles::ResultFiles(const OutputParameters &output)
    : directory(output.directory)
    , results_file(output.results_file)
  {}

  bool
  ResultFiles::is_result_file(const std::string &file_name) const
  {
    return file_name == results_file ||
           file_name == AtomicFile::temporary_name(results_file) ||
           std::regex_match(file_name, catalogue_names());
  }

  std::string
  ResultFiles::path_of(const std::string &file_name) const
  {
    AssertThrow(file_name.find('{') == std::string::npos &&
                  is_result_file(file_name),
                ExcMessage("internal error: '" + file_name +
                           "' is not in the catalogue of result files"));
    return directory + "/" + file_name;
  }

  ResultFiles::~ResultFiles()
  {
    // The run ended (it succeeded, or discard_results removed its files):
    // an interrupt now finds nothing of it to remove.
    const InterruptedRunFiles *files = interrupted_run_files.load();
    if (files != nullptr && files->owner == this)
      interrupted_run_files.store(nullptr);
  }

  std::string
  ResultFiles::claim(const std::string &file_name)
  {
    // The harmonics' writers claim from their threads.
    static std::mutex                 claim_mutex;
    const std::lock_guard<std::mutex> lock(claim_mutex);
    const std::string                 path = path_of(file_name);
    if (std::find(claimed_paths.begin(), claimed_paths.end(), path) ==
        claimed_paths.end())
      {
        claimed_paths.push_back(path);
        publish_claimed(this, claimed_paths);
      }
    return path;
  }

  std::string
  ResultFiles::claim_results_file()
  {
    return claim(results_file);
  }

  void
  ResultFiles::claim_paths(const std::vector<std::string> &paths)
  {
    for (const std::string &path : paths)
      claim(std::filesystem::path(path).filename().string());
  }

  void
  ResultFiles::remove_stale() const
  {
    std::error_code ignored;
    if (directory.empty() || !std::filesystem::is_directory(directory, ignored))
      return;
    for (const auto &entry :
         std::filesystem::directory_iterator(directory, ignored))
      if (is_result_file(entry.path().filename().string()) &&
          !entry.is_directory(ignored))
        std::filesystem::remove(entry.path(), ignored);
    // A Results file in a subfolder of the output folder.
    for (const std::string &name :
         {results_file, AtomicFile::temporary_name(results_file)})
      if (!name.empty() &&
          std::filesystem::is_regular_file(directory + "/" + name, ignored))
        std::filesystem::remove(directory + "/" + name, ignored);
  }

  void
  ResultFiles::remove_claimed() noexcept
  {
    std::error_code ignored;
    for (const std::string &path : claimed_paths)
      std::filesystem::remove(path, ignored);
    claimed_paths.clear();
    const InterruptedRunFiles *files = interrupted_run_files.load();
    if (files != nullptr && files->owner == this)
      interrupted_run_files.store(nullptr);
  }

  void
  remove_claimed_results_on_interrupt()
  {
    for (const int signal_number : {SIGTERM, SIGINT, SIGHUP})
      std::signal(signal_number, remove_claimed_and_stop);
  }

  void
  remove_stale_results_of(const std::string &prm_file)
  {
    const std::optional<OutputParameters> output =
      OutputParameters::read_folder_of(prm_file);
    if (output)
      ResultFiles(*output).remove_stale();
  }
} // namespace FourierSSI
