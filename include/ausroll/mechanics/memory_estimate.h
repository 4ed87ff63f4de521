/**
 * @file memory_estimate.h
 * The memory a discretisation will need, estimated from the cell count, the element, the
 * dimension, the quadrature and the probes before anything is allocated, and compared with the
 * memory of the machine (so that a too large input is refused with a message instead of
 * exhausting the memory).
 */
#pragma once

#include <string>

namespace ausroll::mechanics
{
  /** What a discretisation will hold, with the estimated bytes of each part. */
  struct MemoryEstimate
  {
    unsigned int dim = 2;                    ///< dimension
    unsigned int degree = 1;                 ///< polynomial degree
    unsigned int quadrature_points_1d = 2;   ///< Gauss points per direction
    double       cells = 0.;                 ///< active cells
    double       dofs = 0.;                  ///< unknowns
    double       quadrature_points = 0.;     ///< material points (cells x points per cell)
    double       matrix_nonzeros = 0.;       ///< entries of the tangent matrix
    double       factor_entries = 0.;        ///< entries of the LU factors (direct solver)
    double       bytes_mesh = 0.;            ///< triangulation and DoF numbering
    double       bytes_material_points = 0.; ///< the material points (committed + trial state)
    double       bytes_matrix = 0.;          ///< matrix, its sparsity and the preconditioner
    double       bytes_factor = 0.;          ///< LU factors of a direct solve
    double       bytes_vectors = 0.;         ///< the step-state and work vectors
    double       bytes_output = 0.;          ///< VTU patches and line-probe samples
    double       bytes = 0.;                 ///< everything

    /**
     * One line: "N cells, N DoFs, N quadrature points, N matrix entries: about X GB (material
     * points X, matrix X, LU factors X, ...)".
     */
    std::string describe() const;
  };

  /**
   * Estimate for @p n_cells cells of degree @p degree in @p dim dimensions with
   * @p quadrature_points_1d Gauss points per direction, a direct (LU) solver if @p direct_solver,
   * and @p probe_points line-probe samples. The counts are those of a large mesh: unknowns
   * dim n_cells p^dim, nonzeros per row dim (p + 2)^dim (the average coupling of vertex, edge,
   * face and interior nodes), 2D LU factors 2 nnz log2(N) / 4, 3D nnz N^(1/3) / 2 (nested
   * dissection orders of growth). It errs on the large side: prm/upsetting_3d.prm (3D, AMG)
   * estimates 0.40 GB and its first step peaks 0.11 GB above the 0.19 GB of a process that only
   * reads the input; tests/checks/scenes/upsetting_3d_short.prm.in 0.029 GB against 0.018 GB.
   */
  MemoryEstimate estimate_memory(unsigned int dim,
                                 double       n_cells,
                                 unsigned int degree,
                                 unsigned int quadrature_points_1d,
                                 bool         direct_solver,
                                 double       probe_points);

  /**
   * Memory the run may use (bytes): the machine's physical memory (sysconf), or the process's
   * address-space or data-size limit (ulimit -v / -d) if lower.
   */
  double available_memory();

  /**
   * InputError naming @p entries (the entries that set the size) and the estimate if
   * @p estimate needs more than available_memory().
   */
  void require_memory(const MemoryEstimate &estimate, const std::string &entries);
} // namespace ausroll::mechanics
