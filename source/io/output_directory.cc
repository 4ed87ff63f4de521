#include <ausroll/core/exceptions.h>
#include <ausroll/io/output_directory.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>

namespace ausroll::io
{
  namespace fs = std::filesystem;

  std::vector<std::string> earlier_results(const std::string &directory)
  {
    const std::regex numbered(
        R"((solution_[0-9]+(\.[0-9]+)?\.(vtu|pvtu)|(contact|profile)_[0-9]{4}\.csv|probe_.+_[0-9]{4}\.csv|dies_[0-9]+(_[0-9]+)?\.(vtu|vtm)))");
    std::vector<std::string> found;
    std::error_code          ec;
    for (const auto &entry : fs::directory_iterator(directory, ec))
    {
      const std::string name = entry.path().filename().string();
      if (entry.is_directory(ec)
              ? (name == "checkpoint" || name == "checkpoint.old" || name == "checkpoint.new")
              : (name == "history.csv" || name == "solution.pvd" || name == "dies.pvd"
                 || name == "history_units.csv" || name == "solution_units.csv"
                 || name == "parameters.prm" || std::regex_match(name, numbered)))
        found.push_back(name);
    }
    std::sort(found.begin(), found.end());
    return found;
  }

  void
  prepare_output_directory(const std::string &directory, const bool overwrite, const MPI_Comm comm)
  {
    std::string error;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
    {
      std::error_code                ec;
      const std::vector<std::string> found = earlier_results(directory);
      if (!found.empty() && !overwrite)
      {
        std::string list;
        for (std::size_t k = 0; k < found.size() && k < 4; ++k)
          list += (k > 0 ? ", " : "") + found[k];
        if (found.size() > 4)
          list += " and " + std::to_string(found.size() - 4) + " more";
        error = "Output/Directory: '" + directory + "' holds results of an earlier run (" + list
                + "); use --overwrite (or Output/Overwrite = true) to replace them, --resume to "
                  "continue that run, or choose another Output/Directory";
      }
      else
      {
        for (const std::string &name : found)
          fs::remove_all(fs::path(directory) / name, ec);
        fs::create_directories(directory, ec);
        if (ec || !fs::is_directory(directory))
          error = "Output/Directory: cannot create '" + directory + "'";
      }
    }
    error = dealii::Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw InputError(error);
  }

  void
  write_parameter_copy(const std::string &directory, const std::string &text, const MPI_Comm comm)
  {
    std::string error;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
    {
      const std::string file = directory + "/parameters.prm";
      std::ofstream     out(file);
      out << "# The effective parameters of this run (the .prm as parsed, includes expanded,\n"
             "# --set overrides applied), every entry; an entry that differs from its default\n"
             "# ends in '# default: ...'. Relative file names are relative to the original .prm.\n"
          << text;
      out.close();
      if (!out)
        error = "Output/Directory: cannot write '" + file + "'";
    }
    error = dealii::Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw InputError(error);
  }
} // namespace ausroll::io
