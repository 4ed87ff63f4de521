/**
 * @file refinement_indicators.h
 * Where to refine and coarsen (`Adaptivity/Indicators`): the registry of refinement indicators
 * (core/registry.h; one file per indicator in source/adaptivity/indicators/: Kelly, contact,
 * plastic strain) and mark_cells(), which combines the selected ones and applies the limits.
 *
 * A new indicator: a class derived from IndicatorBase<Class> with a template
 * `mark<dim>(const IndicatorInput<dim> &, CellFlags &) const` in its own `.cc` and
 * AUSROLL_REGISTER_REFINEMENT_INDICATOR at the end of it; the `Indicators` selection, its help
 * text and doc/parameters.md follow from the registry. Its entries, if it needs new ones, go into
 * subsection `Adaptivity` (AdaptivityParameters).
 */
#pragma once

#include <ausroll/adaptivity/adaptivity_parameters.h>
#include <ausroll/core/registry.h>
#include <ausroll/mechanics/material_point_storage.h>

#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <functional>
#include <string>
#include <vector>

namespace ausroll::adaptivity
{
  /** Distance of a (deformed) point to the nearest die, at the current and the next step. */
  template <int dim>
  using DieDistance = std::function<double(const dealii::Point<dim> &)>;

  /** What an indicator sees of the discrete state (const except for the triangulation's flags,
      which fixed_fraction_flags() uses as scratch). */
  template <int dim>
  struct IndicatorInput
  {
    const AdaptivityParameters                        &parameters;
    dealii::parallel::distributed::Triangulation<dim> &triangulation;
    const dealii::Mapping<dim>                        &mapping;
    const dealii::DoFHandler<dim>                     &dof_handler;
    const dealii::TrilinosWrappers::MPI::Vector       &solution;
    const mechanics::MaterialPointStorage<dim>        &material_points;
    const DieDistance<dim>                            &die_distance;
  };

  /** The wishes of the indicators per active cell (index: active_cell_index()). */
  struct CellFlags
  {
    std::vector<bool> refine;  ///< some indicator asks for refinement (or of the indicators)
    std::vector<bool> coarsen; ///< every indicator allows coarsening (and of the indicators)
    /** Highest level the cell may be refined to (graded contact band: Maximum level - 1). */
    std::vector<unsigned int> level_cap;
    /** The cell may be coarsened down to level_cap even where coarsen is false. */
    std::vector<bool> coarsen_to_cap;
  };

  /**
   * One refinement indicator (a value of `Adaptivity/Indicators`): adds its wishes to the flags.
   * A cell is flagged for refinement if any indicator wants it; for coarsening only if all allow
   * it. Derive from IndicatorBase<Class> to write mark() once as a template of the dimension.
   */
  class RefinementIndicator
  {
  public:
    virtual ~RefinementIndicator() = default;

    /** The entries of an indicator are in `Adaptivity` itself: nothing to declare. */
    static void declare_parameters(dealii::ParameterHandler &) {}

    /** Nothing to read (the entries are read by AdaptivityParameters). */
    virtual void parse(dealii::ParameterHandler &, const std::string &, const std::string &) {}

    /** Add this indicator's wishes in a 2D run. */
    virtual void mark(const IndicatorInput<2> &input, CellFlags &flags) const = 0;

    /** Add this indicator's wishes in a 3D run. */
    virtual void mark(const IndicatorInput<3> &input, CellFlags &flags) const = 0;
  };

  /** RefinementIndicator whose mark() is the template `Class::mark_cells<dim>()`. */
  template <class Class>
  class IndicatorBase : public RefinementIndicator
  {
  public:
    void mark(const IndicatorInput<2> &input, CellFlags &flags) const override
    {
      static_cast<const Class &>(*this).template mark_cells<2>(input, flags);
    }
    void mark(const IndicatorInput<3> &input, CellFlags &flags) const override
    {
      static_cast<const Class &>(*this).template mark_cells<3>(input, flags);
    }
  };

  /** The registry of the refinement indicators (`Adaptivity/Indicators`). */
  using IndicatorRegistry = Registry<RefinementIndicator>;

  /**
   * A fixed-fraction marking (`Refine fraction`, `Coarsen fraction`) on @p indicator (one value
   * per active cell), added to @p flags: refine where it refines, coarsen only where it coarsens.
   */
  template <int dim>
  void fixed_fraction_flags(const IndicatorInput<dim>   &input,
                            const dealii::Vector<float> &indicator,
                            CellFlags                   &flags);

  /**
   * Set refine and coarsen flags on the locally owned cells of @p triangulation from the
   * indicators selected in @p parameters, then apply the level and size limits. A cell is flagged
   * for refinement if any indicator wants it; for coarsening only if all allow it.
   *  - Kelly: KellyErrorEstimator of the displacement, fixed fractions.
   *  - contact: the deformed cell centre is closer than `Contact band` plus half the cell size to a
   *    die (@p die_distance covers the present and the next die position); coarsening allowed
   *    beyond twice that (or beyond `Coarsening distance` plus the cell size if that is set). With
   * `Fine contact band` > 0 the band is graded: cells farther than that (plus half their size) are
   * refined at most to `Maximum level` - 1 (whichever indicator asks), and cells on `Maximum level`
   * beyond twice it plus their size are coarsened to that level.
   *  - plastic strain: max - min of the equivalent plastic strain over the cell's points, fixed
   *    fractions (marks the elastic-plastic front and strong gradients).
   *  - `Keep plastic strain above` > 0: no cell with a point above that equivalent plastic strain
   *    is coarsened; with `Plastic coarsening level` >= 0 such a cell is coarsened where the
   *    indicators allow it, but not below that level (the plastic groove behind a die is kept at
   *    an intermediate level instead of the finest one).
   * Returns true if any cell (on any rank) is flagged.
   */
  template <int dim>
  bool mark_cells(const AdaptivityParameters                        &parameters,
                  dealii::parallel::distributed::Triangulation<dim> &triangulation,
                  const dealii::Mapping<dim>                        &mapping,
                  const dealii::DoFHandler<dim>                     &dof_handler,
                  const dealii::TrilinosWrappers::MPI::Vector       &solution,
                  const mechanics::MaterialPointStorage<dim>        &material_points,
                  const DieDistance<dim>                            &die_distance);
} // namespace ausroll::adaptivity

/** Register the refinement indicator @p Class under @p name (see AUSROLL_REGISTER). */
#define AUSROLL_REGISTER_REFINEMENT_INDICATOR(Class, name, description) \
  AUSROLL_REGISTER(::ausroll::adaptivity::RefinementIndicator, Class, name, "", description)
