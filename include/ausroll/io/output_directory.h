/**
 * @file output_directory.h
 * The output directory of a new run: created, and kept safe from being overwritten by accident.
 */
#pragma once

#include <mpi.h>
#include <string>
#include <vector>

namespace ausroll::io
{
  /**
   * The results of an earlier run in @p directory: history.csv, solution.pvd, the numbered
   * outputs (solution_*.vtu/.pvtu, contact/profile/probe CSV) and checkpoint directories
   * (names relative to @p directory; empty if none or if the directory does not exist).
   */
  std::vector<std::string> earlier_results(const std::string &directory);

  /**
   * Prepare @p directory for a new run (collective). If it holds earlier results, refuse with an
   * InputError naming `Output/Directory` and the files found, unless @p overwrite; then delete
   * those results (other files are left alone). Create the directory if missing (InputError if
   * that fails).
   */
  void
  prepare_output_directory(const std::string &directory, const bool overwrite, const MPI_Comm comm);

  /**
   * Write @p text (the effective parameters of the run, SceneParameters::effective_parameters)
   * to `<directory>/parameters.prm` on rank 0 of @p comm before the first step (collective:
   * InputError naming the file on every rank if it cannot be written).
   */
  void
  write_parameter_copy(const std::string &directory, const std::string &text, const MPI_Comm comm);
} // namespace ausroll::io
