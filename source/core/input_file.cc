#include <ausroll/core/exceptions.h>
#include <ausroll/core/input_file.h>

#include <cerrno>
#include <cstring>
#include <sys/stat.h>
#include <unistd.h>

namespace ausroll
{
  std::string input_file_problem(const std::string &path, const std::uintmax_t max_bytes)
  {
    if (path.empty())
      return "no file name given";
    struct stat status;
    // stat() follows symbolic links and does not open the file: a FIFO is refused before
    // anything waits for a writer.
    if (::stat(path.c_str(), &status) != 0)
    {
      const int error = errno;
      if (error == ENOENT)
      {
        struct stat link;
        if (::lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode))
          return "a symbolic link to a file that does not exist";
        return "no such file";
      }
      if (error == ELOOP)
        return "too many levels of symbolic links (a symbolic-link loop?)";
      if (error == EACCES)
        return "permission denied (a directory on its path cannot be searched)";
      return std::strerror(error);
    }
    if (S_ISDIR(status.st_mode))
      return "is a directory, not a file";
    if (S_ISFIFO(status.st_mode))
      return "is a FIFO (named pipe), not a regular file";
    if (S_ISCHR(status.st_mode) || S_ISBLK(status.st_mode))
      return "is a device, not a regular file";
    if (S_ISSOCK(status.st_mode))
      return "is a socket, not a regular file";
    if (!S_ISREG(status.st_mode))
      return "is not a regular file";
    if (::access(path.c_str(), R_OK) != 0)
      return "permission denied (the file is not readable)";
    if (static_cast<std::uintmax_t>(status.st_size) > max_bytes)
      return "is " + std::to_string(static_cast<std::uintmax_t>(status.st_size))
             + " bytes, more than the " + std::to_string(max_bytes) + " accepted for such a file";
    return "";
  }

  std::ifstream open_input_file(const std::string   &path,
                                const std::string   &what,
                                const std::uintmax_t max_bytes,
                                const bool           binary)
  {
    const std::string problem = input_file_problem(path, max_bytes);
    if (!problem.empty())
      throw InputError(what + " '" + path + "': " + problem);
    std::ifstream in(path, binary ? std::ios::in | std::ios::binary : std::ios::in);
    if (!in)
      throw InputError(what + " '" + path + "': cannot be opened for reading ("
                       + std::strerror(errno) + ")");
    return in;
  }
} // namespace ausroll
