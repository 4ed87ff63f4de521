/**
 * @file follower_pressure.h
 * Follower pressure on the deformed surface of a 2D model: its nominal traction and load
 * stiffness at one face quadrature point (used by the face-load term,
 * mechanics/terms/face_loads.h).
 */
#pragma once

#include <ausroll/mechanics/planar_kinematics.h>
#include <ausroll/mechanics/terms/interface.h>

#include <deal.II/fe/fe_values.h>

namespace ausroll::mechanics
{
  /**
   * Pressure @p p on the deformed surface at face quadrature point @p q of @p fe_face_values
   * (reference point @p X, unit normal @p N, Grad u @p grad_u and u @p u there, area weight
   * @p dA): the nominal traction t0 = -p J F^-T N, from the deformed tangent a = F T of the face
   * (T the reference unit tangent), t0 dA = -p (a_y, -a_x) dL times the hoop stretch r / R of
   * @p Hoop (axisymmetric models: the deformed area element is 2 pi r dl) and the out-of-plane
   * stretch @p lambda of generalized plane strain (the deformed face is lambda dl long out of
   * plane; 1 otherwise), is added to @p t; with @p need_matrix its derivative, the load stiffness
   * (non-symmetric), is added to @p matrix and, if @p column is not empty (generalized plane
   * strain), d(-f_ext)/dlambda to @p column.
   */
  template <typename Hoop>
  struct FollowerPressure
  {
    static void add(const double                   p,
                    const unsigned int             q,
                    const dealii::FEFaceValues<2> &fe_face_values,
                    const AssemblyLayout          &layout,
                    const dealii::Point<2>        &X,
                    const dealii::Tensor<1, 2>    &N,
                    const dealii::Tensor<2, 2>    &grad_u,
                    const dealii::Tensor<1, 2>    &u,
                    const double                   dA,
                    const bool                     need_matrix,
                    const double                   lambda,
                    dealii::Tensor<1, 2>          &t,
                    dealii::FullMatrix<double>    &matrix,
                    dealii::Vector<double>        &column);
  };
} // namespace ausroll::mechanics
