/**
 * @file face_loads.h
 * The face-load term of the mechanical assembly: surface loads on the boundary faces of a cell.
 */
#pragma once

#include <ausroll/mechanics/boundary_conditions.h>
#include <ausroll/mechanics/planar_kinematics.h>
#include <ausroll/mechanics/terms/interface.h>

#include <deal.II/base/quadrature.h>
#include <deal.II/fe/mapping.h>

#include <memory>

namespace ausroll::mechanics
{
  /**
   * The face-load term for @p boundary_conditions on the element @p fe of @p layout with the face
   * @p quadrature: on boundary faces with a surface load, the dead traction per reference area
   * and the pressure, on the reference surface for a small-strain model (@p follower false) or
   * on the deformed surface (follower pressure with its load stiffness, FollowerPressure::add(),
   * 2D models only) into the cell's external force and matrix. The area element is
   * PlanarKinematics::volume_factor() dA; the hoop stretch comes from the kinematics' hoop entry.
   * Not part of the cached cell part (computed at every assembly). The boundary-condition
   * functions keep their time in the object: the term evaluates them under its own lock.
   */
  template <int dim>
  struct FaceLoads
  {
    /** The face-load term (see above); the references must outlive it. */
    static std::unique_ptr<AssemblyTerm<dim>>
    create(const AssemblyLayout              &layout,
           const dealii::Mapping<dim>        &mapping,
           const dealii::FiniteElement<dim>  &fe,
           const dealii::Quadrature<dim - 1> &quadrature,
           const PlanarKinematics<dim>       &kinematics,
           const BoundaryConditions<dim>     &boundary_conditions,
           const bool                         follower);
  };
} // namespace ausroll::mechanics
