#include <ausroll/adaptivity/adaptivity_parameters.h>
#include <ausroll/adaptivity/refinement_indicators.h>
#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>

#include <algorithm>

namespace ausroll::adaptivity
{
  using namespace dealii;

  void AdaptivityParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Adaptivity");
    prm.declare_entry("Interval",
                      "0",
                      Patterns::Integer(0),
                      "Adapt the mesh after every this many load steps (0: never during the run).");
    prm.declare_entry(
        "Initial refinement cycles",
        "0",
        Patterns::Integer(0, 20),
        "Refinement cycles before the first step (contact band around the dies at the "
        "start and end of the first step).");
    prm.declare_entry("Indicators",
                      "contact",
                      Patterns::MultipleSelection(IndicatorRegistry::instance().selection()),
                      "Comma-separated combination: " + IndicatorRegistry::instance().descriptions()
                          + ".");
    prm.declare_entry("Refine fraction",
                      "0.3",
                      Patterns::Double(0., 1.),
                      "Kelly / plastic strain: fraction of the indicator to refine.");
    prm.declare_entry("Coarsen fraction",
                      "0.05",
                      Patterns::Double(0., 1.),
                      "Kelly / plastic strain: fraction of the indicator that may be coarsened.");
    prm.declare_entry(
        "Contact band",
        "1",
        Patterns::Double(0.),
        "contact: cells closer than this to a die (mm) are refined; cells farther than "
        "twice the band plus their size may be coarsened.");
    prm.declare_entry(
        "Fine contact band",
        "0",
        Patterns::Double(0.),
        "contact: a graded band (0: off). Only cells closer than this to a die (mm) are refined "
        "to Maximum level; the other cells of the Contact band are refined to Maximum level - 1, "
        "and cells on Maximum level farther than twice this value plus their size may be "
        "coarsened to Maximum level - 1. Must not exceed Contact band.");
    prm.declare_entry(
        "Maximum level", "8", Patterns::Integer(0, 30), "No cell is refined beyond this level.");
    prm.declare_entry(
        "Minimum level", "0", Patterns::Integer(0, 30), "No cell is coarsened below this level.");
    prm.declare_entry("Minimum cell size",
                      "0",
                      Patterns::Double(0.),
                      "Cells smaller than this (mm) are not refined.");
    prm.declare_entry("Keep plastic strain above",
                      "0",
                      Patterns::Double(0.),
                      "Cells with a material point whose equivalent plastic strain exceeds this "
                      "value are not coarsened (0: no such limit): the plastically deformed layer "
                      "left behind a die keeps the resolution it was formed on. Works with every "
                      "indicator.");
    prm.declare_entry(
        "Plastic coarsening level",
        "-1",
        Patterns::Integer(-1, 30),
        "With Keep plastic strain above > 0: the level down to which a cell with a material point "
        "above that plastic strain may still be coarsened where every indicator allows it (with "
        "contact: farther from the die than the coarsening distance, i.e. once the die has left); "
        "-1: such cells are never coarsened. E.g. 1 with Maximum level = 2 keeps the groove behind "
        "a die at level 1 instead of the finest level, so that the refined band does not grow with "
        "the rolled length. Must lie between Minimum level and Maximum level.");
    prm.declare_entry(
        "Case level",
        "-1",
        Patterns::Integer(-1, 30),
        "Cells with a material point whose carbon content exceeds Case carbon above (the "
        "carburized case of Phases/Carbon content) are refined to this level and not coarsened "
        "below it (-1: off), so that the case that transforms on cooling is resolved along the "
        "whole outline, not only where a die touches. Works with every indicator; at most "
        "Maximum level; needs Phases/Enabled.");
    prm.declare_entry("Case carbon above",
                      "0.2",
                      Patterns::Double(0.),
                      "Carbon content (wt%) above which a material point belongs to the case "
                      "of Case level.");
    prm.declare_entry(
        "Coarsening distance",
        "0",
        Patterns::Double(0.),
        "contact: cells farther than this (mm) plus their size from a die may be coarsened (0: "
        "twice the Contact band plus the cell size). Must be 0 or at least the Contact band, so "
        "that a coarsened cell is not refined again at the next adaptation.");
    prm.declare_entry(
        "State transfer",
        "polynomial",
        Patterns::Selection("polynomial|nearest point"),
        "Material-point state across refinement: polynomial (interpolation through the "
        "Gauss points / least-squares fit when coarsening, then projection onto the "
        "yield surface) or nearest point (copy / average; more diffusive).");
    prm.declare_entry("Re-equilibrate",
                      "true",
                      Patterns::Bool(),
                      "Solve for equilibrium on the new mesh before the next step (recommended; "
                      "if that fails, a warning, and the next step starts from the transferred "
                      "state as without it).");
    prm.leave_subsection();
  }

  void AdaptivityParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Adaptivity");
    interval = prm.get_integer("Interval");
    initial_cycles = prm.get_integer("Initial refinement cycles");
    const std::vector<std::string> selected = split_and_trim(prm.get("Indicators"), ',');
    indicators.clear();
    for (const std::string &name : IndicatorRegistry::instance().names())
      if (std::find(selected.begin(), selected.end(), name) != selected.end())
        indicators.push_back(name);
    refine_fraction = prm.get_double("Refine fraction");
    coarsen_fraction = prm.get_double("Coarsen fraction");
    contact_band = prm.get_double("Contact band");
    fine_contact_band = prm.get_double("Fine contact band");
    max_level = prm.get_integer("Maximum level");
    min_level = prm.get_integer("Minimum level");
    min_cell_size = prm.get_double("Minimum cell size");
    keep_plastic_strain = prm.get_double("Keep plastic strain above");
    plastic_coarsening_level = prm.get_integer("Plastic coarsening level");
    case_level = prm.get_integer("Case level");
    case_carbon = prm.get_double("Case carbon above");
    coarsening_distance = prm.get_double("Coarsening distance");
    reequilibrate = prm.get_bool("Re-equilibrate");
    polynomial_transfer = prm.get("State transfer") == "polynomial";
    prm.leave_subsection();
    require(refine_fraction + coarsen_fraction <= 1.,
            "Adaptivity/Coarsen fraction",
            "Refine fraction + Coarsen fraction must not exceed 1");
    require(fine_contact_band <= contact_band,
            "Adaptivity/Fine contact band",
            "must not exceed Contact band");
    require(fine_contact_band == 0. || max_level >= 1,
            "Adaptivity/Fine contact band",
            "needs Maximum level >= 1");
    require(min_level <= max_level, "Adaptivity/Minimum level", "must not exceed Maximum level");
    require(plastic_coarsening_level < 0 || keep_plastic_strain > 0.,
            "Adaptivity/Plastic coarsening level",
            "needs Keep plastic strain above > 0 (it applies to the cells kept by that limit)");
    require(plastic_coarsening_level < 0
                || (plastic_coarsening_level >= static_cast<int>(min_level)
                    && plastic_coarsening_level <= static_cast<int>(max_level)),
            "Adaptivity/Plastic coarsening level",
            "must lie between Minimum level and Maximum level (or be -1: off)");
    require(case_level <= static_cast<int>(max_level),
            "Adaptivity/Case level",
            "must not exceed Maximum level");
    require(coarsening_distance == 0. || coarsening_distance >= contact_band,
            "Adaptivity/Coarsening distance",
            "must be 0 or at least Contact band (a coarsened cell would be refined again)");
  }
} // namespace ausroll::adaptivity
