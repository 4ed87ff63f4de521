/**
 * @file assembler_test_problem.h
 * The set-up that the assembler's unit tests and the assembly benchmark share: a serial mesh with
 * its element, mapping and DoFs, a ConstitutiveModel, surface loads, the Assembler, the material
 * points, and the Trilinos targets (vectors over all DoFs, the tangent with the mesh's sparsity)
 * with one call that zeroes and fills them. Test support only (tests/unit/, benchmarks/): not part
 * of the library.
 */
#pragma once

#include <ausroll/material/constitutive_model.h>
#include <ausroll/mechanics/assembler.h>
#include <ausroll/mechanics/boundary_conditions.h>
#include <ausroll/mechanics/planar_kinematics.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace ausroll::test_support
{
  /** What an assembler test problem is made of (the mesh comes as a function). */
  struct AssemblerTestOptions
  {
    unsigned int                              degree = 1;         ///< FE_Q degree
    unsigned int                              mapping_degree = 1; ///< MappingQ degree
    unsigned int                              n_q_points_1d = 0;  ///< 0: degree + 1
    material::KinematicsType                  kinematics = material::KinematicsType::small_strain;
    material::MaterialParameters              material;
    std::vector<mechanics::BoundaryCondition> conditions; ///< surface loads
    mechanics::PlanarModel                    planar = mechanics::PlanarModel::plane_strain;
    mechanics::VolumetricLocking              locking = mechanics::VolumetricLocking::none;
  };

  /** A surface load of @p type on boundary @p id with the function expression @p value. */
  inline mechanics::BoundaryCondition surface_load(const dealii::types::boundary_id       id,
                                                   const mechanics::BoundaryConditionType type,
                                                   const std::string                     &value)
  {
    mechanics::BoundaryCondition condition;
    condition.id = id;
    condition.type = type;
    condition.value = value;
    return condition;
  }

  /** The rectangle [@p p0, @p p1] in @p n cells, boundary ids coloured (0..3: x0, x1, y0, y1). */
  inline std::function<void(dealii::Triangulation<2> &)> rectangle(
      const std::vector<unsigned int> &n, const dealii::Point<2> &p0, const dealii::Point<2> &p1)
  {
    return [=](dealii::Triangulation<2> &tria)
    { dealii::GridGenerator::subdivided_hyper_rectangle(tria, n, p0, p1, /*colorize=*/true); };
  }

  /** The 2 x 2 cell block [1, 2.2] x [0, 1.1] of the tangent tests (boundary ids coloured) with
      its interior vertex moved by (0.07, -0.05): no cell is a parallelogram. */
  inline std::function<void(dealii::Triangulation<2> &)> distorted_block()
  {
    return [](dealii::Triangulation<2> &tria)
    {
      rectangle({2, 2}, dealii::Point<2>(1., 0.), dealii::Point<2>(2.2, 1.1))(tria);
      for (auto &cell : tria.active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          if (std::abs(cell->vertex(v)[0] - 1.6) < 1e-12
              && std::abs(cell->vertex(v)[1] - 0.55) < 1e-12)
            cell->vertex(v) += dealii::Point<2>(0.07, -0.05);
    };
  }

  /**
   * The options of the tangent tests (with distorted_block()): Q@p degree with MappingQ@p degree,
   * E = 1000, nu = 0.3, hardening 50; @p plastic: yield stress 2 and kinematic hardening 30 (the
   * random states yield), else elastic (1e9); no surface loads yet.
   */
  inline AssemblerTestOptions tangent_test_options(const material::KinematicsType     kinematics,
                                                   const unsigned int                 degree,
                                                   const bool                         plastic,
                                                   const mechanics::PlanarModel       planar,
                                                   const mechanics::VolumetricLocking locking)
  {
    AssemblerTestOptions options;
    options.degree = degree;
    options.mapping_degree = degree;
    options.kinematics = kinematics;
    options.material.youngs_modulus = 1000.;
    options.material.poissons_ratio = 0.3;
    options.material.yield_stress = plastic ? 2. : 1e9;
    options.material.hardening_modulus = 50.;
    options.material.kinematic_hardening_modulus = plastic ? 30. : 0.;
    options.planar = planar;
    options.locking = locking;
    return options;
  }

  /**
   * The surface loads of the tangent tests: a follower pressure 30 + 5 x on the top (boundary 3)
   * and a dead traction (4, -3 y) on the right (boundary 1).
   */
  inline std::vector<mechanics::BoundaryCondition> tangent_test_loads()
  {
    return {surface_load(3, mechanics::BoundaryConditionType::pressure, "30 + 5 * x"),
            surface_load(1, mechanics::BoundaryConditionType::traction, "4; -3 * y")};
  }

  /**
   * Finite-strain plastic steel-like block under a follower pressure (the threads test and the
   * assembly benchmark): Q2 with MappingQ2 and 3 x 3 Gauss points, F-bar, plane strain, yield
   * stress 240, hardening 1000, pressure @p pressure on the top (boundary 3).
   */
  inline AssemblerTestOptions plastic_block_under_pressure(const std::string &pressure)
  {
    AssemblerTestOptions options;
    options.degree = 2;
    options.mapping_degree = 2;
    options.n_q_points_1d = 3;
    options.kinematics = material::KinematicsType::finite_strain;
    options.material.yield_stress = 240.;
    options.material.hardening_modulus = 1000.;
    options.conditions = {surface_load(3, mechanics::BoundaryConditionType::pressure, pressure)};
    options.locking = mechanics::VolumetricLocking::f_bar;
    return options;
  }

  /** The values of a (serial) Trilinos vector. */
  /** A slipping node's row transform on DoFs 0, 1: matrix [[1, 0.3], [0, 1]], offset (2.5, 0). */
  inline mechanics::RowTransforms<2> slipping_node_transform()
  {
    mechanics::RowTransforms<2>     transforms;
    mechanics::NodalRowTransform<2> t;
    t.dofs = {{0, 1}};
    t.matrix[0][0] = t.matrix[1][1] = 1.;
    t.matrix[0][1] = 0.3;
    t.offset[0] = 2.5;
    transforms.emplace(0, t);
    return transforms;
  }

  inline std::vector<double> values(const dealii::TrilinosWrappers::MPI::Vector &v)
  {
    std::vector<double> result(v.size());
    for (unsigned int i = 0; i < v.size(); ++i)
      result[i] = v[i];
    return result;
  }

  /**
   * Mesh, element, mapping, DoFs, model, loads, Assembler<dim> and material points of one test,
   * with the targets of an assembly over all DoFs (one MPI rank: every DoF owned).
   */
  template <int dim>
  struct AssemblerTestProblem
  {
    AssemblerTestProblem(const AssemblerTestOptions                              &options,
                         const std::function<void(dealii::Triangulation<dim> &)> &make_mesh)
        : fe(dealii::FE_Q<dim>(options.degree), dim)
        , mapping(options.mapping_degree)
        , model(material::create_constitutive_model(options.kinematics, options.material, false))
        , boundary_conditions(mechanics::BoundaryConditionParameters{options.conditions})
        , kinematics(options.planar, 1., &stretch)
        , assembler(mapping,
                    fe,
                    options.n_q_points_1d > 0 ? options.n_q_points_1d : options.degree + 1,
                    kinematics,
                    *model,
                    boundary_conditions,
                    options.locking)
    {
      make_mesh(tria);
      dof_handler.reinit(tria);
      dof_handler.distribute_dofs(fe);
      points.initialize(tria.begin_active(), tria.end(), assembler.quadrature().size());
      none.close();
      all = dealii::complete_index_set(n_dofs());
      sparsity.reinit(n_dofs(), n_dofs());
      dealii::DoFTools::make_sparsity_pattern(dof_handler, sparsity);
      matrix.reinit(all, all, sparsity, MPI_COMM_WORLD);
      for (auto *v : {&u, &residual, &external, &free_residual, &rhs})
        *v = vector();
    }

    unsigned int n_dofs() const { return dof_handler.n_dofs(); }

    /** Number of material points whose trial state has plastic strain. */
    unsigned int n_plastic_points() const
    {
      unsigned int n = 0;
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto &p : points.get_data(cell))
          n += p->trial.equivalent_plastic_strain > 0.;
      return n;
    }

    /** A zero vector over all DoFs. */
    dealii::TrilinosWrappers::MPI::Vector vector() const
    {
      return dealii::TrilinosWrappers::MPI::Vector(all, MPI_COMM_WORLD);
    }

    /** A zero matrix with the sparsity of the mesh. */
    dealii::TrilinosWrappers::SparseMatrix new_matrix() const
    {
      dealii::TrilinosWrappers::SparseMatrix m;
      m.reinit(all, all, sparsity, MPI_COMM_WORLD);
      return m;
    }

    /** Targets pointing at the members: residual and external force, the tangent and rhs if
        @p with_matrix, the free residual if @p with_free. */
    mechanics::AssemblyTargets targets(const bool with_matrix, const bool with_free = false)
    {
      mechanics::AssemblyTargets t;
      t.residual = &residual;
      t.external_force = &external;
      t.free_residual = with_free ? &free_residual : nullptr;
      t.matrix = with_matrix ? &matrix : nullptr;
      t.rhs = with_matrix ? &rhs : nullptr;
      return t;
    }

    /**
     * Zero @p t, then assemble at @p at (time 1, no hanging nodes) with the Newton constraints
     * @p newton (none if null) and the row transforms @p transforms.
     */
    mechanics::AssemblyStatus assemble(const dealii::TrilinosWrappers::MPI::Vector &at,
                                       const mechanics::AssemblyTargets            &t,
                                       const dealii::AffineConstraints<double> *newton = nullptr,
                                       const mechanics::RowTransforms<dim> *transforms = nullptr)
    {
      for (auto *v : {t.residual, t.external_force, t.free_residual, t.rhs})
        if (v != nullptr)
          *v = 0.;
      if (t.matrix != nullptr)
        *t.matrix = 0.;
      return assembler.assemble(
          dof_handler, at, 1., points, none, newton != nullptr ? *newton : none, transforms, t);
    }

    /** assemble() at @p at into the members (tangent and rhs if @p with_matrix). */
    mechanics::AssemblyStatus assemble(const dealii::TrilinosWrappers::MPI::Vector &at,
                                       const bool                                   with_matrix)
    {
      return assemble(at, targets(with_matrix));
    }

    dealii::Triangulation<dim>                         tria;
    const dealii::FESystem<dim>                        fe;
    const dealii::MappingQ<dim>                        mapping;
    dealii::DoFHandler<dim>                            dof_handler;
    const std::unique_ptr<material::ConstitutiveModel> model;
    const mechanics::BoundaryConditions<dim>           boundary_conditions;
    /** F_zz of generalized plane strain (the kinematics reads it; 1 for the other models). */
    double                                 stretch = 1.;
    const mechanics::PlanarKinematics<dim> kinematics;
    const mechanics::Assembler<dim>        assembler;
    mechanics::MaterialPointStorage<dim>   points;

    dealii::IndexSet                       all;
    dealii::AffineConstraints<double>      none; ///< no constraints (closed)
    dealii::DynamicSparsityPattern         sparsity;
    dealii::TrilinosWrappers::SparseMatrix matrix;
    dealii::TrilinosWrappers::MPI::Vector  u, residual, external, free_residual, rhs;
  };
} // namespace ausroll::test_support
