/**
 * @file adaptivity_parameters.h
 * The `Adaptivity` subsection: when and where the mesh is refined and coarsened.
 */
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace ausroll::adaptivity
{
  /**
   * Parameters of subsection `Adaptivity`. Indicators combine: a cell is refined if any selected
   * indicator asks for it, and coarsened only if every selected indicator allows it.
   */
  struct AdaptivityParameters
  {
    unsigned int interval = 0;       ///< `Interval`: adapt every this many steps (0: never)
    unsigned int initial_cycles = 0; ///< `Initial refinement cycles` before the first step
    /** `Indicators`: the selected registered indicators (refinement_indicators.h), each once,
        in the registry's order. */
    std::vector<std::string> indicators;
    double                   refine_fraction = 0.3; ///< `Refine fraction` (Kelly, plastic strain)
    double coarsen_fraction = 0.05;                 ///< `Coarsen fraction` (Kelly, plastic strain)
    double contact_band = 1.;                       ///< `Contact band` (mm)
    /** `Fine contact band` (mm; 0: off): with the contact indicator, only cells this close to a
        die reach `Maximum level`; the rest of the `Contact band` stops one level below. */
    double       fine_contact_band = 0.;
    unsigned int max_level = 8;      ///< `Maximum level` of refinement
    unsigned int min_level = 0;      ///< `Minimum level` (no coarsening below)
    double       min_cell_size = 0.; ///< `Minimum cell size` (mm; cells this small are not refined)
    /** `Keep plastic strain above`: cells with a point above this equivalent plastic strain are
        not coarsened (0: off), so that the plastically deformed layer keeps its resolution. */
    double keep_plastic_strain = 0.;
    /** `Plastic coarsening level` (-1: off): cells kept by `Keep plastic strain above` may still
        be coarsened, but not below this level, where every indicator allows coarsening (with the
        contact indicator: farther from the die than the coarsening distance). */
    int plastic_coarsening_level = -1;
    /** `Case level` (-1: off): cells with a point whose carbon content exceeds `Case carbon
        above` are refined to this level and not coarsened below it (the carburized case). */
    int    case_level = -1;
    double case_carbon = 0.2; ///< `Case carbon above` (wt%)
    /** `Coarsening distance` (mm; 0: twice `Contact band` plus the cell size): with the contact
        indicator, cells farther than this plus their size from a die may be coarsened. */
    double coarsening_distance = 0.;
    bool   reequilibrate = true;       ///< `Re-equilibrate` after transfer
    bool   polynomial_transfer = true; ///< `State transfer` = polynomial (else nearest point)

    /** True if the mesh is adapted at all. */
    bool active() const { return (interval > 0 || initial_cycles > 0) && !indicators.empty(); }

    /** Declare subsection `Adaptivity`. */
    static void declare_parameters(dealii::ParameterHandler &prm);
    /** Read subsection `Adaptivity`. */
    void parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace ausroll::adaptivity
