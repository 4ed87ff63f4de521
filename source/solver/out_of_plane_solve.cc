#include <ausroll/core/exceptions.h>
#include <ausroll/solver/out_of_plane_solve.h>

#include <cmath>
#include <sstream>

namespace ausroll::solver
{
  using namespace dealii;

  template <int dim>
  LinearSolveInfo solve_out_of_plane_increment(const LinearSolver<dim>          &linear_solver,
                                               mechanics::MechanicalSystem<dim> &system)
  {
    using Vector = typename mechanics::MechanicalSystem<dim>::Vector;
    mechanics::GeneralizedPlaneStrain &gps = system.out_of_plane;
    gps.newton_start = gps.stretch;
    Vector x_e(system.owned_dofs, system.comm);
    system.increment = 0.;
    const LinearSolveInfo info = linear_solver.solve(
        system.system_matrix, {&system.increment, &x_e}, {&system.rhs, &gps.column});
    // x_r with the constraints' inhomogeneities g, x_e without: C x_e = distribute(x_e) - g
    Vector inhomogeneity(system.owned_dofs, system.comm);
    system.newton_constraints.distribute(inhomogeneity);
    system.newton_constraints.distribute(system.increment);
    system.newton_constraints.distribute(x_e);
    x_e -= inhomogeneity;
    const double schur = gps.stiffness - gps.row * x_e;
    if (!(std::abs(schur) > 0.) || !std::isfinite(schur))
    {
      std::ostringstream msg;
      msg << "generalized plane strain: the axial stiffness of the section vanishes (k_ee - k_eu "
             "K^-1 k_ue = "
          << schur << ")";
      throw RunFailure(msg.str());
    }
    gps.increment = (-gps.residual() - gps.row * system.increment) / schur;
    system.increment.add(-gps.increment, x_e);
    return info;
  }

  template LinearSolveInfo solve_out_of_plane_increment(const LinearSolver<2> &,
                                                        mechanics::MechanicalSystem<2> &);
  template LinearSolveInfo solve_out_of_plane_increment(const LinearSolver<3> &,
                                                        mechanics::MechanicalSystem<3> &);
} // namespace ausroll::solver
