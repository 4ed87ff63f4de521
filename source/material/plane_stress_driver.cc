#include <ausroll/core/exceptions.h>
#include <ausroll/material/plane_stress_driver.h>

#include <cmath>
#include <sstream>

namespace ausroll::material
{
  using dealii::Tensor;

  PlaneStressDriver::PlaneStressDriver(std::unique_ptr<ConstitutiveModel> model)
      : WrappedModel(std::move(model))
  {
  }

  void PlaneStressDriver::evaluate(const Tensor<2, 3>  &F_in_plane,
                                   const MaterialState &old,
                                   MaterialState       &state,
                                   Tensor<2, 3>        &P,
                                   Tensor<4, 3>        *tangent) const
  {
    Tensor<2, 3> F = F_in_plane;
    F[0][2] = F[2][0] = F[1][2] = F[2][1] = 0.;
    F[2][2] = old.deformation_gradient[2][2];

    Tensor<4, 3> A;
    const double scale = inner->plasticity().elasticity(old.temperature).youngs_modulus;
    for (unsigned int it = 0;; ++it)
    {
      inner->evaluate(F, old, state, P, &A);
      if (std::abs(P[2][2]) <= 1e-12 * scale)
        break;
      if (it == 30 || !(A[2][2][2][2] > 0.))
      {
        std::ostringstream msg;
        msg << "plane stress: no out-of-plane stretch with zero normal stress found "
            << "(P_zz = " << P[2][2] << ")";
        throw RunFailure(msg.str());
      }
      F[2][2] -= P[2][2] / A[2][2][2][2];
    }

    if (tangent != nullptr)
    {
      const double a_zz = A[2][2][2][2];
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int l = 0; l < 3; ++l)
              (*tangent)[i][j][k][l] = A[i][j][k][l] - A[i][j][2][2] * A[2][2][k][l] / a_zz;
    }
  }

  void PlaneStressDriver::rebase(MaterialState &state, const Tensor<2, 3> &F_in_plane) const
  {
    Tensor<2, 3> F = F_in_plane;
    F[0][2] = F[2][0] = F[1][2] = F[2][1] = 0.;
    F[2][2] = state.deformation_gradient[2][2];
    inner->rebase(state, F);
  }
} // namespace ausroll::material
