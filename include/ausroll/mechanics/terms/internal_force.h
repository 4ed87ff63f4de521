/**
 * @file internal_force.h
 * The internal-force term of the mechanical assembly: the quadrature loop of a cell with the
 * material points, internal forces and material tangent (with the volumetric locking treatment
 * of mechanics/terms/f_bar.h).
 */
#pragma once

#include <ausroll/material/constitutive_model.h>
#include <ausroll/mechanics/model_parameters.h>
#include <ausroll/mechanics/planar_kinematics.h>
#include <ausroll/mechanics/terms/interface.h>

#include <deal.II/base/quadrature.h>
#include <deal.II/fe/mapping.h>

#include <memory>
#include <vector>

namespace ausroll::mechanics
{
  /**
   * Internal forces int P : G_i dV and the material tangent of one cell: per quadrature point F
   * (PlanarKinematics), the deformation gradient the material point sees (F, or F_bar of FBar),
   * ConstitutiveModel::evaluate(), the residual and, with a matrix, A : G_j contracted with G_i
   * plus the F-bar reference term. Part of the cell part that AssemblyCache keeps. Fails the cell
   * for an inverted element (large strain) or a material failure (RunFailure).
   */
  template <int dim>
  class InternalForce : public AssemblyTerm<dim>
  {
  public:
    /**
     * The internal-force term for @p model on the element @p fe of @p layout with the cell
     * @p quadrature, specialised for the hoop entry of @p kinematics and the volumetric
     * @p locking treatment (FBar or none). The references must outlive the term.
     */
    static std::unique_ptr<InternalForce<dim>> create(const AssemblyLayout              &layout,
                                                      const dealii::Mapping<dim>        &mapping,
                                                      const dealii::FiniteElement<dim>  &fe,
                                                      const dealii::Quadrature<dim>     &quadrature,
                                                      const PlanarKinematics<dim>       &kinematics,
                                                      const material::ConstitutiveModel &model,
                                                      const VolumetricLocking            locking);

    bool cached() const override { return true; }

    /**
     * The deformation gradients the material points of @p cell see at the displacement
     * @p solution (ghosted): F, or F_bar with the volumetric correction of the assembly.
     */
    virtual std::vector<dealii::Tensor<2, 3>>
    material_deformation_gradients(const typename AssemblyTerm<dim>::ActiveCell &cell,
                                   const dealii::TrilinosWrappers::MPI::Vector &solution) const = 0;
  };

} // namespace ausroll::mechanics
