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
 * Runs on any number of MPI ranks (mpirun -np 2 amg_3d ...; on 2 ranks the ML set-up fails today,
 * doc/benchmarks.md). Prints per solve: DoFs, AMG set-up
 * (wall and CPU), iterations, solve time, and per process the peak resident memory (getrusage);
 * no pass/fail (doc/benchmarks.md, section "3D linear solver").
 */
#include <ausroll/geometry/geometry_parameters.h>
#include <ausroll/geometry/workpiece.h>
#include <ausroll/material/constitutive_model.h>
#include <ausroll/mechanics/assembler.h>
#include <ausroll/mechanics/boundary_conditions.h>
#include <ausroll/mechanics/planar_kinematics.h>
#include <ausroll/solver/linear_solver.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <sys/resource.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

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
  const double       delta = 0.002;

  Timer                                   setup_timer;
  geometry::GeometryParameters            geometry;
  parallel::distributed::Triangulation<3> tria(comm);
  geometry.type = geometry::WorkpieceType::block;
  geometry.block_cells = {n, n, n};
  geometry::create_workpiece(geometry, tria);
  const FESystem<3> fe(FE_Q<3>(degree), 3);
  const MappingQ<3> mapping(1);
  DoFHandler<3>     dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  const IndexSet owned = dof_handler.locally_owned_dofs();
  const IndexSet relevant = DoFTools::extract_locally_relevant_dofs(dof_handler);

  material::MaterialParameters mat;
  mat.youngs_modulus = 210000.;
  mat.poissons_ratio = 0.3;
  mat.yield_stress = mode == "elastic" ? 1e12 : 240.;
  mat.hardening_modulus = 1000.;
  const auto kinematics_type = mode == "finite" ? material::KinematicsType::finite_strain
                                                : material::KinematicsType::small_strain;
  const auto model = material::create_constitutive_model(kinematics_type, mat, false);

  // symmetry planes and the prescribed top (Geometry/Block ids 0, 2, 4 and 5)
  mechanics::BoundaryConditionParameters bc;
  const char                            *components[] = {"x", "y", "z"};
  for (unsigned int d = 0; d < 3; ++d)
  {
    mechanics::BoundaryCondition c;
    c.id = 2 * d;
    c.type = mechanics::BoundaryConditionType::displacement;
    c.components = components[d];
    c.value = "0";
    bc.conditions.push_back(c);
  }
  mechanics::BoundaryCondition top;
  top.id = 5;
  top.type = mechanics::BoundaryConditionType::displacement;
  top.components = "z";
  top.value = mode == "elastic" ? "-0.002" : "-0.002 * (0.5 + x) / 1.5";
  bc.conditions.push_back(top);
  const mechanics::BoundaryConditions<3> bcs(bc);
  const mechanics::PlanarKinematics<3>   kinematics(mechanics::PlanarModel::plane_strain, 1.);
  const mechanics::Assembler<3>          assembler(mapping,
                                          fe,
                                          degree + 1,
                                          kinematics,
                                          *model,
                                          bcs,
                                          mode == "finite" ? mechanics::VolumetricLocking::f_bar
                                                                    : mechanics::VolumetricLocking::none);
  mechanics::MaterialPointStorage<3>     points;
  points.initialize(tria.begin_active(), tria.end(), assembler.quadrature().size());

  TrilinosWrappers::MPI::Vector u(owned, comm), u_ghosted(owned, relevant, comm),
      residual(owned, comm), external(owned, comm), rhs(owned, comm), x(owned, comm);
  if (mode != "elastic")
  {
    std::map<types::global_dof_index, Point<3>> support;
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, support);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          if (owned.is_element(dofs[i]))
          {
            const Point<3>    &p = support.at(dofs[i]);
            const unsigned int c = fe.system_to_component_index(i).first;
            u[dofs[i]] = c < 2 ? 0.3 * delta * p[c] : -delta * p[2] * (0.5 + p[0]) / 1.5;
          }
      }
    u.compress(VectorOperation::insert);
  }
  u_ghosted = u;

  AffineConstraints<double> hanging, newton;
  hanging.reinit(relevant);
  hanging.close();
  newton.reinit(relevant);
  bcs.add_increment_constraints(dof_handler, 1., u_ghosted, newton);
  newton.close();

  TrilinosWrappers::SparseMatrix matrix;
  {
    DynamicSparsityPattern dsp(relevant);
    DoFTools::make_sparsity_pattern(dof_handler, dsp, hanging, true);
    SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
    matrix.reinit(owned, owned, dsp, comm);
  }

  Timer assembly_timer;
  residual = 0.;
  external = 0.;
  mechanics::AssemblyTargets targets;
  targets.residual = &residual;
  targets.external_force = &external;
  targets.matrix = &matrix;
  targets.rhs = &rhs;
  const auto status
      = assembler.assemble(dof_handler, u_ghosted, 1., points, hanging, newton, nullptr, targets);
  assembly_timer.stop();
  if (!status.ok)
  {
    std::fprintf(stderr, "assembly failed: %s\n", status.message.c_str());
    return 3;
  }
  unsigned int plastic_local = 0, points_local = 0;
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->is_locally_owned())
      for (const auto &p : points.get_data(cell))
      {
        ++points_local;
        plastic_local += p->trial.equivalent_plastic_strain > 0. ? 1 : 0;
      }
  const unsigned int plastic = Utilities::MPI::sum(plastic_local, comm);
  const unsigned int n_points = Utilities::MPI::sum(points_local, comm);

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
  linear_solver.set_rigid_body_modes(dof_handler, mapping);

  if (rank == 0)
    std::printf("amg_3d %s N=%u Q%u %s np=%u: %u cells, %u DoFs, %u nonzeros, plastic points "
                "%u of %u, set-up + assembly %.1f s (assembly CPU %.1f s)\n",
                mode.c_str(),
                n,
                degree,
                method.c_str(),
                Utilities::MPI::n_mpi_processes(comm),
                tria.n_global_active_cells(),
                dof_handler.n_dofs(),
                static_cast<unsigned int>(matrix.n_nonzero_elements()),
                plastic,
                n_points,
                setup_timer.wall_time(),
                assembly_timer.cpu_time());
  for (unsigned int k = 0; k < n_solves; ++k)
  {
    x = 0.;
    const solver::LinearSolveInfo info = linear_solver.solve(matrix, x, rhs);
    // residual check: |b - A x| / |b|
    TrilinosWrappers::MPI::Vector r(owned, comm);
    matrix.vmult(r, x);
    r.sadd(-1., 1., rhs);
    const double cpu = Utilities::MPI::sum(info.cpu_seconds, comm);
    const double setup_cpu = Utilities::MPI::sum(info.setup_cpu_seconds, comm);
    if (rank == 0)
      std::printf("solve %u: %s iterations %u, AMG set-up %.2f s wall %.2f s CPU, total %.2f s "
                  "wall, %.2f s CPU (CPU: all ranks), |b - Ax| / |b| = %.1e\n",
                  k,
                  info.iterative ? "AMG" : "direct",
                  info.iterations,
                  info.setup_seconds,
                  setup_cpu,
                  info.seconds,
                  cpu,
                  r.l2_norm() / rhs.l2_norm());
  }
  const double peak = Utilities::MPI::max(peak_memory_mb(), comm);
  const double peak_sum = Utilities::MPI::sum(peak_memory_mb(), comm);
  if (rank == 0)
    std::printf("peak resident memory: %.0f MB max per rank, %.0f MB all ranks (%.2f kB/DoF)\n",
                peak,
                peak_sum,
                1024. * peak_sum / dof_handler.n_dofs());
  return 0;
}
