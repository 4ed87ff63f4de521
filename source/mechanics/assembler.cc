#include <ausroll/core/exceptions.h>
#include <ausroll/mechanics/assembler.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <sstream>

namespace ausroll::mechanics
{
  using namespace dealii;

  template <int dim>
  Assembler<dim>::Assembler(const Mapping<dim>                &mapping,
                            const FiniteElement<dim>          &fe,
                            const unsigned int                 n_q_points_1d,
                            const PlanarKinematics<dim>       &kinematics,
                            const material::ConstitutiveModel &model,
                            const BoundaryConditions<dim>     &boundary_conditions)
      : mapping(mapping)
      , fe(fe)
      , cell_quadrature(n_q_points_1d)
      , face_quadrature(n_q_points_1d)
      , kinematics(kinematics)
      , model(model)
      , boundary_conditions(boundary_conditions)
  {
  }

  template <int dim>
  AssemblyStatus Assembler<dim>::assemble(const DoFHandler<dim>               &dof_handler,
                                          const TrilinosWrappers::MPI::Vector &solution,
                                          const double                         time,
                                          MaterialPointStorage<dim>           &material_points,
                                          const AffineConstraints<double>     &hanging,
                                          const AffineConstraints<double>     &newton,
                                          const RowTransforms<dim>            *row_transforms,
                                          const AssemblyTargets               &targets) const
  {
    Assert(targets.residual != nullptr && targets.external_force != nullptr, ExcInternalError());
    const bool need_matrix = targets.matrix != nullptr;

    FEValues<dim>     fe_values(mapping,
                            fe,
                            cell_quadrature,
                            update_values | update_gradients | update_quadrature_points
                                | update_JxW_values);
    FEFaceValues<dim> fe_face_values(mapping,
                                     fe,
                                     face_quadrature,
                                     update_values | update_quadrature_points
                                         | update_normal_vectors | update_JxW_values);

    const unsigned int n_dofs = fe.n_dofs_per_cell();
    const unsigned int n_q = cell_quadrature.size();
    const unsigned int n_base = n_dofs / dim; // support points of the FE_Q base element

    FullMatrix<double>                   cell_matrix(n_dofs, n_dofs);
    Vector<double>                       cell_residual(n_dofs), cell_external(n_dofs);
    Vector<double>                       cell_free(n_dofs), cell_rhs(n_dofs);
    std::vector<types::global_dof_index> dofs(n_dofs);
    std::vector<Tensor<2, dim>>          grad_u(n_q);
    std::vector<Tensor<1, dim>>          u_values(n_q);
    const FEValuesExtractors::Vector     displacement(0);

    // Component of each shape function and the local DoFs of each support point.
    std::vector<unsigned int>            component(n_dofs);
    std::vector<std::array<unsigned, 3>> node_dofs(n_base);
    for (unsigned int i = 0; i < n_dofs; ++i)
    {
      const auto ci = fe.system_to_component_index(i);
      component[i] = ci.first;
      node_dofs[ci.second][ci.first] = i;
    }

    // Rows of the 3D gradient of each shape function: g[i][J] = dF[c_i][J] / du_i.
    std::vector<std::array<double, 3>> g(n_dofs);
    // h[j][c][I] = sum_J A[c][I][c_j][J] g[j][J]
    std::vector<std::array<std::array<double, 3>, dim>> h(n_dofs);

    Tensor<2, 3> P;
    Tensor<4, 3> A;
    const bool   check_inversion = !model.is_small_strain();

    bool        ok = true;
    double      min_jacobian = 1e300;
    std::string message;

    for (const auto &cell : dof_handler.active_cell_iterators())
    {
      if (!cell->is_locally_owned())
        continue;
      fe_values.reinit(cell);
      fe_values[displacement].get_function_gradients(solution, grad_u);
      fe_values[displacement].get_function_values(solution, u_values);
      const std::vector<std::shared_ptr<material::MaterialPoint>> points
          = material_points.get_data(cell);

      cell_matrix = 0.;
      cell_residual = 0.;
      cell_external = 0.;

      for (unsigned int q = 0; q < n_q && ok; ++q)
      {
        const Point<dim>  &X = fe_values.quadrature_point(q);
        const double       dV = fe_values.JxW(q) * kinematics.volume_factor(X);
        const Tensor<2, 3> F = kinematics.deformation_gradient(grad_u[q], u_values[q], X);
        const double       J = determinant(F);
        min_jacobian = std::min(min_jacobian, J);
        if (check_inversion && !(J > 0.))
        {
          std::ostringstream msg;
          msg << "inverted element (det F = " << J << ") at (" << X << ")";
          ok = false;
          message = msg.str();
          break;
        }
        try
        {
          model.evaluate(F, points[q]->committed, points[q]->trial, P, need_matrix ? &A : nullptr);
        }
        catch (const RunFailure &e)
        {
          ok = false;
          message = e.what();
          break;
        }

        for (unsigned int i = 0; i < n_dofs; ++i)
        {
          const unsigned int   c = component[i];
          const Tensor<1, dim> grad = fe_values.shape_grad_component(i, q, c);
          for (unsigned int J = 0; J < dim; ++J)
            g[i][J] = grad[J];
          if (dim == 2)
            g[i][2] = (kinematics.is_axisymmetric() && c == 0)
                          ? fe_values.shape_value_component(i, q, c) / X[0]
                          : 0.;
          double r = 0.;
          for (unsigned int J = 0; J < 3; ++J)
            r += P[c][J] * g[i][J];
          cell_residual(i) += r * dV;
        }

        if (need_matrix)
        {
          for (unsigned int j = 0; j < n_dofs; ++j)
            for (unsigned int c = 0; c < dim; ++c)
              for (unsigned int I = 0; I < 3; ++I)
              {
                double s = 0.;
                for (unsigned int J = 0; J < 3; ++J)
                  s += A[c][I][component[j]][J] * g[j][J];
                h[j][c][I] = s;
              }
          for (unsigned int i = 0; i < n_dofs; ++i)
          {
            const unsigned int c = component[i];
            for (unsigned int j = 0; j < n_dofs; ++j)
              cell_matrix(i, j)
                  += (g[i][0] * h[j][c][0] + g[i][1] * h[j][c][1] + g[i][2] * h[j][c][2]) * dV;
          }
        }
      }
      if (!ok)
        continue; // keep looping so that every rank reaches the collective calls below

      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && boundary_conditions.has_surface_load(face->boundary_id()))
        {
          fe_face_values.reinit(cell, face);
          for (unsigned int q = 0; q < face_quadrature.size(); ++q)
          {
            const Point<dim>    &X = fe_face_values.quadrature_point(q);
            const Tensor<1, dim> t = boundary_conditions.traction(
                face->boundary_id(), X, fe_face_values.normal_vector(q), time);
            const double dA = fe_face_values.JxW(q) * kinematics.volume_factor(X);
            for (unsigned int i = 0; i < n_dofs; ++i)
              cell_external(i) += t[component[i]]
                                  * fe_face_values.shape_value_component(i, q, component[i]) * dA;
          }
        }
      cell_residual -= cell_external;

      cell->get_dof_indices(dofs);
      hanging.distribute_local_to_global(cell_residual, dofs, *targets.residual);
      hanging.distribute_local_to_global(cell_external, dofs, *targets.external_force);

      // Row transforms (friction) act on the equations of whole nodes.
      cell_free = cell_residual;
      if (row_transforms != nullptr && !row_transforms->empty())
        for (unsigned int b = 0; b < n_base; ++b)
        {
          const auto it = row_transforms->find(dofs[node_dofs[b][0]]);
          if (it == row_transforms->end())
            continue;
          const Tensor<2, dim>   &T = it->second.matrix;
          std::array<double, dim> old_r;
          for (unsigned int c = 0; c < dim; ++c)
            old_r[c] = cell_residual(node_dofs[b][c]);
          for (unsigned int c = 0; c < dim; ++c)
          {
            double s = 0.;
            for (unsigned int d = 0; d < dim; ++d)
              s += T[c][d] * old_r[d];
            cell_free(node_dofs[b][c]) = s;
          }
          if (need_matrix)
            for (unsigned int j = 0; j < n_dofs; ++j)
            {
              std::array<double, dim> old_k;
              for (unsigned int c = 0; c < dim; ++c)
                old_k[c] = cell_matrix(node_dofs[b][c], j);
              for (unsigned int c = 0; c < dim; ++c)
              {
                double s = 0.;
                for (unsigned int d = 0; d < dim; ++d)
                  s += T[c][d] * old_k[d];
                cell_matrix(node_dofs[b][c], j) = s;
              }
            }
        }

      if (targets.free_residual != nullptr)
        newton.distribute_local_to_global(cell_free, dofs, *targets.free_residual);
      if (need_matrix)
      {
        cell_rhs = cell_free;
        cell_rhs *= -1.;
        newton.distribute_local_to_global(
            cell_matrix, cell_rhs, dofs, *targets.matrix, *targets.rhs, true);
      }
    }

    targets.residual->compress(VectorOperation::add);
    targets.external_force->compress(VectorOperation::add);
    if (targets.free_residual != nullptr)
      targets.free_residual->compress(VectorOperation::add);
    if (need_matrix)
    {
      targets.matrix->compress(VectorOperation::add);
      targets.rhs->compress(VectorOperation::add);
    }

    // Agree on the outcome across ranks; the message comes from the lowest failing rank.
    const MPI_Comm     comm = dof_handler.get_communicator();
    const unsigned int my_rank = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const unsigned int bad_rank = Utilities::MPI::min(ok ? n_ranks : my_rank, comm);
    AssemblyStatus     status;
    status.min_jacobian = Utilities::MPI::min(min_jacobian, comm);
    if (bad_rank < n_ranks)
    {
      status.ok = false;
      status.message = Utilities::MPI::broadcast(comm, message, bad_rank);
    }
    return status;
  }

  template class Assembler<2>;
} // namespace ausroll::mechanics
