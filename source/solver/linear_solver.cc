#include <ausroll/core/exceptions.h>
#include <ausroll/mechanics/rigid_body_modes.h>
#include <ausroll/solver/linear_solver.h>

#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <Amesos.h>
#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace ausroll::solver
{
  using namespace dealii;

  template <int dim>
  LinearSolverType automatic_solver_type(const LinearSolverParameters &parameters,
                                         const double                  n_dofs)
  {
    return AutomaticSolverChoice<dim>::iterative_from_threshold
                   && n_dofs >= parameters.automatic_iterative_threshold
               ? LinearSolverType::iterative
               : LinearSolverType::direct;
  }

  template <int dim>
  LinearSolver<dim>::LinearSolver(const LinearSolverParameters &parameters)
      : parameters(parameters)
      , amg_reuse(parameters.amg_reuse, parameters.amg_rebuild_factor)
  {
  }

  template <int dim>
  void LinearSolver<dim>::set_rigid_body_modes(const DoFHandler<dim> &dof_handler,
                                               const Mapping<dim>    &mapping)
  {
    const IndexSet &owned = dof_handler.locally_owned_dofs();
    const unsigned  n_modes = mechanics::n_rigid_body_modes<dim>;
    rigid_body_modes.assign(n_modes, std::vector<double>(owned.n_elements(), 0.));
    amg_reuse.invalidate(); // a kept AMG has the modes of the old DoFs

    std::map<types::global_dof_index, Point<dim>> points;
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, points);
    const FiniteElement<dim>            &fe = dof_handler.get_fe();
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          if (owned.is_element(dofs[i]))
          {
            const unsigned int c = fe.system_to_component_index(i).first;
            const unsigned int row = owned.index_within_set(dofs[i]);
            const Point<dim>  &x = points[dofs[i]];
            for (unsigned int m = 0; m < n_modes; ++m)
              rigid_body_modes[m][row] = mechanics::rigid_body_mode<dim>(m, c, x);
          }
      }
  }

  template <int dim>
  void LinearSolver<dim>::matrix_pattern_changed()
  {
    direct_solver.reset();
    direct_problem.reset();
    factored_matrix = nullptr;
    factored_package.clear();
    amg.reset();
    amg_matrix = nullptr;
    amg_reuse.invalidate();
  }

  template <int dim>
  void LinearSolver<dim>::set_pivot_reuse(const bool reuse) const
  {
    Teuchos::ParameterList list;
    list.set("Refactorize", reuse);
    direct_solver->SetParameters(list);
  }

  template <int dim>
  void LinearSolver<dim>::solve_direct(const TrilinosWrappers::SparseMatrix &A,
                                       const VectorList                     &xs,
                                       const ConstVectorList                &bs,
                                       const std::string                    &package) const
  {
    const Epetra_CrsMatrix &matrix = A.trilinos_matrix();
    if (!direct_solver || factored_matrix != &matrix || factored_package != package)
    {
      // new pattern (or package): analysis and symbolic factorisation
      direct_solver.reset();
      direct_problem = std::make_unique<Epetra_LinearProblem>();
      direct_problem->SetOperator(const_cast<Epetra_CrsMatrix *>(&matrix));
      Amesos factory;
      direct_solver.reset(factory.Create(package.c_str(), *direct_problem));
      AssertThrow(direct_solver, ExcMessage("Amesos package " + package + " is not available"));
      factored_matrix = nullptr;
      AssertThrow(direct_solver->SymbolicFactorization() == 0,
                  ExcMessage(package + ": symbolic factorisation failed"));
      factored_matrix = &matrix;
      factored_package = package;
      reuse_pivots = package == "Amesos_Klu";
      set_pivot_reuse(reuse_pivots);
    }
    try
    {
      const auto solve_one = [&](const unsigned int k)
      {
        direct_problem->SetLHS(&xs[k]->trilinos_vector());
        direct_problem->SetRHS(const_cast<Epetra_MultiVector *>(
            static_cast<const Epetra_MultiVector *>(&bs[k]->trilinos_vector())));
        AssertThrow(direct_solver->Solve() == 0, ExcMessage(package + ": solve failed"));
      };
      const auto factor_and_solve = [&]()
      {
        AssertThrow(direct_solver->NumericFactorization() == 0,
                    ExcMessage(package + ": numeric factorisation failed"));
        for (unsigned int k = 0; k < xs.size(); ++k)
          solve_one(k);
      };
      factor_and_solve();
      if (reuse_pivots)
      {
        // KLU refactorises with the pivot order of its last pivoting factorisation (Amesos
        // "Refactorize"; it falls back to pivoting by itself only when the diagonal of U is
        // nearly singular). The pivots of a status or tangent change may still be poor: check the
        // residual (one product with A, cheap against the factorisation) and factorise with
        // pivoting when it is not at round-off level. A relative linear residual of 1e-10 keeps
        // Newton quadratic down to its tolerance; on the gear scene the kept pivots leave
        // 4e-16 to 3e-13 (doc/benchmarks.md, "Direct solver: kept pivots").
        TrilinosWrappers::MPI::Vector &r = pivot_check_residual;
        bool                           accurate = true;
        for (unsigned int k = 0; k < xs.size() && accurate; ++k)
        {
          const TrilinosWrappers::MPI::Vector &b = *bs[k];
          if (r.size() != b.size() || r.locally_owned_elements() != b.locally_owned_elements())
            r.reinit(b, true);
          A.vmult(r, *xs[k]);
          r -= b;
          accurate = r.l2_norm() <= 1e-10 * b.l2_norm();
        }
        if (!accurate)
        {
          set_pivot_reuse(false);
          factor_and_solve();
          set_pivot_reuse(true);
          ++pivoting_refactorisations;
        }
      }
    }
    catch (...)
    {
      // start from a fresh analysis next time
      direct_solver.reset();
      direct_problem.reset();
      factored_matrix = nullptr;
      factored_package.clear();
      throw;
    }
  }

  template <int dim>
  LinearSolverType LinearSolver<dim>::resolved_type(const types::global_dof_index n_dofs) const
  {
    if (parameters.type != LinearSolverType::automatic)
      return parameters.type;
    return automatic_solver_type<dim>(parameters, double(n_dofs));
  }

  template <int dim>
  LinearSolveInfo LinearSolver<dim>::solve(const TrilinosWrappers::SparseMatrix &A,
                                           TrilinosWrappers::MPI::Vector        &x,
                                           const TrilinosWrappers::MPI::Vector  &b) const
  {
    return solve(A, VectorList{&x}, ConstVectorList{&b}, parameters.relative_tolerance);
  }

  template <int dim>
  LinearSolveInfo LinearSolver<dim>::solve(const TrilinosWrappers::SparseMatrix &A,
                                           TrilinosWrappers::MPI::Vector        &x,
                                           const TrilinosWrappers::MPI::Vector  &b,
                                           const double relative_tolerance) const
  {
    return solve(A, VectorList{&x}, ConstVectorList{&b}, relative_tolerance);
  }

  template <int dim>
  LinearSolveInfo LinearSolver<dim>::solve(const TrilinosWrappers::SparseMatrix &A,
                                           const VectorList                     &xs,
                                           const ConstVectorList                &bs) const
  {
    return solve(A, xs, bs, parameters.relative_tolerance);
  }

  template <int dim>
  void LinearSolver<dim>::set_up_amg(const TrilinosWrappers::SparseMatrix &A) const
  {
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic = true;
    data.higher_order_elements = true;
    data.smoother_sweeps = parameters.amg_smoother_sweeps;
    data.aggregation_threshold = parameters.amg_aggregation_threshold;
    data.smoother_type = parameters.amg_smoother_type.c_str();
    Teuchos::ParameterList              list;
    std::unique_ptr<Epetra_MultiVector> unused_modes;
    data.set_parameters(list, unused_modes, A.trilinos_matrix());

    // (an Epetra_MultiVector of no vectors throws: create it only when there are modes)
    const unsigned int                  n_local = A.local_range().second - A.local_range().first;
    std::unique_ptr<Epetra_MultiVector> modes;
    // ML's parameters must agree on every rank (its set-up reduces over them): use the modes
    // only if every rank has them for its rows
    const bool modes_here = !rigid_body_modes.empty() && rigid_body_modes[0].size() == n_local;
    double     dummy_mode_value = 0.;
    if (Utilities::MPI::min(modes_here ? 1u : 0u, A.get_mpi_communicator()) == 1u)
    {
      modes = std::make_unique<Epetra_MultiVector>(A.trilinos_matrix().DomainMap(),
                                                   rigid_body_modes.size());
      for (unsigned int m = 0; m < rigid_body_modes.size(); ++m)
        for (unsigned int i = 0; i < n_local; ++i)
          (*modes)[m][i] = rigid_body_modes[m][i];
      // aggregate nodes (the dim displacement DoFs of a support point are consecutive in
      // deal.II's FESystem numbering and owned by one rank), as ML expects for elasticity
      // (3D block, doc/benchmarks.md: 14 instead of 17 CG iterations and 1.0 instead of
      // 1.8 s CPU per solve at 1.1e5 DoFs)
      list.set("PDE equations", int(dim));
      list.set("null space: type", "pre-computed");
      list.set("null space: dimension", modes->NumVectors());
      // (a rank without rows still passes a valid pointer, as ML requires)
      list.set("null space: vectors", n_local > 0 ? modes->Values() : &dummy_mode_value);
    }
    amg.reset();
    amg_matrix = nullptr;
    auto fresh = std::make_unique<TrilinosWrappers::PreconditionAMG>();
    fresh->initialize(A, list);
    amg = std::move(fresh);
    amg_matrix = &A.trilinos_matrix();
    amg_reuse.set_up();
    ++amg_setups;
  }

  template <int dim>
  void LinearSolver<dim>::solve_iterative(const TrilinosWrappers::SparseMatrix &A,
                                          const VectorList                     &xs,
                                          const ConstVectorList                &bs,
                                          const double                          relative_tolerance,
                                          LinearSolveInfo                      &info) const
  {
    Timer timer;
    info.relative_tolerance = relative_tolerance;
    // a kept AMG belongs to this very matrix object (its finest level reads the current values)
    if (amg_matrix != &A.trilinos_matrix())
      amg_reuse.invalidate();
    const auto new_setup = [&]()
    {
      const double wall = timer.wall_time(), cpu = timer.cpu_time();
      set_up_amg(A);
      info.setup_seconds += timer.wall_time() - wall;
      info.setup_cpu_seconds += timer.cpu_time() - cpu;
      info.amg_setup = true;
    };
    if (!amg || amg_reuse.needs_setup())
      new_setup();

    // one Krylov solve per right-hand side with the one preconditioner; the message of a failure
    // (empty: converged)
    const auto krylov = [&](const unsigned int k) -> std::string
    {
      TrilinosWrappers::MPI::Vector       &x = *xs[k];
      const TrilinosWrappers::MPI::Vector &b = *bs[k];
      SolverControl control(parameters.max_iterations, relative_tolerance * b.l2_norm());
      x = 0.;
      try
      {
        if (parameters.krylov_method == KrylovMethod::cg)
        {
          SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
          cg.solve(A, x, b, *amg);
        }
        else
        {
          // right preconditioning: GMRES then measures the true residual |b - A x|, which the
          // tolerance refers to (left preconditioning stops on the preconditioned residual,
          // measured up to 1e3 times smaller than the true one for the 3D F-bar tangent)
          SolverGMRES<TrilinosWrappers::MPI::Vector> gmres(
              control,
              SolverGMRES<TrilinosWrappers::MPI::Vector>::AdditionalData(
                  parameters.restart, /*right_preconditioning=*/true));
          gmres.solve(A, x, b, *amg);
        }
      }
      catch (const SolverControl::NoConvergence &e)
      {
        info.iterations += e.last_step;
        std::ostringstream msg;
        msg << "linear solver failed: the iterative solve did not converge in " << e.last_step
            << " iterations (relative residual " << e.last_residual / b.l2_norm() << ", tolerance "
            << relative_tolerance << "): try Solver/Linear solver/Type = direct";
        return msg.str();
      }
      info.iterations += control.last_step();
      // the true residual: a Krylov method stops on its own (recursive) residual estimate;
      // accepted up to 100 x the tolerance (round-off of the recursion at tight tolerances),
      // and never above sqrt(tolerance) (a loose forcing term: still a contraction)
      TrilinosWrappers::MPI::Vector r(b);
      A.vmult(r, x);
      r.sadd(-1., 1., b);
      const double limit
          = std::min(100. * relative_tolerance, std::sqrt(relative_tolerance)) * b.l2_norm();
      if (!(r.l2_norm() <= limit || r.l2_norm() == 0.))
        return "linear solver failed: the iterative solve stopped at a true relative residual "
               + std::to_string(r.l2_norm() / b.l2_norm()) + " (tolerance "
               + std::to_string(relative_tolerance) + "): try Solver/Linear solver/Type = direct";
      amg_reuse.solved(control.last_step(), b.l2_norm() > 0. ? r.l2_norm() / b.l2_norm() : 0.);
      return std::string();
    };
    for (unsigned int k = 0; k < xs.size(); ++k)
    {
      std::string failure = krylov(k);
      if (!failure.empty() && !info.amg_setup)
      {
        // a kept AMG may be too far from this matrix: once more with a new one
        amg_reuse.invalidate();
        new_setup();
        failure = krylov(k);
      }
      if (!failure.empty())
      {
        amg_reuse.invalidate();
        throw IterativeSolveFailure(failure);
      }
    }
    if (!parameters.amg_reuse)
    {
      // (without reuse the hierarchy is not kept: the memory of a run stays that of one solve)
      amg.reset();
      amg_matrix = nullptr;
    }
  }

  template <int dim>
  LinearSolveInfo LinearSolver<dim>::solve(const TrilinosWrappers::SparseMatrix &A,
                                           const VectorList                     &xs,
                                           const ConstVectorList                &bs,
                                           const double relative_tolerance) const
  {
    AssertThrow(xs.size() == bs.size() && !xs.empty(), ExcInternalError());
    Timer           timer;
    LinearSolveInfo info;
    try
    {
      info.iterative = resolved_type(A.m()) == LinearSolverType::iterative;
      if (!info.iterative)
      {
        SolverControl control(1, 0.);
        // automatic: KLU on one rank for small systems (less set-up per solve; solver study in
        // doc/benchmarks.md: KLU 4.3 ms vs MUMPS 6.9 ms per solve at 1728 DoFs, equal near 10^4),
        // MUMPS otherwise (distributed, and 2-4x faster than KLU from 6e4 DoFs).
        // In 3D KLU only on the smallest systems: its fill-in grows much faster (3D block,
        // doc/benchmarks.md "3D linear solver": equal to MUMPS at 2187 DoFs, 7x slower at 14739).
        const bool mumps
            = parameters.direct_package == "MUMPS"
              || (parameters.direct_package == "automatic"
                  && (A.m() >= AutomaticSolverChoice<dim>::klu_limit
                      || Utilities::MPI::n_mpi_processes(A.get_mpi_communicator()) > 1));
        (void)control;
        try
        {
          solve_direct(A, xs, bs, mumps ? "Amesos_Mumps" : "Amesos_Klu");
        }
        catch (const std::exception &)
        {
          // MUMPS sizes its workspace from the analysis; the pivoting of a non-symmetric matrix
          // (F-bar, follower loads, friction) can exceed it (INFOG(1) = -9). KLU has no such
          // limit: retry with it before giving up.
          if (!mumps)
            throw;
          solve_direct(A, xs, bs, "Amesos_Klu");
        }
      }
      else
        solve_iterative(A, xs, bs, relative_tolerance, info);
    }
    catch (const IterativeSolveFailure &)
    {
      throw; // a failed attempt of the Newton step (see IterativeSolveFailure)
    }
    catch (const std::exception &e)
    {
      throw RunFailure(std::string("linear solver failed: ") + e.what());
    }
    info.seconds = timer.wall_time();
    info.cpu_seconds = timer.cpu_time();
    return info;
  }

  template LinearSolverType automatic_solver_type<2>(const LinearSolverParameters &, const double);
  template LinearSolverType automatic_solver_type<3>(const LinearSolverParameters &, const double);
  template class LinearSolver<2>;
  template class LinearSolver<3>;
} // namespace ausroll::solver
