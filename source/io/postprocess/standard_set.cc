#include <ausroll/core/parse_utilities.h>
#include <ausroll/io/postprocess/die_forces.h>
#include <ausroll/io/postprocess/die_geometry.h>
#include <ausroll/io/postprocess/field_files.h>
#include <ausroll/io/postprocess/material_state.h>
#include <ausroll/io/postprocess/monitor_points.h>
#include <ausroll/io/postprocess/reaction_forces.h>
#include <ausroll/io/postprocess/standard_set.h>
#include <ausroll/io/postprocess/step_statistics.h>

namespace ausroll::io
{
  template <int dim>
  std::unique_ptr<PostprocessorSet<dim>>
  make_standard_postprocessors(const OutputParameters      &output,
                               const PostprocessParameters &p,
                               const double                 end_time,
                               const double                 yield_stress,
                               const unsigned int           quadrature_points,
                               const MPI_Comm               comm,
                               const bool                   time_in_seconds)
  {
    // The order of these lines is the order of the history columns and output files.
    namespace pp = postprocess;
    auto set = std::make_unique<PostprocessorSet<dim>>(output, comm);
    set->add(std::make_unique<pp::StepStatistics<dim>>(end_time, time_in_seconds));
    set->add(std::make_unique<pp::AppliedPressures<dim>>());
    set->add(std::make_unique<pp::MonitorPoints<dim>>(p.monitor_points));
    set->add(std::make_unique<pp::ReactionForces<dim>>(
        parse_unsigned_list(p.reaction_boundaries, "Postprocess/Reaction boundaries")));
    set->add(std::make_unique<pp::DieForces<dim>>());
    set->add(std::make_unique<pp::YieldExcess<dim>>(yield_stress));
    set->add(std::make_unique<pp::LineProbeFiles<dim>>(p.line_probes, quadrature_points));
    set->add(std::make_unique<pp::BoundaryProfileFiles<dim>>(p.boundary_profile));
    set->add(std::make_unique<pp::ContactFiles<dim>>());
    set->add(std::make_unique<pp::CellAverages<dim>>());
    set->add(std::make_unique<pp::DieGeometry<dim>>(output.write_vtu));
    return set;
  }

  template std::unique_ptr<PostprocessorSet<2>>
  make_standard_postprocessors(const OutputParameters &,
                               const PostprocessParameters &,
                               const double,
                               const double,
                               const unsigned int,
                               const MPI_Comm,
                               const bool);
  template std::unique_ptr<PostprocessorSet<3>>
  make_standard_postprocessors(const OutputParameters &,
                               const PostprocessParameters &,
                               const double,
                               const double,
                               const unsigned int,
                               const MPI_Comm,
                               const bool);
} // namespace ausroll::io
