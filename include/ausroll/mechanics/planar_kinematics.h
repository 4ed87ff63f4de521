/**
 * @file planar_kinematics.h
 * Embedding of a dim-dimensional displacement field into 3x3 deformation gradients.
 */
#pragma once

#include <ausroll/mechanics/model_parameters.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

namespace ausroll::mechanics
{
  /**
   * The out-of-plane (hoop) entry of the 3D shape-function gradient, as the assembly terms see
   * it: plane strain, plane stress and 3D models have none (F_zz does not depend on the
   * displacement DoFs), axisymmetric models have F_thetatheta = 1 + u_r / R, whose derivative by
   * a radial shape function phi is phi / R. The terms are templates on one of the two and ask it
   * for the entry instead of testing the planar model: with NoHoopEntry every hoop product is
   * a compile-time zero that the compiler drops, so plane models do not pay for the hoop.
   * PlanarKinematics::with_hoop_entry() picks the one of the model (once, when the terms are
   * built). The area/volume factor (thickness, 2 pi R) is PlanarKinematics::volume_factor().
   */
  struct NoHoopEntry
  {
    /** Number of out-of-plane gradient entries (loops over them vanish). */
    static constexpr unsigned int n_entries = 0;

    /** Whether a shape function of component @p c has a hoop entry. */
    static constexpr bool has_entry(const unsigned int /*c*/) { return false; }

    /** The hoop entry phi / R of a shape function with radial value @p phi (never called). */
    template <int dim>
    static double entry(const double /*phi*/, const dealii::Point<dim> & /*X*/)
    {
      return 0.;
    }

    /** a * b where the hoop entry exists, else 0 (the product is not formed). */
    static constexpr double product(const double /*a*/, const double /*b*/) { return 0.; }

    /** The hoop stretch r / R = 1 + u_r / R of the displacement @p u at @p X (here 1). */
    template <int dim>
    static double stretch(const dealii::Tensor<1, dim> & /*u*/, const dealii::Point<dim> & /*X*/)
    {
      return 1.;
    }
  };

  /** The hoop entry of axisymmetric models, (x, y) = (r, z): see NoHoopEntry. */
  struct AxisymmetricHoopEntry
  {
    static constexpr unsigned int n_entries = 1;

    static constexpr bool has_entry(const unsigned int c) { return c == 0; }

    template <int dim>
    static double entry(const double phi, const dealii::Point<dim> &X)
    {
      return phi / X[0];
    }

    static constexpr double product(const double a, const double b) { return a * b; }

    template <int dim>
    static double stretch(const dealii::Tensor<1, dim> &u, const dealii::Point<dim> &X)
    {
      return 1. + u[0] / X[0];
    }
  };

  /**
   * Maps displacement gradients of a planar (dim = 2) or 3D model to the 3x3 deformation gradient
   * the material points work with, and gives the volume measure. Set by `Model/Planar model` and
   * `Model/Thickness`.
   *  - plane strain: F_zz = 1; dV = thickness dA.
   *  - plane stress: F_zz = 1 here, the PlaneStressDriver finds the actual stretch; dV = thickness
   * dA.
   *  - axisymmetric: (x, y) = (r, z); F_thetatheta = 1 + u_r / r; dV = 2 pi r dA.
   *  - generalized plane strain: F_zz = lambda, the one out-of-plane unknown of the section
   * (GeneralizedPlaneStrain::stretch, read through the pointer given to the constructor; it does
   * not depend on the displacement DoFs, so the hoop entry is NoHoopEntry); dV = thickness dA.
   * For dim = 3 the embedding is the identity.
   */
  template <int dim>
  class PlanarKinematics
  {
  public:
    /**
     * Kinematics of @p model with out-of-plane @p thickness (ignored when axisymmetric); for
     * generalized plane strain F_zz = *@p out_of_plane_stretch (the current lambda, owned by
     * the caller, e.g. MechanicalSystem::out_of_plane; nullptr: 1).
     */
    PlanarKinematics(const PlanarModel model,
                     const double      thickness,
                     const double     *out_of_plane_stretch = nullptr);

    /** The kinematics of subsection `Model` (`Planar model`, `Thickness`), as above. */
    PlanarKinematics(const ModelParameters &model, const double *out_of_plane_stretch)
        : PlanarKinematics(model.planar_model, model.thickness, out_of_plane_stretch)
    {
    }

    /** F = I + Grad u embedded in 3D, at reference point @p X with displacement @p u. */
    dealii::Tensor<2, 3> deformation_gradient(const dealii::Tensor<2, dim> &grad_u,
                                              const dealii::Tensor<1, dim> &u,
                                              const dealii::Point<dim>     &X) const;

    /**
     * The 3D gradient dF/du_i of a vector-valued shape function with value @p phi and gradient
     * @p grad_phi (the variation of F caused by that shape function).
     */
    dealii::Tensor<2, 3> shape_gradient(const dealii::Tensor<2, dim> &grad_phi,
                                        const dealii::Tensor<1, dim> &phi,
                                        const dealii::Point<dim>     &X) const;

    /** Factor turning the reference area element dA into the volume element dV. */
    double volume_factor(const dealii::Point<dim> &X) const;

    /**
     * Number n of directions that carry volume change in the F-bar method, for the cell-centre J0
     * of Q1 (@p mean_dilatation false) or the cell-average J0 of Q2 and higher (true): 3 for 3D
     * and axisymmetric models (the whole F, hoop stretch included, is scaled); 2 for plane stress
     * (only the in-plane block, F_zz comes from sigma_zz = 0); plane strain 2 for Q1 (F_bar_zz = 1)
     * and 3 with mean dilatation (F_bar_zz = s, as Hughes' B-bar with eps_bar_zz = (theta_0 -
     * theta) / 3: the in-plane scaling leaks the volume correction into the 3D deviatoric strain
     * and made Q2 too soft, flat punch 0.928 p_lim instead of 0.998).
     */
    unsigned int volumetric_dimensions(const bool mean_dilatation) const
    {
      if (dim == 3 || is_axisymmetric())
        return 3;
      return mean_dilatation
                     && (model == PlanarModel::plane_strain
                         || model == PlanarModel::generalized_plane_strain)
                 ? 3
                 : 2;
    }

    /** True for generalized plane strain (dim = 2): F_zz is the global unknown lambda. */
    bool is_generalized_plane_strain() const
    {
      return model == PlanarModel::generalized_plane_strain && dim == 2;
    }

    /** True for the axisymmetric model (shape function values enter the gradient). */
    bool is_axisymmetric() const { return model == PlanarModel::axisymmetric && dim == 2; }

    /**
     * Call @p f with the hoop-entry object of this model (AxisymmetricHoopEntry for the
     * axisymmetric model, NoHoopEntry otherwise) and return its result: the one place where the
     * assembly terms are specialised for the planar model.
     */
    template <typename Function>
    decltype(auto) with_hoop_entry(Function &&f) const
    {
      if constexpr (dim == 2)
        if (is_axisymmetric())
          return f(AxisymmetricHoopEntry());
      return f(NoHoopEntry());
    }

    /** F_zz of generalized plane strain (the current lambda), 1 for the other models. */
    double out_of_plane_stretch() const
    {
      return is_generalized_plane_strain() && stretch != nullptr ? *stretch : 1.;
    }

    /** The planar model. */
    PlanarModel planar_model() const { return model; }

  private:
    PlanarModel   model;     ///< idealisation
    double        thickness; ///< out-of-plane thickness of plane models
    const double *stretch;   ///< lambda of generalized plane strain (nullptr: 1)
  };
} // namespace ausroll::mechanics
