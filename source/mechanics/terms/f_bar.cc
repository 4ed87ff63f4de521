#include <ausroll/mechanics/terms/f_bar.h>

#include <deal.II/base/quadrature.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace ausroll::mechanics
{
  using namespace dealii;

  namespace
  {
    template <int dim>
    Point<dim> unit_cell_center()
    {
      Point<dim> unit_center;
      for (unsigned int d = 0; d < dim; ++d)
        unit_center[d] = 0.5;
      return unit_center;
    }
  } // namespace

  template <int dim, typename Hoop>
  FBar<dim, Hoop>::Scratch::Scratch(const Mapping<dim> &mapping, const FiniteElement<dim> &fe)
      : fe_center(mapping,
                  fe,
                  Quadrature<dim>(unit_cell_center<dim>()),
                  update_values | update_gradients | update_quadrature_points)
      , grad_u_center(1)
      , u_center(1)
      , dlnJ0(fe.n_dofs_per_cell())
      , dlnJ(fe.n_dofs_per_cell())
      , q_coefficient(fe.n_dofs_per_cell())
  {
  }

  template <int dim, typename Hoop>
  FBar<dim, Hoop>::Scratch::Scratch(const Scratch &other)
      : Scratch(other.fe_center.get_mapping(), other.fe_center.get_fe())
  {
  }

  template <int dim, typename Hoop>
  FBar<dim, Hoop>::FBar(const AssemblyLayout        &layout,
                        const unsigned int           degree,
                        const PlanarKinematics<dim> &kinematics,
                        const bool                   small_strain)
      : layout(layout)
      , kinematics(kinematics)
      , small_strain(small_strain)
      , cell_average(degree > 1)
  {
    // n of the F-bar scaling (Q2 and higher in plane strain scale the whole F: see
    // PlanarKinematics::volumetric_dimensions)
    n_vol = kinematics.volumetric_dimensions(cell_average);
    alpha = 1. / n_vol;
    for (unsigned int d = 0; d < n_vol; ++d)
      E[d][d] = 1.;
  }

  template <int dim, typename Hoop>
  bool FBar<dim, Hoop>::reference(const typename DoFHandler<dim>::active_cell_iterator &cell,
                                  const CellFields<dim>                                &fields,
                                  const bool   check_inversion,
                                  Scratch     &scratch,
                                  LocalSystem &local) const
  {
    const FEValuesExtractors::Vector displacement(0);
    const std::vector<unsigned int> &component = layout.component;
    std::vector<double>             &dlnJ0 = scratch.dlnJ0;
    double                          &J0 = scratch.J0;
    double                          &trace_H0 = scratch.trace_H0;
    J0 = 1.;
    trace_H0 = 0.;
    if (!cell_average)
    {
      // Q1: the deformation gradient at the cell centre
      FEValues<dim> &fe_center = scratch.fe_center;
      fe_center.reinit(cell);
      // (the cell's DoF values were read once by the internal-force term)
      fe_center[displacement].get_function_gradients_from_local_dof_values(fields.local_u,
                                                                           scratch.grad_u_center);
      fe_center[displacement].get_function_values_from_local_dof_values(fields.local_u,
                                                                        scratch.u_center);
      const Point<dim>  &X0 = fe_center.quadrature_point(0);
      const Tensor<2, 3> F0
          = kinematics.deformation_gradient(scratch.grad_u_center[0], scratch.u_center[0], X0);
      J0 = determinant(F0);
      trace_H0 = trace(F0) - 3.;
      if (check_inversion && !(J0 > 0.))
      {
        std::ostringstream msg;
        msg << "inverted element (det F = " << J0 << " at the cell centre " << X0 << ")";
        local.fail(msg.str());
        return false;
      }
      Tensor<2, 3> F0_inv;
      if (!small_strain)
        F0_inv = invert(F0);
      for (unsigned int j = 0; j < layout.n_dofs; ++j)
      {
        // tr G0_j (small strain) or tr(F0^-1 G0_j) = d ln J0 / du_j
        const unsigned int   c = component[j];
        const Tensor<1, dim> grad = fe_center.shape_grad_component(j, 0, c);
        const double         hoop0
            = Hoop::has_entry(c) ? Hoop::entry(fe_center.shape_value_component(j, 0, c), X0) : 0.;
        dlnJ0[j] = volume_change_rate<dim>(small_strain, F0_inv, c, grad, hoop0);
      }
      return true;
    }

    // Q2 and higher: volume average over the cell (mean dilatation), J0 = int J dV / V
    // (small strain: the average of tr(F - I)); d ln J0 / du_j = int J tr(F^-1 G_j) dV / (V J0)
    const FEValues<dim> &fe_values = fields.fe_values;
    double               volume = 0.;
    J0 = 0.;
    std::fill(dlnJ0.begin(), dlnJ0.end(), 0.);
    for (unsigned int q = 0; q < layout.n_q; ++q)
    {
      const Point<dim>  &X = fe_values.quadrature_point(q);
      const double       dV = fe_values.JxW(q) * kinematics.volume_factor(X);
      const Tensor<2, 3> F
          = kinematics.deformation_gradient(fields.grad_u[q], fields.u_values[q], X);
      const double       J = determinant(F);
      const double       weight = small_strain ? dV : J * dV;
      const Tensor<2, 3> F_inv = small_strain ? Tensor<2, 3>() : invert(F);
      volume += dV;
      J0 += J * dV;
      trace_H0 += (trace(F) - 3.) * dV;
      for (unsigned int j = 0; j < layout.n_dofs; ++j)
      {
        const unsigned int   c = component[j];
        const Tensor<1, dim> grad = fe_values.shape_grad_component(j, q, c);
        const double         hoop_j
            = Hoop::has_entry(c) ? Hoop::entry(fe_values.shape_value_component(j, q, c), X) : 0.;
        dlnJ0[j] += weight * volume_change_rate<dim>(small_strain, F_inv, c, grad, hoop_j);
      }
    }
    J0 /= volume;
    trace_H0 /= volume;
    for (unsigned int j = 0; j < layout.n_dofs; ++j)
      dlnJ0[j] /= small_strain ? volume : volume * J0;
    if (check_inversion && !(J0 > 0.))
    {
      std::ostringstream msg;
      msg << "inverted element (mean det F = " << J0 << " in the cell at " << cell->center() << ")";
      local.fail(msg.str());
      return false;
    }
    return true;
  }

  template <int dim, typename Hoop>
  FBarPoint
  FBar<dim, Hoop>::point(const Scratch &scratch, const Tensor<2, 3> &F, const double J) const
  {
    FBarPoint point;
    point.F_material = F;
    if (small_strain)
      point.F_material += (alpha * (scratch.trace_H0 - (trace(F) - 3.))) * E;
    else
    {
      point.s = std::pow(scratch.J0 / J, alpha);
      point.kappa = std::pow(point.s, 1. - n_vol);
      point.s_zz = n_vol == 3 ? point.s : 1.;
      for (unsigned int a = 0; a < n_vol; ++a)
        for (unsigned int b = 0; b < n_vol; ++b)
          point.F_material[a][b] *= point.s;
      point.F_inv = invert(F);
    }
    return point;
  }

  template <int dim, typename Hoop>
  void FBar<dim, Hoop>::add_tangent(const FBarPoint                            &point,
                                    const Tensor<2, 3>                         &F,
                                    const double                                dV,
                                    const std::vector<std::array<double, dim>> &g,
                                    const std::vector<double>                  &hoop,
                                    const Tensor<2, 3>                         &P_bar,
                                    const Tensor<4, 3>                         &A,
                                    Scratch                                    &scratch,
                                    FullMatrix<double>                         &matrix) const
  {
    // d F_bar / du_j = s G_j + alpha s (d ln J0 - d ln J) E F (large strain) or
    // G_j + alpha (tr G0_j - tr G_j) E (small strain); d kappa / du_j = (alpha - 1)
    // kappa (d ln J0 - d ln J). The terms in (d ln J0 - d ln J) form the rank-one matrix
    // q_i (dlnJ0_j - dlnJ_j) with q_i = G_i : Qt dV,
    // Qt = kappa [(alpha - 1) P_bar + alpha s A : (E F)] (small strain: alpha A : E).
    const double       s = point.s, kappa = point.kappa;
    Tensor<2, 3>       Qt;
    const Tensor<2, 3> EF = small_strain ? E : E * F;
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
      {
        double sum = 0.;
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int l = 0; l < 3; ++l)
            sum += A[a][b][k][l] * EF[k][l];
        Qt[a][b]
            = small_strain ? alpha * sum : kappa * ((alpha - 1.) * P_bar[a][b] + alpha * s * sum);
      }
    for (unsigned int i = 0; i < layout.n_dofs; ++i)
    {
      const unsigned int c = layout.component[i];
      scratch.q_coefficient[i] = contract<dim>(Qt, c, g[i], hoop[i]) * dV;
      scratch.dlnJ[i] = volume_change_rate<dim>(small_strain, point.F_inv, c, g[i], hoop[i]);
    }
    for (unsigned int i = 0; i < layout.n_dofs; ++i)
      for (unsigned int j = 0; j < layout.n_dofs; ++j)
        matrix(i, j) += scratch.q_coefficient[i] * (scratch.dlnJ0[j] - scratch.dlnJ[j]);
  }

  template <int dim, typename Hoop>
  void FBar<dim, Hoop>::add_out_of_plane_row(const FBarPoint    &point,
                                             const Tensor<2, 3> &F,
                                             const double        dV,
                                             const Tensor<2, 3> &P_bar,
                                             const Tensor<4, 3> &A,
                                             const Scratch      &scratch,
                                             Vector<double>     &row) const
  {
    // Qt_zz of add_tangent(): the zz row of the rank-one term (the "shape gradient" of lambda
    // is e_z (x) e_z)
    const Tensor<2, 3> EF = small_strain ? E : E * F;
    double             sum = 0.;
    for (unsigned int k = 0; k < 3; ++k)
      for (unsigned int l = 0; l < 3; ++l)
        sum += A[2][2][k][l] * EF[k][l];
    const double Qt_zz = small_strain
                             ? alpha * sum
                             : point.kappa * ((alpha - 1.) * P_bar[2][2] + alpha * point.s * sum);
    for (unsigned int j = 0; j < layout.n_dofs; ++j)
      row(j) += Qt_zz * dV * (scratch.dlnJ0[j] - scratch.dlnJ[j]);
  }

  template class FBar<2, NoHoopEntry>;
  template class FBar<2, AxisymmetricHoopEntry>;
  template class FBar<3, NoHoopEntry>;
} // namespace ausroll::mechanics
