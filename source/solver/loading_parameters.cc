#include <ausroll/core/exceptions.h>
#include <ausroll/solver/loading_parameters.h>

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
    prm.leave_subsection();
  }

  void LoadingParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Loading");
    end_time = prm.get_double("End time");
    const int steps = prm.get_integer("Number of steps");
    max_cutbacks = prm.get_integer("Maximum cutbacks");
    step_growth_factor = prm.get_double("Step growth factor");
    predictor = prm.get("Predictor") == "none" ? Predictor::none : Predictor::linear_extrapolation;
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
