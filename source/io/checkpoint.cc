#include <ausroll/core/exceptions.h>
#include <ausroll/io/checkpoint.h>

#include <deal.II/base/mpi.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

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

  void CheckpointMetadata::write(const std::string &filename) const
  {
    std::ofstream out(filename);
    out << std::setprecision(17);
    for (const auto &[key, v] : values)
    {
      out << "value " << key << ' ' << v.size();
      for (const double x : v)
        out << ' ' << x;
      out << '\n';
    }
    for (const auto &[key, text] : strings)
      out << "string " << key << ' ' << text << '\n';
    out << "end\n";
    if (!out)
      throw RunFailure("cannot write checkpoint file '" + filename + "'");
  }

  void CheckpointMetadata::read(const std::string &filename)
  {
    std::ifstream in(filename);
    if (!in)
      throw RunFailure("cannot read checkpoint file '" + filename + "'");
    values.clear();
    strings.clear();
    std::string line;
    bool        complete = false;
    while (std::getline(in, line))
    {
      std::istringstream words(line);
      std::string        kind, key;
      words >> kind;
      if (kind == "end")
      {
        complete = true;
        break;
      }
      words >> key;
      if (kind == "value")
      {
        std::size_t n = 0;
        words >> n;
        std::vector<double> v(n);
        for (double &x : v)
          words >> x;
        values[key] = v;
      }
      else if (kind == "string")
      {
        std::string text;
        std::getline(words, text);
        strings[key] = text.empty() ? text : text.substr(1);
      }
    }
    if (!complete)
      throw RunFailure("checkpoint file '" + filename + "' is incomplete");
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
    /** Entries whose change makes the checkpoint's mesh, DoFs or material points meaningless. */
    bool fixes_discretisation(const std::string &entry)
    {
      for (const char *prefix : {"Geometry/", "Model/", "Material/", "Adaptivity/"})
        if (entry.rfind(prefix, 0) == 0)
          return true;
      if (entry == "Contact/Number of dies")
        return true;
      return entry.rfind("Contact/Die ", 0) == 0 && entry.size() > 21
             && entry.compare(entry.size() - 21, 21, "Candidate boundaries") == 0;
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
      else
        warnings.push_back("--resume: " + line + " changed since the checkpoint was written");
    }
    if (!refused.empty())
      throw InputError("--resume: entries that fix the mesh, the discretisation or the material "
                       "differ from those of the checkpoint in "
                       + directory + ":" + refused
                       + "\nResume with the values of the checkpoint, or start a new run "
                         "(--overwrite).");
    return warnings;
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
