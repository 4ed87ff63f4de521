/**
 * @file check_input.cc
 * `ausroll FILE.prm --check-input`: the sizes of a scene built and checked but not run.
 */
#include <ausroll/mechanics/memory_estimate.h>
#include <ausroll/scene/scene.h>
#include <ausroll/scene/setup_checks.h>

#include <iomanip>
#include <ostream>

namespace ausroll::scene
{
  template <int dim>
  void Scene<dim>::print_sizes(std::ostream &out) const
  {
    const double                    cells = system.triangulation.n_global_active_cells();
    const mechanics::MemoryEstimate estimate = check_sizes(parameters, cells, dim);
    const double                    dofs = system.dof_handler.n_dofs();
    const double                    points = cells * assembler->quadrature().size();
    const double                    entries = system.system_matrix.n_nonzero_elements();
    if (rank != 0)
      return;
    out << std::setprecision(3) << "ausroll --check-input: '" << parameters.name << "' (" << dim
        << "D) is consistent; nothing was written\n"
        << "  cells:                 " << cells << "\n"
        << "  DoFs:                  " << dofs << "\n"
        << "  quadrature points:     " << points << " (" << assembler->quadrature().size()
        << " per cell)\n"
        << "  matrix entries:        " << entries << "\n"
        << "  estimated memory:      " << estimate.bytes / 1e9 << " GB (limit "
        << mechanics::available_memory() / 1e9 << " GB)\n"
        << "  load steps:            " << parameters.loading.number_of_steps
        << " nominal (sizes at the start: adaptive refinement changes them)" << std::endl;
  }

  template void Scene<2>::print_sizes(std::ostream &) const;
  template void Scene<3>::print_sizes(std::ostream &) const;
} // namespace ausroll::scene
