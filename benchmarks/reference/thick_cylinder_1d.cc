// Independent reference solution for the plane-strain thick-walled cylinder under internal
// pressure (Owen & Hinton benchmark), solved as a 1D radial boundary value problem.
//
// Problem (axisymmetric, plane strain, small strain):
//   a <= r <= b, unknown radial displacement u(r),
//   eps_r = du/dr, eps_theta = u/r, eps_z = 0, no shear (principal axes r, theta, z are fixed),
//   equilibrium  d(sigma_r)/dr + (sigma_r - sigma_theta)/r = 0,
//   boundary conditions sigma_r(a) = -p, sigma_r(b) = 0.
// Material: isotropic linear elasticity (E, nu) + von Mises plasticity with associative flow and
// isotropic hardening sigma_y(ep) = sy * (1 + ep/e0)^n + H * ep (default: H = 0, n = 0, i.e.
// perfect plasticity). The full 3D stress state (sigma_r, sigma_theta, sigma_z) is computed: the
// plastic strain has r, theta and z components, so sigma_z evolves with the plastic flow.
//
// Discretisation: 1D Lagrange finite elements (quadratic by default) on a uniform mesh of [a, b],
// weak form  int_a^b (sigma_r d(du)/dr + sigma_theta du/r) r dr = p a du(a)  (per radian),
// 3-point Gauss quadrature, backward-Euler radial return at each quadrature point, and Newton's
// method with the consistent (algorithmic) tangent. The pressure is applied in small increments.
//
// The program is deliberately independent of the ausroll code (standard library only) so that
// it can serve as a reference for the 2D/3D scene checks. Build:
//   g++ -O2 -std=c++17 thick_cylinder_1d.cc -o thick_cylinder_1d
// Run `thick_cylinder_1d --help` for the options.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
  // ------------------------------------------------------------------------------------ options

  /// Command-line options; defaults reproduce the Owen & Hinton benchmark.
  struct Options
  {
    double      a = 100.0;            // inner radius [mm]
    double      b = 200.0;            // outer radius [mm]
    double      E = 210000.0;         // Young's modulus [MPa]
    double      nu = 0.3;             // Poisson's ratio
    double      sy = 240.0;           // initial yield stress [MPa]
    double      H = 0.0;              // linear isotropic hardening modulus [MPa]
    double      power_n = 0.0;        // power-law hardening exponent n (0: off)
    double      power_e0 = 0.002;     // power-law reference strain e0
    double      pmax_fraction = 0.99; // final pressure as a fraction of p_c
    double      pmax = -1.0;          // final pressure [MPa] (overrides the fraction if > 0)
    int         steps = 200;          // pressure steps (load CSV rows, besides inserted levels)
    int         substeps = 1;         // internal increments per pressure step
    double      grading = 1.0;        // pressure levels p_k = pmax (1 - (1 - k/steps)^grading)
    int         elements = 2000;      // number of finite elements
    int         degree = 2;           // polynomial degree (1 or 2)
    double      profile_p = 180.0;    // pressure at which the radial profile is written [MPa]
    int         profile_points = 201; // number of equally spaced radii in the profile CSV
    std::string out_prefix = "thick_cylinder";
    bool        checks = true; // run the cross-checks (b) first yield, (c) nu -> 0.5
  };

  void print_usage()
  {
    std::printf(
        "Usage: thick_cylinder_1d [options]\n"
        "  --a R                inner radius (100)\n"
        "  --b R                outer radius (200)\n"
        "  --E E                Young's modulus (210000)\n"
        "  --nu NU              Poisson's ratio (0.3)\n"
        "  --sy S               initial yield stress (240)\n"
        "  --H H                linear isotropic hardening modulus (0)\n"
        "  --power-n N          power-law hardening sy*(1+ep/e0)^N, 0 = off (0)\n"
        "  --power-e0 E0        power-law reference strain e0 (0.002)\n"
        "  --pmax-fraction F    final pressure / p_c, p_c = 2/sqrt(3)*sy*ln(b/a) (0.99)\n"
        "  --pmax P             final pressure (overrides --pmax-fraction)\n"
        "  --steps N            pressure steps (200); the load CSV has a row for p=0, each\n"
        "                       step, and the levels inserted exactly: 50, first yield p_y,\n"
        "                       profile pressure\n"
        "  --substeps M         internal load increments per pressure step (1)\n"
        "  --step-grading G     pressure levels pmax*(1-(1-k/steps)^G): G=1 uniform, G>1\n"
        "                       refines towards pmax where the curve bends (1)\n"
        "  --elements N         number of elements (2000)\n"
        "  --degree D           element degree, 1 or 2 (2)\n"
        "  --profile-pressure P pressure of the radial profile, hit exactly (180)\n"
        "  --profile-points N   radii in the profile CSV, equally spaced in [a,b] (201)\n"
        "  --out-prefix PATH    output prefix: PATH_load.csv, PATH_profile.csv (thick_cylinder)\n"
        "  --no-checks          skip the first-yield and nu=0.4999 (Hill) cross-checks\n");
  }

  Options parse_options(int argc, char **argv)
  {
    Options o;
    for (int i = 1; i < argc; ++i)
    {
      const std::string key = argv[i];
      if (key == "--help" || key == "-h")
      {
        print_usage();
        std::exit(0);
      }
      if (key == "--no-checks")
      {
        o.checks = false;
        continue;
      }
      if (i + 1 >= argc)
        throw std::runtime_error("missing value after " + key);
      const std::string val = argv[++i];
      auto              num = [&]()
      {
        std::size_t  pos = 0;
        const double v = std::stod(val, &pos);
        if (pos != val.size())
          throw std::runtime_error("invalid number '" + val + "' for " + key);
        return v;
      };
      auto integer = [&]()
      {
        const double v = num();
        if (v != std::floor(v))
          throw std::runtime_error("expected an integer for " + key);
        return static_cast<int>(v);
      };
      if (key == "--a")
        o.a = num();
      else if (key == "--b")
        o.b = num();
      else if (key == "--E")
        o.E = num();
      else if (key == "--nu")
        o.nu = num();
      else if (key == "--sy")
        o.sy = num();
      else if (key == "--H")
        o.H = num();
      else if (key == "--power-n")
        o.power_n = num();
      else if (key == "--power-e0")
        o.power_e0 = num();
      else if (key == "--pmax-fraction")
        o.pmax_fraction = num();
      else if (key == "--pmax")
        o.pmax = num();
      else if (key == "--steps")
        o.steps = integer();
      else if (key == "--substeps")
        o.substeps = integer();
      else if (key == "--step-grading")
        o.grading = num();
      else if (key == "--elements")
        o.elements = integer();
      else if (key == "--degree")
        o.degree = integer();
      else if (key == "--profile-pressure")
        o.profile_p = num();
      else if (key == "--profile-points")
        o.profile_points = integer();
      else if (key == "--out-prefix")
        o.out_prefix = val;
      else
        throw std::runtime_error("unknown option " + key + " (see --help)");
    }
    if (!(o.a > 0 && o.b > o.a))
      throw std::runtime_error("need 0 < a < b");
    if (!(o.E > 0 && o.nu > -1 && o.nu < 0.5))
      throw std::runtime_error("need E > 0 and -1 < nu < 0.5");
    if (!(o.sy > 0 && o.H >= 0 && o.power_n >= 0 && o.power_e0 > 0))
      throw std::runtime_error("need sy > 0, H >= 0, power-n >= 0, power-e0 > 0");
    if (o.steps < 1 || o.substeps < 1 || o.elements < 1 || o.profile_points < 2)
      throw std::runtime_error("steps, substeps, elements must be >= 1, profile-points >= 2");
    if (!(o.grading >= 1.0))
      throw std::runtime_error("step-grading must be >= 1");
    if (o.degree != 1 && o.degree != 2)
      throw std::runtime_error("degree must be 1 or 2");
    return o;
  }

  // ----------------------------------------------------------------------------------- material

  /// Elastic constants and the hardening law sigma_y(ep) = sy (1 + ep/e0)^n + H ep.
  struct Material
  {
    double E, nu, sy, H, n, e0;
    double G() const { return E / (2.0 * (1.0 + nu)); }
    double K() const { return E / (3.0 * (1.0 - 2.0 * nu)); }
    double yield_stress(const double ep) const
    {
      return sy * (n > 0 ? std::pow(1.0 + ep / e0, n) : 1.0) + H * ep;
    }
    double hardening_slope(const double ep) const
    {
      return (n > 0 ? sy * n / e0 * std::pow(1.0 + ep / e0, n - 1.0) : 0.0) + H;
    }
  };

  /// History of one material point: plastic strain (r, theta, z) and equivalent plastic strain.
  struct PointState
  {
    std::array<double, 3> eps_p{{0, 0, 0}};
    double                ep = 0;
  };

  /// Result of the constitutive update: stresses (r, theta, z) and the consistent tangent
  /// d sigma_i / d eps_j restricted to the normal components (no shear in this problem).
  struct PointResponse
  {
    std::array<double, 3>                sigma{{0, 0, 0}};
    std::array<std::array<double, 3>, 3> D{};
    bool                                 plastic = false;
  };

  /// Backward-Euler radial return for J2 plasticity with isotropic hardening
  /// (e.g. de Souza Neto, Peric & Owen, "Computational Methods for Plasticity", Box 7.3/7.4).
  /// eps is the total strain (eps_r, eps_theta, eps_z); old is the converged history.
  PointResponse radial_return(const Material              &m,
                              const std::array<double, 3> &eps,
                              const PointState            &old,
                              PointState                  &updated)
  {
    const double G = m.G(), K = m.K();
    // elastic trial state
    std::array<double, 3> ee;
    for (int i = 0; i < 3; ++i)
      ee[i] = eps[i] - old.eps_p[i];
    const double          tr = ee[0] + ee[1] + ee[2];
    std::array<double, 3> s_trial;
    for (int i = 0; i < 3; ++i)
      s_trial[i] = 2.0 * G * (ee[i] - tr / 3.0);
    const double s_norm
        = std::sqrt(s_trial[0] * s_trial[0] + s_trial[1] * s_trial[1] + s_trial[2] * s_trial[2]);
    const double q_trial = std::sqrt(1.5) * s_norm; // von Mises equivalent trial stress

    PointResponse res;
    updated = old;
    const double f_trial = q_trial - m.yield_stress(old.ep);
    // relative tolerance so that round-off in the elastic range never triggers plasticity
    if (f_trial <= 1e-12 * m.sy)
    {
      for (int i = 0; i < 3; ++i)
      {
        res.sigma[i] = s_trial[i] + K * tr;
        for (int j = 0; j < 3; ++j)
          res.D[i][j] = K + 2.0 * G * ((i == j ? 1.0 : 0.0) - 1.0 / 3.0);
      }
      return res;
    }

    // plastic: solve q_trial - 3 G dg - sigma_y(ep_old + dg) = 0 for dg >= 0 (Newton, bracketed)
    double dg = f_trial / (3.0 * G + m.hardening_slope(old.ep));
    double lo = 0.0, hi = q_trial / (3.0 * G);
    for (int it = 0; it < 100; ++it)
    {
      const double r = q_trial - 3.0 * G * dg - m.yield_stress(old.ep + dg);
      if (std::abs(r) <= 1e-13 * m.sy)
        break;
      if (r > 0)
        lo = dg;
      else
        hi = dg;
      dg += r / (3.0 * G + m.hardening_slope(old.ep + dg));
      if (!(dg > lo && dg < hi)) // Newton left the bracket: bisect
        dg = 0.5 * (lo + hi);
    }
    const double Hp = m.hardening_slope(old.ep + dg);

    // flow direction N = s_trial/|s_trial|; n = 3/2 s/q = sqrt(3/2) N
    std::array<double, 3> N;
    for (int i = 0; i < 3; ++i)
      N[i] = s_trial[i] / s_norm;
    const double factor = 1.0 - 3.0 * G * dg / q_trial; // s = factor * s_trial
    for (int i = 0; i < 3; ++i)
    {
      updated.eps_p[i] = old.eps_p[i] + dg * std::sqrt(1.5) * N[i];
      res.sigma[i] = factor * s_trial[i] + K * tr;
    }
    updated.ep = old.ep + dg;
    res.plastic = true;

    // consistent tangent (de Souza Neto et al., eq. 7.120):
    // D = K 1x1 + 2G (1 - 3G dg/q_trial) I_dev + 6G^2 (dg/q_trial - 1/(3G+H')) N x N
    const double c_nn = 6.0 * G * G * (dg / q_trial - 1.0 / (3.0 * G + Hp));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        res.D[i][j]
            = K + 2.0 * G * factor * ((i == j ? 1.0 : 0.0) - 1.0 / 3.0) + c_nn * N[i] * N[j];
    return res;
  }

  double von_mises(const std::array<double, 3> &s)
  {
    return std::sqrt(0.5
                     * ((s[0] - s[1]) * (s[0] - s[1]) + (s[1] - s[2]) * (s[1] - s[2])
                        + (s[2] - s[0]) * (s[2] - s[0])));
  }

  // ----------------------------------------------------------------------------- banded solver

  /// Square banded matrix with equal lower/upper half-bandwidth w; solved by Gaussian
  /// elimination without pivoting (the tangent is symmetric positive definite while an elastic
  /// zone remains, i.e. below the collapse load of a perfectly plastic material).
  class BandMatrix
  {
  public:
    BandMatrix(const int n, const int w)
        : n_(n)
        , w_(w)
        , data_(static_cast<std::size_t>(n) * (2 * w + 1), 0.0)
    {
    }
    void    clear() { std::fill(data_.begin(), data_.end(), 0.0); }
    double &operator()(const int i, const int j)
    {
      return data_[std::size_t(i) * (2 * w_ + 1) + (j - i + w_)];
    }

    /// Solves A x = rhs in place (A is overwritten by its LU factors).
    void solve(std::vector<double> &x)
    {
      for (int k = 0; k < n_; ++k)
      {
        const double piv = (*this)(k, k);
        if (!(std::abs(piv) > 0.0) || !std::isfinite(piv))
          throw std::runtime_error("singular tangent matrix");
        for (int i = k + 1; i <= std::min(n_ - 1, k + w_); ++i)
        {
          const double l = (*this)(i, k) / piv;
          if (l == 0.0)
            continue;
          for (int j = k + 1; j <= std::min(n_ - 1, k + w_); ++j)
            (*this)(i, j) -= l * (*this)(k, j);
          x[i] -= l * x[k];
        }
      }
      for (int k = n_ - 1; k >= 0; --k)
      {
        double s = x[k];
        for (int j = k + 1; j <= std::min(n_ - 1, k + w_); ++j)
          s -= (*this)(k, j) * x[j];
        x[k] = s / (*this)(k, k);
      }
    }

  private:
    int                 n_, w_;
    std::vector<double> data_;
  };

  // ----------------------------------------------------------------------------------- FE model

  /// Output of one converged load level.
  struct LoadPoint
  {
    double pressure, u_outer, u_inner, plastic_radius;
    double plastic_radius_qp; // outermost plastic quadrature point (diagnostic)
  };

  /// Radial profile at one radius.
  struct ProfilePoint
  {
    double r, sigma_r, sigma_theta, sigma_z, ep;
  };

  /// 1D radial finite element model of the cylinder wall with J2 material points.
  class CylinderModel
  {
  public:
    CylinderModel(const Options &o, const Material &m)
        : a_(o.a)
        , b_(o.b)
        , mat_(m)
        , ne_(o.elements)
        , deg_(o.degree)
        , nn_(o.elements * o.degree + 1)
        , u_(nn_, 0.0)
        , K_(nn_, o.degree)
    {
      // 3-point Gauss rule on [-1, 1] (exact for the polynomial part of the integrands)
      const double g = std::sqrt(0.6);
      xi_ = {-g, 0.0, g};
      w_ = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
      qp_old_.assign(std::size_t(ne_) * 3, PointState());
      qp_new_ = qp_old_;
      // tracer material points at the profile radii (r = a and r = b included): they follow
      // the same strain history as the quadrature points but do not contribute to equilibrium
      for (int i = 0; i < o.profile_points; ++i)
        tracer_r_.push_back(a_ + (b_ - a_) * i / (o.profile_points - 1.0));
      tracer_r_.back() = b_;
      tracers_.assign(tracer_r_.size(), PointState());
    }

    /// Radius of node i (uniform mesh).
    double node_r(const int i) const { return a_ + (b_ - a_) * i / (nn_ - 1.0); }

    /// Strain (eps_r, eps_theta, 0) at reference coordinate xi of element e.
    std::array<double, 3> strain(const int e, const double xi, double *r_out = nullptr) const
    {
      double N[3], dN[3];
      shape(xi, N, dN);
      const double r0 = node_r(e * deg_), h = node_r((e + 1) * deg_) - r0;
      const double r = r0 + 0.5 * (xi + 1.0) * h;
      double       u = 0, du = 0;
      for (int k = 0; k <= deg_; ++k)
      {
        u += N[k] * u_[e * deg_ + k];
        du += dN[k] * 2.0 / h * u_[e * deg_ + k];
      }
      if (r_out)
        *r_out = r;
      return {{du, u / r, 0.0}};
    }

    /// Advances the pressure from the current converged level p_old to p_new (Newton with the
    /// consistent tangent; the increment is bisected if Newton fails). Commits the new state.
    void advance(const double p_old, const double p_new, const int depth = 0)
    {
      const std::vector<double> u_saved = u_;
      if (newton(p_new))
      {
        commit();
        return;
      }
      u_ = u_saved;
      if (depth > 12)
        throw std::runtime_error("Newton failed to converge at p = " + std::to_string(p_new));
      const double p_mid = 0.5 * (p_old + p_new);
      advance(p_old, p_mid, depth + 1);
      advance(p_mid, p_new, depth + 1);
    }

    double u_inner() const { return u_.front(); }
    double u_outer() const { return u_.back(); }
    int    newton_iterations() const { return total_iterations_; }

    /// Stresses and equivalent plastic strain at the tracer points (converged state).
    std::vector<ProfilePoint> profile() const
    {
      std::vector<ProfilePoint> out;
      for (std::size_t i = 0; i < tracer_r_.size(); ++i)
      {
        PointState          dummy;
        const PointResponse s
            = radial_return(mat_, tracer_strain(tracer_r_[i]), tracers_[i], dummy);
        out.push_back({tracer_r_[i], s.sigma[0], s.sigma[1], s.sigma[2], tracers_[i].ep});
      }
      return out;
    }

    /// Converged von Mises stress at r = a (tracer 0).
    double q_inner() const
    {
      PointState dummy;
      return von_mises(radial_return(mat_, tracer_strain(a_), tracers_.front(), dummy).sigma);
    }

    /// True once the material point at r = a has yielded.
    bool inner_yielded() const { return tracers_.front().ep > 0; }

    /// Plastic radius c. If the plastic zone is strictly inside the wall, the outer zone c<r<b
    /// is elastic with Lame stresses sigma_r = B (1/b^2 - 1/r^2), sigma_theta = B (1/b^2 + 1/r^2),
    /// sigma_z = 2 nu B/b^2, whose von Mises stress is q(r) = B sqrt(3/r^4 + (1-2nu)^2/b^4).
    /// B follows from u(b) = 2 (1-nu^2) B/(E b), and c solves q(c) = sigma_y(0). This gives a
    /// smooth sub-element estimate of the elastic-plastic interface; it is clamped to the
    /// interval between the outermost plastic and the innermost elastic quadrature point.
    /// Returns a when no point has yielded and b when the whole wall is plastic.
    void plastic_radius(double &c, double &c_qp) const
    {
      double r_plastic = -1, r_elastic = b_;
      for (int e = 0; e < ne_; ++e)
        for (int q = 0; q < 3; ++q)
        {
          double r;
          strain(e, xi_[q], &r);
          if (qp_old_[std::size_t(e) * 3 + q].ep > 0)
            r_plastic = std::max(r_plastic, r);
          else
            r_elastic = std::min(r_elastic, r);
        }
      if (r_plastic < 0)
      {
        c = c_qp = a_;
        return;
      }
      c_qp = r_plastic;
      if (r_elastic < r_plastic) // elastic point inside the plastic zone: not expected here
        r_elastic = r_plastic;
      if (tracers_.back().ep > 0 || r_elastic >= b_)
      {
        c = b_;
        return;
      }
      const double B = mat_.E * u_outer() * b_ / (2.0 * (1.0 - mat_.nu * mat_.nu));
      const double gamma = (1.0 - 2.0 * mat_.nu) / (b_ * b_);
      const double x = (mat_.sy * mat_.sy / (B * B) - gamma * gamma) / 3.0; // = 1/c^4
      c = x > 0 ? std::pow(x, -0.25) : b_;
      c = std::min(std::max(c, r_plastic), r_elastic);
    }

  private:
    void shape(const double xi, double *N, double *dN) const
    {
      if (deg_ == 1)
      {
        N[0] = 0.5 * (1 - xi);
        N[1] = 0.5 * (1 + xi);
        dN[0] = -0.5;
        dN[1] = 0.5;
      }
      else
      {
        N[0] = 0.5 * xi * (xi - 1);
        N[1] = 1 - xi * xi;
        N[2] = 0.5 * xi * (xi + 1);
        dN[0] = xi - 0.5;
        dN[1] = -2 * xi;
        dN[2] = xi + 0.5;
      }
    }

    std::array<double, 3> tracer_strain(const double r) const
    {
      int e = static_cast<int>(std::floor((r - a_) / (b_ - a_) * ne_));
      e = std::min(std::max(e, 0), ne_ - 1);
      const double r0 = node_r(e * deg_), h = node_r((e + 1) * deg_) - r0;
      return strain(e, 2.0 * (r - r0) / h - 1.0);
    }

    /// Assembles the residual R = f_int - f_ext (and the tangent if wanted) for pressure p,
    /// updating the trial histories qp_new_ from the converged ones qp_old_.
    void assemble(const double p, std::vector<double> &R, const bool tangent)
    {
      std::fill(R.begin(), R.end(), 0.0);
      if (tangent)
        K_.clear();
      double N[3], dN[3];
      for (int e = 0; e < ne_; ++e)
      {
        const double r0 = node_r(e * deg_), h = node_r((e + 1) * deg_) - r0;
        for (int q = 0; q < 3; ++q)
        {
          shape(xi_[q], N, dN);
          const double r = r0 + 0.5 * (xi_[q] + 1.0) * h;
          const double dV = w_[q] * 0.5 * h * r; // r dr (per radian)
          // strain-displacement rows: eps_r = Br . u_e, eps_theta = Bt . u_e
          double Br[3], Bt[3];
          for (int k = 0; k <= deg_; ++k)
          {
            Br[k] = dN[k] * 2.0 / h;
            Bt[k] = N[k] / r;
          }
          std::array<double, 3> eps{{0, 0, 0}};
          for (int k = 0; k <= deg_; ++k)
          {
            eps[0] += Br[k] * u_[e * deg_ + k];
            eps[1] += Bt[k] * u_[e * deg_ + k];
          }
          const std::size_t   iq = std::size_t(e) * 3 + q;
          const PointResponse s = radial_return(mat_, eps, qp_old_[iq], qp_new_[iq]);
          for (int i = 0; i <= deg_; ++i)
          {
            R[e * deg_ + i] += (s.sigma[0] * Br[i] + s.sigma[1] * Bt[i]) * dV;
            if (tangent)
              for (int j = 0; j <= deg_; ++j)
                K_(e * deg_ + i, e * deg_ + j)
                    += (Br[i] * (s.D[0][0] * Br[j] + s.D[0][1] * Bt[j])
                        + Bt[i] * (s.D[1][0] * Br[j] + s.D[1][1] * Bt[j]))
                       * dV;
          }
        }
      }
      // sigma_r(a) = -p: the traction on the inner surface (normal -e_r) is +p e_r
      R[0] -= p * a_;
    }

    /// Newton iteration for equilibrium at pressure p. Converged when the residual is below
    /// 1e-9 of the applied force p*a, or (round-off floor, which grows like the mesh size^-1)
    /// when it is below 1e-6 p*a and the last correction is below 1e-10 max|u|.
    /// Returns false if it does not converge.
    bool newton(const double p)
    {
      std::vector<double> R(nn_), du(nn_);
      const double        f_ref = std::max(p, 1e-3 * mat_.sy) * a_; // reference force
      double              last_du = -1;
      for (int it = 0; it < 25; ++it)
      {
        assemble(p, R, true);
        double rnorm = 0, unorm = 0;
        for (int i = 0; i < nn_; ++i)
        {
          rnorm = std::max(rnorm, std::abs(R[i]));
          unorm = std::max(unorm, std::abs(u_[i]));
        }
        if (!std::isfinite(rnorm))
          return false;
        if (rnorm <= 1e-9 * f_ref
            || (rnorm <= 1e-6 * f_ref && last_du >= 0 && last_du <= 1e-10 * unorm))
          return true;
        du = R;
        try
        {
          K_.solve(du);
        }
        catch (const std::exception &)
        {
          return false;
        }
        last_du = 0;
        for (int i = 0; i < nn_; ++i)
        {
          u_[i] -= du[i];
          last_du = std::max(last_du, std::abs(du[i]));
        }
        ++total_iterations_;
      }
      return false;
    }

    /// Accepts the trial state: quadrature-point and tracer histories.
    void commit()
    {
      std::vector<double> R(nn_);
      assemble(0.0, R, false); // recompute qp_new_ for the converged u
      qp_old_ = qp_new_;
      for (std::size_t i = 0; i < tracers_.size(); ++i)
      {
        PointState updated;
        radial_return(mat_, tracer_strain(tracer_r_[i]), tracers_[i], updated);
        tracers_[i] = updated;
      }
    }

    double                  a_, b_;
    Material                mat_;
    int                     ne_, deg_, nn_;
    std::vector<double>     u_;
    BandMatrix              K_;
    std::array<double, 3>   xi_, w_;
    std::vector<PointState> qp_old_, qp_new_;
    std::vector<double>     tracer_r_;
    std::vector<PointState> tracers_;
    int                     total_iterations_ = 0;
  };

  // ------------------------------------------------------------------------- closed-form checks

  /// Collapse pressure of a perfectly plastic cylinder (Tresca/von Mises plane strain, nu = 0.5):
  /// p_c = 2/sqrt(3) sigma_y ln(b/a).
  double collapse_pressure(const Options &o)
  {
    return 2.0 / std::sqrt(3.0) * o.sy * std::log(o.b / o.a);
  }

  /// Lame plane-strain elastic displacement u(r) under internal pressure p.
  double lame_displacement(const Options &o, const double nu, const double p, const double r)
  {
    const double A = p * o.a * o.a / (o.b * o.b - o.a * o.a);
    const double B = A * o.b * o.b;
    return (1.0 + nu) / o.E * ((1.0 - 2.0 * nu) * A * r + B / r);
  }

  /// Exact first-yield pressure for plane strain with Poisson's ratio nu: the Lame stresses
  /// sigma_r = A - B/r^2, sigma_theta = A + B/r^2, sigma_z = nu (sigma_r + sigma_theta) = 2 nu A
  /// (A = B/b^2) have the von Mises stress q(r) = B sqrt(3/r^4 + (1-2nu)^2/b^4), largest at r = a.
  /// For nu = 0.5 this is p_y = sigma_y/sqrt(3) (1 - a^2/b^2).
  double first_yield_pressure(const Options &o, const double nu)
  {
    const double B_per_p = o.a * o.a * o.b * o.b / (o.b * o.b - o.a * o.a);
    const double g = (1.0 - 2.0 * nu) / (o.b * o.b);
    const double a4 = std::pow(o.a, 4);
    return o.sy / (B_per_p * std::sqrt(3.0 / a4 + g * g));
  }

  /// Hill's closed form (incompressible, perfectly plastic, plane strain): pressure at which the
  /// elastic-plastic interface is at radius c.
  double hill_pressure(const Options &o, const double c)
  {
    return o.sy / std::sqrt(3.0) * (1.0 - c * c / (o.b * o.b) + 2.0 * std::log(c / o.a));
  }

  // ------------------------------------------------------------------------------------ driver

  struct RunResult
  {
    std::vector<LoadPoint>    load;
    std::vector<ProfilePoint> profile;
    double                    q_inner_elastic = -1; // q(a) at the elastic check pressure
    double                    p_elastic = -1;       // that pressure
    double                    u_outer_elastic = 0;  // u(b) at that pressure
    double                    p_yield_lo = -1, p_yield_hi = -1; // load steps bracketing 1st yield
    int                       newton_iterations = 0;
  };

  /// Pressure levels of the load path: p_k = pmax (1 - (1 - k/steps)^grading), k = 0..steps
  /// (uniform for grading = 1; grading > 1 gives small steps near pmax, where u(p) bends
  /// sharply, and large ones in the linear elastic range), plus the extra levels (profile
  /// pressure, elastic check pressure, exact first-yield pressure, where the plastic radius
  /// curve has a corner) inserted so that they are hit exactly.
  std::vector<double>
  load_path(const double pmax, const int steps, const double grading, std::vector<double> extra)
  {
    std::vector<double> p;
    for (int k = 0; k <= steps; ++k)
      p.push_back(k == steps ? pmax : pmax * (1.0 - std::pow(1.0 - double(k) / steps, grading)));
    for (const double x : extra)
      if (x > 0 && x < pmax)
        p.push_back(x);
    std::sort(p.begin(), p.end());
    std::vector<double> out;
    for (const double x : p) // drop levels closer than 1e-9 pmax (keep the first)
      if (out.empty() || x - out.back() > 1e-9 * pmax)
        out.push_back(x);
      else if (std::find(extra.begin(), extra.end(), x) != extra.end())
        out.back() = x; // an exact extra level replaces a nearly equal uniform level
    return out;
  }

  RunResult run(const Options &o,
                const double   nu,
                const double   H,
                const double   power_n,
                const double   pmax,
                const bool     write_profile,
                const double   p_elastic_check)
  {
    const Material m{o.E, nu, o.sy, H, power_n, o.power_e0};
    if (write_profile && !(o.profile_p > 0 && o.profile_p <= pmax * (1 + 1e-12)))
      throw std::runtime_error("profile pressure must lie in (0, pmax]");
    const std::vector<double> path = load_path(
        pmax, o.steps, o.grading, {o.profile_p, p_elastic_check, first_yield_pressure(o, nu)});

    CylinderModel model(o, m);
    RunResult     res;
    res.load.push_back({0.0, 0.0, 0.0, o.a, o.a});
    for (std::size_t k = 1; k < path.size(); ++k)
    {
      for (int s = 0; s < o.substeps; ++s)
        model.advance(path[k - 1] + (path[k] - path[k - 1]) * s / o.substeps,
                      path[k - 1] + (path[k] - path[k - 1]) * (s + 1) / o.substeps);
      LoadPoint lp{path[k], model.u_outer(), model.u_inner(), 0, 0};
      model.plastic_radius(lp.plastic_radius, lp.plastic_radius_qp);
      res.load.push_back(lp);
      if (path[k] == p_elastic_check)
      {
        res.p_elastic = path[k];
        res.q_inner_elastic = model.q_inner();
        res.u_outer_elastic = model.u_outer();
      }
      if (model.inner_yielded() && res.p_yield_hi < 0)
      {
        res.p_yield_lo = path[k - 1];
        res.p_yield_hi = path[k];
      }
      if (write_profile && path[k] == o.profile_p)
        res.profile = model.profile();
    }
    res.newton_iterations = model.newton_iterations();
    return res;
  }

  void write_csv(const Options &o, const RunResult &r)
  {
    const std::string load_name = o.out_prefix + "_load.csv";
    FILE             *f = std::fopen(load_name.c_str(), "w");
    if (!f)
      throw std::runtime_error("cannot write " + load_name);
    std::fprintf(f, "pressure,u_outer,u_inner,plastic_radius\n");
    for (const LoadPoint &p : r.load)
      std::fprintf(
          f, "%.10g,%.10g,%.10g,%.10g\n", p.pressure, p.u_outer, p.u_inner, p.plastic_radius);
    std::fclose(f);

    const std::string prof_name = o.out_prefix + "_profile.csv";
    f = std::fopen(prof_name.c_str(), "w");
    if (!f)
      throw std::runtime_error("cannot write " + prof_name);
    std::fprintf(f, "r,sigma_r,sigma_theta,sigma_z,eq_plastic_strain\n");
    for (const ProfilePoint &p : r.profile)
      std::fprintf(
          f, "%.10g,%.10g,%.10g,%.10g,%.10g\n", p.r, p.sigma_r, p.sigma_theta, p.sigma_z, p.ep);
    std::fclose(f);
    std::printf("wrote %s (%zu rows), %s (%zu rows)\n",
                load_name.c_str(),
                r.load.size(),
                prof_name.c_str(),
                r.profile.size());
  }

  /// One line of the summary table.
  bool report(const char  *name,
              const double value,
              const double reference,
              const double err,
              const double tol)
  {
    const bool ok = err <= tol;
    std::printf("  %-44s %14.8g %14.8g %10.2e %9.1e  %s\n",
                name,
                value,
                reference,
                err,
                tol,
                ok ? "ok" : "FAIL");
    return ok;
  }
} // namespace

int main(int argc, char **argv)
{
  try
  {
    const Options o = parse_options(argc, argv);
    const double  pc = collapse_pressure(o);
    const double  p_el = 50.0; // elastic check pressure
    const double  py = first_yield_pressure(o, o.nu);
    const bool    do_el = p_el < py;
    const double  pmax = o.pmax > 0 ? o.pmax : o.pmax_fraction * pc;

    std::printf("thick_cylinder_1d: a=%g b=%g E=%g nu=%g sy=%g H=%g power-n=%g power-e0=%g\n",
                o.a,
                o.b,
                o.E,
                o.nu,
                o.sy,
                o.H,
                o.power_n,
                o.power_e0);
    std::printf(
        "  p_c = %.6f, pmax = %.6f, steps = %d x %d (grading %g), elements = %d (degree %d)\n",
        pc,
        pmax,
        o.steps,
        o.substeps,
        o.grading,
        o.elements,
        o.degree);

    const RunResult r = run(o, o.nu, o.H, o.power_n, pmax, true, do_el ? p_el : -1.0);
    write_csv(o, r);
    const LoadPoint &last = r.load.back();
    std::printf("  Newton iterations: %d\n", r.newton_iterations);
    std::printf("  final: p = %.6f  u(b) = %.12g  u(a) = %.12g  plastic radius = %.6f (qp %.4f)\n",
                last.pressure,
                last.u_outer,
                last.u_inner,
                last.plastic_radius,
                last.plastic_radius_qp);
    for (const LoadPoint &lp : r.load)
      if (lp.pressure == o.profile_p)
        std::printf("  at p = %.6f: u(b) = %.12g  u(a) = %.12g  plastic radius = %.6f\n",
                    lp.pressure,
                    lp.u_outer,
                    lp.u_inner,
                    lp.plastic_radius);

    bool ok = true;
    std::printf(
        "\ncross-checks                                          value      reference  rel.error"
        "       tol\n");
    // (a) elastic range: u(b) against the Lame plane-strain solution
    if (do_el)
    {
      const double ref = lame_displacement(o, o.nu, p_el, o.b);
      ok &= report("(a) u(b) at p=50, Lame plane strain",
                   r.u_outer_elastic,
                   ref,
                   std::abs(r.u_outer_elastic - ref) / std::abs(ref),
                   1e-6);
    }
    else
      std::printf("  (a) skipped: p=50 is not in the elastic range\n");

    // profile consistency: integrating equilibrium d(sigma_r)/dr = (sigma_theta - sigma_r)/r
    // from a to b gives p = int_a^b (sigma_theta - sigma_r)/r dr (trapezoidal rule on the
    // profile radii; its error is O(h^2) with a kink of the integrand at the plastic front).
    {
      const std::vector<ProfilePoint> &pr = r.profile;
      double                           integral = 0;
      for (std::size_t i = 1; i < pr.size(); ++i)
        integral += 0.5 * (pr[i].r - pr[i - 1].r)
                    * ((pr[i].sigma_theta - pr[i].sigma_r) / pr[i].r
                       + (pr[i - 1].sigma_theta - pr[i - 1].sigma_r) / pr[i - 1].r);
      const double tol = 10.0 * std::pow((o.b - o.a) / (pr.size() - 1.0) / o.a, 2);
      ok &= report("profile: int (s_t - s_r)/r dr = p",
                   integral,
                   o.profile_p,
                   std::abs(integral - o.profile_p) / o.profile_p,
                   tol);
      ok &= report("profile: -sigma_r(a) = p",
                   -pr.front().sigma_r,
                   o.profile_p,
                   std::abs(pr.front().sigma_r + o.profile_p) / o.profile_p,
                   1e-5);
      std::printf("  profile: sigma_r(b) = %.3g (should be ~0)\n", pr.back().sigma_r);
    }

    if (o.checks)
    {
      // (b) first yield. The response is linear until first yield, so the solver's first-yield
      // pressure is p_el * sigma_y / q(a) with q(a) from the FE strain at r = a; the load step
      // at which the material point at r = a first yields must bracket the exact value.
      if (do_el)
      {
        const double py_num = r.p_elastic * o.sy / r.q_inner_elastic;
        ok &= report("(b) first-yield pressure (elastic scaling)",
                     py_num,
                     py,
                     std::abs(py_num - py) / py,
                     1e-5);
      }
      // (the exact p_y is itself a load level, hence the 1e-6 slack)
      const bool bracket
          = pmax < py || (r.p_yield_lo <= py * (1 + 1e-6) && py * (1 - 1e-6) <= r.p_yield_hi);
      std::printf("  (b) first yield at r=a between load steps p = %.4f and %.4f: exact %.6f %s "
                  "(nu=0.5 value %.6f)\n",
                  r.p_yield_lo,
                  r.p_yield_hi,
                  py,
                  bracket ? "inside, ok" : "OUTSIDE, FAIL",
                  first_yield_pressure(o, 0.5));
      ok &= bracket;

      // (c) nearly incompressible, perfectly plastic run against Hill's closed form:
      // p(c) = sigma_y/sqrt(3) (1 - c^2/b^2 + 2 ln(c/a)) for every load step with a < c < b.
      // Hill's plastic zone has the constant deviator (-k, k, 0): the stress path is
      // proportional, so backward Euler is exact there and the load-step size drops out.
      // What remains is small: nu = 0.4999 instead of 0.5 lowers sigma_theta - sigma_r only
      // at second order in (1-2nu), i.e. ~1e-8; the kink of u at the front is resolved to
      // O(h^2) by the mesh. 1e-4 bounds these with a wide margin (observed ~1e-8 with the
      // default settings, ~2e-5 with 50 quadratic elements) and is still far below what a
      // flawed flow rule or volumetric locking (linear elements: ~4e-2) produce.
      // (perfect plasticity, so the final pressure is capped at 0.99 p_c)
      const double    nu_c = 0.4999;
      const RunResult h = run(o,
                              nu_c,
                              0.0,
                              0.0,
                              std::min(pmax, 0.99 * pc),
                              false,
                              p_el < first_yield_pressure(o, nu_c) ? p_el : -1);
      double          err_max = 0, p_at = 0, c_at = 0;
      int             n_cmp = 0;
      for (const LoadPoint &lp : h.load)
        if (lp.plastic_radius > o.a && lp.plastic_radius < o.b)
        {
          const double ph = hill_pressure(o, lp.plastic_radius);
          const double err = std::abs(lp.pressure - ph) / ph;
          ++n_cmp;
          if (err >= err_max)
          {
            err_max = err;
            p_at = lp.pressure;
            c_at = lp.plastic_radius;
          }
        }
      if (n_cmp == 0)
      {
        std::printf("  (c) FAIL: no load step with a < c < b in the nu=%g run\n", nu_c);
        ok = false;
      }
      else
      {
        char name[128];
        std::snprintf(name, sizeof(name), "(c) nu=%g: max |p - p_Hill(c)| (c=%.3f)", nu_c, c_at);
        ok &= report(name, p_at, hill_pressure(o, c_at), err_max, 1e-4);
        std::printf("      (%d load steps with a < c < b compared)\n", n_cmp);
      }
      const double py_hill = o.sy / std::sqrt(3.0) * (1.0 - o.a * o.a / (o.b * o.b));
      if (h.q_inner_elastic > 0)
      {
        const double py_num = h.p_elastic * o.sy / h.q_inner_elastic;
        ok &= report("(c) nu=0.4999: first yield vs sy/sqrt3(1-a2/b2)",
                     py_num,
                     py_hill,
                     std::abs(py_num - py_hill) / py_hill,
                     1e-5);
      }
      std::printf("  (c) nu=%g: final p = %.6f  u(b) = %.10g  plastic radius = %.6f (Hill: p(c) = "
                  "%.6f)\n",
                  nu_c,
                  h.load.back().pressure,
                  h.load.back().u_outer,
                  h.load.back().plastic_radius,
                  hill_pressure(o, h.load.back().plastic_radius));
    }
    std::printf("\n%s\n", ok ? "all cross-checks passed" : "CROSS-CHECK FAILED");
    return ok ? 0 : 1;
  }
  catch (const std::exception &e)
  {
    std::fflush(stdout);
    std::fprintf(stderr, "thick_cylinder_1d: error: %s\n", e.what());
    return 2;
  }
}
