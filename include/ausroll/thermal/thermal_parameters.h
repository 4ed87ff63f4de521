/**
 * @file thermal_parameters.h
 * The `Thermal` subsection: the temperature field, its material data and boundary conditions.
 */
#pragma once

#include <ausroll/material/property_table.h>
#include <ausroll/material/thermal_expansion_model.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <string>
#include <vector>

namespace ausroll::thermal
{
  /** Kind of a thermal boundary condition (`Thermal/Condition k/Type`). */
  enum class ThermalConditionType
  {
    temperature, ///< prescribed temperature T = Value(x, t)
    flux,        ///< prescribed heat flux into the body q = Value(x, t) (N/(mm s) = kW/m^2)
    convection   ///< q = h (Value(x, t) - T), Value the ambient temperature
  };

  /** One thermal boundary condition (`Thermal/Condition k`). */
  struct ThermalCondition
  {
    dealii::types::boundary_id id = 0;                                  ///< `Boundary id`
    ThermalConditionType       type = ThermalConditionType::convection; ///< `Type`
    std::string                value = "20";                            ///< `Value` expression
    double heat_transfer_coefficient = 0.; ///< `Heat transfer coefficient` h (N/(mm s K))
  };

  /**
   * Parameters of the temperature field (subsection `Thermal`). Units of the shipped scenes (mm,
   * N, s, degrees C): density t/mm^3 (steel 7.85e-9), specific heat mm^2/(s^2 K) (460 J/(kg K) =
   * 4.6e8), conductivity N/(s K) (numerically W/(m K)), heat transfer coefficients N/(mm s K)
   * (1 kW/(m^2 K) = 1 N/(mm s K) = 1000 W/(m^2 K)). With `Enabled = true` the load parameter t of
   * `Loading` is the time in seconds.
   */
  struct ThermalParameters
  {
    bool        enabled = false;            ///< `Enabled`
    std::string initial_temperature = "20"; ///< `Initial temperature` (expression of x, y, z)
    material::ThermalExpansionParameters
                                  expansion;     ///< `Thermal expansion`, `Reference temperature`
    material::PropertyTable       density;       ///< `Density` rho(T) (t/mm^3)
    material::PropertyTable       specific_heat; ///< `Specific heat` c(T) (mm^2/(s^2 K))
    material::PropertyTable       conductivity;  ///< `Conductivity` k(T) (N/(s K))
    double                        taylor_quinney = 0.9; ///< `Taylor-Quinney coefficient` beta
    std::vector<ThermalCondition> conditions; ///< `Condition 0..` (`Number of conditions`)
    double contact_conductance = 0.;          ///< `Contact conductance` h_c (N/(mm s K))
    /** `Die temperatures`: expressions of t, one per die (or one for all). */
    std::vector<std::string> die_temperatures{"20"};
    double friction_heat_partition = 0.5; ///< `Friction heat partition` (into the workpiece)
    /** Latent heat of martensite and bainite per unit mass (mm^2/s^2): not entries of `Thermal`
        but `Phases/Latent heat` and `Phases/Bainite latent heat`, copied here by
        SceneParameters (0 without phases): the source rho (L_M df_M + L_B df_B) / dt. */
    double latent_heat_martensite = 0.;
    double latent_heat_bainite = 0.; ///< see latent_heat_martensite

    static constexpr unsigned int max_conditions = 8; ///< declared `Condition 0..7`

    static void declare_parameters(dealii::ParameterHandler &prm);

    /** Read the subsection; @p input_directory resolves table files. Throws InputError naming
        the entry for out-of-range values and for thermal entries set while `Enabled = false`. */
    void parse_parameters(dealii::ParameterHandler &prm, const std::string &input_directory);
  };
} // namespace ausroll::thermal
