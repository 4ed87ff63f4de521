/**
 * @file material_point_cost.cc
 * Cost of one material-point evaluation (stress + consistent tangent, and stress only) of every
 * `Model/Kinematics`, in an elastic and in a plastic step after a plastic history. These run at
 * every quadrature point in every Newton iteration.
 *
 * Usage: material_point_cost [n_evaluations = 100000]
 */
#include <ausroll/material/constitutive_model.h>
#include <ausroll/material/material_point.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

using namespace ausroll::material;
using dealii::Tensor;

namespace
{
  Tensor<2, 3> deformation(const double angle, const double a, const double b, const double s)
  {
    Tensor<2, 3> R, U;
    R[0][0] = R[1][1] = std::cos(angle);
    R[0][1] = -std::sin(angle);
    R[1][0] = std::sin(angle);
    R[2][2] = 1.;
    U[0][0] = a;
    U[1][1] = b;
    U[2][2] = 1.;
    U[0][1] = s;
    return R * U;
  }

  /** Nanoseconds per evaluation. */
  double time_evaluations(const ConstitutiveModel &model,
                          const MaterialState     &old,
                          const Tensor<2, 3>      &F,
                          const bool               with_tangent,
                          const int                n)
  {
    MaterialState trial;
    Tensor<2, 3>  P;
    Tensor<4, 3>  A;
    double        sink = 0.;
    const auto    start = std::chrono::steady_clock::now();
    for (int i = 0; i < n; ++i)
    {
      Tensor<2, 3> Fi = F;
      Fi[0][0] += 1e-12 * (i % 7); // defeat hoisting, keep the state
      model.evaluate(Fi, old, trial, P, with_tangent ? &A : nullptr);
      sink += P[0][0] + (with_tangent ? A[0][1][1][0] : 0.);
    }
    const auto stop = std::chrono::steady_clock::now();
    if (sink == 0.12345)
      std::printf(" ");
    return std::chrono::duration<double, std::nano>(stop - start).count() / n;
  }
} // namespace

int main(int argc, char **argv)
{
  const int n = argc > 1 ? std::atoi(argv[1]) : 100000;

  MaterialParameters steel;
  steel.hardening_modulus = 1000.;
  MaterialParameters steel_kinematic = steel;
  steel_kinematic.kinematic_hardening_modulus = 5000.;

  std::printf("ns per evaluation (%d evaluations each)\n", n);
  std::printf("%-20s %-6s %14s %14s %14s %14s\n",
              "kinematics",
              "H_k",
              "elastic+A",
              "plastic+A",
              "elastic P only",
              "plastic P only");
  for (const KinematicsType kin : {KinematicsType::small_strain,
                                   KinematicsType::total_lagrangian,
                                   KinematicsType::updated_lagrangian,
                                   KinematicsType::finite_strain})
    for (const MaterialParameters *mat : {&steel, &steel_kinematic})
    {
      const auto    model = create_constitutive_model(kin, *mat, false);
      MaterialPoint point;
      Tensor<2, 3>  P;
      const double  small = kin == KinematicsType::small_strain ? 0. : 1.;
      for (int s = 1; s <= 10; ++s)
      {
        model->evaluate(deformation(small * 0.05 * s, 1. + 0.01 * s, 1. - 0.005 * s, 0.003 * s),
                        point.committed,
                        point.trial,
                        P,
                        nullptr);
        point.commit();
      }
      const Tensor<2, 3> F_n = point.committed.deformation_gradient;
      const Tensor<2, 3> F_plastic = deformation(small * 0.55, 1.11, 0.944, 0.033); // loading
      const Tensor<2, 3> F_elastic
          = F_n - 0.0005 * (F_n - deformation(small * 0.5, 1., 1., 0.)); // unloading
      std::printf("%-20s %-6s %14.0f %14.0f %14.0f %14.0f\n",
                  to_string(kin).c_str(),
                  mat->kinematic_hardening_modulus > 0. ? "> 0" : "0",
                  time_evaluations(*model, point.committed, F_elastic, true, n),
                  time_evaluations(*model, point.committed, F_plastic, true, n),
                  time_evaluations(*model, point.committed, F_elastic, false, n),
                  time_evaluations(*model, point.committed, F_plastic, false, n));
    }
  return 0;
}
