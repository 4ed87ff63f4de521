/**
 * @file standard_set.h
 * The postprocessors every run has, in the order of their history columns and output files.
 */
#pragma once

#include <ausroll/io/output_parameters.h>
#include <ausroll/io/postprocess/interface.h>

#include <memory>

namespace ausroll::io
{
  /**
   * The postprocessors of a run writing as @p output says, configured by @p postprocess: step
   * statistics (load factor of @p end_time), applied pressures, monitor points, reaction forces,
   * die forces, yield excess (over @p yield_stress), line probes (@p quadrature_points per
   * direction), boundary profiles, contact files, cell averages, die geometry (dies.pvd). The order
   * is the order of the history columns and output files (part of the output format).
   */
  template <int dim>
  std::unique_ptr<PostprocessorSet<dim>>
  make_standard_postprocessors(const OutputParameters      &output,
                               const PostprocessParameters &postprocess,
                               const double                 end_time,
                               const double                 yield_stress,
                               const unsigned int           quadrature_points,
                               const MPI_Comm               comm,
                               const bool                   time_in_seconds = false);
} // namespace ausroll::io
