/**
 * @file history.h
 * history.csv: one row per converged load step.
 */
#pragma once

#include <mpi.h>

#include <fstream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace ausroll::io
{
  /** One history row: (column name, value) in column order. */
  using HistoryRow = std::vector<std::pair<std::string, double>>;

  /**
   * Writes history.csv on rank 0. The first row fixes the columns (header line); every row is
   * flushed at once so that the file stays complete if a run is stopped.
   */
  class History
  {
  public:
    /** History file @p path (truncated, or appended to when @p append). */
    History(const MPI_Comm comm, const std::string &path, const bool append = false);

    /**
     * Resume a history: keep the header and the rows of steps up to @p last_step of the existing
     * file @p path (rank 0 rewrites it), then append. InputError naming the file and line if it
     * cannot be read or a row does not start with a step number (an edited file); the first
     * row added must have the columns of the file's header (InputError otherwise: a resume that
     * adds a monitor point would write rows that do not fit the header).
     */
    static std::unique_ptr<History>
    resume(const MPI_Comm comm, const std::string &path, const unsigned int last_step);

    /** Append @p row; its column names must match the first row's. */
    void add_row(const HistoryRow &row);

  private:
    bool                     writer;                ///< true on rank 0
    std::ofstream            file;                  ///< the CSV file (rank 0)
    std::vector<std::string> columns;               ///< names fixed by the first row
    std::string              path;                  ///< file name, for messages
    bool                     header_pending = true; ///< the file has no header line yet
    std::string resumed_header; ///< header of a resumed file, checked against the first new row
  };
} // namespace ausroll::io
