/**
 * @file generalized_plane_strain.h
 * The global out-of-plane unknown of generalized plane strain (`Model/Planar model =
 * generalized plane strain`): its step state and the border of the Newton system.
 */
#pragma once

#include <ausroll/mechanics/model_parameters.h>

#include <deal.II/lac/trilinos_vector.h>

#include <cmath>

namespace ausroll::mechanics
{
  /**
   * Generalized plane strain: the out-of-plane stretch F_zz = lambda is one unknown of the whole
   * section (a uniform eps_zz, as Abaqus' CPE*G elements, CalculiX and MOOSE's
   * GeneralizedPlaneStrain with its scalar variable), conjugate to the axial force on the
   * section. Its equation is the axial equilibrium
   *
   *   r_lambda = int P_zz dV - L N_target = L (N - N_target) = 0,  N = int P_zz dA = int sigma_zz
   * da
   *
   * (L = `Model/Thickness`, dV = L dA; P_zz = J sigma_zz / lambda and da = J / lambda dA without
   * out-of-plane shear, so int P_zz dA is the force on the deformed section; with F-bar P is the
   * residual's stress kappa P(F_bar)). r_lambda = dPi/dlambda is the work-conjugate of lambda, so
   * the Newton system of (u, lambda) is the bordered one
   *
   *   [ K     k_ue ] [du     ]     [ r        ]     k_ue = dr/dlambda (a column, condensed
   *   [ k_eu  k_ee ] [dlambda] = - [ r_lambda ],    like the residual), k_eu = dr_lambda/du,
   *                                                 k_ee = dr_lambda/dlambda
   *
   * (solver/out_of_plane_solve.h solves it by the Schur complement on the scalar). The
   * InternalForce term adds the border from the 3x3 material tangent; PlanarKinematics reads
   * @ref stretch (the current iterate) for F_zz. The step state mirrors the displacement's
   * vectors in MechanicalSystem (stretch ~ solution, step_start, previous_start, newton_start,
   * increment); checkpoints keep step_start and previous_start. Inactive (all other planar
   * models and 3D) it stays lambda = 1 and is never assembled.
   */
  struct GeneralizedPlaneStrain
  {
    using Vector = dealii::TrilinosWrappers::MPI::Vector;

    bool   active = false;      ///< `Model/Planar model = generalized plane strain` (2D)
    double target = 0.;         ///< `Model/Axial force` N_target (N)
    double thickness = 1.;      ///< `Model/Thickness` L
    double stretch = 1.;        ///< lambda of the current iterate (PlanarKinematics reads it)
    double step_start = 1.;     ///< lambda of the last converged state
    double previous_start = 1.; ///< ... of the converged state before it (predictor)
    double newton_start = 1.;   ///< lambda at the last linear solve
    double increment = 0.;      ///< dlambda of the last linear solve

    // of the last assembly (Assembler::assemble with AssemblyTargets::out_of_plane)
    double axial_work = 0.; ///< int P_zz dV = L N
    double stiffness = 0.;  ///< k_ee (with a matrix)
    Vector column;          ///< k_ue, condensed with the Newton constraints and row transforms
    Vector row;             ///< k_eu, hanging-node condensed (dotted with distributed increments)

    /**
     * Set up from subsection `Model` (active for generalized plane strain in 2D) and return
     * the address of @ref stretch, which the kinematics reads (nullptr when inactive).
     */
    const double *configure(const ModelParameters &model, const int dim)
    {
      active = dim == 2 && model.planar_model == PlanarModel::generalized_plane_strain;
      target = model.axial_force;
      thickness = model.thickness;
      return active ? &stretch : nullptr;
    }

    /** The axial force N = int sigma_zz da of the last assembly (N). */
    double axial_force() const { return axial_work / thickness; }

    /** r_lambda = L (N - N_target) of the last assembly. */
    double residual() const { return axial_work - thickness * target; }

    /** N - N_target: the force the residual norm of the Newton iteration sees (N). */
    double force_error() const { return axial_force() - target; }
  };
} // namespace ausroll::mechanics
