#include <ausroll/mechanics/terms/follower_pressure.h>

namespace ausroll::mechanics
{
  using namespace dealii;

  template <typename Hoop>
  void FollowerPressure<Hoop>::add(const double           p,
                                   const unsigned int     q,
                                   const FEFaceValues<2> &fe_face_values,
                                   const AssemblyLayout  &layout,
                                   const Point<2>        &X,
                                   const Tensor<1, 2>    &N,
                                   const Tensor<2, 2>    &grad_u,
                                   const Tensor<1, 2>    &u,
                                   const double           dA,
                                   const bool             need_matrix,
                                   const double           lambda,
                                   Tensor<1, 2>          &t,
                                   FullMatrix<double>    &matrix,
                                   Vector<double>        &column)
  {
    const std::vector<unsigned int> &component = layout.component;
    // deformed tangent a = F T (T = N rotated by +90 degrees), deformed normal times
    // dl/dL = (a_y, -a_x); times the hoop stretch r / R of the kinematics
    const Tensor<1, 2> T({-N[1], N[0]});
    const Tensor<1, 2> a = T + grad_u * T;
    const Tensor<1, 2> n_scaled({a[1], -a[0]});
    // (times the out-of-plane stretch lambda of generalized plane strain, 1 otherwise)
    const double hoop_stretch = Hoop::stretch(u, X) * lambda;
    t -= (p * hoop_stretch) * n_scaled;
    if (!need_matrix)
      return;
    // d(-f_ext,i)/dlambda = p (r/R) n_scaled[c_i] phi_i dA
    if (column.size() > 0)
      for (unsigned int i = 0; i < layout.n_dofs; ++i)
        column(i) += p * (hoop_stretch / lambda) * n_scaled[component[i]]
                     * fe_face_values.shape_value_component(i, q, component[i]) * dA;
    for (unsigned int j = 0; j < layout.n_dofs; ++j)
    {
      // d t0 / du_j = -p (r/R d n_scaled + d(r/R) n_scaled), d a = (grad phi_j . T) e_cj
      const unsigned int cj = component[j];
      const double       da = fe_face_values.shape_grad_component(j, q, cj) * T;
      Tensor<1, 2>       dt;
      if (cj == 0)
        dt[1] = -hoop_stretch * da;
      else
        dt[0] = hoop_stretch * da;
      if (Hoop::has_entry(cj))
        dt += (lambda * Hoop::entry(fe_face_values.shape_value_component(j, q, cj), X)) * n_scaled;
      dt *= -p * dA;
      for (unsigned int i = 0; i < layout.n_dofs; ++i)
        matrix(i, j) -= dt[component[i]] * fe_face_values.shape_value_component(i, q, component[i]);
    }
  }

  template struct FollowerPressure<NoHoopEntry>;
  template struct FollowerPressure<AxisymmetricHoopEntry>;
} // namespace ausroll::mechanics
