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
                            const BoundaryConditions<dim>     &boundary_conditions,
                            const VolumetricLocking            locking)
      : mapping(mapping)
      , fe(fe)
      , cell_quadrature(n_q_points_1d)
      , face_quadrature(n_q_points_1d)
      , kinematics(kinematics)
      , model(model)
      , boundary_conditions(boundary_conditions)
      , locking(locking)
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

    const bool small_strain = model.is_small_strain();
    const bool f_bar = locking == VolumetricLocking::f_bar;
    // J0: value at the cell centre for Q1 (de Souza Neto), cell average for higher degrees (a
    // single centre value leaves volumetric modes of Q2 unconstrained: too soft)
    const bool cell_average = fe.degree > 1;
    const bool follower = !small_strain; // pressure on the deformed surface

    FEValues<dim>     fe_values(mapping,
                            fe,
                            cell_quadrature,
                            update_values | update_gradients | update_quadrature_points
                                | update_JxW_values);
    FEFaceValues<dim> fe_face_values(mapping,
                                     fe,
                                     face_quadrature,
                                     update_values | update_gradients | update_quadrature_points
                                         | update_normal_vectors | update_JxW_values);
    // F-bar: values and gradients at the cell centre
    Point<dim> unit_center;
    for (unsigned int d = 0; d < dim; ++d)
      unit_center[d] = 0.5;
    FEValues<dim> fe_center(mapping,
                            fe,
                            Quadrature<dim>(unit_center),
                            update_values | update_gradients | update_quadrature_points);

    const unsigned int n_dofs = fe.n_dofs_per_cell();
    const unsigned int n_q = cell_quadrature.size();
    const unsigned int n_face_q = face_quadrature.size();
    const unsigned int n_base = n_dofs / dim; // support points of the FE_Q base element

    FullMatrix<double>                   cell_matrix(n_dofs, n_dofs);
    Vector<double>                       cell_residual(n_dofs), cell_external(n_dofs);
    Vector<double>                       cell_free(n_dofs), cell_rhs(n_dofs);
    std::vector<types::global_dof_index> dofs(n_dofs);
    std::vector<Tensor<2, dim>>          grad_u(n_q), grad_u_face(n_face_q), grad_u_center(1);
    std::vector<Tensor<1, dim>>          u_values(n_q), u_face(n_face_q), u_center(1);
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

    // The 3D gradient G_i = dF/du_i of each shape function (3x3): row c_i holds the in-plane
    // gradient, g[i][J] = dF[c_i][J] / du_i (J < dim), and axisymmetric models add the hoop entry
    // hoop[i] = dF[2][2] / du_i = phi_i / R for the radial component (c_i = 0).
    std::vector<std::array<double, dim>> g(n_dofs);
    std::vector<double>                  hoop(n_dofs, 0.);
    // h[j][c][I] = (A : G_j)[c][I] for c, I < dim and h_hoop[j] = (A : G_j)[2][2]
    std::vector<std::array<std::array<double, dim>, dim>> h(n_dofs);
    std::vector<double>                                   h_hoop(n_dofs, 0.);
    const bool axisymmetric = kinematics.is_axisymmetric();
    // G_i : M for a 3x3 M
    auto contract = [&](const Tensor<2, 3> &M, const unsigned int i)
    {
      const unsigned int c = component[i];
      double             sum = M[2][2] * hoop[i];
      for (unsigned int J = 0; J < dim; ++J)
        sum += M[c][J] * g[i][J];
      return sum;
    };
    // F-bar: d ln J0 / du_j at the centre, d ln J / du_j at the point (tr G for small strain), and
    // the coefficients q_i of the rank-one cell-centre term of the tangent
    std::vector<double> dlnJ0(n_dofs), dlnJ(n_dofs), q_coefficient(n_dofs);

    // n of the F-bar scaling and the in-plane/volumetric projection E (I_n)
    // Q2 and higher in plane strain: isotropic scaling of the whole F (n = 3, F_bar_zz = s, as the
    // B-bar of Hughes with eps_bar_zz = (theta_0 - theta) / 3); the in-plane scaling leaks the
    // volume correction into the 3D deviatoric strain and made Q2 too soft (flat punch: 0.928
    // p_lim instead of 0.998)
    const unsigned int n_vol = f_bar_dimensions();
    const double       alpha = 1. / n_vol;
    Tensor<2, 3>       E;
    for (unsigned int d = 0; d < n_vol; ++d)
      E[d][d] = 1.;

    Tensor<2, 3> P, P_bar;
    Tensor<4, 3> A;
    const bool   check_inversion = !small_strain;

    bool        ok = true;
    double      min_jacobian = 1e300;
    std::string message;

    auto fail = [&](const std::string &text)
    {
      ok = false;
      message = text;
    };

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

      // F-bar: the deformation gradient at the cell centre and d(ln J0)/du_j (small strain:
      // tr(F0 - I) and tr G0_j)
      double       J0 = 1., trace_H0 = 0.;
      Tensor<2, 3> F0_inv;
      if (f_bar && !cell_average)
      {
        // Q1: the deformation gradient at the cell centre
        fe_center.reinit(cell);
        fe_center[displacement].get_function_gradients(solution, grad_u_center);
        fe_center[displacement].get_function_values(solution, u_center);
        const Point<dim>  &X0 = fe_center.quadrature_point(0);
        const Tensor<2, 3> F0 = kinematics.deformation_gradient(grad_u_center[0], u_center[0], X0);
        J0 = determinant(F0);
        trace_H0 = trace(F0) - 3.;
        if (check_inversion && !(J0 > 0.))
        {
          std::ostringstream msg;
          msg << "inverted element (det F = " << J0 << " at the cell centre " << X0 << ")";
          fail(msg.str());
          continue;
        }
        if (!small_strain)
          F0_inv = invert(F0);
        for (unsigned int j = 0; j < n_dofs; ++j)
        {
          // tr G0_j (small strain) or tr(F0^-1 G0_j) = d ln J0 / du_j
          const unsigned int   c = component[j];
          const Tensor<1, dim> grad = fe_center.shape_grad_component(j, 0, c);
          const double         hoop0
              = (axisymmetric && c == 0) ? fe_center.shape_value_component(j, 0, c) / X0[0] : 0.;
          if (small_strain)
            dlnJ0[j] = grad[c] + hoop0;
          else
          {
            double l = F0_inv[2][2] * hoop0;
            for (unsigned int J = 0; J < dim; ++J)
              l += F0_inv[J][c] * grad[J];
            dlnJ0[j] = l;
          }
        }
      }
      else if (f_bar)
      {
        // Q2 and higher: volume average over the cell (mean dilatation), J0 = int J dV / V
        // (small strain: the average of tr(F - I)); d ln J0 / du_j = int J tr(F^-1 G_j) dV / (V J0)
        double volume = 0.;
        J0 = 0.;
        std::fill(dlnJ0.begin(), dlnJ0.end(), 0.);
        for (unsigned int q = 0; q < n_q; ++q)
        {
          const Point<dim>  &X = fe_values.quadrature_point(q);
          const double       dV = fe_values.JxW(q) * kinematics.volume_factor(X);
          const Tensor<2, 3> F = kinematics.deformation_gradient(grad_u[q], u_values[q], X);
          const double       J = determinant(F);
          const double       weight = small_strain ? dV : J * dV;
          const Tensor<2, 3> F_inv = small_strain ? Tensor<2, 3>() : invert(F);
          volume += dV;
          J0 += J * dV;
          trace_H0 += (trace(F) - 3.) * dV;
          for (unsigned int j = 0; j < n_dofs; ++j)
          {
            const unsigned int   c = component[j];
            const Tensor<1, dim> grad = fe_values.shape_grad_component(j, q, c);
            const double         hoop_j
                = (axisymmetric && c == 0) ? fe_values.shape_value_component(j, q, c) / X[0] : 0.;
            double l = 0.;
            if (small_strain)
              l = grad[c] + hoop_j;
            else
            {
              l = F_inv[2][2] * hoop_j;
              for (unsigned int J = 0; J < dim; ++J)
                l += F_inv[J][c] * grad[J];
            }
            dlnJ0[j] += weight * l;
          }
        }
        J0 /= volume;
        trace_H0 /= volume;
        for (unsigned int j = 0; j < n_dofs; ++j)
          dlnJ0[j] /= small_strain ? volume : volume * J0;
        if (check_inversion && !(J0 > 0.))
        {
          std::ostringstream msg;
          msg << "inverted element (mean det F = " << J0 << " in the cell at " << cell->center()
              << ")";
          fail(msg.str());
          continue;
        }
      }

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
          fail(msg.str());
          break;
        }

        for (unsigned int i = 0; i < n_dofs; ++i)
        {
          const unsigned int   c = component[i];
          const Tensor<1, dim> grad = fe_values.shape_grad_component(i, q, c);
          for (unsigned int J = 0; J < dim; ++J)
            g[i][J] = grad[J];
          if (axisymmetric && c == 0)
            hoop[i] = fe_values.shape_value_component(i, q, c) / X[0];
        }

        // Deformation gradient seen by the material point; residual stress P_res (P = P(F) or
        // kappa P(F_bar)) and the factor of the material tangent term.
        Tensor<2, 3> F_material = F;
        double       s = 1., kappa = 1.;
        Tensor<2, 3> F_inv;
        if (f_bar)
        {
          if (small_strain)
            F_material += (alpha * (trace_H0 - (trace(F) - 3.))) * E;
          else
          {
            s = std::pow(J0 / J, alpha);
            kappa = std::pow(s, 1. - n_vol);
            for (unsigned int a = 0; a < n_vol; ++a)
              for (unsigned int b = 0; b < n_vol; ++b)
                F_material[a][b] *= s;
            F_inv = invert(F);
          }
        }
        try
        {
          model.evaluate(F_material,
                         points[q]->committed,
                         points[q]->trial,
                         P_bar,
                         need_matrix ? &A : nullptr);
        }
        catch (const RunFailure &e)
        {
          fail(e.what());
          break;
        }
        P = kappa * P_bar;

        for (unsigned int i = 0; i < n_dofs; ++i)
          cell_residual(i) += contract(P, i) * dV;

        if (need_matrix)
        {
          for (unsigned int j = 0; j < n_dofs; ++j)
          {
            const unsigned int cj = component[j];
            for (unsigned int c = 0; c < dim; ++c)
              for (unsigned int I = 0; I < dim; ++I)
              {
                double sum = A[c][I][2][2] * hoop[j];
                for (unsigned int J = 0; J < dim; ++J)
                  sum += A[c][I][cj][J] * g[j][J];
                h[j][c][I] = sum;
              }
            if (axisymmetric)
            {
              double sum = A[2][2][2][2] * hoop[j];
              for (unsigned int J = 0; J < dim; ++J)
                sum += A[2][2][cj][J] * g[j][J];
              h_hoop[j] = sum;
            }
          }
          const double material_factor = kappa * s * dV;
          for (unsigned int i = 0; i < n_dofs; ++i)
          {
            const unsigned int c = component[i];
            for (unsigned int j = 0; j < n_dofs; ++j)
            {
              double sum = hoop[i] * h_hoop[j];
              for (unsigned int I = 0; I < dim; ++I)
                sum += g[i][I] * h[j][c][I];
              cell_matrix(i, j) += sum * material_factor;
            }
          }

          if (f_bar)
          {
            // d F_bar / du_j = s G_j + alpha s (d ln J0 - d ln J) E F (large strain) or
            // G_j + alpha (tr G0_j - tr G_j) E (small strain); d kappa / du_j = (alpha - 1)
            // kappa (d ln J0 - d ln J). The terms in (d ln J0 - d ln J) form the rank-one matrix
            // q_i (dlnJ0_j - dlnJ_j) with q_i = G_i : Qt dV,
            // Qt = kappa [(alpha - 1) P_bar + alpha s A : (E F)] (small strain: alpha A : E).
            Tensor<2, 3>       Qt;
            const Tensor<2, 3> EF = small_strain ? E : E * F;
            for (unsigned int a = 0; a < 3; ++a)
              for (unsigned int b = 0; b < 3; ++b)
              {
                double sum = 0.;
                for (unsigned int k = 0; k < 3; ++k)
                  for (unsigned int l = 0; l < 3; ++l)
                    sum += A[a][b][k][l] * EF[k][l];
                Qt[a][b] = small_strain ? alpha * sum
                                        : kappa * ((alpha - 1.) * P_bar[a][b] + alpha * s * sum);
              }
            for (unsigned int i = 0; i < n_dofs; ++i)
            {
              const unsigned int c = component[i];
              q_coefficient[i] = contract(Qt, i) * dV;
              if (small_strain)
                dlnJ[i] = g[i][c] + hoop[i]; // tr G_i
              else
              {
                double l = F_inv[2][2] * hoop[i];
                for (unsigned int J = 0; J < dim; ++J)
                  l += F_inv[J][c] * g[i][J];
                dlnJ[i] = l;
              }
            }
            for (unsigned int i = 0; i < n_dofs; ++i)
              for (unsigned int j = 0; j < n_dofs; ++j)
                cell_matrix(i, j) += q_coefficient[i] * (dlnJ0[j] - dlnJ[j]);
          }
        }
      }
      if (!ok)
        continue; // keep looping so that every rank reaches the collective calls below

      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && boundary_conditions.has_surface_load(face->boundary_id()))
        {
          fe_face_values.reinit(cell, face);
          if (follower)
          {
            fe_face_values[displacement].get_function_gradients(solution, grad_u_face);
            fe_face_values[displacement].get_function_values(solution, u_face);
          }
          for (unsigned int q = 0; q < n_face_q; ++q)
          {
            const Point<dim>        &X = fe_face_values.quadrature_point(q);
            const Tensor<1, dim>    &N = fe_face_values.normal_vector(q);
            const double             dA = fe_face_values.JxW(q) * kinematics.volume_factor(X);
            const types::boundary_id id = face->boundary_id();
            Tensor<1, dim>           t = follower ? boundary_conditions.dead_traction(id, X, time)
                                                  : boundary_conditions.traction(id, X, N, time);
            const double             p = follower ? boundary_conditions.pressure(id, X, time) : 0.;
            AssertThrow(dim == 2 || p == 0.,
                        ExcMessage("follower pressure is implemented for 2D models only"));
            if constexpr (dim == 2)
              if (follower && p != 0.)
              {
                // deformed tangent a = F T (T = N rotated by +90 degrees), deformed normal times
                // dl/dL = (a_y, -a_x); axisymmetric: times the hoop stretch r / R
                const Tensor<1, 2> T({-N[1], N[0]});
                const Tensor<1, 2> a = T + grad_u_face[q] * T;
                const Tensor<1, 2> n_scaled({a[1], -a[0]});
                const double       hoop_stretch = axisymmetric ? 1. + u_face[q][0] / X[0] : 1.;
                t -= (p * hoop_stretch) * n_scaled;
                if (need_matrix)
                  for (unsigned int j = 0; j < n_dofs; ++j)
                  {
                    // d t0 / du_j = -p (r/R d n_scaled + d(r/R) n_scaled), d a = (grad phi_j . T)
                    // e_cj
                    const unsigned int cj = component[j];
                    const double       da = fe_face_values.shape_grad_component(j, q, cj) * T;
                    Tensor<1, 2>       dt;
                    if (cj == 0)
                      dt[1] = -hoop_stretch * da;
                    else
                      dt[0] = hoop_stretch * da;
                    if (axisymmetric && cj == 0)
                      dt += (fe_face_values.shape_value_component(j, q, cj) / X[0]) * n_scaled;
                    dt *= -p * dA;
                    for (unsigned int i = 0; i < n_dofs; ++i)
                      cell_matrix(i, j)
                          -= dt[component[i]]
                             * fe_face_values.shape_value_component(i, q, component[i]);
                  }
              }
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

  template <int dim>
  unsigned int Assembler<dim>::f_bar_dimensions() const
  {
    return (fe.degree > 1 && dim == 2 && kinematics.planar_model() == PlanarModel::plane_strain)
               ? 3
               : kinematics.volumetric_dimensions();
  }

  template <int dim>
  std::vector<Tensor<2, 3>> Assembler<dim>::material_deformation_gradients(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      const TrilinosWrappers::MPI::Vector                  &solution) const
  {
    FEValues<dim> fe_values(mapping,
                            fe,
                            cell_quadrature,
                            update_values | update_gradients | update_quadrature_points
                                | update_JxW_values);
    fe_values.reinit(cell);
    const unsigned int               n_q = cell_quadrature.size();
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<2, dim>>      grad_u(n_q);
    std::vector<Tensor<1, dim>>      u(n_q);
    fe_values[displacement].get_function_gradients(solution, grad_u);
    fe_values[displacement].get_function_values(solution, u);
    std::vector<Tensor<2, 3>> F(n_q);
    for (unsigned int q = 0; q < n_q; ++q)
      F[q] = kinematics.deformation_gradient(grad_u[q], u[q], fe_values.quadrature_point(q));
    if (locking != VolumetricLocking::f_bar)
      return F;

    // J0 and tr(F0 - I) as in assemble(): at the centre (Q1) or averaged over the cell
    double J0 = 0., trace_H0 = 0.;
    if (fe.degree == 1)
    {
      Point<dim> unit_center;
      for (unsigned int d = 0; d < dim; ++d)
        unit_center[d] = 0.5;
      FEValues<dim> fe_center(mapping,
                              fe,
                              Quadrature<dim>(unit_center),
                              update_values | update_gradients | update_quadrature_points);
      fe_center.reinit(cell);
      std::vector<Tensor<2, dim>> g0(1);
      std::vector<Tensor<1, dim>> u0(1);
      fe_center[displacement].get_function_gradients(solution, g0);
      fe_center[displacement].get_function_values(solution, u0);
      const Tensor<2, 3> F0
          = kinematics.deformation_gradient(g0[0], u0[0], fe_center.quadrature_point(0));
      J0 = determinant(F0);
      trace_H0 = trace(F0) - 3.;
    }
    else
    {
      double volume = 0.;
      for (unsigned int q = 0; q < n_q; ++q)
      {
        const double dV
            = fe_values.JxW(q) * kinematics.volume_factor(fe_values.quadrature_point(q));
        volume += dV;
        J0 += determinant(F[q]) * dV;
        trace_H0 += (trace(F[q]) - 3.) * dV;
      }
      J0 /= volume;
      trace_H0 /= volume;
    }
    const unsigned int n_vol = f_bar_dimensions();
    const double       alpha = 1. / n_vol;
    for (unsigned int q = 0; q < n_q; ++q)
      if (model.is_small_strain())
      {
        const double shift = alpha * (trace_H0 - (trace(F[q]) - 3.));
        for (unsigned int d = 0; d < n_vol; ++d)
          F[q][d][d] += shift;
      }
      else
      {
        const double s = std::pow(J0 / determinant(F[q]), alpha);
        for (unsigned int a = 0; a < n_vol; ++a)
          for (unsigned int b = 0; b < n_vol; ++b)
            F[q][a][b] *= s;
      }
    return F;
  }

  template class Assembler<2>;
} // namespace ausroll::mechanics
