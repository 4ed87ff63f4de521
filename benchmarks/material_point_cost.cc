/**
 * @file material_point_cost.cc
 * Cost of one material-point evaluation (stress + consistent tangent, and stress only) of every
 * `Model/Kinematics`, in an elastic and in a plastic step after a plastic history. These run at
 * every quadrature point in every Newton iteration.
 *
 * Usage: material_point_cost [n_evaluations = 100000]
 *
 * The program also counts the calls of the global operator new during the timed loops (the
 * evaluation must not allocate; the count is printed and should be 0).
 */
#include <ausroll/material/constitutive_model.h>
#include <ausroll/material/material_point.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>

namespace
{
  std::atomic<long> n_allocations{0}; ///< calls of the global operator new
} // namespace

void *operator new(std::size_t size)
{
  ++n_allocations;
  if (void *p = std::malloc(size == 0 ? 1 : size))
    return p;
  throw std::bad_alloc();
}

void operator delete(void *p) noexcept
{
  std::free(p);
}

void operator delete(void *p, std::size_t) noexcept
{
  std::free(p);
}

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

  /** Nanoseconds per evaluation (the best of 3 repetitions: the machine may be shared). */
  double time_evaluations(const ConstitutiveModel &model,
                          const MaterialState     &old,
                          const Tensor<2, 3>      &F,
                          const bool               with_tangent,
                          const int                n)
  {
    MaterialState trial;
    Tensor<2, 3>  P;
    Tensor<4, 3>  A;
    double        sink = 0., best = 1e300;
    for (int repetition = 0; repetition < 3; ++repetition)
    {
      const auto start = std::chrono::steady_clock::now();
      for (int i = 0; i < n; ++i)
      {
        Tensor<2, 3> Fi = F;
        Fi[0][0] += 1e-12 * (i % 7); // defeat hoisting, keep the state
        model.evaluate(Fi, old, trial, P, with_tangent ? &A : nullptr);
        sink += P[0][0] + (with_tangent ? A[0][1][1][0] : 0.);
      }
      const auto stop = std::chrono::steady_clock::now();
      best = std::min(best, std::chrono::duration<double, std::nano>(stop - start).count() / n);
    }
    if (sink == 0.12345)
      std::printf(" ");
    return best;
  }
} // namespace

int main(int argc, char **argv)
{
  const int n = argc > 1 ? std::atoi(argv[1]) : 100000;

  MaterialParameters steel;
  steel.hardening_modulus = 1000.;
  MaterialParameters steel_kinematic = steel;
  steel_kinematic.kinematic_hardening_modulus = 5000.;

  std::printf("ns per evaluation (best of 3 x %d evaluations)\n", n);
  std::printf("%-20s %-6s %14s %14s %14s %14s %12s\n",
              "kinematics",
              "H_k",
              "elastic+A",
              "plastic+A",
              "elastic P only",
              "plastic P only",
              "allocations");
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
      const long   allocations_before = n_allocations;
      const double t_elastic_tangent
          = time_evaluations(*model, point.committed, F_elastic, true, n);
      const double t_plastic_tangent
          = time_evaluations(*model, point.committed, F_plastic, true, n);
      const double t_elastic = time_evaluations(*model, point.committed, F_elastic, false, n);
      const double t_plastic = time_evaluations(*model, point.committed, F_plastic, false, n);
      const long   allocations = n_allocations - allocations_before;
      std::printf("%-20s %-6s %14.0f %14.0f %14.0f %14.0f %12ld\n",
                  to_string(kin).c_str(),
                  mat->kinematic_hardening_modulus.value(0.) > 0. ? "> 0" : "0",
                  t_elastic_tangent,
                  t_plastic_tangent,
                  t_elastic,
                  t_plastic,
                  allocations);
    }
  return 0;
}
