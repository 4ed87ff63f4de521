/**
 * @file f_bar.h
 * Volumetric locking treatment of the internal-force term: F-bar (B-bar for small strain) and the
 * identity treatment, each a policy of InternalForceTerm (mechanics/terms/internal_force.h).
 */
#pragma once

#include <ausroll/mechanics/planar_kinematics.h>
#include <ausroll/mechanics/terms/interface.h>

#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>

#include <array>
#include <vector>

namespace ausroll::mechanics
{
  /** What the material point sees at one quadrature point: F_bar, s, kappa, F^-1. */
  struct FBarPoint
  {
    dealii::Tensor<2, 3> F_material; ///< F_bar (F without F-bar)
    double               s = 1.;     ///< F_bar = s F (in the scaled block; 1 for small strain)
    double               kappa = 1.; ///< P = kappa P(F_bar), kappa = s^(1 - n)
    /** dF_bar_zz / dF_zz at fixed in-plane displacement: s where the scaling covers zz
        (n = 3), else 1 (J0 / J does not depend on a uniform F_zz; generalized plane strain) */
    double               s_zz = 1.;
    dealii::Tensor<2, 3> F_inv; ///< F^-1 (large strain with F-bar; else zero)
  };

  /** The cell's fields the internal-force term has evaluated (at its reinitialised FEValues). */
  template <int dim>
  struct CellFields
  {
    const dealii::FEValues<dim>               &fe_values;
    const std::vector<double>                 &local_u;  ///< the cell's DoF values
    const std::vector<dealii::Tensor<2, dim>> &grad_u;   ///< Grad u at the quadrature points
    const std::vector<dealii::Tensor<1, dim>> &u_values; ///< u at the quadrature points
  };

  /**
   * F-bar (de Souza Neto, Peric, Dutko and Owen 1996; see Assembler for the method): per cell the
   * reference volume change J0 (cell centre for Q1, cell average for higher degrees) and
   * d ln J0 / du_j (reference()), per point F_bar = s F with s = (J0 / J)^(1/n) and
   * kappa = s^(1 - n) (point()), and the rank-one term of the exact tangent (add_tangent()). Small
   * strain: the B-bar shift of the trace. @p Hoop is the hoop entry of the kinematics
   * (planar_kinematics.h).
   */
  template <int dim, typename Hoop>
  class FBar
  {
  public:
    /** Per-thread data: centre FEValues, J0, tr(F0 - I), d ln J0 / du_j. */
    struct Scratch
    {
      Scratch(const dealii::Mapping<dim> &mapping, const dealii::FiniteElement<dim> &fe);
      Scratch(const Scratch &other);

      dealii::FEValues<dim>               fe_center; ///< values and gradients at the centre (Q1)
      std::vector<dealii::Tensor<2, dim>> grad_u_center;
      std::vector<dealii::Tensor<1, dim>> u_center;
      /** d ln J0 / du_j of the reference, d ln J / du_j at the point (tr G for small strain),
          and the coefficients q_i of the rank-one reference term of the tangent. */
      std::vector<double> dlnJ0, dlnJ, q_coefficient;
      double              J0 = 1., trace_H0 = 0.; ///< the reference of the current cell
    };

    /** F-bar for the element of @p layout (@p degree its polynomial degree) and @p kinematics;
        @p small_strain: the B-bar form. */
    FBar(const AssemblyLayout        &layout,
         const unsigned int           degree,
         const PlanarKinematics<dim> &kinematics,
         const bool                   small_strain);

    /**
     * Per cell: J0 and tr(F0 - I) at the cell centre (Q1) or their volume averages over the
     * quadrature points of @p fields (higher degrees), and d ln J0 / du_j (small strain:
     * d tr(F0 - I) / du_j) into @p scratch. Returns false and sets @p local's failure for an
     * inverted reference when @p check_inversion.
     */
    bool reference(const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
                   const CellFields<dim>                                        &fields,
                   const bool                                                    check_inversion,
                   Scratch                                                      &scratch,
                   LocalSystem                                                  &local) const;

    /** Per point: F_bar = s F (in the n x n block; small strain: the B-bar shift of the trace),
        s and kappa from the reference in @p scratch. */
    FBarPoint point(const Scratch &scratch, const dealii::Tensor<2, 3> &F, const double J) const;

    /**
     * Tangent: the rank-one term q_i (d ln J0_j - d ln J_j) of the exact linearisation at one
     * point (weight @p dV, shape-function gradients @p g and hoop entries @p hoop, material
     * stress @p P_bar and tangent @p A) added to @p matrix.
     */
    void add_tangent(const FBarPoint                            &point,
                     const dealii::Tensor<2, 3>                 &F,
                     const double                                dV,
                     const std::vector<std::array<double, dim>> &g,
                     const std::vector<double>                  &hoop,
                     const dealii::Tensor<2, 3>                 &P_bar,
                     const dealii::Tensor<4, 3>                 &A,
                     Scratch                                    &scratch,
                     dealii::FullMatrix<double>                 &matrix) const;

    /**
     * Generalized plane strain: the F-bar part of the row k_eu = d(int P_zz dV) / du_j at one
     * point, Qt_zz dV (dlnJ0_j - dlnJ_j) with Qt of add_tangent() (call after it: it reuses the
     * d ln J of @p scratch), added to @p row.
     */
    void add_out_of_plane_row(const FBarPoint            &point,
                              const dealii::Tensor<2, 3> &F,
                              const double                dV,
                              const dealii::Tensor<2, 3> &P_bar,
                              const dealii::Tensor<4, 3> &A,
                              const Scratch              &scratch,
                              dealii::Vector<double>     &row) const;

  private:
    const AssemblyLayout        &layout;
    const PlanarKinematics<dim> &kinematics;
    const bool                   small_strain;
    /** J0: value at the cell centre for Q1 (de Souza Neto), cell average for higher degrees (a
        single centre value leaves volumetric modes of Q2 unconstrained: too soft). */
    const bool cell_average;
    /** n of the F-bar scaling and the in-plane/volumetric projection E (I_n). */
    unsigned int         n_vol = 2;
    double               alpha = 0.5;
    dealii::Tensor<2, 3> E;
  };

  /** The identity treatment (`Volumetric locking treatment = none`): the material points see F,
      no tangent term; the same interface as FBar, all of it inline and empty. */
  template <int dim, typename Hoop>
  class NoVolumetricCorrection
  {
  public:
    struct Scratch
    {
      Scratch(const dealii::Mapping<dim> &, const dealii::FiniteElement<dim> &) {}
    };

    bool reference(const typename dealii::DoFHandler<dim>::active_cell_iterator &,
                   const CellFields<dim> &,
                   const bool,
                   Scratch &,
                   LocalSystem &) const
    {
      return true;
    }

    FBarPoint point(const Scratch &, const dealii::Tensor<2, 3> &F, const double) const
    {
      FBarPoint point;
      point.F_material = F;
      return point;
    }

    void add_tangent(const FBarPoint &,
                     const dealii::Tensor<2, 3> &,
                     const double,
                     const std::vector<std::array<double, dim>> &,
                     const std::vector<double> &,
                     const dealii::Tensor<2, 3> &,
                     const dealii::Tensor<4, 3> &,
                     Scratch &,
                     dealii::FullMatrix<double> &) const
    {
    }

    void add_out_of_plane_row(const FBarPoint &,
                              const dealii::Tensor<2, 3> &,
                              const double,
                              const dealii::Tensor<2, 3> &,
                              const dealii::Tensor<4, 3> &,
                              const Scratch &,
                              dealii::Vector<double> &) const
    {
    }
  };
} // namespace ausroll::mechanics
