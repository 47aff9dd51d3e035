#include <deal.II/base/utilities.h>
#include <fourier_ssi/input/choice.h>
#include <fourier_ssi/input/discretization_parameters.h>
#include <optional>

namespace FourierSSI
{
  namespace
  {
    /** Discretization/Family: the families each listed n is solved in. */
    const Choices<std::vector<Family>> &
    family_choices()
    {
      static const Choices<std::vector<Family>> choices{
        {"symmetric", {Family::symmetric}},
        {"antisymmetric", {Family::antisymmetric}},
        {"both", {Family::symmetric, Family::antisymmetric}}};
      return choices;
    }

    /** Discretization/Volumetric strain; auto: chosen with the materials. */
    const Choices<std::optional<VolumetricStrain>> &
    volumetric_choices()
    {
      static const Choices<std::optional<VolumetricStrain>> choices{
        {"auto", std::nullopt},
        {"standard", VolumetricStrain::standard},
        {"bbar", VolumetricStrain::bbar}};
      return choices;
    }
  } // namespace

  void
  DiscretizationParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Discretization");
    prm.declare_entry("Harmonics",
                      "auto",
                      Patterns::Anything(),
                      "Fourier harmonics n to solve: 'auto' (those the loads "
                      "contain: foundation resultants and the Loads "
                      "subsection, decomposed in theta) or a list such as "
                      "'0, 1, 3' (with Family).");
    prm.declare_entry("Family",
                      "symmetric",
                      Patterns::Selection(family_choices().selection()),
                      "symmetric: u, v ~ cos n t, w ~ sin n t; "
                      "antisymmetric: u, v ~ sin n t, w ~ cos n t "
                      "(thesis eq. 3.2). For n = 0 symmetric is the "
                      "axisymmetric (u, v) problem, antisymmetric is torsion. "
                      "both: every listed n in both families (symmetric "
                      "first), e.g. n = 0 for V and T together.");
    prm.declare_entry("Polynomial degree",
                      "2",
                      Patterns::Selection("2|4"),
                      "FE_Q degree of the solid elements: 2 (pairs with the "
                      "6-node interface element) or 4 (equidistant nodes, "
                      "pairs with the 10-node interface element).");
    prm.declare_entry("Volumetric strain",
                      "auto",
                      Patterns::Selection(volumetric_choices().selection()),
                      "standard: full integration of the dilatation; bbar: "
                      "the dilatation projected onto linear polynomials per "
                      "cell (B-bar, the Q2-P1disc volumetric space), free "
                      "of volumetric locking as nu -> 0.5, Polynomial "
                      "degree 2 only (FE_Q(4) does not lock); auto: bbar "
                      "for Polynomial degree 2 when a material has nu >= "
                      "0.45, standard otherwise (standard with degree 2 and "
                      "nu >= 0.45 is solved as asked, with a warning: it "
                      "overestimates K_M of the embedded footing by 5.6 % "
                      "at nu = 0.499, doc/robustness.md).");
    prm.declare_entry("Concurrent harmonics",
                      "0",
                      Patterns::Integer(0, 256),
                      "Harmonics solved at the same time in threads (they "
                      "are independent systems); 0: one per core.");
    prm.declare_entry("Refinement cycles",
                      "1",
                      Patterns::Integer(1, 40),
                      "Solve, refine globally, solve again ... (convergence "
                      "studies). Replaced by Target accuracy when that is "
                      "set (the log says so).");
    prm.declare_entry(
      "Target accuracy",
      "",
      Patterns::Anything(),
      "Relative accuracy asked of the goal values: K_H, K_M, "
      "K_MH when Rigid foundation/Stiffness coefficients is "
      "set (and K_V, K_T with Stiffness matrix), else the rigid foundation's motion, else the "
      "reactions of the supports. When set (0 < target < "
      "1, e.g. 1e-4) the program designs the "
      "discretization: FE_Q(4), the scene's mesh graded "
      "toward its singular points (interface line ends, "
      "corners of material and removed regions, the edge of "
      "a surface patch), surface layers where G ~ "
      "depth^alpha, and nested global refinements until the "
      "estimated error is below the target or the next mesh "
      "would exceed Adaptivity/Maximum DoFs (then the run "
      "says so and exits non-zero, unless Adaptivity/Allow "
      "unconverged). Replaces Polynomial degree, "
      "Refinement cycles and Mesh/Global refinements; Point, "
      "Box and Layer refinement "
      "are applied in addition. With plastic soil or a "
      "coulomb interface (displacement control) the goal is "
      "the load at the end of the path (with plastic soil "
      "the capacity; with plastic soil under load control "
      "the work of the loads): the scene's own mesh and "
      "element with "
      "the cells doubled per member, until the mesh, "
      "harmonic-truncation and plateau errors together are "
      "below the target (doc/soil-plasticity.md section "
      "8c). Empty: the mesh as given "
      "(doc/accuracy-vs-time.md).");
    prm.leave_subsection();
  }

  void
  DiscretizationParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Discretization");
    const std::vector<Family> families =
      family_choices().value_of(prm.get("Family"), "Discretization/Family");
    harmonics.clear();
    const std::string list = Utilities::trim(prm.get("Harmonics"));
    automatic              = list == "auto";
    for (const std::string &s : automatic ? std::vector<std::string>() :
                                            Utilities::split_string_list(list))
      {
        int n = -1;
        try
          {
            n = Utilities::string_to_int(s);
          }
        catch (...)
          {}
        AssertThrow(n >= 0 && n <= 1024,
                    ExcMessage("Discretization/Harmonics: '" + s +
                               "' is not 'auto' or a harmonic number 0..1024"));
        // A repeated n would be solved twice and give duplicate rows.
        for (const Harmonic &h : harmonics)
          AssertThrow(h.n != static_cast<unsigned int>(n),
                      ExcMessage("Discretization/Harmonics: n = " + s +
                                 " is listed twice"));
        for (const Family family : families)
          harmonics.push_back({static_cast<unsigned int>(n), family});
      }
    AssertThrow(automatic || !harmonics.empty(),
                ExcMessage("Discretization/Harmonics: empty; write 'auto' or "
                           "a list such as '0, 1'"));
    degree = prm.get_integer("Polynomial degree");
    const std::optional<VolumetricStrain> chosen =
      volumetric_choices().value_of(prm.get("Volumetric strain"),
                                    "Discretization/Volumetric strain");
    volumetric_automatic = !chosen.has_value();
    volumetric           = chosen.value_or(VolumetricStrain::standard);
    AssertThrow(volumetric != VolumetricStrain::bbar || degree == 2,
                ExcMessage("Discretization/Volumetric strain = bbar needs "
                           "Polynomial degree = 2"));
    refinement_cycles        = prm.get_integer("Refinement cycles");
    concurrent_harmonics     = prm.get_integer("Concurrent harmonics");
    const std::string target = Utilities::trim(prm.get("Target accuracy"));
    target_accuracy          = 0.;
    if (!target.empty())
      {
        const std::string error =
          "Discretization/Target accuracy: '" + target +
          "' is not a relative accuracy between 0 and 1 (e.g. 1e-4)";
        try
          {
            target_accuracy = Utilities::string_to_double(target);
          }
        catch (...)
          {
            AssertThrow(false, ExcMessage(error));
          }
        AssertThrow(target_accuracy > 0. && target_accuracy < 1.,
                    ExcMessage(error));
        // The element the target designs with is chosen with the scene's
        // laws known (AllParameters::parse_parameters).
      }
    prm.leave_subsection();
  }
} // namespace FourierSSI
