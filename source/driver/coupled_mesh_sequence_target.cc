// Discretization/Target accuracy for the coupled scenes (plastic soil,
// coulomb interfaces): the goal value of the load path (the capacity, or
// the load at the end of the path) on nested members of the scene's own
// mesh, with its error from the members, the harmonic truncation and the
// plateau (doc/soil-plasticity.md section 8c). The solver-specific parts
// come from the scene run (coupled_scene_run.h).
#include <algorithm>
#include <cmath>
#include <deal.II/base/timer.h>
#include <fourier_ssi/driver/coupled_mesh_sequence.h>
#include <fourier_ssi/driver/load_path_capacity.h>
#include <fourier_ssi/driver/memory_estimate.h>
#include <fourier_ssi/estimation/sequence_error_estimate.h>
#include <fourier_ssi/fourier/theta_sampling.h>
#include <fourier_ssi/input/messages.h>
#include <fourier_ssi/mesh/adaptivity.h>
#include <fourier_ssi/mesh/discretization_design.h>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>

namespace FourierSSI
{
  namespace
  {
    /**
     * The ratio of the goal's changes per doubling of n_max where fewer
     * than three values cannot show it; the capacity studies measured
     * 0.27-0.46 (doc/verification/soil-plasticity.md 8b, 8c).
     */
    constexpr double harmonic_doubling_ratio = 0.5;

    /**
     * n_max = 2 with n = 1 among the listed harmonics (a lateral
     * response; n_max the highest listed, or the Maximum harmonic of the
     * harmonics grown from them): n <= 1 and
     * n <= 2 both lack n = 3, which carries the first correction of a
     * lateral plastic response (odd in the lateral motion: on the pile
     * slice of prm/pile-capacity.prm n <= 1 and n <= 2 differ by 0.45 %
     * while n <= 2 is 6.5 % above n <= 8; doc/soil-plasticity.md 8c), so
     * their difference is no estimate of the truncation.
     */
    bool
    lateral_truncation_unseen(const std::vector<Harmonic> &harmonics,
                              const unsigned int           n_max)
    {
      return n_max == 2 &&
             std::any_of(harmonics.begin(),
                         harmonics.end(),
                         [](const Harmonic &h) { return h.n == 1; });
    }

    /**
     * The truncated sets n <= n_max / 4 and n_max / 2 whose goal values,
     * with the scene's, give the truncation error: those that keep the
     * loaded harmonics (n <= 1) and differ from the scene's; none where
     * they cannot see the truncation (lateral_truncation_unseen()).
     */
    std::vector<unsigned int>
    truncations(const std::vector<Harmonic> &harmonics,
                const unsigned int           n_max)
    {
      std::vector<unsigned int> result;
      if (lateral_truncation_unseen(harmonics, n_max))
        return result;
      for (const unsigned int n : {n_max / 4, n_max / 2})
        if (n >= 1 && n < n_max && (result.empty() || result.back() != n))
          result.push_back(n);
      return result;
    }

    /** n = 0 .. n_max in each family of `harmonics`. */
    std::vector<Harmonic>
    harmonics_up_to(const std::vector<Harmonic> &harmonics,
                    const unsigned int           n_max)
    {
      std::vector<Harmonic> result;
      for (unsigned int n = 0; n <= n_max; ++n)
        for (const Family family : {Family::symmetric, Family::antisymmetric})
          if (std::any_of(harmonics.begin(),
                          harmonics.end(),
                          [&](const Harmonic &h) {
                            return h.family == family;
                          }))
            result.push_back({n, family});
      return result;
    }

    /** "capacity V", "end load H": the goal as the log names it. */
    std::string
    label(const std::string &prefix, const std::string &name)
    {
      std::string text = prefix + name;
      std::replace(text.begin(), text.end(), '_', ' ');
      return text;
    }

    /** The values of a map in the order of its keys. */
    std::vector<double>
    values_of(const std::map<unsigned int, double> &known)
    {
      std::vector<double> values;
      for (const auto &[n_max, value] : known)
        values.push_back(value);
      return values;
    }

    /**
     * How the harmonic part of a target's bar was found, or why it was
     * not: the words of the error line.
     */
    std::string
    harmonic_error_source(const std::vector<Harmonic> &harmonics,
                          const bool                   estimated,
                          const bool                   growth)
    {
      if (highest_harmonic(harmonics) == 0)
        return "none (n = 0 only: an axisymmetric problem)";
      if (estimated && growth)
        return "from Maximum harmonic halved on the coarsest mesh (grown by "
               "the solution)";
      if (estimated)
        return "from n_max halved on the coarsest mesh";
      if (growth)
        return "NOT estimated (Maximum harmonic = 2 or less cannot be "
               "halved; set 4 or more)";
      if (lateral_truncation_unseen(harmonics, highest_harmonic(harmonics)))
        return "NOT estimated (n_max = 2: n <= 1 and n <= 2 both lack n = 3, "
               "the first correction of a lateral response; list n <= 3 or "
               "more)";
      return "NOT estimated (n_max = 1 cannot be halved)";
    }

    std::string
    number(const double value)
    {
      std::ostringstream out;
      out << std::setprecision(2) << value;
      return out.str();
    }

    /** A relative error as printed: two digits, or "not estimated". */
    std::string
    estimate_text(const double value)
    {
      return std::isfinite(value) ? number(value) : "not estimated";
    }
  } // namespace

  bool
  CoupledMeshSequence::grows() const
  {
    return run.get_solver_parameters().load_path.maximum_harmonic >
           highest_harmonic(plan.harmonics);
  }

  unsigned int
  CoupledMeshSequence::truncated_n_max() const
  {
    return grows() ? run.get_solver_parameters().load_path.maximum_harmonic :
                     highest_harmonic(plan.harmonics);
  }

  void
  CoupledMeshSequence::solve_fewer_harmonics(
    std::map<unsigned int, double> &known,
    std::ostream                   &log)
  {
    // With growth the truncation is the Maximum harmonic's: the runs with
    // n <= n_max / 4 and n_max / 2 grow up to those, as the answer's path
    // grows up to n_max.
    const std::vector<Harmonic> all = plan.harmonics;
    const unsigned int          setting =
      run.get_solver_parameters().load_path.maximum_harmonic;
    const bool growth = grows();
    // The answer's harmonics back (the solver released with them).
    const auto restore = [&]() {
      plan.harmonics = all;
      run.set_maximum_harmonic(setting);
    };
    for (const unsigned int n_max : truncations(all, truncated_n_max()))
      {
        if (known.count(n_max) > 0)
          continue; // solved before the last doubling
        plan.harmonics.clear();
        for (const Harmonic &h : all)
          if (h.n <= n_max)
            plan.harmonics.push_back(h);
        run.set_maximum_harmonic(growth ? n_max : setting);
        // Its own log: the study's curves are not the answer's.
        std::ostringstream study_log;
        CoupledGoal        goal;
        try
          {
            goal = run.solve(study_log);
          }
        catch (const std::exception &e)
          {
            // Say which run failed: the answer's harmonics are not these.
            restore();
            AssertThrow(false,
                        ExcMessage(
                          one_line_message(e) +
                          " (in the run with n <= " + std::to_string(n_max) +
                          " that Discretization/Target accuracy "
                          "makes for the harmonic truncation)"));
          }
        known[n_max] = goal.value;
        restore();
        harmonic_set.reset();
        log << "  harmonics n <= " << n_max << (growth ? " (grown)" : "")
            << ": " << goal.name << " = " << goal.value << " " << goal.unit
            << std::endl;
      }
  }

  namespace
  {
    /**
     * The wall time of the next member, from the last one's: times the
     * growth of the last two members' times where two were solved on these
     * harmonics, else as the factorization of a 2D sparse system grows
     * with nested dissection, N^1.5 (an estimate, printed as such).
     */
    double
    next_member_time(const std::vector<double> &member_times,
                     const double               cell_growth)
    {
      if (member_times.empty())
        return std::nan("");
      const std::size_t n      = member_times.size();
      const double      growth = n >= 2 && member_times[n - 2] > 0. ?
                                   member_times[n - 1] / member_times[n - 2] :
                                   std::pow(cell_growth, 1.5);
      return member_times.back() * growth;
    }

    /**
     * The line before a member of the coupled target starts: its size and
     * the estimate of its time, so that a run that grows for minutes says
     * so before each member.
     */
    void
    announce_member(const int          member,
                    const unsigned int n_cells,
                    const double       dofs,
                    const double       estimated_time,
                    std::ostream      &log)
    {
      log << "target accuracy: starting mesh " << member << ", " << n_cells
          << " cells, about " << static_cast<long long>(dofs)
          << " DoFs over all harmonics";
      if (std::isfinite(estimated_time))
        log << ", estimated " << std::setprecision(2) << estimated_time
            << std::setprecision(6) << " s";
      log << std::endl;
    }
  } // namespace

  double
  CoupledMeshSequence::coupled_dofs() const
  {
    double dofs = 0.;
    for (unsigned int h = 0; h < harmonic_set->size(); ++h)
      dofs += harmonic_set->problem(h).get_dof_handler().n_dofs();
    return dofs;
  }

  void
  CoupledMeshSequence::target_unmet(const double       target,
                                    const std::string &why,
                                    std::ostream      &log)
  {
    target_not_reached = "Discretization/Target accuracy " + number(target) +
                         " not reached: " + why;
    log << target_not_reached << std::endl;
  }

  bool
  CoupledMeshSequence::double_harmonics(const double       target,
                                        const std::string &reason,
                                        std::ostream      &log)
  {
    // The DoFs of all harmonics grow with their number (one coupled LU).
    const double       dofs   = coupled_dofs();
    const unsigned int n_max  = truncated_n_max();
    const bool         growth = grows();
    const double       more   = (2. * n_max + 1.) / (n_max + 1.);
    // The doubled set must also fit in memory: its theta samples and its
    // coupled tangent grow with the harmonics, faster than their DoFs.
    // With growth the Maximum harmonic is doubled, the listed ones kept;
    // the estimate counts every harmonic it could add.
    AllParameters doubled_parameters = run.get_solver_parameters();
    ScenePlan     doubled_plan       = plan;
    if (growth)
      doubled_parameters.load_path.maximum_harmonic = 2 * n_max;
    doubled_plan.harmonics      = harmonics_up_to(plan.harmonics, 2 * n_max);
    const std::string shortfall = memory_shortfall(
      estimate_run_memory(doubled_parameters, triangulation, doubled_plan),
      available_memory_on_all_ranks(communicator));
    if (!shortfall.empty())
      {
        target_unmet(target,
                     reason + "; doubling the harmonics: " + shortfall,
                     log);
        return false;
      }
    if (more * dofs > parameters.adaptivity.maximum_dofs || 2 * n_max > 1024)
      {
        std::ostringstream why;
        why << reason << "; doubling the harmonics (about "
            << static_cast<long long>(more * dofs)
            << " DoFs) would exceed Adaptivity/Maximum DoFs = "
            << parameters.adaptivity.maximum_dofs;
        target_unmet(target, why.str(), log);
        return false;
      }
    run.release();
    harmonic_set.reset();
    if (growth)
      run.set_maximum_harmonic(2 * n_max);
    else
      plan.harmonics = doubled_plan.harmonics;
    log << "target accuracy " << number(target) << ": " << reason << ": "
        << (growth ? "Maximum harmonic doubled to n = " :
                     "harmonics doubled to n <= ")
        << 2 * n_max << std::endl;
    return true;
  }

  bool
  CoupledMeshSequence::next_coupled_member(
    const int                    member,
    const CoupledTargetProgress &progress,
    std::ostream                &log)
  {
    const double target = parameters.discretization.target_accuracy;
    // Newton's coupled tangent is one LU over all harmonics: their DoFs
    // together are what Maximum DoFs bounds here.
    const double     dofs = coupled_dofs();
    Triangulation<2> next;
    next_coupled_mesh(member, next);
    const double more = cell_growth(next);
    if (more * dofs > parameters.adaptivity.maximum_dofs)
      {
        std::ostringstream why;
        why << "estimated relative error of the "
            << label(run.goal_prefix(), progress.goal.name) << " "
            << (progress.mesh_values.size() >= 2 ?
                  number(progress.relative(progress.mesh_error +
                                           progress.harmonic_error +
                                           progress.goal.plateau_error)) :
                  std::string("unknown (one mesh solved)"))
            << " with " << static_cast<long long>(dofs)
            << " DoFs (all harmonics); the next mesh (about "
            << static_cast<long long>(more * dofs)
            << ") exceeds Adaptivity/Maximum DoFs = "
            << parameters.adaptivity.maximum_dofs;
        target_unmet(target, why.str(), log);
        return false;
      }
    const std::string shortfall = memory_shortfall(
      estimate_run_memory(run.get_solver_parameters(), next, plan),
      available_memory_on_all_ranks(communicator));
    if (!shortfall.empty())
      {
        target_unmet(target,
                     "the next mesh (" + std::to_string(next.n_active_cells()) +
                       " cells): " + shortfall,
                     log);
        return false;
      }
    announce_member(member,
                    next.n_active_cells(),
                    more * dofs,
                    next_member_time(progress.member_times, more),
                    log);
    adopt_coupled_mesh(next);
    return true;
  }

  CoupledMeshSequence::CoarsestMember
  CoupledMeshSequence::coarsest_member_harmonics(
    CoupledTargetProgress &progress,
    std::ostream          &log)
  {
    const double       target = parameters.discretization.target_accuracy;
    const unsigned int n_max  = truncated_n_max();
    progress.known[n_max]     = progress.goal.value;
    std::string reason;
    if (progress.known.size() >= 2)
      {
        progress.harmonic_error =
          estimate_sequence_error(values_of(progress.known),
                                  harmonic_doubling_ratio)
            .absolute;
        if (progress.relative(progress.harmonic_error) <= 0.5 * target)
          return CoarsestMember::solved;
        reason = "the harmonic truncation (n <= " + std::to_string(n_max) +
                 ") alone is " +
                 number(progress.relative(progress.harmonic_error)) +
                 ", more than half of it";
      }
    else if (lateral_truncation_unseen(plan.harmonics, n_max))
      reason = "n <= 1 and n <= 2 cannot show the truncation of a lateral "
               "response (n = 3 carries its first correction)";
    else
      return CoarsestMember::solved;
    // Double the harmonics and solve this (the cheapest) mesh again, the
    // values of fewer harmonics kept.
    if (!double_harmonics(target, reason, log))
      return CoarsestMember::stop;
    progress.mesh_values.clear();
    progress.member_times.clear();
    return CoarsestMember::solve_again;
  }

  bool
  CoupledMeshSequence::coupled_target_settled(const int              member,
                                              CoupledTargetProgress &progress,
                                              std::ostream          &log)
  {
    const double target       = parameters.discretization.target_accuracy;
    progress.mesh_error       = coupled_mesh_error(progress.mesh_values);
    const double      plateau = progress.goal.plateau_error;
    const double      total   = progress.relative(progress.mesh_error +
                                           progress.harmonic_error + plateau);
    const std::string goal    = label(run.goal_prefix(), progress.goal.name);
    log << "target accuracy " << target << ": mesh " << member
        << ", estimated relative error of the " << goal << " " << number(total)
        << std::endl;
    if (total <= target)
      return true;
    // What a finer mesh cannot lower: stop, saying which.
    if (!(progress.relative(progress.harmonic_error + plateau) > target))
      return false;
    target_unmet(target,
                 "estimated relative error of the " + goal + " " +
                   number(total) + ", of which the harmonic truncation (n <= " +
                   std::to_string(truncated_n_max()) + ") " +
                   number(progress.relative(progress.harmonic_error)) +
                   " and the plateau " + number(progress.relative(plateau)) +
                   " do not fall with the mesh: " +
                   (grows() ?
                      "raise Load path/Maximum harmonic" :
                      "list more harmonics (Discretization/Harmonics)") +
                   " or take the path further (Load path/Target)",
                 log);
    return true;
  }

  void
  CoupledMeshSequence::solve_to_target(std::ostream &log)
  {
    // Members: the scene's mesh and element, 2^k cells per segment
    // (build_plastic_member); on member 0 the harmonic truncation (n_max /
    // 4, n_max / 2, n_max); on every member the plateau's error (capacity
    // runs). With growth (Load path/Maximum harmonic above the listed)
    // n_max is the Maximum harmonic. The answer is the last member's value.
    const double          target = parameters.discretization.target_accuracy;
    Timer                 run_timer;
    double                last_member_time = 0.;
    CoupledTargetProgress progress;
    int                   last_solved = 0;
    for (int member = 0;; ++member)
      {
        if (member > 0 && !next_coupled_member(member, progress, log))
          break;
        Timer member_timer;
        log << "target accuracy " << target << ": mesh " << member << ", "
            << triangulation.n_active_cells() << " cells" << std::endl;
        // The truncation on the coarsest mesh: cheap, and the harmonics'
        // share of the error changes little with the mesh
        // (doc/verification/soil-plasticity.md 8b).
        if (member == 0)
          solve_fewer_harmonics(progress.known, log);
        progress.goal = run.solve(log);
        last_solved   = member;
        progress.mesh_values.push_back(progress.goal.value);
        last_member_time = member_timer.wall_time();
        progress.member_times.push_back(last_member_time);
        if (!std::isfinite(progress.goal.plateau_error))
          {
            target_unmet(target,
                         "the curve does not bend over by its end (no "
                         "plateau: raise Load path/Target)",
                         log);
            break;
          }
        if (member == 0)
          {
            const CoarsestMember next =
              coarsest_member_harmonics(progress, log);
            if (next == CoarsestMember::stop)
              break;
            if (next == CoarsestMember::solve_again)
              --member; // member 0 again (the loop's ++ brings it back)
            continue;   // two meshes are needed for the mesh error
          }
        if (coupled_target_settled(member, progress, log))
          break;
      }
    estimate_wall_time = run_timer.wall_time() - last_member_time;
    write_coupled_mesh(last_solved, Vector<float>());
    // Not estimated: NaN; n = 0 alone is axisymmetric, no truncation.
    const double harmonics =
      progress.known.size() >= 2            ? progress.harmonic_error :
      highest_harmonic(plan.harmonics) == 0 ? 0. :
                                              std::nan("");
    report_coupled_error(progress.goal,
                         progress.mesh_values.size(),
                         progress.mesh_error,
                         harmonics,
                         harmonic_error_source(plan.harmonics,
                                               std::isfinite(harmonics),
                                               grows()),
                         log);
    run.write_files(log);
  }

  void
  CoupledMeshSequence::report_coupled_error(const CoupledGoal &goal,
                                            const unsigned int n_meshes,
                                            const double       mesh_error,
                                            const double       harmonic_error,
                                            const std::string &harmonic_source,
                                            std::ostream      &log)
  {
    const double target = parameters.discretization.target_accuracy;
    const double scale  = std::abs(goal.value);
    const double nan    = std::numeric_limits<double>::quiet_NaN();
    // A part not estimated counts as zero in the total but is said so.
    const double harmonics =
      std::isfinite(harmonic_error) ? harmonic_error : 0.;
    const double total =
      n_meshes >= 2 ? (mesh_error + harmonics + goal.plateau_error) / scale :
                      nan;
    const bool reached = target_not_reached.empty() && total <= target;
    run.add_rows(log);
    log << "error estimate of the " << label(run.goal_prefix(), goal.name)
        << " (relative; the mesh from " << n_meshes
        << " nested meshes, geometric tail; the harmonics " << harmonic_source
        << (run.has_plateau() ? "; the plateau" : "") << "):\n    " << goal.name
        << " = " << std::setprecision(7) << goal.value << " " << goal.unit
        << " \u00b1 " << estimate_text(total) << " (rel): mesh "
        << estimate_text(n_meshes >= 2 ? mesh_error / scale : nan)
        << ", harmonics " << estimate_text(harmonic_error / scale);
    if (run.has_plateau())
      log << ", plateau " << estimate_text(goal.plateau_error / scale);
    log << std::setprecision(6) << std::endl;
    if (run.goal_prefix() == "capacity_")
      report_normalised_capacity(parameters.rigid_foundation,
                                 goal.name,
                                 goal.value,
                                 goal.unit,
                                 total,
                                 "mesh, harmonics and plateau",
                                 goal.steps,
                                 results,
                                 log);
    const Harmonic     any{0, Family::symmetric};
    const unsigned int row  = goal.steps;
    const std::string  name = run.goal_prefix() + goal.name;
    if (run.goal_prefix() != "capacity_") // the capacity has its own row
      results.add(name, any, row, goal.value, goal.unit);
    results.add(name + "_error", any, row, total, "-");
    results.add(name + "_error_mesh",
                any,
                row,
                n_meshes >= 2 ? mesh_error / scale : nan,
                "-");
    results.add(
      name + "_error_harmonics", any, row, harmonic_error / scale, "-");
    if (run.has_plateau())
      results.add(
        name + "_error_plateau", any, row, goal.plateau_error / scale, "-");
    // Refinement cycles have no target.
    if (plan.meshes == MeshSequence::target_accuracy)
      {
        results.add(name + "_converged", any, row, reached ? 1. : 0., "-");
        results.add("target_accuracy", any, row, target, "-");
        results.add(
          "target_accuracy_reached", any, row, reached ? 1. : 0., "-");
      }
    results.add("time_error_estimate", any, row, estimate_wall_time, "s");
  }
} // namespace FourierSSI
