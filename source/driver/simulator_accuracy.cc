// The Simulator's error estimates and Discretization/Target accuracy
// (doc/accuracy-vs-time.md, "Accuracy on demand"): every goal value of a run
// is recorded on each nested mesh it is solved on, and its error estimated
// from those values (sequence_error_estimate.h).
#include <algorithm>
#include <cmath>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <fourier_ssi/driver/input_checks.h>
#include <fourier_ssi/driver/simulator.h>
#include <fourier_ssi/harmonic/distributed_linear_system.h>
#include <fourier_ssi/harmonic/harmonic_problem.h>
#include <fourier_ssi/input/messages.h>
#include <fourier_ssi/linear_algebra/serial_blas.h>
#include <fourier_ssi/mesh/discretization_design.h>
#include <iomanip>
#include <sstream>
#include <thread>

namespace FourierSSI
{
  namespace
  {
    /**
     * The goal values among a harmonic's rows: K_H, K_M, K_MH on the
     * stiffness harmonic, K_V or K_T on the n = 0 harmonics of a
     * stiffness-matrix scene; else the rigid foundation's motions; else the
     * reactions of the supports. Values at round-off next to the largest
     * of their group (a motion or reaction zero by symmetry) have no
     * relative error and are left out.
     */
    std::vector<HarmonicReport::Row>
    goal_rows(const HarmonicReport &report, const bool has_stiffness)
    {
      auto picked = [&](auto &&predicate) {
        std::vector<HarmonicReport::Row> rows;
        double                           largest = 0.;
        for (const HarmonicReport::Row &row : report.rows)
          if (predicate(row.quantity))
            {
              rows.push_back(row);
              largest = std::max(largest, std::abs(row.value));
            }
        rows.erase(std::remove_if(rows.begin(),
                                  rows.end(),
                                  [&](const auto &row) {
                                    return !(std::abs(row.value) >
                                             1e-8 * largest);
                                  }),
                   rows.end());
        return rows;
      };
      if (has_stiffness)
        return picked([](const std::string &q) {
          return q == "K_H" || q == "K_M" || q == "K_MH" || q == "K_V" ||
                 q == "K_T";
        });
      auto motions = picked([](const std::string &q) {
        return q == "foundation_horizontal_displacement" ||
               q == "foundation_rotation" ||
               q == "foundation_vertical_displacement" ||
               q == "foundation_twist";
      });
      if (!motions.empty())
        return motions;
      return picked([](const std::string &q) {
        return q.rfind("reaction_force_boundary_", 0) == 0 ||
               q.rfind("reaction_moment_boundary_", 0) == 0;
      });
    }

    /** The designed mesh of `member` (discretization_design.h), aside. */
    std::unique_ptr<Triangulation<2>>
    member_mesh(const AllParameters                &parameters,
                const unsigned int                  member,
                const std::set<types::boundary_id> &interface_ids)
    {
      auto mesh = std::make_unique<Triangulation<2>>();
      DiscretizationDesign::build_member(parameters,
                                         member,
                                         interface_ids,
                                         *mesh);
      return mesh;
    }

    /**
     * Cells of `next` over those of `current`: how the DoFs scale (the
     * decision is made before the next member is set up).
     */
    double
    cell_growth(const Triangulation<2> &next, const Triangulation<2> &current)
    {
      return static_cast<double>(next.n_active_cells()) /
             current.n_active_cells();
    }

    /** The largest DoF count of the set's harmonics. */
    double
    largest_dofs(const HarmonicSet &set)
    {
      double dofs = 0.;
      for (unsigned int i = 0; i < set.size(); ++i)
        dofs =
          std::max<double>(dofs, set.problem(i).get_dof_handler().n_dofs());
      return dofs;
    }

    /** The cores a simulator may use: `cores`, or the rank's share. */
    unsigned int
    available_cores(const unsigned int cores)
    {
      return cores > 0 ? cores : HarmonicSet::cores_per_rank();
    }

    /**
     * The error of one goal value against which the target is tested:
     * relative to the value itself, except for the coupling term K_MH,
     * whose error is relative to sqrt(K_H K_M) of the same harmonic (the
     * scale of the H-M block: |K_MH| <= sqrt(K_H K_M) for a positive
     * definite K). A coupling near zero (a surface disc at nu -> 0.5)
     * then meets a target its own relative error never could.
     */
    double
    goal_error(const GoalHistory              &history,
               const std::vector<GoalHistory> &histories,
               const double                    ratio)
    {
      const SequenceErrorEstimate e =
        estimate_sequence_error(history.values, ratio);
      if (history.quantity != "K_MH")
        return e.relative;
      const auto last = [&](const std::string &quantity) {
        for (const GoalHistory &h : histories)
          if (h.quantity == quantity && h.harmonic.n == history.harmonic.n &&
              h.harmonic.family == history.harmonic.family)
            return h.values.back();
        return 0.;
      };
      const double scale = std::sqrt(std::abs(last("K_H") * last("K_M")));
      return scale > 0. ? e.absolute / scale : e.relative;
    }

    /**
     * The estimated relative error of every goal value from its nested
     * values (eq. (1) of sequence_error_estimate.h); the largest one.
     */
    double
    largest_estimated_error(const std::vector<GoalHistory> &histories,
                            const double                    ratio)
    {
      double largest = 0.;
      for (const GoalHistory &h : histories)
        if (h.values.size() >= 2)
          largest = std::max(largest, goal_error(h, histories, ratio));
      return largest;
    }
  } // namespace

  double
  Simulator::assumed_ratio() const
  {
    return plan.meshes == MeshSequence::target_accuracy ?
             design_member_ratio(
               largest_poisson_ratio(parameters.materials),
               !DiscretizationDesign::slip_wedge_points(parameters).empty()) :
             one_halving_ratio;
  }

  void
  Simulator::record_goal_values()
  {
    for (unsigned int i = 0; i < outcomes.size(); ++i)
      {
        const Harmonic &harmonic = harmonic_set->harmonic(i);
        for (const HarmonicReport::Row &row :
             goal_rows(outcomes[i].report,
                       outcomes[i].solution.has_coefficients ||
                         outcomes[i].solution.has_axial_stiffness))
          {
            auto history =
              std::find_if(goal_histories.begin(),
                           goal_histories.end(),
                           [&](const GoalHistory &h) {
                             return h.quantity == row.quantity &&
                                    h.harmonic.n == harmonic.n &&
                                    h.harmonic.family == harmonic.family;
                           });
            if (history == goal_histories.end())
              goal_histories.push_back(
                {harmonic, row.quantity, row.unit, {row.value}});
            else
              history->values.push_back(row.value);
          }
      }
  }

  void
  Simulator::solve_coarser_member(std::ostream &log)
  {
    if (!parameters.rigid_foundation.enabled &&
        parameters.boundary_conditions.dirichlet.empty())
      return; // no goal value
    Timer timer;
    if (!DiscretizationDesign::coarsen_once(*triangulation, interface_ids))
      {
        log << "error estimate: none (the mesh has no refinement level to "
               "undo; set Discretization/Target accuracy, or Refinement "
               "cycles >= 2)"
            << std::endl;
        return;
      }
    estimate_only = true;
    try
      {
        solve_harmonics(0);
        record_goal_values();
      }
    catch (const std::exception &e)
      {
        log << "error estimate: none (the mesh coarsened once: "
            << one_line_message(e) << ")" << std::endl;
        goal_histories.clear();
      }
    estimate_only = false;
    harmonic_set.reset();
    outcomes.clear();
    make_mesh();
    estimate_wall_time = timer.wall_time();
  }

  std::unique_ptr<Triangulation<2>>
  Simulator::member_mesh_within_limits(const unsigned int member,
                                       std::ostream      &log)
  {
    const double       dofs = largest_dofs(*harmonic_set);
    std::ostringstream why;
    why << "Discretization/Target accuracy "
        << parameters.discretization.target_accuracy
        << " not reached: estimated relative error ";
    if (member >= 2)
      why << std::setprecision(2)
          << largest_estimated_error(goal_histories, assumed_ratio());
    else
      why << "unknown (one mesh solved)";
    why << " with " << static_cast<long long>(dofs) << " DoFs";
    std::unique_ptr<Triangulation<2>> next;
    try
      {
        next = member_mesh(parameters, member, interface_ids);
        if (dofs * cell_growth(*next, *triangulation) <=
            parameters.adaptivity.maximum_dofs)
          return next;
        why << "; the next mesh (about "
            << static_cast<long long>(dofs * cell_growth(*next, *triangulation))
            << " DoFs) exceeds Adaptivity/Maximum DoFs = "
            << std::setprecision(6) << parameters.adaptivity.maximum_dofs;
      }
    catch (const MeshExceedsMaximumDoFs &limit)
      {
        // Mesh/Maximum DoFs stops the design like Adaptivity/Maximum DoFs:
        // the meshes solved so far are the answer, with the target unmet.
        why << "; the next mesh: " << limit.what();
      }
    target_not_reached = why.str();
    log << target_not_reached << std::endl;
    return nullptr;
  }

  std::unique_ptr<Triangulation<2>>
  Simulator::side_by_side_mesh() const
  {
    // Two members at once need twice the cores the harmonics of one take
    // (a distributed solve's collective calls must not interleave), and
    // member 1 within Maximum DoFs by the rule the sequential path applies
    // after member 0, so that the cores never change which members are
    // solved.
    if (uses_distributed_solve(parameters.solver, communicator) ||
        available_cores(cores) <
          2 * HarmonicSet::concurrent_harmonics(
                parameters,
                plan.harmonics.size(),
                communicator,
                parameters.discretization.concurrent_harmonics,
                0))
      return nullptr;
    std::unique_ptr<Triangulation<2>> next;
    try
      {
        next = member_mesh(parameters, 1, interface_ids);
      }
    catch (const std::exception &)
      {
        return nullptr; // Mesh/Maximum DoFs: after member 0, as in sequence
      }
    DoFHandler<2> dof_handler(*triangulation);
    dof_handler.distribute_dofs(
      *make_displacement_element(parameters.discretization.degree));
    if (dof_handler.n_dofs() * cell_growth(*next, *triangulation) >
        parameters.adaptivity.maximum_dofs)
      return nullptr;
    return next;
  }

  void
  Simulator::solve_two_members(std::unique_ptr<Triangulation<2>> next,
                               std::ostream                     &log)
  {
    // Member 1 aside on its own mesh and half of the cores, member 0 on the
    // current mesh and the other half.
    std::unique_ptr<HarmonicSet> next_set;
    std::vector<HarmonicOutcome> next_outcomes;
    double                       next_wall = 0.;
    std::exception_ptr           next_error, error;
    const unsigned int           share = available_cores(cores);
    log << "meshes 0 and 1 of the design solved side by side on " << share / 2
        << " + " << share - share / 2
        << " cores (the harmonics leave cores idle)" << std::endl;
    // A member's solve with its wall time; a failure is kept for later, so
    // that both threads end before either is reported.
    const auto solve_member = [this](const Triangulation<2>       &mesh,
                                     const unsigned int            member,
                                     const unsigned int            n_cores,
                                     std::unique_ptr<HarmonicSet> &set,
                                     std::vector<HarmonicOutcome> &solved,
                                     std::exception_ptr           &failure,
                                     double                       &wall) {
      Timer timer;
      try
        {
          solve_harmonics_on(mesh, member, n_cores, set, solved);
        }
      catch (...)
        {
          failure = std::current_exception();
        }
      wall = timer.wall_time();
    };
    std::thread aside = serial_thread([&]() {
      solve_member(*next,
                   1,
                   share - share / 2,
                   next_set,
                   next_outcomes,
                   next_error,
                   next_wall);
    });
    solve_member(*triangulation,
                 0,
                 share / 2,
                 harmonic_set,
                 outcomes,
                 error,
                 cycle_wall_time);
    aside.join();
    // Failures as the sequential path reports them: member 0's first.
    if (error || next_error)
      {
        if (!error)
          collect_cycle(0, log); // as member 0 would be before member 1
        for (const HarmonicOutcome &outcome : next_outcomes)
          result_files.claim_paths(outcome.files);
        try
          {
            std::rethrow_exception(error ? error : next_error);
          }
        catch (const std::exception &e)
          {
            fail_cycle(error ? 0 : 1, outcomes, e);
          }
      }
    collect_cycle(0, log);
    record_goal_values();
    // Member 1 becomes the current mesh: the fields of member 0 are
    // released before its mesh.
    reconstruction  = FieldReconstruction();
    harmonic_set    = std::move(next_set);
    outcomes        = std::move(next_outcomes);
    triangulation   = std::move(next);
    cycle_wall_time = next_wall;
    collect_cycle(1, log);
    record_goal_values();
  }

  void
  Simulator::solve_to_target(std::ostream &log)
  {
    const double target = parameters.discretization.target_accuracy;
    // The target decides which meshes are solved: a scene written as a
    // convergence study (Refinement cycles > 1) runs with a target appended,
    // and the log says what the target replaced.
    if (parameters.discretization.refinement_cycles != 1)
      log << "Discretization/Refinement cycles = "
          << parameters.discretization.refinement_cycles
          << ": replaced by the nested meshes of Discretization/Target "
             "accuracy"
          << std::endl;
    Timer        run_timer;
    double       last_member_time = 0.;
    unsigned int member = 0, last_solved = 0;
    for (;; ++member)
      {
        std::unique_ptr<Triangulation<2>> mesh_1 =
          member == 0 ? side_by_side_mesh() : nullptr;
        if (mesh_1)
          {
            solve_two_members(std::move(mesh_1), log);
            member           = 1;
            last_member_time = cycle_wall_time;
          }
        else
          {
            if (member > 0)
              {
                std::unique_ptr<Triangulation<2>> next =
                  member_mesh_within_limits(member, log);
                if (!next)
                  break;
                reconstruction = FieldReconstruction();
                harmonic_set.reset();
                outcomes.clear();
                triangulation = std::move(next);
              }
            Timer member_timer;
            solve_harmonics(member);
            collect_cycle(member, log);
            record_goal_values();
            last_member_time = member_timer.wall_time();
          }
        last_solved = member;
        if (member == 0)
          continue;
        const double error =
          largest_estimated_error(goal_histories, assumed_ratio());
        log << "target accuracy " << target << ": mesh " << member << ", "
            << static_cast<long long>(largest_dofs(*harmonic_set))
            << " DoFs, largest estimated relative error "
            << std::setprecision(2) << error << std::endl;
        if (error <= target)
          break;
      }
    // The meshes before the answer's were solved for the estimate; side by
    // side with the answer's, they cost only the wall time they add.
    estimate_wall_time = run_timer.wall_time() - last_member_time;
    report_error_estimates(last_solved, log);
  }

  void
  Simulator::report_error_estimates(const unsigned int cycle, std::ostream &log)
  {
    unsigned int n_meshes = 0;
    for (const GoalHistory &h : goal_histories)
      n_meshes = std::max<unsigned int>(n_meshes, h.values.size());
    const double target = parameters.discretization.target_accuracy;
    if (goal_histories.empty() || (n_meshes < 2 && target == 0.))
      return;
    log << "error estimates (relative, from the goal values on the last "
        << std::min(n_meshes, 3u)
        << " nested meshes, geometric tail; doc/accuracy-vs-time.md):";
    for (const GoalHistory &h : goal_histories)
      {
        // The answer is the last mesh's (a quantity missing on the last
        // mesh, e.g. zero there, keeps its own last row).
        const unsigned int row_cycle =
          std::min<unsigned int>(cycle, h.values.size() - 1);
        bool converged = false;
        if (h.values.size() >= 2)
          {
            const SequenceErrorEstimate e =
              estimate_sequence_error(h.values, assumed_ratio());
            const double error = goal_error(h, goal_histories, assumed_ratio());
            results.add(
              h.quantity + "_error", h.harmonic, row_cycle, error, "-");
            converged = target_not_reached.empty() && error <= target;
            log << "\n    " << h.harmonic.name() << ": " << h.quantity << " = "
                << std::setprecision(7) << h.values.back() << " " << h.unit
                << " \u00b1 " << std::setprecision(2) << error
                << (h.quantity == "K_MH" && error != e.relative ?
                      " (rel. to sqrt(K_H K_M); " +
                        (std::ostringstream()
                         << std::setprecision(2) << e.relative)
                          .str() +
                        " rel. to K_MH)" :
                      " (rel)")
                << (e.asymptotic ? "" : ", rate assumed");
          }
        else
          log << "\n    " << h.harmonic.name() << ": " << h.quantity << " = "
              << std::setprecision(7) << h.values.back() << " " << h.unit
              << " (no estimate: one mesh)";
        if (plan.meshes == MeshSequence::target_accuracy)
          results.add(h.quantity + "_converged",
                      h.harmonic,
                      row_cycle,
                      converged ? 1. : 0.,
                      "-");
      }
    log << std::endl;
    const Harmonic &first = goal_histories.front().harmonic;
    results.add("time_error_estimate", first, cycle, estimate_wall_time, "s");
    if (plan.meshes == MeshSequence::target_accuracy)
      {
        results.add("target_accuracy", first, cycle, target, "-");
        results.add("target_accuracy_reached",
                    first,
                    cycle,
                    target_not_reached.empty() ? 1. : 0.,
                    "-");
      }
  }
} // namespace FourierSSI
