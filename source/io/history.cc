#include <ausroll/core/exceptions.h>
#include <ausroll/io/history.h>

#include <deal.II/base/mpi.h>

#include <iomanip>

namespace ausroll::io
{
  History::History(const MPI_Comm comm, const std::string &path, const bool append)
      : writer(dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      , path(path)
  {
    if (writer)
    {
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
      if (writer && file.tellp() == 0)
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
} // namespace ausroll::io
