#include <ausroll/core/exceptions.h>
#include <ausroll/core/input_file.h>
#include <ausroll/core/parse_utilities.h>
#include <ausroll/io/checkpoint.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

#include <sys/resource.h>
#include <sys/statvfs.h>

namespace ausroll::io
{
  using namespace dealii;
  namespace fs = std::filesystem;

  void CheckpointParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Checkpoint");
    prm.declare_entry("Interval",
                      "0",
                      Patterns::Integer(0),
                      "Write a checkpoint (mesh, solution, material points, contact statuses, "
                      "history position) into <Output directory>/checkpoint every this many steps "
                      "(0: never). Continue a run with 'ausroll FILE.prm --resume'.");
    prm.declare_entry("Abort after step",
                      "0",
                      Patterns::Integer(0),
                      "Testing aid: terminate the process abruptly (as if killed) after this step "
                      "(0: never).");
    prm.leave_subsection();
  }

  void abort_if_asked(const CheckpointParameters &parameters,
                      const unsigned int          step,
                      ConditionalOStream         &log)
  {
    if (parameters.abort_after_step != step)
      return;
    log << "  aborting after step " << step << " (Checkpoint/Abort after step)" << std::endl;
    std::_Exit(99);
  }

  void CheckpointParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Checkpoint");
    interval = prm.get_integer("Interval");
    abort_after_step = prm.get_integer("Abort after step");
    prm.leave_subsection();
  }

  namespace
  {
    /** FNV-1a (64 bit) of @p bytes, continuing from @p hash. */
    std::uint64_t fnv1a(const char *bytes, const std::size_t n, std::uint64_t hash)
    {
      for (std::size_t i = 0; i < n; ++i)
      {
        hash ^= static_cast<unsigned char>(bytes[i]);
        hash *= 0x100000001b3ULL;
      }
      return hash;
    }

    constexpr std::uint64_t fnv1a_basis = 0xcbf29ce484222325ULL;

    std::string hex(const std::uint64_t x)
    {
      std::ostringstream out;
      out << std::hex << std::setw(16) << std::setfill('0') << x;
      return out.str();
    }

    /** Size and FNV-1a 64 of the file @p path (InputError naming it if it cannot be read). */
    std::pair<std::uintmax_t, std::string> size_and_checksum(const std::string &path)
    {
      std::ifstream in = open_input_file(
          path, "checkpoint file", std::numeric_limits<std::uintmax_t>::max(), true);
      std::vector<char> buffer(1 << 20);
      std::uint64_t     hash = fnv1a_basis;
      std::uintmax_t    size = 0;
      while (in)
      {
        in.read(buffer.data(), buffer.size());
        hash = fnv1a(buffer.data(), in.gcount(), hash);
        size += in.gcount();
      }
      if (in.bad())
        throw InputError("checkpoint file '" + path + "': read error");
      return {size, hex(hash)};
    }
  } // namespace

  void CheckpointMetadata::record_files(const std::string &directory)
  {
    std::vector<std::string> names;
    for (const auto &entry : fs::directory_iterator(directory))
      if (entry.path().filename() != "metadata.txt")
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    for (const std::string &name : names)
    {
      const auto [size, checksum] = size_and_checksum(directory + "/" + name);
      strings["file:" + name] = std::to_string(size) + " " + checksum;
    }
  }

  std::string CheckpointMetadata::damaged_file(const std::string &directory) const
  {
    for (const auto &[key, text] : strings)
    {
      if (key.rfind("file:", 0) != 0)
        continue;
      const std::string  path = directory + "/" + key.substr(5);
      std::istringstream recorded(text);
      std::uintmax_t     size = 0;
      std::string        checksum;
      recorded >> size >> checksum;
      try
      {
        const auto [now_size, now_checksum] = size_and_checksum(path);
        if (now_size != size)
          return "checkpoint file '" + path + "' is damaged: " + std::to_string(now_size)
                 + " bytes, written with " + std::to_string(size)
                 + " (truncated or emptied?); start a new run (--overwrite)";
        if (now_checksum != checksum)
          return "checkpoint file '" + path
                 + "' is damaged: its checksum (FNV-1a) differs from the one recorded when it "
                   "was written; start a new run (--overwrite)";
      }
      catch (const InputError &e)
      {
        return std::string(e.what()) + " (the checkpoint in '" + directory
               + "' is incomplete); start a new run (--overwrite)";
      }
    }
    return "";
  }

  void CheckpointMetadata::write(const std::string &filename) const
  {
    std::ostringstream text;
    text << std::setprecision(17);
    text << "format " << format_version << '\n';
    for (const auto &[key, v] : values)
    {
      text << "value " << key << ' ' << v.size();
      for (const double x : v)
        text << ' ' << x;
      text << '\n';
    }
    for (const auto &[key, line] : strings)
      text << "string " << key << ' ' << line << '\n';
    const std::string body = text.str();
    std::ofstream     out(filename);
    out << body << "checksum " << hex(fnv1a(body.data(), body.size(), fnv1a_basis)) << '\n'
        << "end\n";
    out.close();
    if (!out)
      throw RunFailure("cannot write checkpoint file '" + filename
                       + "' (disk full or no permission?); the previous checkpoint is kept");
  }

  void CheckpointMetadata::read(const std::string &filename)
  {
    if (!fs::exists(filename))
      throw RunFailure("cannot read checkpoint file '" + filename + "'");
    std::ifstream     in = open_input_file(filename, "checkpoint file", 1u << 30);
    const std::string damaged = "checkpoint file '" + filename + "' is damaged: ";
    std::string       body, line, checksum;
    bool              complete = false;
    while (std::getline(in, line))
    {
      if (line.rfind("checksum ", 0) == 0)
        checksum = line.substr(9);
      else if (line == "end")
      {
        complete = true;
        break;
      }
      else if (checksum.empty())
        body += line + '\n';
    }
    if (!complete)
      throw InputError(damaged + "incomplete (no 'end' line); start a new run (--overwrite)");
    if (body.rfind("format ", 0) != 0)
      throw InputError("checkpoint file '" + filename
                       + "' has no format version (written by an older ausroll): resume it with "
                         "that version or start a new run (--overwrite)");
    if (checksum != hex(fnv1a(body.data(), body.size(), fnv1a_basis)))
      throw InputError(damaged
                       + "its checksum differs from its contents (edited?); start a new "
                         "run (--overwrite)");
    values.clear();
    strings.clear();
    std::istringstream lines(body);
    while (std::getline(lines, line))
    {
      std::istringstream words(line);
      std::string        kind, key;
      words >> kind;
      if (kind == "format")
      {
        unsigned int version = 0;
        words >> version;
        if (version != format_version)
          throw InputError("checkpoint file '" + filename + "' has format version "
                           + std::to_string(version) + ", this ausroll reads version "
                           + std::to_string(format_version) + "; start a new run (--overwrite)");
        continue;
      }
      if (kind == "value")
      {
        words >> key;
        std::size_t n = 0;
        words >> n;
        if (!words || n > (1u << 28))
          throw InputError(damaged + "bad line 'value " + key + "'");
        std::vector<double> v(n);
        for (double &x : v)
          words >> x;
        if (!words)
          throw InputError(damaged + "bad line 'value " + key + "'");
        values[key] = v;
      }
      else if (kind == "string")
      {
        words >> key;
        std::string text;
        std::getline(words, text);
        strings[key] = text.empty() ? text : text.substr(1);
      }
      else
        throw InputError(damaged + "unknown line '" + abbreviate(line) + "'");
    }
  }

  double CheckpointMetadata::get(const std::string &key) const
  {
    const auto it = values.find(key);
    if (it == values.end() || it->second.empty())
      throw RunFailure("checkpoint lacks '" + key + "'");
    return it->second[0];
  }

  void CheckpointMetadata::set_parameters(const std::map<std::string, std::string> &entries)
  {
    unsigned int k = 0;
    for (const auto &[entry, value] : entries)
    {
      std::ostringstream key;
      key << "parameter_" << std::setw(4) << std::setfill('0') << k++;
      strings[key.str()] = entry + '\t' + value;
    }
  }

  std::map<std::string, std::string> CheckpointMetadata::parameters() const
  {
    std::map<std::string, std::string> entries;
    for (const auto &[key, text] : strings)
      if (key.rfind("parameter_", 0) == 0)
      {
        const auto tab = text.find('\t');
        entries[text.substr(0, tab)] = tab == std::string::npos ? "" : text.substr(tab + 1);
      }
    return entries;
  }

  namespace
  {
    /** Whether @p entry is `Contact/Die <k>/<name>` (exactly that entry of some die). */
    bool is_die_entry(const std::string &entry, const std::string &name)
    {
      const std::string prefix = "Contact/Die ", suffix = "/" + name;
      if (entry.rfind(prefix, 0) != 0 || entry.size() <= prefix.size() + suffix.size())
        return false;
      const std::string number
          = entry.substr(prefix.size(), entry.size() - prefix.size() - suffix.size());
      return entry.compare(entry.size() - suffix.size(), suffix.size(), suffix) == 0
             && number.find_first_not_of("0123456789") == std::string::npos;
    }

    /** Entries whose change makes the checkpoint's mesh, DoFs or material points meaningless. */
    bool fixes_discretisation(const std::string &entry)
    {
      for (const char *prefix : {"Geometry/", "Model/", "Material/", "Adaptivity/"})
        if (entry.rfind(prefix, 0) == 0)
          return true;
      if (entry == "Contact/Number of dies")
        return true;
      return is_die_entry(entry, "Candidate boundaries");
    }

    /** Entries whose change adds, removes or renames columns of history.csv. */
    bool fixes_history_columns(const std::string &entry)
    {
      return entry == "Postprocess/Monitor points" || entry == "Postprocess/Reaction boundaries"
             || is_die_entry(entry, "Name");
    }

    /** Entries that do not change the computed results. */
    bool ignored_on_resume(const std::string &entry)
    {
      return entry == "Output/Overwrite" || entry == "Checkpoint/Abort after step";
    }
  } // namespace

  std::vector<std::string> compare_resume_parameters(const CheckpointMetadata                 &meta,
                                                     const std::map<std::string, std::string> &now,
                                                     const std::string &directory)
  {
    const std::map<std::string, std::string> then = meta.parameters();
    std::vector<std::string>                 warnings;
    if (then.empty())
    {
      warnings.push_back("the checkpoint in " + directory
                         + " stores no parameters: cannot check that FILE.prm is unchanged");
      return warnings;
    }
    std::string refused;
    for (const auto &[entry, value] : now)
    {
      const auto        it = then.find(entry);
      const std::string old = it == then.end() ? "(not stored)" : it->second;
      if (old == value || ignored_on_resume(entry))
        continue;
      const std::string line = entry + " (checkpoint: '" + old + "', now: '" + value + "')";
      if (fixes_discretisation(entry))
        refused += "\n  " + line;
      else if (fixes_history_columns(entry))
        refused += "\n  " + line + " (it changes the columns of history.csv)";
      else
        warnings.push_back("--resume: " + line + " changed since the checkpoint was written");
    }
    if (!refused.empty())
      throw InputError(
          "--resume: entries that fix the mesh, the discretisation, the material or the "
          "history columns "
          "differ from those of the checkpoint in "
          + directory + ":" + refused
          + "\nResume with the values of the checkpoint, or start a new run "
            "(--overwrite).");
    return warnings;
  }

  std::string incomplete_cell_data(const std::string &path, const std::uint64_t n_cells)
  {
    std::error_code     ec;
    const std::uint64_t size = fs::file_size(path, ec);
    if (ec)
      return "cannot read the checkpoint file '" + path + "' just written: " + ec.message();
    std::ifstream in(path, std::ios::binary);
    // the header: cumulative sizes, increasing; the true length k is the one whose total
    // matches (a truncated file matches none)
    std::vector<std::uint64_t> header;
    for (unsigned int k = 1; k <= 64 && in; ++k)
    {
      std::uint32_t value = 0;
      if (!in.read(reinterpret_cast<char *>(&value), sizeof(value)))
        break;
      if (!header.empty() && value < header.back())
        break;
      header.push_back(value);
      if (4 * std::uint64_t(k) + n_cells * header.back() == size)
        return "";
    }
    std::uint64_t expected = 0;
    if (!header.empty())
      expected = 4 * header.size() + n_cells * header.back();
    return "the checkpoint file '" + path + "' was written incompletely (" + std::to_string(size)
           + " bytes"
           + (expected > size ? ", at least " + std::to_string(expected) + " expected" : "")
           + "): the disk is full or the file-size limit (ulimit -f) was reached";
  }

  void require_room(const std::string &directory, std::uintmax_t bytes, std::uintmax_t largest_file)
  {
    const auto megabytes = [](const double b)
    {
      std::ostringstream text;
      text << std::setprecision(3) << b / 1048576. << " MB";
      return text.str();
    };
    struct statvfs fs_info;
    if (statvfs(directory.c_str(), &fs_info) == 0)
    {
      const double available = double(fs_info.f_bavail) * double(fs_info.f_frsize);
      if (available < double(bytes))
        throw RunFailure("cannot write a checkpoint into '" + directory + "': it needs about "
                         + megabytes(bytes) + ", the file system has " + megabytes(available)
                         + " free (the previous checkpoint is kept)");
    }
    struct rlimit limit;
    if (getrlimit(RLIMIT_FSIZE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY
        && double(limit.rlim_cur) < double(largest_file))
      throw RunFailure("cannot write a checkpoint into '" + directory + "': its largest file needs "
                       + "about " + megabytes(largest_file)
                       + ", the file-size limit (ulimit -f) is " + megabytes(limit.rlim_cur)
                       + " (the previous checkpoint is kept)");
  }

  CheckpointDirectory::CheckpointDirectory(const std::string &output_directory, const MPI_Comm comm)
      : base(output_directory + "/checkpoint")
      , comm(comm)
  {
  }

  std::string CheckpointDirectory::begin_write() const
  {
    const std::string dir = base + ".new";
    if (Utilities::MPI::this_mpi_process(comm) == 0)
    {
      std::error_code ec;
      fs::remove_all(dir, ec);
      fs::create_directories(dir, ec);
    }
    MPI_Barrier(comm);
    return dir;
  }

  void CheckpointDirectory::commit() const
  {
    MPI_Barrier(comm);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
    {
      std::error_code ec;
      fs::remove_all(base + ".old", ec);
      if (fs::exists(base))
        fs::rename(base, base + ".old");
      fs::rename(base + ".new", base);
      fs::remove_all(base + ".old", ec);
    }
    MPI_Barrier(comm);
  }

  std::string CheckpointDirectory::latest() const
  {
    for (const std::string &dir : {base, base + ".old"})
      if (fs::exists(dir + "/metadata.txt"))
        return dir;
    throw RunFailure("--resume: no checkpoint in '" + base + "' (was Checkpoint/Interval set?)");
  }
} // namespace ausroll::io
