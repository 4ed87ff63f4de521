/**
 * @file gather_rows.h
 * Collect table rows (CSV output) from all MPI ranks on rank 0.
 */
#pragma once

#include <mpi.h>

#include <vector>

namespace ausroll
{
  /**
   * The rows of every rank of @p comm gathered on rank 0 and sorted lexicographically (so that
   * the output does not depend on the partition); an empty table on the other ranks. Used by the
   * CSV writers (contact, line probes, boundary profiles).
   */
  std::vector<std::vector<double>> gather_sorted_rows(const MPI_Comm                          comm,
                                                      const std::vector<std::vector<double>> &rows);
} // namespace ausroll
