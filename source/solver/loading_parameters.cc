#include <ausroll/core/exceptions.h>
#include <ausroll/solver/loading_parameters.h>
#include <ausroll/solver/step_control.h>

namespace ausroll::solver
{
  using namespace dealii;

  void LoadingParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Loading");
    prm.declare_entry("End time", "1", Patterns::Double(), "Final pseudo-time of the run.");
    prm.declare_entry("Number of steps",
                      "10",
                      Patterns::Integer(),
                      "Nominal number of load steps (step size = End time / Number of steps), "
                      "at most 1000000.");
    prm.declare_entry("Maximum cutbacks",
                      "6",
                      Patterns::Integer(0, 30),
                      "How often a failing step may be halved before the run stops.");
    prm.declare_entry(
        "Step growth factor",
        "1.5",
        Patterns::Double(1.),
        "After a cut-back step, later steps grow by this factor up to the nominal size.");
    prm.declare_entry(
        "Predictor",
        "none",
        Patterns::Selection("none|linear extrapolation"),
        "First Newton iterate of a step: none (the last converged state) or linear "
        "extrapolation of the last step's displacement increment, scaled to the step size. "
        "Extrapolation saves many iterations in large rotations of slender bodies, where the "
        "first iterate from the converged state carries large spurious membrane forces.");
    prm.declare_entry("Step control",
                      "halving",
                      Patterns::Selection(StepControlRegistry::instance().selection()),
                      "How the size of the next step is chosen (a rule's entries are in the "
                      "subsection of its name): "
                          + StepControlRegistry::instance().descriptions()
                          + ". Steps never exceed the nominal size and still end on the nominal "
                            "grid (doc/scenes/hard_cases.md).");
    StepControlRegistry::instance().declare_subsections(prm);
    prm.declare_entry(
        "Minimum step fraction",
        "1e-4",
        Patterns::Double(0., 1.),
        "Smallest step, as a fraction of the nominal step End time / Number of steps. A cutback "
        "that would make a step smaller ends the run (exit status 3) with a message naming the "
        "step, and the last converged state is written, instead of creeping on with ever smaller "
        "steps; the adaptive step control does not go below it. Steps shortened to end on the "
        "nominal grid or at a contact status change (Contact/Strategy = load increment ratio) "
        "may be smaller. 0: no limit.");
    prm.declare_entry(
        "Volume change limit",
        "0.2",
        Patterns::Double(0., 1.),
        "After every converged step the volume change J = det F at the quadrature points is "
        "checked: plastic flow is isochoric and the elastic volume change of metals below 1 %, "
        "so J < limit or J > 1 / limit means that an element folds (e.g. the corner of an "
        "upsetting where the free surface rolls onto the platen). The run then warns once, "
        "naming the place and the time, and the failure message of a later step repeats it; "
        "forces from that time on are not mesh-converged. 0: no check.");
    prm.declare_entry("Stop at distorted mesh",
                      "false",
                      Patterns::Bool(),
                      "Stop the run (exit status 3, last converged state written) instead of "
                      "warning when the Volume change limit is crossed.");
    prm.leave_subsection();
  }

  std::map<std::string, std::string> LoadingParameters::moved_entries()
  {
    std::map<std::string, std::string> moved;
    for (const char *entry :
         {"Target Newton iterations", "Target status changes", "Minimum step factor"})
      moved["Loading/" + std::string(entry)] = "`Loading/Adaptive/" + std::string(entry) + "`";
    return moved;
  }

  void LoadingParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Loading");
    end_time = prm.get_double("End time");
    const int steps = prm.get_integer("Number of steps");
    max_cutbacks = prm.get_integer("Maximum cutbacks");
    step_growth_factor = prm.get_double("Step growth factor");
    predictor = prm.get("Predictor") == "none" ? Predictor::none : Predictor::linear_extrapolation;
    step_control = prm.get("Step control");
    step_control_parameters
        = StepControlRegistry::instance().parse(step_control, prm, "Loading/", "", "Step control");
    minimum_step_fraction = prm.get_double("Minimum step fraction");
    volume_change_limit = prm.get_double("Volume change limit");
    stop_at_distortion = prm.get_bool("Stop at distorted mesh");
    prm.leave_subsection();
    require(end_time > 0., "Loading/End time", "must be positive");
    require(steps > 0, "Loading/Number of steps", "must be at least 1");
    require(steps <= max_steps,
            "Loading/Number of steps",
            std::to_string(steps) + " is more than ausroll accepts (" + std::to_string(max_steps)
                + "); use fewer, larger steps");
    number_of_steps = steps;
  }
} // namespace ausroll::solver
