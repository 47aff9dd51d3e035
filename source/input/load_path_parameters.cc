#include <fourier_ssi/input/choice.h>
#include <fourier_ssi/input/load_path_parameters.h>
#include <fourier_ssi/input/load_path_targets.h>

namespace FourierSSI
{
  namespace
  {
    using Control      = LoadPathParameters::Control;
    using Motion       = LoadPathParameters::Motion;
    using Acceleration = LoadPathParameters::Acceleration;
    using Stiffness    = LoadPathParameters::Stiffness;

    const Choices<Control> &
    controls()
    {
      static const Choices<Control> choices{{"load", Control::load},
                                            {"displacement",
                                             Control::displacement}};
      return choices;
    }

    const Choices<Motion> &
    motions()
    {
      static const Choices<Motion> choices{{"vertical", Motion::vertical},
                                           {"twist", Motion::twist},
                                           {"horizontal", Motion::horizontal},
                                           {"rotation", Motion::rotation}};
      return choices;
    }

    const Choices<Acceleration> &
    accelerations()
    {
      static const Choices<Acceleration> choices{
        {"aitken", Acceleration::aitken},
        {"anderson", Acceleration::anderson},
        {"none", Acceleration::none}};
      return choices;
    }

    const Choices<Stiffness> &
    stiffnesses()
    {
      static const Choices<Stiffness> choices{{"auto", Stiffness::automatic},
                                              {"initial", Stiffness::initial},
                                              {"tangent", Stiffness::tangent}};
      return choices;
    }

    /** Theta samples and the load steps. */
    void
    declare_sampling_and_step_entries(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Theta samples",
        "0",
        Patterns::Integer(0, LoadPathParameters::most_theta_samples),
        "Angles N at which the interface law and the soil law are "
        "evaluated. 0: 4 (n_max + 1); 2 n_max + 1 (one sample per value "
        "of a band-limited gap) in an interface-only scene with a contact "
        "interface or a stiff coulomb penalty (as Stiffness = auto "
        "decides it; whichever Stiffness is chosen). With plastic soil it sets "
        "the soil's samples, and a contact interface always takes "
        "2 n_max + 1. Must exceed 2 n_max (n_max "
        "the highest harmonic), else a band-limited field aliases. At "
        "most 8192; the memory of the coupled state (N times "
        "the soil's quadrature points) is checked against the "
        "free memory before the run.");
      prm.declare_entry("Load steps",
                        "10",
                        Patterns::Integer(1,
                                          LoadPathParameters::most_load_steps),
                        "Equal steps from 0 to the full loads (load control) "
                        "or to the target motion (displacement control). At "
                        "most 10000.");
      prm.declare_entry("Held load steps",
                        "4",
                        Patterns::Integer(1,
                                          LoadPathParameters::most_load_steps),
                        "Equal load-controlled steps from 0 to the held loads "
                        "(with a Rigid foundation: its Held ... loads, the "
                        "Body force and the tractions, e.g. self-weight and "
                        "surcharges), taken before the Load steps, which then "
                        "start from the held state and scale only the "
                        "foundation's loads or motion. At most 10000.");
    }

    /** Load or displacement control and its target. */
    void
    declare_control_entries(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Control",
        "load",
        Patterns::Selection(controls().selection()),
        "load: the Rigid foundation loads (H, M, V, T) times step/steps "
        "(body force and tractions are held, see Held load steps; without a "
        "Rigid foundation they are the loads scaled). displacement: those "
        "loads give the direction, their factor is found so that the "
        "controlled motion reaches Target (past a peak too); after held "
        "loads, in equal steps from the motion they left.");
      prm.declare_entry("Controlled motion",
                        "vertical",
                        Patterns::Selection(motions().selection()),
                        "Displacement control: the rigid-foundation motion "
                        "prescribed (vertical [m], twist about z [rad], "
                        "horizontal along x [m], rotation about y [rad]).");
      prm.declare_entry("Target",
                        "0",
                        Patterns::Double(),
                        "Displacement control: final value of the controlled "
                        "motion [m or rad].");
      prm.declare_entry(
        "Targets",
        "",
        Patterns::Anything(),
        "A cyclic path instead of Target: the turning points, e.g. "
        "'0.01, -0.01, 0.01', each reached in Load steps steps from the "
        "one before (the first from 0). Displacement control: values of "
        "the controlled motion [m or rad]; load control: factors on the "
        "Rigid foundation loads. The path must reverse at every target. "
        "Per cycle (turning point to the next but one) the run prints and "
        "writes load-cycles.csv: peak loads, secant stiffness, dissipated "
        "energy, damping ratio, the motions at zero load "
        "(doc/cyclic-loading.md). Empty: a monotonic path.");
      prm.declare_entry("Cycles",
                        "0",
                        Patterns::Integer(0,
                                          LoadPathParameters::most_load_steps),
                        "With Targets = t1, t2: the path t1, t2, t1, ... "
                        "of this many cycles between them (t1 and t2 about "
                        "a mean give a one-way cyclic load). 0: Targets as "
                        "listed.");
    }

    /** Convergence, iteration, acceleration and step cuts. */
    void
    declare_iteration_entries(ParameterHandler &prm)
    {
      prm.declare_entry("Tolerance",
                        "1e-10",
                        Patterns::Double(0.),
                        "Converged when |out-of-balance force| <= Tolerance "
                        "times the internal force scale, the larger of "
                        "|applied load| and |G|, the load of the plastic part "
                        "(slip, gaps, plastic strain) that the iteration "
                        "balances (2-norms over all harmonics). With a stiff "
                        "interface G ~ kn gap dwarfs the load, and a test "
                        "against the load alone asks for round-off. "
                        "0 < Tolerance < 1e-2: a larger one accepts steps "
                        "that have not iterated (the elastic answer).");
      prm.declare_entry("Maximum iterations",
                        "2000",
                        Patterns::Integer(1,
                                          LoadPathParameters::most_iterations),
                        "Out-of-balance solves per step before it is cut. At "
                        "most 100000.");
      prm.declare_entry("Acceleration",
                        "aitken",
                        Patterns::Selection(accelerations().selection()),
                        "aitken: Aitken's Delta^2 relaxation of the "
                        "out-of-balance load (one previous residual); "
                        "anderson: Anderson (multisecant) update from the last "
                        "Anderson depth residuals (fewer iterations, about the "
                        "same time, a worse worst case: "
                        "benchmarks/nonlinear-interfaces); none: plain initial "
                        "stiffness.");
      prm.declare_entry(
        "Stiffness",
        "auto",
        Patterns::Selection(stiffnesses().selection()),
        "Interface-only scenes: initial = the kept elastic factorizations, "
        "accelerated as Acceleration says; tangent = Newton on the "
        "interface DoFs with the closed-form consistent tangent of the "
        "coulomb return mapping, safeguarded by a line search on the "
        "residual norm (on several MPI ranks each fills the Jacobian "
        "columns of its harmonics); auto = tangent for a contact interface "
        "or a stiff coulomb penalty (max(kn, ks) l / G >= 5e3 on some face, "
        "l the interface's mean face length, G the softer side's shear "
        "modulus), else initial: the faster one on each side of that ratio "
        "(benchmarks/nonlinear-engine; doc/nonlinear-interfaces.md section "
        "5b). The run prints the choice and the ratio. Plastic soil takes "
        "Soil plasticity/Stiffness.");
      prm.declare_entry("Anderson depth",
                        "10",
                        Patterns::Integer(1, 50),
                        "Acceleration = anderson: how many previous residuals "
                        "(m) the update combines.");
      prm.declare_entry("Maximum step cuts",
                        "4",
                        Patterns::Integer(0,
                                          LoadPathParameters::most_step_cuts),
                        "Halvings of each step that does not converge "
                        "before the run stops with an error; a cut step "
                        "size doubles back after two converged steps, twice "
                        "as many after a doubling that failed. Under load "
                        "control (the held stage, Control = load) it is also "
                        "the floor of the step size, 2^-N of a load step: "
                        "steps that converge ever closer to a load below "
                        "that are at a limit load, and the run stops with "
                        "one line saying how much of the load is carried "
                        "(displacement control passes limits; its floor is "
                        "2^-20). At most 20 (a millionth of the step).");
    }

    /** Harmonics added by the solution. */
    void
    declare_harmonic_growth_entries(ParameterHandler &prm)
    {
      prm.declare_entry("Maximum harmonic",
                        "0",
                        Patterns::Integer(0,
                                          LoadPathParameters::largest_harmonic),
                        "Harmonics chosen by the solution: after each "
                        "converged step, every harmonic n <= Maximum harmonic "
                        "not solved yet whose amplitude in the plastic soil's "
                        "stress or in the interface traction exceeds Harmonic "
                        "tolerance times that one's largest is added (its own "
                        "factorization) and the step solved again. 0: only "
                        "the listed harmonics; below the highest listed one: "
                        "refused. At most 1024 (as Discretization/Harmonics); "
                        "coupled runs only, not with a swipe.");
      prm.declare_entry("Harmonic tolerance",
                        "1e-3",
                        Patterns::Double(0.),
                        "Maximum harmonic > highest listed: the relative "
                        "amplitude of the soil-stress or interface-traction "
                        "spectrum above which a harmonic is added.");
    }
  } // namespace

  void
  LoadPathParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Load path");
    declare_sampling_and_step_entries(prm);
    declare_control_entries(prm);
    declare_iteration_entries(prm);
    declare_harmonic_growth_entries(prm);
    prm.leave_subsection();
  }

  void
  LoadPathParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Load path");
    theta_samples   = prm.get_integer("Theta samples");
    load_steps      = prm.get_integer("Load steps");
    held_load_steps = prm.get_integer("Held load steps");
    control   = controls().value_of(prm.get("Control"), "Load path/Control");
    motion    = motions().value_of(prm.get("Controlled motion"),
                                "Load path/Controlled motion");
    target    = prm.get_double("Target");
    cycles    = prm.get_integer("Cycles");
    targets   = parse_load_path_targets(prm.get("Targets"), cycles, target);
    tolerance = prm.get_double("Tolerance");
    AssertThrow(tolerance > 0. && tolerance < largest_tolerance,
                ExcMessage("Load path/Tolerance: " + prm.get("Tolerance") +
                           " is outside 0 < Tolerance < 1e-2 (a step would "
                           "be accepted with that fraction of the load out "
                           "of balance, at 1 without iterating)"));
    maximum_iterations = prm.get_integer("Maximum iterations");
    acceleration       = accelerations().value_of(prm.get("Acceleration"),
                                            "Load path/Acceleration");
    stiffness =
      stiffnesses().value_of(prm.get("Stiffness"), "Load path/Stiffness");
    anderson_depth     = prm.get_integer("Anderson depth");
    maximum_step_cuts  = prm.get_integer("Maximum step cuts");
    maximum_harmonic   = prm.get_integer("Maximum harmonic");
    harmonic_tolerance = prm.get_double("Harmonic tolerance");
    prm.leave_subsection();
  }
} // namespace FourierSSI
