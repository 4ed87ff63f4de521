/**
 * @file model_parameters.h
 * The `Model` subsection: kinematics, planar idealisation and finite element.
 */
#pragma once

#include <ausroll/material/constitutive_model.h>

#include <deal.II/base/parameter_handler.h>

namespace ausroll::mechanics
{
  /** Two-dimensional idealisation of the workpiece (`Model/Planar model`). */
  enum class PlanarModel
  {
    plane_strain, ///< eps_zz = 0
    plane_stress, ///< sigma_zz = 0 (out-of-plane stretch solved at each material point)
    axisymmetric, ///< x = radius r, y = axial coordinate z; hoop strain u_r / r; volume 2 pi r dA
    /** F_zz = lambda, one global unknown of the section, with the axial force int sigma_zz da
        = `Model/Axial force` (GeneralizedPlaneStrain) */
    generalized_plane_strain
  };

  /**
   * Treatment of volumetric locking of nearly incompressible (plastic) flow
   * (`Model/Volumetric locking treatment`).
   */
  enum class VolumetricLocking
  {
    none, ///< standard displacement element (Q1 locks in plastic flow)
    f_bar ///< F-bar (de Souza Neto et al. 1996): the volume change of each cell is taken from its
          ///< centre, F_bar = (J0 / J)^(1/n) F; for small strain the mean-dilatation B-bar
  };

  /**
   * Parameters of subsection `Model`.
   */
  struct ModelParameters
  {
    material::KinematicsType kinematics = material::KinematicsType::finite_strain; ///< `Kinematics`
    PlanarModel              planar_model = PlanarModel::plane_strain; ///< `Planar model`
    double                   thickness = 1.; ///< `Thickness` of plane models (forces scale with it)
    /** `Axial force` N = int sigma_zz da on the section (generalized plane strain only; N) */
    double       axial_force = 0.;
    unsigned int degree = 2;            ///< `Polynomial degree` of the displacement FE_Q
    unsigned int quadrature_points = 0; ///< `Quadrature points` per direction (0: degree+1)
    /** `Volumetric locking treatment` */
    VolumetricLocking volumetric_locking = VolumetricLocking::none;

    /** Declare subsection `Model`. */
    static void declare_parameters(dealii::ParameterHandler &prm);
    /** Read subsection `Model`. */
    void parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace ausroll::mechanics
