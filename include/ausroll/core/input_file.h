/**
 * @file input_file.h
 * Opening a file that ausroll reads (the .prm and its includes, `Geometry/Mesh file`, a die's
 * `Points file`, checkpoint files): one shared check that it is a readable regular file of a
 * sensible size before a single byte is read, so that a FIFO, a device (`/dev/zero`), a
 * directory or a symbolic-link loop give a message naming the file instead of a hang, an
 * exhausted memory or "no such file".
 */
#pragma once

#include <cstdint>
#include <fstream>
#include <string>

namespace ausroll
{
  /** Size bounds of the files ausroll reads (bytes). */
  namespace file_size_limit
  {
    /** A .prm file or an include (the shipped ones are below 20 kB). */
    constexpr std::uintmax_t parameter_file = 16u << 20;
    /** A die's `Points file` (a million points are about 40 MB). */
    constexpr std::uintmax_t points_file = 256u << 20;
    /** `Geometry/Mesh file`. */
    constexpr std::uintmax_t mesh_file = 1u << 30;
  } // namespace file_size_limit

  /**
   * Why @p path cannot be read as an input file of at most @p max_bytes bytes, or "" if it can:
   * "no such file", "too many levels of symbolic links", "is a directory", "is a FIFO (named
   * pipe), not a regular file" (also character/block devices and sockets), "permission denied",
   * "is N bytes, more than the M accepted". Never blocks (the file is not opened for a FIFO).
   */
  std::string input_file_problem(const std::string &path, std::uintmax_t max_bytes);

  /**
   * Open @p path for reading after input_file_problem(): InputError
   * "<what> '<path>': <problem>" if it cannot be read (e.g. @p what = "Geometry/Mesh file").
   * @p binary opens in binary mode.
   */
  std::ifstream open_input_file(const std::string &path,
                                const std::string &what,
                                std::uintmax_t     max_bytes,
                                bool               binary = false);
} // namespace ausroll
