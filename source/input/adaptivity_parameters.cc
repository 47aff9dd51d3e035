#include <deal.II/base/utilities.h>
#include <fourier_ssi/input/adaptivity_parameters.h>
#include <fourier_ssi/input/choice.h>
#include <fourier_ssi/input/mesh_parameters.h>

namespace FourierSSI
{
  namespace
  {
    const Choices<RefinementStrategy> &
    strategies()
    {
      static const Choices<RefinementStrategy> choices{
        {"global", RefinementStrategy::global},
        {"kelly", RefinementStrategy::kelly},
        {"goal", RefinementStrategy::goal}};
      return choices;
    }

    const Choices<StiffnessGoal> &
    goals()
    {
      static const Choices<StiffnessGoal> choices{{"K_H", StiffnessGoal::K_H},
                                                  {"K_M", StiffnessGoal::K_M},
                                                  {"K_MH", StiffnessGoal::K_MH},
                                                  {"all", StiffnessGoal::all}};
      return choices;
    }
  } // namespace

  namespace
  {
    /** Strategy, its refine fraction and the stiffness goal. */
    void
    declare_strategy_entries(ParameterHandler &prm)
    {
      prm.declare_entry("Strategy",
                        "global",
                        Patterns::Selection(strategies().selection()),
                        "Refinement between cycles: global (uniform), kelly "
                        "(Kelly indicators summed over the harmonics) or goal "
                        "(dual-weighted residual for the rigid-foundation "
                        "stiffness named by 'Goal': needs Rigid foundation/"
                        "Stiffness coefficients = true, harmonic n = 1 "
                        "symmetric and Polynomial degree = 2; the error is "
                        "estimated with an FE_Q(4) solve on the same mesh, "
                        "doc/accuracy-vs-time.md). Both sides of an interface "
                        "are refined alike. With plastic soil or a coulomb "
                        "interface (Refinement cycles or Target accuracy): "
                        "global takes the uniform members, kelly refines "
                        "where the last step's mechanism is (Kelly of its "
                        "displacement increment), goal is refused "
                        "(doc/soil-plasticity.md 8d).");
      prm.declare_entry("Refine fraction",
                        "0.3",
                        Patterns::Double(0., 1.),
                        "kelly, goal: the cells holding this fraction of the "
                        "summed indicator are refined per cycle (deal.II fixed "
                        "fraction; goal indicators are squared quantities, so "
                        "a larger fraction, e.g. 0.8, suits them).");
      prm.declare_entry("Goal",
                        "all",
                        Patterns::Selection(goals().selection()),
                        "goal: the stiffness coefficient whose error steers "
                        "the mesh and stops the cycles (all: the largest "
                        "relative error of K_H, K_M, K_MH).");
      prm.declare_entry("Goal tolerance",
                        "0",
                        Patterns::Double(0.),
                        "goal: stop refining once the estimated relative error "
                        "of the goal is below this value (0: run every "
                        "Refinement cycle).");
    }

    /** The work bound of Discretization/Target accuracy. */
    void
    declare_work_bound_entries(ParameterHandler &prm)
    {
      prm.declare_entry("Maximum DoFs",
                        "5e5",
                        Patterns::Double(1.),
                        "Discretization/Target accuracy: the work bound, in "
                        "DoFs per harmonic (linear scenes: the harmonics are "
                        "solved one by one); with plastic soil or a coulomb "
                        "interface in DoFs of all harmonics together (they "
                        "are solved together), so that doubling the harmonics "
                        "is bounded too. When the next designed mesh would "
                        "exceed it, the refinement stops: the run prints the "
                        "accuracy reached and this limit, results.csv has "
                        "target_accuracy_reached = 0, and the exit code is "
                        "non-zero (unless Allow unconverged). 5e5 is about 2 "
                        "GB with the direct solver. Mesh/Maximum DoFs stays "
                        "the hard memory guard of every run.");
      prm.declare_entry("Allow unconverged",
                        "false",
                        Patterns::Bool(),
                        "Discretization/Target accuracy: true makes a run "
                        "that stops at Maximum DoFs before the target exit "
                        "with 0 (the line and the results.csv rows "
                        "target_accuracy_reached = 0, <goal>_converged = 0 "
                        "stay), for sweeps that want every case's best "
                        "value.");
    }

    /** Point, box and layer refinement before the first cycle. */
    void
    declare_a_priori_entries(ParameterHandler &prm)
    {
      prm.declare_entry("Point refinement",
                        "",
                        Patterns::Anything(),
                        "A priori grading toward singular points, before the "
                        "first cycle: 'r, z: levels; ...' refines the cells "
                        "touching each point (a vertex of the mesh, e.g. a "
                        "foundation edge) that many times, halving their size "
                        "each time (at most 25 levels: a cell 3e-8 times its "
                        "coarse size; much beyond, the vertex positions reach "
                        "round-off). Empty: none.");
      prm.declare_entry("Box refinement",
                        "",
                        Patterns::Anything(),
                        "A priori, before the point refinement: 'r0, r1, z0, "
                        "z1: levels; ...' refines the cells whose centre lies "
                        "in each box that many times (e.g. the near field of a "
                        "footing), in the order given. Empty: none.");
      prm.declare_entry("Layer refinement",
                        "",
                        Patterns::Anything(),
                        "A priori, after the point refinement: 'z=0, r=1..20: "
                        "levels; r=..., z=a..b: levels' cuts the cells with a "
                        "face on each straight segment across the segment only "
                        "(anisotropic), that many times, as long as they are "
                        "wider along it than across: thin layers graded toward "
                        "a ground surface where G(depth) vanishes (square "
                        "cells, e.g. of a corner grading on square base cells, "
                        "are left alone). Empty: none.");
    }
  } // namespace

  void
  AdaptivityParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Adaptivity");
    declare_strategy_entries(prm);
    declare_work_bound_entries(prm);
    declare_a_priori_entries(prm);
    prm.leave_subsection();
  }

  std::string
  name_of(const StiffnessGoal goal)
  {
    return goals().name_of(goal);
  }

  namespace
  {
    /** 'r, z: levels' of Adaptivity/Point refinement. */
    std::pair<Point<2>, unsigned int>
    parse_point_refinement(const std::string &item)
    {
      const std::vector<std::string> parts =
        Utilities::split_string_list(item, ':');
      const std::vector<std::string> coordinates =
        parts.size() == 2 ? Utilities::split_string_list(parts[0], ',') :
                            std::vector<std::string>();
      AssertThrow(coordinates.size() == 2,
                  ExcMessage("Adaptivity/Point refinement: '" + item +
                             "' is not 'r, z: levels'"));
      int      levels = -1;
      Point<2> point;
      try
        {
          levels = Utilities::string_to_int(parts[1]);
          point  = Point<2>(Utilities::string_to_double(coordinates[0]),
                           Utilities::string_to_double(coordinates[1]));
        }
      catch (...)
        {
          levels = -1;
        }
      AssertThrow(levels >= 0,
                  ExcMessage("Adaptivity/Point refinement: '" + item +
                             "' is not 'r, z: levels' with numbers "
                             "and levels >= 0"));
      const unsigned int limit =
        AdaptivityParameters::max_point_refinement_levels;
      AssertThrow(levels <= int(limit),
                  ExcMessage("Adaptivity/Point refinement: '" + item +
                             "' asks for " + std::to_string(levels) +
                             " levels, above the limit of " +
                             std::to_string(limit)));
      return {point, static_cast<unsigned int>(levels)};
    }

    /** 'r0, r1, z0, z1: levels' of Adaptivity/Box refinement. */
    std::pair<BoundingBox<2>, unsigned int>
    parse_box_refinement(const std::string &item)
    {
      const auto colon = item.rfind(':');
      AssertThrow(colon != std::string::npos,
                  ExcMessage("Adaptivity/Box refinement: '" + item +
                             "' is not 'r0, r1, z0, z1: levels'"));
      int levels = -1;
      try
        {
          levels =
            Utilities::string_to_int(Utilities::trim(item.substr(colon + 1)));
        }
      catch (...)
        {}
      AssertThrow(levels >= 0,
                  ExcMessage("Adaptivity/Box refinement: '" + item +
                             "' needs levels >= 0 after ':'"));
      return {parse_box(item.substr(0, colon), "Adaptivity/Box refinement"),
              static_cast<unsigned int>(levels)};
    }

    /** 'z=value, r=from..to: levels' or 'r=value, z=from..to: levels'. */
    AdaptivityParameters::LayerRefinement
    parse_layer_refinement(const std::string &item)
    {
      const std::string error = "Adaptivity/Layer refinement: '" + item +
                                "' is not 'z=value, r=from..to: levels' "
                                "or 'r=value, z=from..to: levels'";
      AdaptivityParameters::LayerRefinement layer{};
      bool                                  ok    = false;
      const auto                            colon = item.rfind(':');
      const auto                            parts =
        Utilities::split_string_list(item.substr(0, colon), ',');
      try
        {
          if (colon != std::string::npos && parts.size() == 2 &&
              parts[0].size() > 2 && parts[1].size() > 2 &&
              parts[0][1] == '=' && parts[1][1] == '=')
            {
              const char fixed = parts[0][0], along = parts[1][0];
              const auto dots = parts[1].find("..");
              if (((fixed == 'z' && along == 'r') ||
                   (fixed == 'r' && along == 'z')) &&
                  dots != std::string::npos)
                {
                  layer.fixed_coordinate = fixed == 'r' ? 0 : 1;
                  layer.value = Utilities::string_to_double(parts[0].substr(2));
                  layer.from =
                    Utilities::string_to_double(parts[1].substr(2, dots - 2));
                  layer.to =
                    Utilities::string_to_double(parts[1].substr(dots + 2));
                  const int levels = Utilities::string_to_int(
                    Utilities::trim(item.substr(colon + 1)));
                  layer.levels = levels;
                  ok           = levels >= 0 && layer.from < layer.to;
                }
            }
        }
      catch (...)
        {
          ok = false;
        }
      AssertThrow(ok, ExcMessage(error));
      return layer;
    }
  } // namespace

  void
  AdaptivityParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Adaptivity");
    const std::string strategy_name = prm.get("Strategy");
    strategy = strategies().value_of(strategy_name, "Adaptivity/Strategy");
    refine_fraction = prm.get_double("Refine fraction");
    AssertThrow(strategy == RefinementStrategy::global || refine_fraction > 0.,
                ExcMessage("Adaptivity/Refine fraction: 0 refines no cell, so "
                           "every cycle would solve the same mesh; give 0 < "
                           "fraction <= 1 with Strategy = " +
                           strategy_name));
    goal              = goals().value_of(prm.get("Goal"), "Adaptivity/Goal");
    goal_tolerance    = prm.get_double("Goal tolerance");
    maximum_dofs      = prm.get_double("Maximum DoFs");
    allow_unconverged = prm.get_bool("Allow unconverged");
    point_refinements.clear();
    for (const std::string &item :
         Utilities::split_string_list(prm.get("Point refinement"), ';'))
      point_refinements.push_back(parse_point_refinement(item));
    box_refinements.clear();
    for (const std::string &item :
         Utilities::split_string_list(prm.get("Box refinement"), ';'))
      box_refinements.push_back(parse_box_refinement(item));
    layer_refinements.clear();
    for (const std::string &item :
         Utilities::split_string_list(prm.get("Layer refinement"), ';'))
      layer_refinements.push_back(parse_layer_refinement(item));
    prm.leave_subsection();
  }
} // namespace FourierSSI
