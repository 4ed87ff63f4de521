/**
 * @file amg_3d.cc
 * Linear solver cost in 3D (issue 14, deliverable 5): the tangent system of a block
 * (`Geometry/Type = block`, unit cube in N x N x N cells, Q1 or Q2) with three symmetry planes
 * (u_x = 0 on x = 0, u_y = 0 on y = 0, u_z = 0 on z = 0) and a prescribed top displacement,
 * assembled by mechanics::Assembler<3> and solved by solver::LinearSolver<3>:
 *
 * - elastic: small strain, u = 0 (the first Newton system), CG + ML AMG;
 * - plastic: small strain J2 (steel-like: E 210 GPa, yield 240 MPa, H 1 GPa) at a prescribed
 *   compression u_z = -delta z (0.5 + x) / 1.5, delta = 0.002 (yield strain 0.00114: the part
 *   x > 0.36 is plastic, the rest elastic), lateral u_x = 0.3 delta x, u_y = 0.3 delta y: the
 *   consistent (symmetric) tangent of that state, CG + AMG;
 * - finite: the same state with finite-strain J2 and F-bar: an unsymmetric tangent, GMRES + AMG.
 *
 * Usage: amg_3d MODE N DEGREE SOLVER [N_SOLVES = 2]
 *   MODE elastic | plastic | finite; SOLVER amg | mumps | klu
 * The problem is test_support::compressed_cube (tests/support/block_3d_problem.h), shared with
 * the unit tests. Runs on any number of MPI ranks (mpirun -np 2 amg_3d ...). Prints the wall and
 * CPU time (CPU: sum over the ranks) of the set-up (mesh, DoFs, sparsity) and of the assembly,
 * per solve the AMG set-up, iterations, solve time and the true residual, and the peak resident
 * memory (getrusage); no pass/fail (doc/benchmarks.md, section "3D linear solver").
 */
#include <ausroll/solver/linear_solver.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <sys/resource.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "support/block_3d_problem.h"

using namespace dealii;
using namespace ausroll;

namespace
{
  /** Peak resident memory of this process (MB). */
  double peak_memory_mb()
  {
    rusage usage;
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024.;
  }
} // namespace

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  if (argc < 5)
  {
    std::fprintf(stderr,
                 "usage: amg_3d elastic|plastic|finite N DEGREE amg|mumps|klu [N_SOLVES]\n");
    return 1;
  }
  const std::string  mode = argv[1];
  const unsigned int n = std::atoi(argv[2]), degree = std::atoi(argv[3]);
  const std::string  method = argv[4];
  const unsigned int n_solves = argc > 5 ? std::atoi(argv[5]) : 2;
  const MPI_Comm     comm = MPI_COMM_WORLD;
  const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
  if (mode != "elastic" && mode != "plastic" && mode != "finite")
  {
    std::fprintf(stderr, "amg_3d: unknown MODE %s\n", mode.c_str());
    return 1;
  }

  // (every figure is reduced on all ranks: norms and sums are collective; rank 0 prints)
  Timer      setup_timer;
  const auto problem = test_support::compressed_cube(comm, mode, n, degree);
  setup_timer.stop();
  Timer      assembly_timer;
  const auto status = problem->assemble();
  assembly_timer.stop();
  if (!status.ok)
  {
    std::fprintf(stderr, "assembly failed: %s\n", status.message.c_str());
    return 3;
  }
  unsigned int plastic_local = 0, points_local = 0;
  for (const auto &cell : problem->tria.active_cell_iterators())
    if (cell->is_locally_owned())
      for (const auto &p : problem->points.get_data(cell))
      {
        ++points_local;
        plastic_local += p->trial.equivalent_plastic_strain > 0. ? 1 : 0;
      }
  const unsigned int plastic = Utilities::MPI::sum(plastic_local, comm);
  const unsigned int n_points = Utilities::MPI::sum(points_local, comm);
  const double       setup_cpu = Utilities::MPI::sum(setup_timer.cpu_time(), comm);
  const double       assembly_cpu = Utilities::MPI::sum(assembly_timer.cpu_time(), comm);
  const double       assembly_cpu_max = Utilities::MPI::max(assembly_timer.cpu_time(), comm);
  const double       setup_wall = Utilities::MPI::max(setup_timer.wall_time(), comm);
  const double       assembly_wall = Utilities::MPI::max(assembly_timer.wall_time(), comm);

  solver::LinearSolverParameters parameters;
  if (method == "amg")
  {
    parameters.type = solver::LinearSolverType::iterative;
    parameters.krylov_method
        = mode == "finite" ? solver::KrylovMethod::gmres : solver::KrylovMethod::cg;
  }
  else
  {
    parameters.type = solver::LinearSolverType::direct;
    parameters.direct_package = method == "klu" ? "KLU" : "MUMPS";
  }
  solver::LinearSolver<3> linear_solver(parameters);
  linear_solver.set_rigid_body_modes(problem->dof_handler, problem->mapping);

  if (rank == 0)
    std::printf("amg_3d %s N=%u Q%u %s np=%u: %u cells, %u DoFs, %u nonzeros, plastic points "
                "%u of %u; set-up %.2f s wall %.2f s CPU, assembly %.2f s wall %.2f s CPU (CPU: "
                "all ranks; %.2f s on the busiest)\n",
                mode.c_str(),
                n,
                degree,
                method.c_str(),
                Utilities::MPI::n_mpi_processes(comm),
                problem->tria.n_global_active_cells(),
                problem->dof_handler.n_dofs(),
                static_cast<unsigned int>(problem->matrix.n_nonzero_elements()),
                plastic,
                n_points,
                setup_wall,
                setup_cpu,
                assembly_wall,
                assembly_cpu,
                assembly_cpu_max);
  TrilinosWrappers::MPI::Vector x(problem->rhs), r(problem->rhs);
  for (unsigned int k = 0; k < n_solves; ++k)
  {
    x = 0.;
    const solver::LinearSolveInfo info = linear_solver.solve(problem->matrix, x, problem->rhs);
    // residual check: |b - A x| / |b|
    problem->matrix.vmult(r, x);
    r.sadd(-1., 1., problem->rhs);
    const double relative_residual = r.l2_norm() / problem->rhs.l2_norm();
    const double cpu = Utilities::MPI::sum(info.cpu_seconds, comm);
    const double cpu_max = Utilities::MPI::max(info.cpu_seconds, comm);
    const double amg_setup_cpu = Utilities::MPI::sum(info.setup_cpu_seconds, comm);
    const double wall = Utilities::MPI::max(info.seconds, comm);
    const double amg_setup_wall = Utilities::MPI::max(info.setup_seconds, comm);
    if (rank == 0)
      std::printf(
          "solve %u: %s iterations %u, AMG set-up %.2f s wall %.2f s CPU, total %.2f s "
          "wall, %.2f s CPU (CPU: all ranks; %.2f s on the busiest), |b - Ax| / |b| = %.1e\n",
          k,
          info.iterative ? "AMG" : "direct",
          info.iterations,
          amg_setup_wall,
          amg_setup_cpu,
          wall,
          cpu,
          cpu_max,
          relative_residual);
  }
  const double peak = Utilities::MPI::max(peak_memory_mb(), comm);
  const double peak_sum = Utilities::MPI::sum(peak_memory_mb(), comm);
  if (rank == 0)
    std::printf("peak resident memory: %.0f MB max per rank, %.0f MB all ranks (%.2f kB/DoF)\n",
                peak,
                peak_sum,
                1024. * peak_sum / problem->dof_handler.n_dofs());
  return 0;
}
