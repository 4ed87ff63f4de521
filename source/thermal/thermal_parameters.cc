#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>
#include <ausroll/thermal/thermal_parameters.h>

#include <map>

namespace ausroll::thermal
{
  using namespace dealii;

  namespace
  {
    /** The entries of `Thermal` (outside the conditions) with their defaults. */
    const std::vector<std::pair<std::string, std::string>> &plain_entries()
    {
      static const std::vector<std::pair<std::string, std::string>> entries{
          {"Initial temperature", "20"},
          {"Reference temperature", "20"},
          {"Density", "7.85e-9"},
          {"Specific heat", "4.6e8"},
          {"Conductivity", "45"},
          {"Thermal expansion", "1.2e-5"},
          {"Taylor-Quinney coefficient", "0.9"},
          {"Contact conductance", "0"},
          {"Die temperatures", "20"},
          {"Friction heat partition", "0.5"},
          {"Number of conditions", "0"}};
      return entries;
    }
  } // namespace

  void ThermalParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Thermal");
    prm.declare_entry("Enabled",
                      "false",
                      Patterns::Bool(),
                      "Solve the transient heat equation rho c dT/dt = div(k grad T) + r on the "
                      "workpiece mesh, coupled to the mechanics by an isothermal split per load "
                      "step: the mechanical step at the temperature of its start (thermal strain), "
                      "then the heat equation (backward Euler) with the step's plastic heating. "
                      "With true, the load parameter t of Loading is the time in seconds, so die "
                      "motions and boundary values written in t are rates per second. With false "
                      "the scene is isothermal and no other entry of this subsection may be set.");
    const auto &defaults = plain_entries();
    const auto  def = [&](const std::string &name)
    {
      for (const auto &[n, v] : defaults)
        if (n == name)
          return v;
      return std::string();
    };
    prm.declare_entry("Initial temperature",
                      def("Initial temperature"),
                      Patterns::Anything(),
                      "Temperature at t = 0, an expression of x, y (and z in 3D), e.g. '20' or "
                      "'20 + 0.5 * y' (degrees C in the shipped scenes).");
    prm.declare_entry("Reference temperature",
                      def("Reference temperature"),
                      Patterns::Double(),
                      "Temperature at which the material is free of thermal strain.");
    prm.declare_entry("Density",
                      def("Density"),
                      Patterns::Anything(),
                      "Mass density rho(T) in t/mm^3 (steel 7.85e-9): a number or a table "
                      "'T1: v1, T2: v2, ...' (linear between rows, constant beyond) or "
                      "'file: NAME.csv' (columns temperature, value; next to the .prm).");
    prm.declare_entry("Specific heat",
                      def("Specific heat"),
                      Patterns::Anything(),
                      "Specific heat capacity c(T) in mm^2/(s^2 K) (460 J/(kg K) = 4.6e8); "
                      "number, table or file as Density.");
    prm.declare_entry("Conductivity",
                      def("Conductivity"),
                      Patterns::Anything(),
                      "Thermal conductivity k(T) in N/(s K) (numerically W/(m K)); number, table "
                      "or file as Density.");
    prm.declare_entry("Thermal expansion",
                      def("Thermal expansion"),
                      Patterns::Anything(),
                      "Secant coefficient of linear thermal expansion alpha(T) in 1/K from the "
                      "Reference temperature: thermal strain alpha(T) (T - T_ref); number, table "
                      "or file as Density. 0: no thermal strain.");
    prm.declare_entry("Taylor-Quinney coefficient",
                      def("Taylor-Quinney coefficient"),
                      Patterns::Double(),
                      "Fraction beta of the plastic work that becomes heat (0 to 1; 0.9 is the "
                      "usual value for steels).");
    prm.declare_entry("Contact conductance",
                      def("Contact conductance"),
                      Patterns::Double(0.),
                      "Heat transfer coefficient h_c between a die and the closed contact nodes "
                      "of the workpiece, q = h_c (T_die - T) over each node's tributary area, "
                      "in N/(mm s K) (1 = 1000 W/(m^2 K); lubricated steel on steel under forming "
                      "pressure about 5 to 50). 0: the dies are insulators.");
    prm.declare_entry("Die temperatures",
                      def("Die temperatures"),
                      Patterns::Anything(),
                      "Temperature of each die (Contact/Die 0, 1, ...), expressions of t separated "
                      "by ';', or one expression for all dies (the dies are rigid and hold their "
                      "temperature).");
    prm.declare_entry("Friction heat partition",
                      def("Friction heat partition"),
                      Patterns::Double(),
                      "Fraction of the frictional work at slipping nodes (|R_t| times the slip "
                      "relative to the die) that flows into the workpiece (0 to 1); the rest goes "
                      "into the die.");
    prm.declare_entry("Number of conditions",
                      def("Number of conditions"),
                      Patterns::Integer(0, max_conditions),
                      "How many of the subsections 'Condition 0', 'Condition 1', ... are used. A "
                      "boundary without a condition is insulated (no heat flux).");
    for (unsigned int i = 0; i < max_conditions; ++i)
    {
      prm.enter_subsection("Condition " + std::to_string(i));
      prm.declare_entry("Boundary id", "0", Patterns::Integer(0, 255), "Boundary id.");
      prm.declare_entry("Type",
                        "convection",
                        Patterns::Selection("temperature|flux|convection"),
                        "temperature: T = Value; flux: heat flux into the body q = Value in "
                        "N/(mm s) (= kW/m^2); convection: q = h (Value - T) with Value the "
                        "ambient (bath) temperature and h the Heat transfer coefficient.");
      prm.declare_entry(
          "Value", "20", Patterns::Anything(), "Expression of x, y (z in 3D) and t (seconds).");
      prm.declare_entry("Heat transfer coefficient",
                        "0",
                        Patterns::Double(0.),
                        "Convection: h in N/(mm s K) (1 = 1000 W/(m^2 K); quenching oil "
                        "about 0.5 to 2).");
      prm.leave_subsection();
    }
    prm.leave_subsection();
  }

  void ThermalParameters::parse_parameters(ParameterHandler &prm, const std::string &directory)
  {
    prm.enter_subsection("Thermal");
    enabled = prm.get_bool("Enabled");
    if (!enabled)
    {
      // An entry set while the field is off would silently do nothing.
      for (const auto &[name, value] : plain_entries())
        require(prm.get(name) == value,
                "Thermal/" + name,
                "is set, but Thermal/Enabled = false: enable the thermal field or remove the "
                "entry");
      prm.leave_subsection();
      return;
    }
    initial_temperature = prm.get("Initial temperature");
    require_expression_length(initial_temperature, "Thermal/Initial temperature");
    expansion.reference_temperature = prm.get_double("Reference temperature");
    density
        = material::PropertyTable::parse(prm.get("Density"), "Thermal/Density", directory, true);
    specific_heat = material::PropertyTable::parse(
        prm.get("Specific heat"), "Thermal/Specific heat", directory, true);
    conductivity = material::PropertyTable::parse(
        prm.get("Conductivity"), "Thermal/Conductivity", directory, false, true);
    expansion.expansion = material::PropertyTable::parse(
        prm.get("Thermal expansion"), "Thermal/Thermal expansion", directory, false);
    taylor_quinney = prm.get_double("Taylor-Quinney coefficient");
    require(taylor_quinney >= 0. && taylor_quinney <= 1.,
            "Thermal/Taylor-Quinney coefficient",
            "must lie in [0, 1] (the fraction of plastic work turned into heat), found "
                + prm.get("Taylor-Quinney coefficient"));
    contact_conductance = prm.get_double("Contact conductance");
    die_temperatures = split_and_trim(prm.get("Die temperatures"), ';');
    require(!die_temperatures.empty(), "Thermal/Die temperatures", "is empty");
    for (const std::string &e : die_temperatures)
      require_expression_length(e, "Thermal/Die temperatures");
    friction_heat_partition = prm.get_double("Friction heat partition");
    require(friction_heat_partition >= 0. && friction_heat_partition <= 1.,
            "Thermal/Friction heat partition",
            "must lie in [0, 1], found " + prm.get("Friction heat partition"));
    const unsigned int n = prm.get_integer("Number of conditions");
    conditions.clear();
    for (unsigned int i = 0; i < n; ++i)
    {
      const std::string path = "Thermal/Condition " + std::to_string(i);
      prm.enter_subsection("Condition " + std::to_string(i));
      ThermalCondition c;
      c.id = prm.get_integer("Boundary id");
      const std::string type = prm.get("Type");
      c.type = type == "temperature" ? ThermalConditionType::temperature
               : type == "flux"      ? ThermalConditionType::flux
                                     : ThermalConditionType::convection;
      c.value = prm.get("Value");
      require_expression_length(c.value, path + "/Value");
      c.heat_transfer_coefficient = prm.get_double("Heat transfer coefficient");
      require(c.type != ThermalConditionType::convection || c.heat_transfer_coefficient > 0.,
              path + "/Heat transfer coefficient",
              "must be positive for Type = convection");
      for (const ThermalCondition &other : conditions)
        require(other.id != c.id,
                path + "/Boundary id",
                "boundary " + std::to_string(c.id) + " has a thermal condition already");
      conditions.push_back(c);
      prm.leave_subsection();
    }
    prm.leave_subsection();
  }
} // namespace ausroll::thermal
