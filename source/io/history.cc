#include <ausroll/core/exceptions.h>
#include <ausroll/io/history.h>

#include <deal.II/base/mpi.h>

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
    if (row.size() != columns.size())
      throw std::logic_error("history row does not match the columns of " + path);
    if (!writer)
      return;
    for (unsigned int i = 0; i < row.size(); ++i)
      file << (i ? "," : "") << row[i].second;
    file << std::endl;
  }

  std::unique_ptr<History>
  History::resume(const MPI_Comm comm, const std::string &path, const unsigned int last_step)
  {
    std::vector<std::string> columns;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
    {
      std::ifstream            in(path);
      std::vector<std::string> kept;
      std::string              line;
      while (std::getline(in, line))
        if (kept.empty() || std::stod(line.substr(0, line.find(','))) <= last_step)
          kept.push_back(line);
      in.close();
      std::ofstream out(path, std::ios::trunc);
      for (const std::string &l : kept)
        out << l << '\n';
    }
    MPI_Barrier(comm);
    auto history = std::make_unique<History>(comm, path, true);
    return history;
  }
} // namespace ausroll::io
