/**
 * @file standard_set.h
 * The registry of the postprocessors (core/registry.h) and the set a run has: every registered
 * postprocessor that applies to the run, in the order of its registered position, which is the
 * order of the history columns and output files (part of the output format).
 *
 * A new postprocessor: its class (interface.h) and, at the end of its `.cc`, a function template
 * `template <int dim> std::unique_ptr<Postprocessor<dim>> make_x(const PostprocessorContext &)`
 * (nullptr when it does not apply to the run) and
 * `AUSROLL_REGISTER_POSTPROCESSOR(ausroll::io::postprocess::make_x, "x", position, "...")` with a
 * position after the last one (140 today, `stage`) so that existing histories keep their columns.
 */
#pragma once

#include <ausroll/core/registry.h>
#include <ausroll/io/output_parameters.h>
#include <ausroll/io/postprocess/interface.h>

#include <deal.II/base/parameter_handler.h>

#include <memory>
#include <string>
#include <vector>

namespace ausroll::io
{
  /** What the postprocessors of a run are made from. */
  struct PostprocessorContext
  {
    const OutputParameters      &output;       ///< `Output`
    const PostprocessParameters &postprocess;  ///< `Postprocess`
    double                       end_time;     ///< `Loading/End time` (load factor t / end time)
    double                       yield_stress; ///< `Material/Yield stress` (yield excess)
    unsigned int quadrature_points; ///< `Model/Quadrature points` per direction (line probes)
    bool         thermal = false;   ///< a temperature field is solved (time in s, its columns)
    bool         phases = false;    ///< `Phases` enabled (phase fraction columns)
    bool         bainite = false;   ///< bainite kinetics given (bainite columns)
    bool generalized_plane_strain = false; ///< `Model/Planar model` (stretch_z, axial_force)
    /** `Stages/Stage k/End time` of the stages (empty: no stages, no stage column). */
    std::vector<double> stage_end_times = {};
  };

  /** A function making one postprocessor of a run, or nullptr if it does not apply. */
  template <int dim>
  using PostprocessorMaker = std::unique_ptr<Postprocessor<dim>> (*)(const PostprocessorContext &);

  /**
   * One registered postprocessor: its position among the others (the order of the history
   * columns and output files) and its makers for 2D and 3D runs. Its entries, if any, are in
   * `Postprocess` (PostprocessParameters), so it declares and parses nothing itself.
   */
  class PostprocessorFactory
  {
  public:
    virtual ~PostprocessorFactory() = default;

    /** No subsection of its own: nothing to declare. */
    static void declare_parameters(dealii::ParameterHandler &) {}

    /** Nothing to read. */
    virtual void parse(dealii::ParameterHandler &, const std::string &, const std::string &) {}

    /** Position of its columns and files: smaller first; unique among the postprocessors. */
    virtual unsigned int position() const = 0;

    /** The postprocessor of a 2D run, or nullptr if it does not apply. */
    virtual std::unique_ptr<Postprocessor<2>> create_2d(const PostprocessorContext &) const = 0;

    /** The postprocessor of a 3D run, or nullptr if it does not apply. */
    virtual std::unique_ptr<Postprocessor<3>> create_3d(const PostprocessorContext &) const = 0;
  };

  /** The registry of the postprocessors. */
  using PostprocessorRegistry = Registry<PostprocessorFactory>;

  /**
   * The postprocessors of a run made from @p context on @p comm: every registered one that
   * applies, in the order of their positions (today: step statistics, applied pressures, monitor
   * points, reaction forces, die forces, yield excess, line probes, boundary profile, contact
   * nodes, cell averages, die geometry, temperature, phases, stage). Two postprocessors with the
   * same position are an internal error (std::logic_error).
   */
  template <int dim>
  std::unique_ptr<PostprocessorSet<dim>>
  make_standard_postprocessors(const PostprocessorContext &context, const MPI_Comm comm);

  namespace internal
  {
    /** The factory AUSROLL_REGISTER_POSTPROCESSOR registers. */
    template <unsigned int Position, PostprocessorMaker<2> make_2d, PostprocessorMaker<3> make_3d>
    class RegisteredPostprocessor : public PostprocessorFactory
    {
    public:
      unsigned int                      position() const override { return Position; }
      std::unique_ptr<Postprocessor<2>> create_2d(const PostprocessorContext &c) const override
      {
        return make_2d(c);
      }
      std::unique_ptr<Postprocessor<3>> create_3d(const PostprocessorContext &c) const override
      {
        return make_3d(c);
      }
    };
  } // namespace internal
} // namespace ausroll::io

/**
 * Register the postprocessor made by the function template @p make (fully qualified;
 * `make<dim>(const PostprocessorContext &)`) under @p name at @p position (the order of the
 * history columns) with a one-sentence @p description. At namespace scope, at the end of its
 * `.cc`.
 */
#define AUSROLL_REGISTER_POSTPROCESSOR(make, name, position, description)                 \
  namespace                                                                               \
  {                                                                                       \
    using AUSROLL_REGISTRY_CONCAT(ausroll_postprocessor_, __LINE__)                       \
        = ::ausroll::io::internal::RegisteredPostprocessor<position, &make<2>, &make<3>>; \
  }                                                                                       \
  AUSROLL_REGISTER(::ausroll::io::PostprocessorFactory,                                   \
                   AUSROLL_REGISTRY_CONCAT(ausroll_postprocessor_, __LINE__),             \
                   name,                                                                  \
                   "",                                                                    \
                   description)
