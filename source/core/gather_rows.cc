#include <ausroll/core/gather_rows.h>

#include <deal.II/base/mpi.h>

#include <algorithm>

namespace ausroll
{
  std::vector<std::vector<double>> gather_sorted_rows(const MPI_Comm                          comm,
                                                      const std::vector<std::vector<double>> &rows)
  {
    const auto                       gathered = dealii::Utilities::MPI::gather(comm, rows, 0);
    std::vector<std::vector<double>> all;
    for (const auto &part : gathered)
      all.insert(all.end(), part.begin(), part.end());
    std::sort(all.begin(), all.end());
    return all;
  }
} // namespace ausroll
