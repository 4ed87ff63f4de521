/**
 * @file check_input.cc
 * `ausroll FILE.prm --check-input`: the sizes of a scene built and checked but not run.
 */
#include <ausroll/mechanics/memory_estimate.h>
#include <ausroll/scene/scene.h>
#include <ausroll/scene/setup_checks.h>

#include <deal.II/base/timer.h>

#include <iomanip>
#include <ostream>

namespace ausroll::scene
{
  namespace
  {
    /**
     * Linear solves per load step of the shipped scenes (doc/benchmarks.md, 2026-12-07,
     * accepted + discarded): 2.1 (thick cylinder, smooth plasticity) to 12.1 (quick disk,
     * rolling contact); the flagship gear 9.4, the indentation 3.6. Each solve comes with 1.3 to
     * 1.6 assemblies of residual and tangent.
     */
    constexpr double fewest_solves_per_step = 2.;
    constexpr double most_solves_per_step = 13.;
    constexpr double assemblies_per_solve = 1.5;
  } // namespace

  template <int dim>
  void Scene<dim>::print_sizes(std::ostream &out)
  {
    // One Newton iteration of the first nominal step, timed (CPU of this process): the
    // assembly of residual and tangent and one linear solve. Nothing is committed and nothing
    // is written; the run would start from the same state.
    double       assembly_cpu = -1., solve_cpu = -1.;
    std::string  why_not;
    const double first_time = parameters.loading.end_time / parameters.loading.number_of_steps;
    try
    {
      begin_step(0.);
      time = first_time;
      system.start_step(0.);
      dealii::Timer timer_one(comm);
      std::string   message;
      if (equilibrium->assemble(true, message))
      {
        assembly_cpu = timer_one.cpu_time();
        timer_one.restart();
        equilibrium->solve_for_increment();
        solve_cpu = timer_one.cpu_time();
      }
      else
        why_not = message;
    }
    catch (const std::exception &e)
    {
      why_not = e.what();
    }

    const double                    cells = system.triangulation.n_global_active_cells();
    const mechanics::MemoryEstimate estimate = check_sizes<dim>(parameters, cells);
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
        << " nominal (sizes at the start: adaptive refinement changes them)\n";
    if (solve_cpu < 0.)
    {
      out << "  time per step:         not measured (the first assembly or solve failed: "
          << why_not << ")" << std::endl;
      return;
    }
    const double iteration = assemblies_per_solve * assembly_cpu + solve_cpu;
    const double steps = parameters.loading.number_of_steps;
    out << "  one Newton iteration:  " << assembly_cpu + solve_cpu << " s CPU measured now ("
        << assembly_cpu << " s assembly, " << solve_cpu << " s linear solve)\n"
        << "  time per step:         " << fewest_solves_per_step * iteration << " to "
        << most_solves_per_step * iteration
        << " s CPU estimated (2 to 13 linear solves per step, as the shipped scenes: smooth "
           "plasticity at the low end, rolling contact at the high end)\n"
        << "  whole run:             " << steps * fewest_solves_per_step * iteration / 60. << " to "
        << steps * most_solves_per_step * iteration / 60.
        << " min CPU estimated for the nominal steps (cutbacks and refinement add)\n";
    if (parameters.adaptivity.active())
      out << "  note:                  Adaptivity is on: these figures are for the mesh at the "
             "start; the shipped adaptive gear and disk scenes refine to several times its size "
             "and run 1.3 to 3 times above the upper estimate\n";
    out << std::flush;
  }

  template void Scene<2>::print_sizes(std::ostream &);
  template void Scene<3>::print_sizes(std::ostream &);
} // namespace ausroll::scene
