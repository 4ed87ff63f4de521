/**
 * @file block_3d_problem.h
 * The set-up that the 3D block unit tests (tests/unit/test_block_3d.cc) and the 3D linear-solver
 * benchmark (benchmarks/amg_3d.cc) share: a `Geometry/Type = block` mesh distributed over a
 * communicator (parallel::distributed::Triangulation<3>; one rank: the whole mesh), FE_Q^3 of a
 * degree, a ConstitutiveModel, `Boundary conditions`, the Assembler, the material points, the
 * locally owned / relevant DoFs, and the Trilinos targets (tangent and vectors) with one call that
 * builds the Newton constraints at a time and assembles the tangent system at the current
 * displacement. Test support only (tests/unit/, benchmarks/): not part of the library.
 */
#pragma once

#include <ausroll/geometry/geometry_parameters.h>
#include <ausroll/geometry/workpiece.h>
#include <ausroll/material/constitutive_model.h>
#include <ausroll/mechanics/assembler.h>
#include <ausroll/mechanics/boundary_conditions.h>
#include <ausroll/mechanics/planar_kinematics.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
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

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ausroll::test_support
{
  /** What a 3D block problem is made of besides its mesh and boundary conditions. */
  struct Block3dOptions
  {
    unsigned int                 degree = 1; ///< FE_Q degree (quadrature: degree + 1 points)
    material::KinematicsType     kinematics = material::KinematicsType::small_strain;
    material::MaterialParameters material;
    mechanics::VolumetricLocking locking = mechanics::VolumetricLocking::none;
  };

  /**
   * The `Boundary conditions` of a block with the three symmetry planes (`Geometry/Block` ids 0,
   * 2, 4: u_x = 0 on x = 0, u_y = 0 on y = 0, u_z = 0 on z = 0) and u_z = @p top_value (a function
   * expression of x, y, z, t) on the top (id 5).
   */
  inline mechanics::BoundaryConditionParameters
  symmetry_planes_and_top(const std::string &top_value)
  {
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
    top.value = top_value;
    bc.conditions.push_back(top);
    return bc;
  }

  /** A locally owned DoF: global index, vector component and support point. */
  struct OwnedDof
  {
    dealii::types::global_dof_index index;
    unsigned int                    component;
    dealii::Point<3>                point;
  };

  /** The 3D block problem (see the file comment). */
  struct Block3dProblem
  {
    MPI_Comm                                        comm;
    dealii::parallel::distributed::Triangulation<3> tria;
    dealii::FESystem<3>                             fe;
    dealii::MappingQ<3>                             mapping{1};
    dealii::DoFHandler<3>                           dof_handler;
    dealii::IndexSet                                owned, relevant;
    std::unique_ptr<material::ConstitutiveModel>    model;
    mechanics::BoundaryConditions<3>                bcs;
    mechanics::PlanarKinematics<3>         kinematics{mechanics::PlanarModel::plane_strain, 1.};
    mechanics::Assembler<3>                assembler;
    mechanics::MaterialPointStorage<3>     points;
    dealii::TrilinosWrappers::SparseMatrix matrix;
    /** Displacement (owned; u_ghosted: with the relevant ghosts), residual, external force, rhs. */
    dealii::TrilinosWrappers::MPI::Vector u, u_ghosted, residual, external, rhs;
    /** Hanging-node constraints (none: uniform mesh) and the Newton constraints of assemble(). */
    dealii::AffineConstraints<double> hanging, newton;

    Block3dProblem(const MPI_Comm                                communicator,
                   const geometry::GeometryParameters           &geometry,
                   const mechanics::BoundaryConditionParameters &conditions,
                   const Block3dOptions                         &options)
        : comm(communicator)
        , tria(communicator)
        , fe(dealii::FE_Q<3>(options.degree), 3)
        , model(material::create_constitutive_model(options.kinematics, options.material, false))
        , bcs(conditions)
        , assembler(mapping, fe, options.degree + 1, kinematics, *model, bcs, options.locking)
    {
      geometry::create_workpiece(geometry, tria);
      dof_handler.reinit(tria);
      dof_handler.distribute_dofs(fe);
      owned = dof_handler.locally_owned_dofs();
      relevant = dealii::DoFTools::extract_locally_relevant_dofs(dof_handler);
      points.initialize(tria.begin_active(), tria.end(), assembler.quadrature().size());
      hanging.reinit(relevant);
      hanging.close();

      dealii::DynamicSparsityPattern dsp(relevant);
      dealii::DoFTools::make_sparsity_pattern(dof_handler, dsp, hanging, true);
      dealii::SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
      matrix.reinit(owned, owned, dsp, comm);
      for (auto *v : {&u, &residual, &external, &rhs})
        v->reinit(owned, comm);
      u_ghosted.reinit(owned, relevant, comm);
    }

    /** The locally owned DoFs with their components and support points. */
    std::vector<OwnedDof> owned_dofs() const
    {
      std::map<dealii::types::global_dof_index, dealii::Point<3>> support;
      dealii::DoFTools::map_dofs_to_support_points(mapping, dof_handler, support);
      std::vector<OwnedDof>                        result;
      std::vector<bool>                            seen(owned.n_elements(), false);
      std::vector<dealii::types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (owned.is_element(dofs[i]) && !seen[owned.index_within_set(dofs[i])])
            {
              seen[owned.index_within_set(dofs[i])] = true;
              result.push_back(
                  {dofs[i], fe.system_to_component_index(i).first, support.at(dofs[i])});
            }
        }
      return result;
    }

    /** u = @p f (support point, component) at every DoF. */
    template <typename Function>
    void set_displacement(const Function &f)
    {
      for (const OwnedDof &d : owned_dofs())
        u[d.index] = f(d.point, d.component);
      u.compress(dealii::VectorOperation::insert);
    }

    /** Newton constraints at @p time and the tangent system (matrix, rhs, residual) at u. */
    mechanics::AssemblyStatus assemble(const double time = 1.)
    {
      u_ghosted = u;
      newton.clear();
      newton.reinit(relevant);
      bcs.add_increment_constraints(dof_handler, time, u_ghosted, newton);
      newton.close();
      residual = 0.;
      external = 0.;
      matrix = 0.;
      rhs = 0.;
      mechanics::AssemblyTargets targets;
      targets.residual = &residual;
      targets.external_force = &external;
      targets.matrix = &matrix;
      targets.rhs = &rhs;
      return assembler.assemble(
          dof_handler, u_ghosted, time, points, hanging, newton, nullptr, targets);
    }
  };

  /**
   * The systems of benchmarks/amg_3d.cc: the unit cube in @p n x @p n x @p n cells, FE_Q^3 of
   * @p degree, symmetry planes and a prescribed top on @p comm, steel-like (E 210 GPa, nu 0.3),
   * for @p mode
   * - "elastic": small strain, u = 0, top u_z = -delta (delta = 0.002);
   * - "plastic": small-strain J2 (yield 240 MPa, H 1 GPa) at u_z = -delta z (0.5 + x) / 1.5,
   *   u_x = 0.3 delta x, u_y = 0.3 delta y (x > 0.36 plastic: yield strain 0.00114);
   * - "finite": that state with finite-strain J2 and F-bar (an unsymmetric tangent).
   * Call assemble() for the tangent system.
   */
  inline std::unique_ptr<Block3dProblem> compressed_cube(const MPI_Comm     comm,
                                                         const std::string &mode,
                                                         const unsigned int n,
                                                         const unsigned int degree)
  {
    const double                 delta = 0.002;
    geometry::GeometryParameters geometry;
    geometry.type = geometry::WorkpieceType::block;
    geometry.block_cells = {n, n, n};
    Block3dOptions options;
    options.degree = degree;
    options.material.youngs_modulus = 210000.;
    options.material.poissons_ratio = 0.3;
    options.material.yield_stress = mode == "elastic" ? 1e12 : 240.;
    options.material.hardening_modulus = 1000.;
    if (mode == "finite")
    {
      options.kinematics = material::KinematicsType::finite_strain;
      options.locking = mechanics::VolumetricLocking::f_bar;
    }
    auto problem = std::make_unique<Block3dProblem>(
        comm,
        geometry,
        symmetry_planes_and_top(mode == "elastic" ? "-0.002" : "-0.002 * (0.5 + x) / 1.5"),
        options);
    if (mode != "elastic")
      problem->set_displacement(
          [delta](const dealii::Point<3> &p, const unsigned int c)
          { return c < 2 ? 0.3 * delta * p[c] : -delta * p[2] * (0.5 + p[0]) / 1.5; });
    return problem;
  }
} // namespace ausroll::test_support
