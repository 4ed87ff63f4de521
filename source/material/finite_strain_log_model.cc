#include <ausroll/material/finite_strain_log_model.h>
#include <ausroll/material/tensor_functions.h>

#include <array>
#include <cmath>

namespace ausroll::material
{
  using dealii::SymmetricTensor;
  using dealii::Tensor;

  namespace
  {
    /** The raw index of entry (i, j) of a SymmetricTensor<2, 3>. */
    constexpr unsigned int raw_index[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};

    /**
     * Off-diagonal entries of eps_e in the eigenbasis of b^trial up to this size (eps_e is a
     * logarithmic strain, dimensionless) are taken as round-off: dropping them changes b_e =
     * exp(2 eps_e) by a relative 4e-15, about 20 machine epsilons.
     */
    constexpr double coaxial_tolerance = 2e-15;

    /** Raw entries of a SymmetricTensor<2, 3>: xx, yy, zz, xy (in-plane problem) and xz, yz. */
    constexpr unsigned int in_plane_entries[4] = {0, 1, 2, 3};
    constexpr unsigned int anti_plane_entries[2] = {4, 5};

    /** True if the xz, yz, zx and zy entries of @p T are zero (a plane-strain or axisymmetric F).
     */
    bool is_planar(const Tensor<2, 3> &T)
    {
      return T[0][2] == 0. && T[1][2] == 0. && T[2][0] == 0. && T[2][1] == 0.;
    }

    bool is_planar(const SymmetricTensor<2, 3> &S)
    {
      return S[0][2] == 0. && S[1][2] == 0.;
    }

    /**
     * True if the raw 6 x 6 matrix of @p D couples neither the in-plane entries (xx, yy, zz, xy)
     * to the anti-plane shears (xz, yz) nor these to those: the return map's tangent of a planar
     * stress state for an isotropic or orthotropic (z-symmetric) criterion.
     */
    bool is_decoupled(const SymmetricTensor<4, 3> &D)
    {
      for (const unsigned int p : in_plane_entries)
        for (const unsigned int q : anti_plane_entries)
          if (D.access_raw_entry(6 * p + q) != 0. || D.access_raw_entry(6 * q + p) != 0.)
            return false;
      return true;
    }

    /**
     * The directions (k, L) of dF, and the entries (i, J) of dP, of the two uncoupled problems of
     * a planar point: the in-plane one (F_xx, F_xy, F_yx, F_yy, F_zz) and the anti-plane shear
     * (F_xz, F_yz, F_zx, F_zy).
     */
    constexpr unsigned int in_plane_pairs[5][2] = {{0, 0}, {0, 1}, {1, 0}, {1, 1}, {2, 2}};
    constexpr unsigned int anti_plane_pairs[4][2] = {{0, 2}, {1, 2}, {2, 0}, {2, 1}};

    /**
     * The range [first, last) of the indices n for which a planar tensor G has G_nL != 0 (or
     * G_Ln != 0): {0, 1} for an in-plane L, {2} for L = 2.
     */
    inline unsigned int range_begin(const unsigned int L)
    {
      return L < 2 ? 0 : 2;
    }

    inline unsigned int range_end(const unsigned int L)
    {
      return L < 2 ? 2 : 3;
    }
  } // namespace

  FiniteStrainLogModel::FiniteStrainLogModel(std::unique_ptr<PlasticityModel> plasticity)
      : stress_return(std::move(plasticity))
  {
  }

  void FiniteStrainLogModel::evaluate(const Tensor<2, 3>  &F,
                                      const MaterialState &old,
                                      MaterialState       &state,
                                      Tensor<2, 3>        &P,
                                      Tensor<4, 3>        *tangent) const
  {
    const Tensor<2, 3> F_n_inv = dealii::invert(old.deformation_gradient);

    // elastic trial state: b_e^trial = F C_p,n^-1 F^T, C_p,n^-1 = F_n^-1 b_e,n F_n^-T
    const SymmetricTensor<2, 3> Cp_inv = rotate(F_n_inv, old.elastic_left_cauchy_green);
    const SymmetricTensor<2, 3> b_trial = rotate(F, Cp_inv);
    const SpectralDecomposition spectral = spectral_decomposition(b_trial);
    SymmetricTensor<4, 3>       dlog_db;
    const SymmetricTensor<2, 3> eps_trial
        = 0.5 * logarithm(spectral, tangent != nullptr ? &dlog_db : nullptr);
    const SymmetricTensor<2, 3> tau_trial
        = stress_return->elasticity(old.temperature).stress(eps_trial);

    // back stress carried along with the rotation of the increment f = F F_n^-1 = dR dU
    const bool            rotate_back_stress = old.back_stress.norm() > 0.;
    Tensor<2, 3>          dR;
    SymmetricTensor<2, 3> dU;
    SymmetricTensor<2, 3> back_trial = old.back_stress;
    if (rotate_back_stress)
    {
      polar_decomposition(F * F_n_inv, dR, dU);
      back_trial = rotate(dR, old.back_stress);
    }

    const ReturnMappingResult    r = stress_return->return_map(tau_trial,
                                                            back_trial,
                                                            old.equivalent_plastic_strain,
                                                            old.temperature,
                                                            PhaseStep::of(old, state));
    const SymmetricTensor<2, 3> &tau = r.stress;

    const double       J = dealii::determinant(F);
    const Tensor<2, 3> F_inv = dealii::invert(F);
    P = Tensor<2, 3>(tau) * dealii::transpose(F_inv);

    state.stress = tau / J;
    state.back_stress = r.back_stress;
    state.equivalent_plastic_strain = old.equivalent_plastic_strain + r.eq_plastic_strain_increment;
    state.deformation_gradient = F;
    if (r.plastic || r.trip)
    {
      // exponential map: b_e = exp(2 eps_e) with eps_e = eps_e^trial - Delta eps_p; output
      // ln(C_p) / 2 with C_p = F^T b_e^-1 F
      const SymmetricTensor<2, 3> eps_e = eps_trial - r.plastic_strain_increment;
      std::array<double, 3>       e;
      SymmetricTensor<2, 3>       b_e_inv;
      if (diagonal_in_eigenbasis(spectral, eps_e, coaxial_tolerance, e))
      {
        // eps_e shares the eigenvectors of b^trial (isotropic elasticity and a return along
        // dev tau^trial, e.g. von Mises without back stress): no second decomposition
        std::array<double, 3> b, b_inv;
        for (unsigned int a = 0; a < 3; ++a)
        {
          b[a] = std::exp(2. * e[a]);
          b_inv[a] = 1. / b[a];
        }
        state.elastic_left_cauchy_green = spectral_sum(spectral, b);
        b_e_inv = spectral_sum(spectral, b_inv);
      }
      else
      {
        state.elastic_left_cauchy_green = exponential(2. * eps_e);
        b_e_inv = dealii::invert(state.elastic_left_cauchy_green);
      }
      state.plastic_strain = 0.5 * logarithm(rotate(dealii::transpose(F), b_e_inv));
    }
    else
    {
      state.elastic_left_cauchy_green = b_trial;
      state.plastic_strain = old.plastic_strain;
    }

    if (tangent == nullptr)
      return;

    // d tau / d b^trial = D : (d ln b / d b) / 2 =: K / 2; with d b^trial = 2 sym(dF C_p,n^-1 F^T)
    // the direction dF = e_k (x) e_L gives d tau_ij = sum_n K_ijkn (F C_p,n^-1)_nL (minor
    // symmetry of K), evaluated on the raw 6 x 6 storage of K.
    const Tensor<2, 3> FG = F * Tensor<2, 3>(Cp_inv);
    double K[6][6]; // r.tangent : dlog_db on the raw entries (off-diagonal pairs count twice)

    // A planar point (F, F_n and b_e,n without xz, yz entries: plane strain, axisymmetry) without
    // a back stress to rotate: b^trial, FG and F^-1 are planar, and so are (checked) tau and P;
    // d ln b / d b and (checked) the return map's tangent do not couple the in-plane entries with
    // the anti-plane shears, so K and dP/dF split into the in-plane problem and the anti-plane
    // shear. Only their terms are summed, in the order of the general loops below, and the terms
    // skipped are exact zeros (products with zero entries of FG, F^-1, dlog_db or r.tangent): the
    // result is the general one to the bit, at about a third of the operations.
    if (!rotate_back_stress && is_planar(F) && is_planar(Cp_inv) && is_planar(tau)
        && is_decoupled(r.tangent))
    {
      const auto ret = [&](const unsigned int p, const unsigned int m)
      { return r.tangent.access_raw_entry(6 * p + m); };
      const auto dlog = [&](const unsigned int m, const unsigned int q)
      { return dlog_db.access_raw_entry(6 * m + q); };
      for (unsigned int p = 0; p < 6; ++p)
        for (unsigned int q = 0; q < 6; ++q)
          K[p][q] = 0.;
      for (const unsigned int p : in_plane_entries)
        for (const unsigned int q : in_plane_entries)
        {
          const double diagonal
              = ret(p, 0) * dlog(0, q) + ret(p, 1) * dlog(1, q) + ret(p, 2) * dlog(2, q);
          K[p][q] = 2. * (ret(p, 3) * dlog(3, q)) + diagonal;
        }
      for (const unsigned int p : anti_plane_entries)
        for (const unsigned int q : anti_plane_entries)
          K[p][q] = 2. * (ret(p, 4) * dlog(4, q) + ret(p, 5) * dlog(5, q));

      *tangent = Tensor<4, 3>();
      const auto directions = [&](const auto &pairs)
      {
        for (const auto &kL : pairs)
        {
          const unsigned int k = kL[0], L = kL[1];
          double             d_tau[6]; // the entries of the problem of (k, L)
          for (unsigned int p = 0; p < 6; ++p)
          {
            double s = 0.;
            for (unsigned int n = range_begin(L); n < range_end(L); ++n)
              s += K[p][raw_index[k][n]] * FG[n][L];
            d_tau[p] = s;
          }
          for (const auto &iJ : pairs)
          {
            const unsigned int i = iJ[0], Jj = iJ[1];
            double             s = 0.;
            for (unsigned int j = range_begin(Jj); j < range_end(Jj); ++j)
              s += d_tau[raw_index[i][j]] * F_inv[Jj][j];
            (*tangent)[i][Jj][k][L] = s - P[i][L] * F_inv[Jj][k];
          }
        }
      };
      directions(in_plane_pairs);
      directions(anti_plane_pairs);
      return;
    }

    for (unsigned int p = 0; p < 6; ++p)
      for (unsigned int q = 0; q < 6; ++q)
      {
        double off = 0., diagonal = 0.;
        for (unsigned int m = 0; m < 3; ++m)
          diagonal += r.tangent.access_raw_entry(6 * p + m) * dlog_db.access_raw_entry(6 * m + q);
        for (unsigned int m = 3; m < 6; ++m)
          off += r.tangent.access_raw_entry(6 * p + m) * dlog_db.access_raw_entry(6 * m + q);
        K[p][q] = 2. * off + diagonal;
      }

    // Back-stress rotation: d(dR) = dR Omega with (tr dU I - dU) omega = axial(dR^T df - df^T dR)
    // (polar decomposition f = dR dU). With df = e_k (x) g_L (g_L = row L of F_n^-1) the right side
    // is g_L x r_k (r_k = row k of dR), and d beta^trial = W beta^trial - beta^trial W with the
    // spatial spin W = dR Omega dR^T, whose axial vector is dR omega.
    Tensor<2, 3>          spin_map; // dR (tr dU I - dU)^-1
    Tensor<2, 3>          back_trial_full;
    SymmetricTensor<4, 3> back_sensitivity;
    if (rotate_back_stress)
    {
      Tensor<2, 3> trU_minus_U = -Tensor<2, 3>(dU);
      for (unsigned int i = 0; i < 3; ++i)
        trU_minus_U[i][i] += dealii::trace(dU);
      spin_map = dR * dealii::invert(trU_minus_U);
      back_trial_full = back_trial;
      back_sensitivity = stress_return->back_stress_sensitivity(r, old.temperature);
    }

    for (unsigned int k = 0; k < 3; ++k)
    {
      double K_k[6][3]; // K_(p)(kn)
      for (unsigned int p = 0; p < 6; ++p)
        for (unsigned int n = 0; n < 3; ++n)
          K_k[p][n] = K[p][raw_index[k][n]];
      for (unsigned int L = 0; L < 3; ++L)
      {
        SymmetricTensor<2, 3> d_tau;
        for (unsigned int p = 0; p < 6; ++p)
          d_tau.access_raw_entry(p)
              = K_k[p][0] * FG[0][L] + K_k[p][1] * FG[1][L] + K_k[p][2] * FG[2][L];

        if (rotate_back_stress)
        {
          const Tensor<1, 3>    omega = spin_map * dealii::cross_product_3d(F_n_inv[L], dR[k]);
          const Tensor<2, 3>    W_beta = skew_from_axial(omega) * back_trial_full;
          SymmetricTensor<2, 3> d_back;
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int j = i; j < 3; ++j)
              d_back[i][j] = W_beta[i][j] + W_beta[j][i];
          d_tau += back_sensitivity * d_back;
        }

        // dP = d tau F^-T - tau F^-T dF^T F^-T
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int Jj = 0; Jj < 3; ++Jj)
          {
            double s = 0.;
            for (unsigned int j = 0; j < 3; ++j)
              s += d_tau.access_raw_entry(raw_index[i][j]) * F_inv[Jj][j];
            (*tangent)[i][Jj][k][L] = s - P[i][L] * F_inv[Jj][k];
          }
      }
    }
  }

  double FiniteStrainLogModel::yield_function(const MaterialState &state) const
  {
    const double J = dealii::determinant(state.deformation_gradient);
    return stress_return->yield_function(J * state.stress,
                                         state.back_stress,
                                         state.equivalent_plastic_strain,
                                         state.temperature,
                                         PhaseStep::at(state));
  }

  void FiniteStrainLogModel::make_admissible(MaterialState &state) const
  {
    const double J = dealii::determinant(state.deformation_gradient);
    state.stress = stress_return->project_onto_yield_surface(J * state.stress,
                                                             state.back_stress,
                                                             state.equivalent_plastic_strain,
                                                             state.temperature,
                                                             PhaseStep::at(state))
                   / J;
  }
} // namespace ausroll::material
