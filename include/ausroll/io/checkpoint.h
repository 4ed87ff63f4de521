/**
 * @file checkpoint.h
 * Checkpoint files: where they live, how they are replaced atomically, and their metadata.
 */
#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>

#include <cstdint>
#include <map>
#include <mpi.h>
#include <string>
#include <vector>

namespace ausroll::io
{
  /** Parameters of subsection `Checkpoint`. */
  struct CheckpointParameters
  {
    unsigned int interval = 0; ///< `Interval`: write a checkpoint every this many steps (0: never)
    unsigned int abort_after_step = 0; ///< `Abort after step` (testing aid: hard exit after step N)

    /** Declare subsection `Checkpoint`. */
    static void declare_parameters(dealii::ParameterHandler &prm);
    /** Read subsection `Checkpoint`. */
    void parse_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * The testing aid `Checkpoint/Abort after step`: if @p step is that step, say so on @p log and
   * end the process at once (exit status 99, as if killed: nothing is closed or flushed).
   */
  void abort_if_asked(const CheckpointParameters &parameters,
                      const unsigned int          step,
                      dealii::ConditionalOStream &log);

  /**
   * Scalars and vectors of a checkpoint (time, step, contact statuses, output records, ...)
   * stored as text with 17 significant digits (exact for doubles), keyed by name.
   */
  struct CheckpointMetadata
  {
    std::map<std::string, std::vector<double>> values;  ///< numeric entries
    std::map<std::string, std::string>         strings; ///< text entries (one line each)

    /** Version of the checkpoint layout; a checkpoint of another version is refused. */
    static constexpr unsigned int format_version = 5;

    /**
     * Write to @p filename (call on one rank): a `format` line, the entries, and a `checksum`
     * line (FNV-1a 64 of everything before it). RunFailure if it cannot be written.
     */
    void write(const std::string &filename) const;
    /**
     * Read from @p filename: RunFailure if it does not exist; InputError naming it if it is
     * damaged (incomplete, checksum differs, unknown line) or of another format version.
     */
    void read(const std::string &filename);

    /**
     * Record size and FNV-1a 64 checksum of every other file in @p directory (the p4est mesh
     * and its data files) as strings `file:<name>` (call on one rank after they are written).
     */
    void record_files(const std::string &directory);
    /**
     * "" if every file recorded by record_files() is in @p directory with its size and
     * checksum; otherwise the message naming the first damaged or missing file.
     */
    std::string damaged_file(const std::string &directory) const;
    /** The single value @p key (RunFailure if missing). */
    double get(const std::string &key) const;

    /** Store every parsed entry ("Section/Entry" -> value) of the run. */
    void set_parameters(const std::map<std::string, std::string> &entries);
    /** The entries stored by set_parameters() (empty for a checkpoint written without them). */
    std::map<std::string, std::string> parameters() const;
  };

  /**
   * Compare the entries of a run being resumed (@p now) with those stored in its checkpoint
   * (@p meta, read from @p directory). Entries that fix the mesh, the discretisation or the
   * material point layout (`Geometry/`, `Model/`, `Material/`, `Adaptivity/`, `Contact/Number of
   * dies`, `Contact/Die N/Candidate boundaries`) or the columns of history.csv
   * (`Postprocess/Monitor points`, `Postprocess/Reaction boundaries`, `Contact/Die N/Name`) must
   * not differ: InputError listing each such entry with both values. Returns a warning line for
   * every other changed entry (e.g. `Loading/End time`, `Output/Interval`), and one if the
   * checkpoint holds no entries.
   */
  std::vector<std::string> compare_resume_parameters(const CheckpointMetadata                 &meta,
                                                     const std::map<std::string, std::string> &now,
                                                     const std::string &directory);

  /**
   * "" if the cell-data file @p path written by Triangulation::save() for @p n_cells active cells
   * is complete, otherwise the message naming it. Such a file is a header of k cumulative sizes
   * (unsigned int; the first one is the cell status, the last one the bytes of a cell) followed
   * by the bytes of every cell, so its size is 4 k + n_cells * (last size). deal.II writes it
   * with MPI-IO and ignores the number of bytes written: a full disk or a file-size limit
   * (`ulimit -f`) leaves a short file and no error. Call on one rank.
   */
  std::string incomplete_cell_data(const std::string &path, std::uint64_t n_cells);

  /**
   * RunFailure naming @p directory if its file system has fewer than @p bytes free, or if the
   * process's file-size limit (`ulimit -f`) is below @p largest_file bytes. Checked before a
   * checkpoint is written, because p4est aborts the process when it cannot write its mesh file.
   */
  void
  require_room(const std::string &directory, std::uintmax_t bytes, std::uintmax_t largest_file);

  /**
   * The checkpoint directory of an output directory: `<output>/checkpoint/`. A new checkpoint is
   * written into `<output>/checkpoint.new/` and then swapped in (old one renamed to
   * `checkpoint.old/` and removed), so that a run killed at any moment leaves a complete
   * checkpoint behind (either `checkpoint/` or, between the two renames, `checkpoint.old/`).
   */
  class CheckpointDirectory
  {
  public:
    /** Checkpoints of the run writing into @p output_directory. */
    CheckpointDirectory(const std::string &output_directory, const MPI_Comm comm);

    /** Directory to write the next checkpoint into (created, emptied); collective. */
    std::string begin_write() const;

    /** Make the checkpoint written into begin_write()'s directory the current one; collective. */
    void commit() const;

    /** The directory of the latest complete checkpoint; RunFailure if there is none. */
    std::string latest() const;

  private:
    std::string base;
    MPI_Comm    comm;
  };
} // namespace ausroll::io
