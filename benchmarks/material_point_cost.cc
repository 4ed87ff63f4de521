/**
 * @file material_point_cost.cc
 * Cost of one material-point evaluation (stress + consistent tangent, and stress only) of every
 * `Model/Kinematics`, in an elastic and in a plastic step after a plastic history. These run at
 * every quadrature point in every Newton iteration. A second table gives the cost of the tensor
 * functions of the finite-strain model (tensor_functions.h: spectral decomposition, logarithm,
 * exponential, with and without derivative, polar decomposition; and deal.II's eigenvectors() with
 * its three methods, the alternatives to the closed form) on 64 symmetric positive definite
 * tensors (a third of them with two equal eigenvalues), general and with x_3 principal (plane).
 *
 * A third table gives the cost of the metallurgy: every kinematics wrapped with the thermal strain
 * and the phases (PhaseTransformationModel) while martensite forms at 60 C, without TRIP (the
 * default), with TRIP (`Phases/TRIP coefficient`) and with TRIP and the mixture rule of the yield
 * stress, against the isothermal model.
 *
 * Usage: material_point_cost [n_evaluations = 100000]
 *
 * Times are CPU times of the process (clock_gettime(CLOCK_PROCESS_CPUTIME_ID)), not wall times,
 * so that other work on a shared machine inflates them less.
 *
 * The program also counts the calls of the global operator new during the timed loops (the
 * evaluation must not allocate; the count is printed and should be 0).
 */
#include <ausroll/material/constitutive_model.h>
#include <ausroll/material/material_point.h>
#include <ausroll/material/phase_transformation_model.h>
#include <ausroll/material/tensor_functions.h>
#include <ausroll/material/thermal_expansion_model.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <new>
#include <random>
#include <vector>

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

  /** CPU time of the process in nanoseconds. */
  double cpu_nanoseconds()
  {
    timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return 1e9 * t.tv_sec + t.tv_nsec;
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
      const double start = cpu_nanoseconds();
      for (int i = 0; i < n; ++i)
      {
        Tensor<2, 3> Fi = F;
        Fi[0][0] += 1e-12 * (i % 7); // defeat hoisting, keep the state
        model.evaluate(Fi, old, trial, P, with_tangent ? &A : nullptr);
        sink += P[0][0] + (with_tangent ? A[0][1][1][0] : 0.);
      }
      best = std::min(best, (cpu_nanoseconds() - start) / n);
    }
    if (sink == 0.12345)
      std::printf(" ");
    return best;
  }

  /**
   * 64 symmetric positive definite tensors: elastic left Cauchy-Green tensors I + 2 eps (|eps|
   * about 1e-3, as b_e in a forming run), total ones F F^T (stretches up to about 1.5), and in
   * every third one two equal eigenvalues (uniaxial states). With @p plane, x_3 is a principal
   * direction (the tensors of a plane-strain or axisymmetric model).
   */
  std::vector<dealii::SymmetricTensor<2, 3>> tensor_samples(const bool plane)
  {
    std::mt19937                               rng(3);
    std::uniform_real_distribution<double>     u(-1., 1.);
    std::vector<dealii::SymmetricTensor<2, 3>> samples;
    for (int s = 0; s < 64; ++s)
    {
      const double scale = s % 2 == 0 ? 1e-3 : 0.3;
      Tensor<2, 3> G;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          G[i][j]
              = (i == j ? 1. : 0.) + (plane && i != j && (i == 2 || j == 2) ? 0. : scale * u(rng));
      if (s % 3 == 0)
      {
        // uniaxial stretch along a random unit axis a: G = I + c a (x) a (two equal eigenvalues)
        Tensor<1, 3> a;
        for (unsigned int i = 0; i < (plane ? 2u : 3u); ++i)
          a[i] = u(rng);
        a /= a.norm();
        G = Tensor<2, 3>(dealii::unit_symmetric_tensor<3>()) + scale * dealii::outer_product(a, a);
      }
      samples.push_back(dealii::symmetrize(G * dealii::transpose(G)));
    }
    return samples;
  }

  /** Nanoseconds per call of @p f on the samples (the best of 3 repetitions). */
  template <typename Function>
  double time_tensor_function(const std::vector<dealii::SymmetricTensor<2, 3>> &samples,
                              const int                                         n,
                              const Function                                   &f)
  {
    double sink = 0., best = 1e300;
    for (int repetition = 0; repetition < 3; ++repetition)
    {
      const double start = cpu_nanoseconds();
      for (int i = 0; i < n; ++i)
        sink += f(samples[i % samples.size()]);
      best = std::min(best, (cpu_nanoseconds() - start) / n);
    }
    if (sink == 0.12345)
      std::printf(" ");
    return best;
  }

  void time_tensor_functions(const int n)
  {
    using dealii::SymmetricTensor;
    const auto samples_3d = tensor_samples(false), samples_plane = tensor_samples(true);
    std::printf(
        "\nCPU ns per call of the tensor functions (best of 3 x %d calls, 64 tensors; plane: "
        "x_3 principal)\n",
        n);
    std::printf("%-32s %10s %10s\n", "function", "3D", "plane");
    const auto row = [&](const char *name, const auto &f)
    {
      std::printf("%-32s %10.0f %10.0f\n",
                  name,
                  time_tensor_function(samples_3d, n, f),
                  time_tensor_function(samples_plane, n, f));
    };
    row("spectral_decomposition",
        [](const SymmetricTensor<2, 3> &X) { return spectral_decomposition(X).vectors[0][0]; });
    // deal.II's eigensolvers on the same tensors (the alternatives to the closed form)
    row("dealii::eigenvectors, QL",
        [](const SymmetricTensor<2, 3> &X)
        {
          return dealii::eigenvectors(
                     X, dealii::SymmetricTensorEigenvectorMethod::ql_implicit_shifts)[0]
              .second[0];
        });
    row("dealii::eigenvectors, hybrid",
        [](const SymmetricTensor<2, 3> &X) {
          return dealii::eigenvectors(X, dealii::SymmetricTensorEigenvectorMethod::hybrid)[0]
              .second[0];
        });
    row("dealii::eigenvectors, Jacobi",
        [](const SymmetricTensor<2, 3> &X) {
          return dealii::eigenvectors(X, dealii::SymmetricTensorEigenvectorMethod::jacobi)[0]
              .second[0];
        });
    row("logarithm", [](const SymmetricTensor<2, 3> &X) { return logarithm(X)[0][1]; });
    row("logarithm + derivative",
        [](const SymmetricTensor<2, 3> &X)
        {
          SymmetricTensor<4, 3> D;
          return logarithm(X, &D)[0][1] + D[0][1][0][1];
        });
    row("exponential", [](const SymmetricTensor<2, 3> &X) { return exponential(X)[0][1]; });
    row("exponential + derivative",
        [](const SymmetricTensor<2, 3> &X)
        {
          SymmetricTensor<4, 3> D;
          return exponential(X, &D)[0][1] + D[0][1][0][1];
        });
    row("polar_decomposition",
        [](const SymmetricTensor<2, 3> &X)
        {
          Tensor<2, 3>          R;
          SymmetricTensor<2, 3> U;
          Tensor<2, 3>          F = X;
          F[0][1] += 0.1;
          polar_decomposition(F, R, U);
          return R[0][1] + U[0][0];
        });
  }

  /** The metallurgy table (see the file comment). */
  void time_phases(const int n, const MaterialParameters &steel)
  {
    ThermalExpansionParameters thermal;
    thermal.expansion = PropertyTable(1.2e-5);
    PhaseParameters off;
    off.enabled = true;
    PhaseParameters trip = off;
    trip.mechanics.trip_coefficient = 5e-5;
    PhaseParameters mixture = trip;
    mixture.mechanics.martensite_yield_stress = PropertyTable(1400.);
    mixture.mechanics.martensite_yield_given = true;
    std::printf("\nCPU ns per evaluation with stress and tangent, martensite forming at 60 C "
                "(0.8 wt%% C; best of 3 x %d)\n",
                n);
    std::printf("%-20s %-8s %14s %14s %14s %14s\n",
                "kinematics",
                "step",
                "isothermal",
                "phases",
                "phases+TRIP",
                "TRIP+mixture");
    for (const KinematicsType kin : {KinematicsType::small_strain,
                                     KinematicsType::total_lagrangian,
                                     KinematicsType::updated_lagrangian,
                                     KinematicsType::finite_strain})
    {
      const auto    isothermal = create_constitutive_model(kin, steel, false);
      const auto    phases = create_constitutive_model(kin, steel, false, &thermal, &off);
      const auto    with_trip = create_constitutive_model(kin, steel, false, &thermal, &trip);
      const auto    with_mixture = create_constitutive_model(kin, steel, false, &thermal, &mixture);
      MaterialState old;
      old.temperature = 60.;
      old.carbon = 0.8;
      old.martensite = 0.2;
      const double       small = kin == KinematicsType::small_strain ? 0. : 1.;
      const Tensor<2, 3> F_plastic = deformation(small * 0.05, 1.06, 0.97, 0.02);
      const Tensor<2, 3> F_elastic = deformation(small * 0.05, 1.0004, 0.9998, 0.0001);
      for (const auto &[name, F] :
           {std::make_pair("elastic", F_elastic), std::make_pair("plastic", F_plastic)})
        std::printf("%-20s %-8s %14.0f %14.0f %14.0f %14.0f\n",
                    to_string(kin).c_str(),
                    name,
                    time_evaluations(*isothermal, old, F, true, n),
                    time_evaluations(*phases, old, F, true, n),
                    time_evaluations(*with_trip, old, F, true, n),
                    time_evaluations(*with_mixture, old, F, true, n));
    }
  }
} // namespace

int main(int argc, char **argv)
{
  const int n = argc > 1 ? std::atoi(argv[1]) : 100000;

  MaterialParameters steel;
  steel.hardening_modulus = 1000.;
  MaterialParameters steel_kinematic = steel;
  steel_kinematic.kinematic_hardening_modulus = 5000.;

  std::printf("CPU ns per evaluation (best of 3 x %d evaluations)\n", n);
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
  time_tensor_functions(n);
  time_phases(n, steel);
  return 0;
}
