/**
 * @file coupling_parameters.h
 * The `Coupling` subsection: how the temperature field and the mechanics are solved together.
 */
#pragma once

#include <deal.II/base/parameter_handler.h>

namespace ausroll::scene
{
  /**
   * Coupling of the fields of a thermal scene (subsection `Coupling`). Isothermal split per load
   * step: the mechanical step at fixed temperature, then the heat equation over the converged
   * mechanical step. With `Iterations` = 1 the mechanics sees the temperature of the step's start
   * (explicit in the thermal strain, one heat solve per step); with more, the split is repeated
   * within the step (mechanics at the last temperature, heat equation again) until the largest
   * nodal change of the temperature is at most `Tolerance`.
   */
  struct CouplingParameters
  {
    unsigned int iterations = 1;   ///< `Iterations` (heat solves per step at the most)
    double       tolerance = 1e-2; ///< `Tolerance` (K)

    static void declare_parameters(dealii::ParameterHandler &prm);

    /** Read the subsection; @p thermal: `Thermal/Enabled` (entries set without it are refused). */
    void parse_parameters(dealii::ParameterHandler &prm, const bool thermal);
  };
} // namespace ausroll::scene
