#include <ausroll/core/exceptions.h>
#include <ausroll/scene/coupling_parameters.h>

namespace ausroll::scene
{
  using namespace dealii;

  void CouplingParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Coupling");
    prm.declare_entry("Iterations",
                      "1",
                      Patterns::Integer(1, 50),
                      "Thermal scenes: heat-equation solves per load step at the most. 1: "
                      "isothermal split, the mechanical step at the temperature of its start, then "
                      "one heat solve (thermal strain one step behind). More: after each heat "
                      "solve the mechanical step is solved again at the new temperature, until the "
                      "temperature changes by at most Tolerance (each repetition costs a Newton "
                      "solve of the step).");
    prm.declare_entry("Tolerance",
                      "0.01",
                      Patterns::Double(0.),
                      "Largest nodal temperature change (K) between two heat solves of a step at "
                      "which the repeated split stops (Iterations > 1).");
    prm.leave_subsection();
  }

  void CouplingParameters::parse_parameters(ParameterHandler &prm, const bool thermal)
  {
    prm.enter_subsection("Coupling");
    iterations = prm.get_integer("Iterations");
    tolerance = prm.get_double("Tolerance");
    prm.leave_subsection();
    require(thermal || iterations == 1,
            "Coupling/Iterations",
            "is set, but the scene has one field (Thermal/Enabled = false)");
  }
} // namespace ausroll::scene
