#include <ausroll/core/exceptions.h>
#include <ausroll/mechanics/terms/f_bar.h>
#include <ausroll/mechanics/terms/internal_force.h>

#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <sstream>

namespace ausroll::mechanics
{
  using namespace dealii;

  namespace
  {
    /**
     * InternalForce for the hoop entry @p Hoop of the kinematics and the volumetric treatment
     * @p Volumetric (FBar or NoVolumetricCorrection): both are compile-time policies, so the
     * quadrature loop has neither a planar nor a locking branch.
     */
    template <int dim, typename Hoop, typename Volumetric>
    class InternalForceTerm : public InternalForce<dim>
    {
    public:
      using ActiveCell = typename AssemblyTerm<dim>::ActiveCell;

      InternalForceTerm(const AssemblyLayout              &layout,
                        const Mapping<dim>                &mapping,
                        const FiniteElement<dim>          &fe,
                        const Quadrature<dim>             &quadrature,
                        const PlanarKinematics<dim>       &kinematics,
                        const material::ConstitutiveModel &model,
                        Volumetric                         volumetric)
          : layout(layout)
          , mapping(mapping)
          , fe(fe)
          , quadrature(quadrature)
          , kinematics(kinematics)
          , model(model)
          , volumetric(std::move(volumetric))
          , out_of_plane(kinematics.is_generalized_plane_strain())
      {
      }

      /** FEValues, Grad u, the shape-function gradients G_i, P, A and the volumetric scratch. */
      struct Scratch : TermScratch
      {
        Scratch(const Mapping<dim>       &mapping,
                const FiniteElement<dim> &fe,
                const Quadrature<dim>    &quadrature)
            : fe_values(mapping,
                        fe,
                        quadrature,
                        update_values | update_gradients | update_quadrature_points
                            | update_JxW_values)
            , local_u(fe.n_dofs_per_cell())
            , grad_u(quadrature.size())
            , u_values(quadrature.size())
            , g(fe.n_dofs_per_cell())
            , hoop(fe.n_dofs_per_cell(), 0.)
            , h(fe.n_dofs_per_cell())
            , h_hoop(fe.n_dofs_per_cell(), 0.)
            , volumetric(mapping, fe)
        {
        }

        FEValues<dim>               fe_values;
        std::vector<double>         local_u;  // the cell's DoF values of the solution
        std::vector<Tensor<2, dim>> grad_u;   // Grad u at the quadrature points
        std::vector<Tensor<1, dim>> u_values; // u at the quadrature points
        // The 3D gradient G_i = dF/du_i of each shape function (3x3): row c_i holds the in-plane
        // gradient, g[i][J] = dF[c_i][J] / du_i (J < dim), and the hoop entry of the kinematics
        // hoop[i] = dF[2][2] / du_i (phi_i / R for the radial component of axisymmetric models,
        // zero otherwise).
        std::vector<std::array<double, dim>> g;
        std::vector<double>                  hoop;
        // h[j][c][I] = (A : G_j)[c][I] for c, I < dim and h_hoop[j] = (A : G_j)[2][2]
        std::vector<std::array<std::array<double, dim>, dim>> h;
        std::vector<double>                                   h_hoop;
        // stress P = kappa P(F_bar), the material's stress P(F_bar) and its tangent A
        Tensor<2, 3> P, P_bar;
        Tensor<4, 3> A;
        // the cell's material points when the assembly has no point table
        std::vector<material::MaterialPoint *> points;
        typename Volumetric::Scratch           volumetric;
      };

      std::unique_ptr<TermScratch> create_scratch() const override
      {
        return std::make_unique<Scratch>(mapping, fe, quadrature);
      }

      void execute(const ActiveCell          &cell,
                   const AssemblyInputs<dim> &inputs,
                   TermScratch               &term_scratch,
                   LocalSystem               &local) const override;

      std::vector<Tensor<2, 3>>
      material_deformation_gradients(const ActiveCell                    &cell,
                                     const TrilinosWrappers::MPI::Vector &solution) const override;

    private:
      /**
       * Generalized plane strain: the border of the Newton system at one point (weight @p dV)
       * into @p local: k_ue_i = kappa s_zz (A : e_z e_z) : G_i dV, k_eu_j = kappa s (A : G_j)_zz dV
       * plus the F-bar term, k_ee = kappa s_zz A_zzzz dV (P = kappa P(F_bar), dF_bar/dlambda =
       * s_zz e_z e_z: FBarPoint).
       */
      void add_out_of_plane_border(const FBarPoint    &point,
                                   const Tensor<2, 3> &F,
                                   const double        dV,
                                   Scratch            &scratch,
                                   LocalSystem        &local) const;

      /** Reinitialise the FEValues of @p scratch on @p cell and evaluate u and Grad u. */
      CellFields<dim> evaluate_fields(const ActiveCell                    &cell,
                                      const TrilinosWrappers::MPI::Vector &solution,
                                      Scratch                             &scratch) const;

      const AssemblyLayout              &layout;
      const Mapping<dim>                &mapping;
      const FiniteElement<dim>          &fe;
      const Quadrature<dim>             &quadrature;
      const PlanarKinematics<dim>       &kinematics;
      const material::ConstitutiveModel &model;
      const Volumetric                   volumetric;
      const bool out_of_plane; ///< generalized plane strain: assemble the border too
    };

    template <int dim, typename Hoop, typename Volumetric>
    void InternalForceTerm<dim, Hoop, Volumetric>::add_out_of_plane_border(const FBarPoint &point,
                                                                           const Tensor<2, 3> &F,
                                                                           const double        dV,
                                                                           Scratch     &scratch,
                                                                           LocalSystem &local) const
    {
      const Tensor<4, 3> &A = scratch.A;
      const double        column_factor = point.kappa * point.s_zz * dV;
      const double        row_factor = point.kappa * point.s * dV;
      local.axial_stiffness += A[2][2][2][2] * column_factor;
      for (unsigned int i = 0; i < layout.n_dofs; ++i)
      {
        const unsigned int c = layout.component[i];
        double             column = 0., row = 0.;
        for (unsigned int J = 0; J < dim; ++J)
        {
          column += A[c][J][2][2] * scratch.g[i][J];
          row += A[2][2][c][J] * scratch.g[i][J];
        }
        local.column(i) += column * column_factor;
        local.row(i) += row * row_factor;
      }
      volumetric.add_out_of_plane_row(
          point, F, dV, scratch.P_bar, A, scratch.volumetric, local.row);
    }

    template <int dim, typename Hoop, typename Volumetric>
    CellFields<dim> InternalForceTerm<dim, Hoop, Volumetric>::evaluate_fields(
        const ActiveCell                    &cell,
        const TrilinosWrappers::MPI::Vector &solution,
        Scratch                             &scratch) const
    {
      const FEValuesExtractors::Vector displacement(0);
      FEValues<dim>                   &fe_values = scratch.fe_values;
      fe_values.reinit(cell);
      // one read of the cell's DoF values from the Trilinos vector for all evaluations of the
      // cell (FEValuesViews would read and allocate them for each call)
      cell->get_dof_values(solution, scratch.local_u.begin(), scratch.local_u.end());
      fe_values[displacement].get_function_gradients_from_local_dof_values(scratch.local_u,
                                                                           scratch.grad_u);
      fe_values[displacement].get_function_values_from_local_dof_values(scratch.local_u,
                                                                        scratch.u_values);
      return CellFields<dim>{fe_values, scratch.local_u, scratch.grad_u, scratch.u_values};
    }

    template <int dim, typename Hoop, typename Volumetric>
    void InternalForceTerm<dim, Hoop, Volumetric>::execute(const ActiveCell          &cell,
                                                           const AssemblyInputs<dim> &inputs,
                                                           TermScratch               &term_scratch,
                                                           LocalSystem               &local) const
    {
      Scratch                         &scratch = static_cast<Scratch &>(term_scratch);
      const unsigned int               n_dofs = layout.n_dofs;
      const std::vector<unsigned int> &component = layout.component;
      const bool                       need_matrix = inputs.need_matrix;

      const FEValues<dim> &fe_values = scratch.fe_values;
      auto                &g = scratch.g;
      auto                &hoop = scratch.hoop;
      auto                &h = scratch.h;
      auto                &h_hoop = scratch.h_hoop;
      Tensor<2, 3>        &P = scratch.P;
      Tensor<2, 3>        &P_bar = scratch.P_bar;
      Tensor<4, 3>        &A = scratch.A;

      const CellFields<dim>           fields = evaluate_fields(cell, *inputs.solution, scratch);
      material::MaterialPoint *const *points;
      if (inputs.point_table != nullptr)
        points = inputs.point_table + cell->active_cell_index() * layout.n_q;
      else
      {
        const std::vector<std::shared_ptr<material::MaterialPoint>> shared
            = inputs.material_points->get_data(cell);
        scratch.points.resize(shared.size());
        for (unsigned int q = 0; q < shared.size(); ++q)
          scratch.points[q] = shared[q].get();
        points = scratch.points.data();
      }

      FullMatrix<double> &cell_matrix = local.cell_matrix;
      Vector<double>     &cell_residual = local.cell_residual;

      // F-bar: the reference volume change of the cell and its derivative
      if (!volumetric.reference(cell, fields, inputs.check_inversion, scratch.volumetric, local))
        return;

      for (unsigned int q = 0; q < layout.n_q; ++q)
      {
        const Point<dim>  &X = fe_values.quadrature_point(q);
        const double       dV = fe_values.JxW(q) * kinematics.volume_factor(X);
        const Tensor<2, 3> F
            = kinematics.deformation_gradient(scratch.grad_u[q], scratch.u_values[q], X);
        const double J = determinant(F);
        local.min_jacobian = std::min(local.min_jacobian, J);
        if (inputs.check_inversion && !(J > 0.))
        {
          std::ostringstream msg;
          msg << "inverted element (det F = " << J << ") at (" << X << ")";
          local.fail(msg.str());
          return;
        }

        for (unsigned int i = 0; i < n_dofs; ++i)
        {
          const unsigned int   c = component[i];
          const Tensor<1, dim> grad = fe_values.shape_grad_component(i, q, c);
          for (unsigned int J = 0; J < dim; ++J)
            g[i][J] = grad[J];
          if (Hoop::has_entry(c))
            hoop[i] = Hoop::entry(fe_values.shape_value_component(i, q, c), X);
        }

        // Deformation gradient seen by the material point; residual stress P = kappa P(F_bar)
        // (P(F) without F-bar) and the factor of the material tangent term.
        const FBarPoint point = volumetric.point(scratch.volumetric, F, J);
        try
        {
          model.evaluate(point.F_material,
                         points[q]->committed,
                         points[q]->trial,
                         P_bar,
                         need_matrix ? &A : nullptr);
        }
        catch (const RunFailure &e)
        {
          local.fail(e.what());
          return;
        }
        P = point.kappa * P_bar;

        for (unsigned int i = 0; i < n_dofs; ++i)
          cell_residual(i) += contract<dim>(P, component[i], g[i], hoop[i]) * dV;
        if (out_of_plane)
          local.axial_work += P[2][2] * dV;

        if (!need_matrix)
          continue;
        for (unsigned int j = 0; j < n_dofs; ++j)
        {
          const unsigned int cj = component[j];
          for (unsigned int c = 0; c < dim; ++c)
            for (unsigned int I = 0; I < dim; ++I)
            {
              // (the hoop products only where the kinematics has the entry)
              double sum = Hoop::product(A[c][I][2][2], hoop[j]);
              for (unsigned int J = 0; J < dim; ++J)
                sum += A[c][I][cj][J] * g[j][J];
              h[j][c][I] = sum;
            }
          for (unsigned int k = 0; k < Hoop::n_entries; ++k)
          {
            double sum = A[2][2][2][2] * hoop[j];
            for (unsigned int J = 0; J < dim; ++J)
              sum += A[2][2][cj][J] * g[j][J];
            h_hoop[j] = sum;
          }
        }
        const double material_factor = point.kappa * point.s * dV;
        for (unsigned int i = 0; i < n_dofs; ++i)
        {
          const unsigned int c = component[i];
          double *const      row = &cell_matrix(i, 0);
          for (unsigned int j = 0; j < n_dofs; ++j)
          {
            double sum = Hoop::product(hoop[i], h_hoop[j]);
            for (unsigned int I = 0; I < dim; ++I)
              sum += g[i][I] * h[j][c][I];
            row[j] += sum * material_factor;
          }
        }

        volumetric.add_tangent(point, F, dV, g, hoop, P_bar, A, scratch.volumetric, cell_matrix);
        if (out_of_plane)
          add_out_of_plane_border(point, F, dV, scratch, local);
      }
    }

    template <int dim, typename Hoop, typename Volumetric>
    std::vector<Tensor<2, 3>>
    InternalForceTerm<dim, Hoop, Volumetric>::material_deformation_gradients(
        const ActiveCell &cell, const TrilinosWrappers::MPI::Vector &solution) const
    {
      Scratch                   scratch(mapping, fe, quadrature);
      LocalSystem               local(layout.n_dofs);
      const CellFields<dim>     fields = evaluate_fields(cell, solution, scratch);
      std::vector<Tensor<2, 3>> F(layout.n_q);
      for (unsigned int q = 0; q < layout.n_q; ++q)
        F[q] = kinematics.deformation_gradient(
            scratch.grad_u[q], scratch.u_values[q], fields.fe_values.quadrature_point(q));
      // the volumetric reference and point scaling of execute() (no inversion check)
      volumetric.reference(cell, fields, false, scratch.volumetric, local);
      for (unsigned int q = 0; q < layout.n_q; ++q)
        F[q] = volumetric.point(scratch.volumetric, F[q], determinant(F[q])).F_material;
      return F;
    }
  } // namespace

  template <int dim>
  std::unique_ptr<InternalForce<dim>>
  InternalForce<dim>::create(const AssemblyLayout              &layout,
                             const Mapping<dim>                &mapping,
                             const FiniteElement<dim>          &fe,
                             const Quadrature<dim>             &quadrature,
                             const PlanarKinematics<dim>       &kinematics,
                             const material::ConstitutiveModel &model,
                             const VolumetricLocking            locking)
  {
    return kinematics.with_hoop_entry(
        [&](auto hoop) -> std::unique_ptr<InternalForce<dim>>
        {
          using Hoop = decltype(hoop);
          const auto make = [&](auto volumetric) -> std::unique_ptr<InternalForce<dim>>
          {
            return std::make_unique<InternalForceTerm<dim, Hoop, decltype(volumetric)>>(
                layout, mapping, fe, quadrature, kinematics, model, std::move(volumetric));
          };
          if (locking == VolumetricLocking::f_bar)
            return make(FBar<dim, Hoop>(layout, fe.degree, kinematics, model.is_small_strain()));
          return make(NoVolumetricCorrection<dim, Hoop>());
        });
  }

  template class InternalForce<2>;
  template class InternalForce<3>;
} // namespace ausroll::mechanics
