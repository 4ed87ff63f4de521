#include <ausroll/core/exceptions.h>
#include <ausroll/io/history.h>

#include <ausroll/core/parse_utilities.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iomanip>

namespace ausroll::io
{
  History::History(const MPI_Comm comm, const std::string &path, const bool append)
      : writer(dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      , path(path)
  {
    if (writer)
    {
      std::error_code ec;
      header_pending = !append || !std::filesystem::exists(path, ec)
                       || std::filesystem::file_size(path, ec) == 0;
      file.open(path, append ? std::ios::app : std::ios::trunc);
      if (!file)
        throw InputError("Output/Directory: cannot write '" + path + "'");
      file << std::setprecision(10);
    }
  }

  void History::add_row(const HistoryRow &row)
  {
    if (columns.empty())
    {
      for (const auto &entry : row)
        columns.push_back(entry.first);
      if (writer && header_pending)
      {
        for (unsigned int i = 0; i < columns.size(); ++i)
          file << (i ? "," : "") << columns[i];
        file << '\n';
      }
    }
    if (!resumed_header.empty())
    {
      // The rows kept from before the resume have the header of the file: new rows must fit it.
      std::string header;
      for (unsigned int i = 0; i < columns.size(); ++i)
        header += (i ? "," : "") + columns[i];
      if (header != resumed_header)
        throw InputError("--resume: the columns of '" + path
                         + "' differ from those this run writes (monitor points, reaction "
                           "boundaries, dies or probes changed since the checkpoint?); "
                           "file: '"
                         + abbreviate(resumed_header) + "', now: '" + abbreviate(header)
                         + "'. Resume with the entries of the checkpoint or start a new run");
      resumed_header.clear();
    }
    if (row.size() != columns.size())
      throw std::logic_error("history row does not match the columns of " + path);
    if (!writer)
      return;
    for (unsigned int i = 0; i < row.size(); ++i)
      file << (i ? "," : "") << row[i].second;
    file << std::endl;
    if (!file)
      throw RunFailure("cannot write '" + path + "' (disk full or no permission?)");
  }

  std::unique_ptr<History>
  History::resume(const MPI_Comm comm, const std::string &path, const unsigned int last_step)
  {
    std::string header, error;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
    {
      std::ifstream            in(path);
      std::vector<std::string> kept;
      std::string              line;
      unsigned int             number = 0;
      if (!in)
        error = "--resume: cannot read '" + path + "'";
      while (error.empty() && std::getline(in, line))
      {
        ++number;
        if (header.empty() || line.rfind('#', 0) == 0)
        {
          // comment lines and the header line are kept as they are
          if (line.rfind('#', 0) != 0)
            header = line;
          kept.push_back(line);
          continue;
        }
        // the first column is the step number
        const std::string first = line.substr(0, line.find(','));
        char             *end = nullptr;
        const double      step = std::strtod(first.c_str(), &end);
        if (first.empty() || end != first.c_str() + first.size() || !std::isfinite(step))
          error = "--resume: '" + path + "' line " + std::to_string(number) + " does not start "
                  + "with a step number ('" + abbreviate(line)
                  + "'); was the file edited? Restore it or start a new run";
        else if (step <= last_step)
          kept.push_back(line);
      }
      if (error.empty() && header.empty())
        error = "--resume: '" + path + "' has no header line (was the file emptied?); restore "
                + "it or start a new run";
      in.close();
      if (error.empty())
      {
        // write the kept rows next to the file, then replace it: a failed write keeps the old
        const std::string tmp = path + ".tmp";
        std::ofstream     out(tmp, std::ios::trunc);
        for (const std::string &l : kept)
          out << l << '\n';
        out.close();
        if (!out || std::rename(tmp.c_str(), path.c_str()) != 0)
          error = "--resume: cannot rewrite '" + path + "' (disk full or no permission?)";
      }
    }
    error = dealii::Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw InputError(error);
    header = dealii::Utilities::MPI::broadcast(comm, header, 0);
    MPI_Barrier(comm);
    auto history = std::make_unique<History>(comm, path, true);
    history->resumed_header = header;
    return history;
  }
} // namespace ausroll::io
