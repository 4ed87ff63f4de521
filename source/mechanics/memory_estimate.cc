#include <ausroll/core/exceptions.h>
#include <ausroll/material/material_point.h>
#include <ausroll/mechanics/memory_estimate.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <sys/resource.h>
#include <unistd.h>

namespace ausroll::mechanics
{
  namespace
  {
    std::string gigabytes(const double bytes)
    {
      std::ostringstream out;
      out << std::setprecision(bytes < 1e9 ? 2 : 3) << bytes / 1e9 << " GB";
      return out.str();
    }

    std::string count(const double n)
    {
      std::ostringstream out;
      out << std::setprecision(3) << n;
      return out.str();
    }
  } // namespace

  std::string MemoryEstimate::describe() const
  {
    std::ostringstream out;
    out << count(cells) << " cells of degree " << degree << " (" << dim << "D), " << count(dofs)
        << " DoFs, " << count(quadrature_points) << " quadrature points (" << quadrature_points_1d
        << " per direction), " << count(matrix_nonzeros) << " matrix entries: about "
        << gigabytes(bytes) << " (material points " << gigabytes(bytes_material_points)
        << ", matrix and preconditioner " << gigabytes(bytes_matrix);
    if (bytes_factor > 0.)
      out << ", LU factors " << gigabytes(bytes_factor);
    out << ", mesh " << gigabytes(bytes_mesh) << ", vectors " << gigabytes(bytes_vectors)
        << ", output " << gigabytes(bytes_output) << ")";
    return out.str();
  }

  MemoryEstimate estimate_memory(const unsigned int dim,
                                 const double       n_cells,
                                 const unsigned int degree,
                                 const unsigned int quadrature_points_1d,
                                 const bool         direct_solver,
                                 const double       probe_points)
  {
    MemoryEstimate e;
    e.dim = dim;
    e.degree = degree;
    e.quadrature_points_1d = quadrature_points_1d;
    e.cells = n_cells;
    const double nodes_per_cell = std::pow(double(degree), double(dim));
    e.dofs = dim * n_cells * nodes_per_cell;
    e.quadrature_points = n_cells * std::pow(double(quadrature_points_1d), double(dim));
    e.matrix_nonzeros = e.dofs * dim * std::pow(degree + 2., double(dim));
    if (direct_solver && e.dofs > 1.)
      e.factor_entries = dim == 2 ? 0.5 * e.matrix_nonzeros * std::log2(e.dofs)
                                  : 0.5 * e.matrix_nonzeros * std::cbrt(e.dofs);
    // CellDataStorage: a shared_ptr per point and its control block, a map node per cell
    e.bytes_material_points
        = e.quadrature_points * (sizeof(material::MaterialPoint) + 48.) + 96. * n_cells;
    // Trilinos: value (8) + column index (4) in the matrix and again in the sparsity pattern,
    // and the algebraic multigrid hierarchy (about half the matrix again)
    e.bytes_matrix = e.matrix_nonzeros * 12. * 2.5;
    // L and U: value and index, and MUMPS' work space
    e.bytes_factor = e.factor_entries * 12. * 1.5;
    // triangulation (cells, faces, lines and their parents) and DoF indices
    e.bytes_mesh = n_cells * (dim == 2 ? 600. : 1500.) + e.dofs * 16.;
    // about 25 vectors of the step state, Newton, contact and output (ghosted copies included)
    e.bytes_vectors = 25. * 8. * e.dofs;
    // VTU patches: (degree + 1)^dim points per cell with about 25 values each; probe samples
    e.bytes_output = n_cells * std::pow(degree + 1., double(dim)) * 25. * 8. + probe_points * 400.;
    e.bytes = e.bytes_material_points + e.bytes_matrix + e.bytes_factor + e.bytes_mesh
              + e.bytes_vectors + e.bytes_output;
    return e;
  }

  double available_memory()
  {
    double        bytes = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGESIZE));
    struct rlimit limit;
    for (const int resource : {RLIMIT_AS, RLIMIT_DATA})
      if (getrlimit(resource, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
        bytes = std::min(bytes, double(limit.rlim_cur));
    return bytes;
  }

  void require_memory(const MemoryEstimate &estimate, const std::string &entries)
  {
    const double available = available_memory();
    if (estimate.bytes <= available)
      return;
    throw InputError(entries + ": " + estimate.describe() + ", more than the "
                     + gigabytes(available)
                     + " this machine (or ulimit) allows; make the largest part smaller "
                       "through the entries named");
  }
} // namespace ausroll::mechanics
