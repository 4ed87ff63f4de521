/**
 * @file test_contact_3d.cc
 * Node-to-surface contact in 3D (ContactOperator<3> against a RigidSurface<3>, isotropic
 * friction cone), driven without a Scene: an elastic block (small strain, Q1) whose top is held
 * while a rigid `plane` die, read from a `Contact` text as a user writes it, presses its bottom,
 * slides along an oblique direction and is released. The load-step loop makes the calls of
 * Scene::assemble() / Scene::solve_step() / Scene::commit_step() with the real NewtonSolver and
 * each of the three strategies.
 *
 * References (exact, the tolerances are round-off of a converged Newton solve):
 *  - full slip: every bottom node slips along the die's relative motion, so the die's tangential
 *    force on the block is mu F_n e_s (e_s the unit slide direction of the die; the workpiece's
 *    slip direction is -e_s: the force is -mu F_n along it), 1e-9 relative; the top reaction
 *    balances it (global equilibrium, 1e-9);
 *  - stick before slip: after a small slide (below the elastic slip limit) nodes stick and
 *    |F_T| < mu F_n;
 *  - release: the die moves away, every node opens, no die force, and the elastic block returns
 *    to u = 0 (1e-12 of the slide);
 *  - 2D == 3D: a plane-strain slab (one element thick, u_z = 0 on both faces) against the 2D run
 *    of the same block and die: die force per unit thickness equal to 1e-10 relative in every
 *    step (the Q1 element with z-independent u reproduces the plane-strain element exactly).
 */
#include <ausroll/contact/contact_operator.h>
#include <ausroll/contact/contact_parameters.h>
#include <ausroll/contact/contact_strategy.h>
#include <ausroll/mechanics/boundary_conditions.h>
#include <ausroll/solver/linear_solver.h>
#include <ausroll/solver/newton_solver.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/fe/mapping_q.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "support/assembler_test_problem.h"

using namespace dealii;
using namespace ausroll;

namespace
{
  /** One converged load step. */
  template <int dim>
  struct StepRecord
  {
    double         t = 0.;
    Tensor<1, dim> die_force; ///< force of the die on the block
    Tensor<1, dim> top_force; ///< sum of the residual over the held top nodes (reaction)
    unsigned int   n_stick = 0, n_slip = 0;
    double         max_u = 0.; ///< max |u_i|
  };

  /**
   * An elastic block on a rigid die (the die and the boundary conditions from .prm texts), with
   * the contact calls of the scene around the real NewtonSolver.
   */
  template <int dim>
  class BlockOnDie : public solver::NonlinearProblem
  {
  public:
    /**
     * @p mesh: the block; @p contact_text, @p conditions_text: the `Contact` and
     * `Boundary conditions` subsections; @p top_id: the held boundary (its reaction is recorded).
     */
    BlockOnDie(const std::function<void(Triangulation<dim> &)> &mesh,
               const std::string                               &contact_text,
               const std::string                               &conditions_text,
               const unsigned int                               top_id)
        : problem(options(), mesh)
        , top(top_id)
    {
      ParameterHandler prm;
      contact::ContactParameters::declare_parameters(prm);
      mechanics::BoundaryConditionParameters::declare_parameters(prm);
      prm.parse_input_from_string(contact_text + conditions_text);
      contact::ContactParameters contact_parameters;
      contact_parameters.parse_parameters(prm, "");
      mechanics::BoundaryConditionParameters bc;
      bc.parse_parameters(prm);
      conditions = std::make_unique<mechanics::BoundaryConditions<dim>>(bc);
      contact = std::make_unique<contact::ContactOperator<dim>>(contact_parameters);
      contact->setup(
          problem.dof_handler, problem.mapping, [](const Point<dim> &) { return 1.; }, 0.5);
      strategy = contact::make_status_strategy(contact_parameters, *contact, true);
      u = problem.vector();
      u_committed = u;
      u_previous = u;
      start = u;
      increment = u;
    }

    // ---- NonlinearProblem (as Scene)
    bool assemble(const bool with_matrix, std::string &message) override
    {
      strategy->begin_iterate(time);
      for (;;)
      {
        strategy->update_geometry(u);
        newton.clear();
        newton.reinit(problem.all);
        conditions->add_increment_constraints(problem.dof_handler, time, u, newton);
        violation = 0.;
        for (const auto &line : newton.get_lines())
          violation = std::max(violation, std::abs(line.inhomogeneity));
        violation = std::max(violation, contact->add_constraints(u, newton));
        newton.close();
        const mechanics::AssemblyStatus status = problem.assemble(
            u, problem.targets(with_matrix, true), &newton, &contact->row_transforms());
        if (!status.ok)
        {
          message = status.message;
          return false;
        }
        contact->compute_reactions(problem.residual);
        if (strategy->update_at_iterate() == 0)
          break;
      }
      // as EquilibriumProblem::assemble(): the contact tangent terms (here the derivative of the
      // 3D slip direction)
      if (with_matrix)
        for (const auto &term : contact->tangent_terms())
          if (direction_tangent || term->name() != "slip direction")
            term->add_to(
                contact::ContactTangentInput<dim>{*contact, newton, u, problem.residual, time},
                problem.matrix,
                problem.rhs);
      double reaction_sq = 0.;
      for (unsigned int i = 0; i < problem.n_dofs(); ++i)
        if (newton.is_constrained(i))
          reaction_sq += problem.residual[i] * problem.residual[i];
      reference = std::max(problem.external.l2_norm(), std::sqrt(reaction_sq));
      largest_reference = std::max(largest_reference, reference);
      return true;
    }
    double residual_norm() const override { return problem.free_residual.l2_norm(); }
    double reference_force() const override
    {
      return std::max(reference, 1e-3 * largest_reference);
    }
    double                  constraint_violation() const override { return violation; }
    solver::LinearSolveInfo solve_for_increment() override
    {
      start = u;
      increment = 0.;
      const solver::LinearSolveInfo info
          = linear_solver.solve(problem.matrix, increment, problem.rhs);
      newton.distribute(increment);
      return info;
    }
    void apply_increment(const double step) override
    {
      u = start;
      u.add(step, increment);
    }
    double length_scale() const override { return 0.5; }
    double increment_residual_product() const override { return increment * problem.free_residual; }
    unsigned int update_constraints_at_convergence(ConditionalOStream &log) override
    {
      return strategy->update_at_convergence(u, log);
    }
    bool backtrack_with_small_constraint_gaps() const override
    {
      return strategy->backtrack_with_small_constraint_gaps();
    }

    /** Load steps of @p dt up to @p end_time (as Scene::run()); one record per step. */
    std::vector<StepRecord<dim>> run(const double dt_nominal, const double end_time)
    {
      ConditionalOStream log(std::cout, false);
      std::string        message;
      time = 0.;
      contact->set_time(0.);
      assemble(false, message);
      contact->commit(); // gaps of the undeformed state
      std::vector<StepRecord<dim>> records;
      double                       t_done = 0.;
      while (t_done < end_time * (1. - 1e-12) && records.size() < 400)
      {
        double dt = std::min(dt_nominal,
                             dt_nominal * (std::floor(t_done / dt_nominal + 1e-9) + 1.) - t_done);
        strategy->begin_step(u_committed, t_done);
        for (;;)
        {
          time = t_done + dt;
          u = u_committed;
          if (last_dt > 0.) // linear extrapolation predictor (Loading/Predictor default)
          {
            u.add(dt / last_dt, u_committed);
            u.add(-dt / last_dt, u_previous);
          }
          solver::SolverParameters p;
          p.residual_tolerance = 1e-13;
          p.absolute_tolerance = 1e-15;
          p.max_newton_iterations = 40;
          const solver::NewtonResult result = solver::NewtonSolver(p).solve(*this, log);
          EXPECT_TRUE(result.converged) << "t = " << time << ": " << result.reason;
          if (!result.converged)
            return records;
          const contact::StepDecision decision = strategy->end_of_step(dt, end_time, log);
          if (decision.accept)
            break;
          dt *= decision.step_factor;
        }
        for (const auto &cell : problem.tria.active_cell_iterators())
          for (const auto &point : problem.points.get_data(cell))
            point->commit();
        contact->commit();
        u_previous = u_committed;
        u_committed = u;
        last_dt = time - t_done;
        t_done = time;
        records.push_back(record());
      }
      return records;
    }

    /**
     * Finite-difference check of the Newton tangent at the current state u and time @p t (the
     * statuses as they are): central differences (step @p h) of the condensed free residual
     * along a random admissible direction w (free components in [-1, 1], constrained ones from
     * the homogeneous part of their constraint lines) against the assembled tangent times w, on
     * the free rows. Returns max_i |fd_i - (K w)_i| / max_i |(K w)_i|.
     */
    double tangent_error(const double t, const double h, const unsigned int seed)
    {
      std::string message;
      time = t;
      EXPECT_TRUE(assemble(true, message)) << message;
      TrilinosWrappers::MPI::Vector v = u, w = u, Kw = u, plus = u;
      v = 0.;
      std::mt19937                           rng(seed);
      std::uniform_real_distribution<double> uniform(-1., 1.);
      for (unsigned int i = 0; i < problem.n_dofs(); ++i)
        if (!newton.is_constrained(i))
          v[i] = uniform(rng);
      problem.matrix.vmult(Kw, v);
      w = v;
      for (const auto &line : newton.get_lines())
      {
        double value = 0.;
        for (const auto &entry : line.entries)
          value += entry.second * v[entry.first];
        w[line.index] = value;
      }
      const TrilinosWrappers::MPI::Vector u0 = u;
      u.add(h, w);
      EXPECT_TRUE(assemble(false, message)) << message;
      plus = problem.free_residual;
      u = u0;
      u.add(-h, w);
      EXPECT_TRUE(assemble(false, message)) << message;
      double largest = 0., error = 0.;
      for (unsigned int i = 0; i < problem.n_dofs(); ++i)
        if (!newton.is_constrained(i))
        {
          const double fd = (plus[i] - problem.free_residual[i]) / (2. * h);
          largest = std::max(largest, std::abs(Kw[i]));
          error = std::max(error, std::abs(fd - Kw[i]));
        }
      u = u0;
      EXPECT_TRUE(assemble(true, message)) << message;
      return error / largest;
    }

    std::unique_ptr<contact::ContactOperator<dim>> contact;
    /** Add the slip direction term of ContactOperator::tangent_terms() to the tangent (as the
        scene does). */
    bool direction_tangent = true;

  private:
    static test_support::AssemblerTestOptions options()
    {
      test_support::AssemblerTestOptions o;
      o.material.youngs_modulus = 1000.;
      o.material.poissons_ratio = 0.3;
      o.material.yield_stress = 1e9; // elastic
      return o;
    }

    StepRecord<dim> record() const
    {
      StepRecord<dim> r;
      r.t = time;
      const auto c = contact->die_contact(0);
      r.die_force = c.force;
      r.n_stick = c.n_stick;
      r.n_slip = c.n_slip;
      std::vector<types::global_dof_index> face_dofs(problem.fe.n_dofs_per_face());
      std::vector<bool>                    counted(problem.n_dofs(), false);
      for (const auto &cell : problem.dof_handler.active_cell_iterators())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == top)
          {
            cell->face(f)->get_dof_indices(face_dofs);
            for (unsigned int i = 0; i < face_dofs.size(); ++i)
              if (!counted[face_dofs[i]])
              {
                counted[face_dofs[i]] = true;
                r.top_force[problem.fe.face_system_to_component_index(i).first]
                    += problem.residual[face_dofs[i]];
              }
          }
      for (unsigned int i = 0; i < problem.n_dofs(); ++i)
        r.max_u = std::max(r.max_u, std::abs(u[i]));
      return r;
    }

    test_support::AssemblerTestProblem<dim>             problem;
    unsigned int                                        top;
    std::unique_ptr<mechanics::BoundaryConditions<dim>> conditions;
    std::unique_ptr<contact::StatusStrategy>            strategy;
    solver::LinearSolver<dim>     linear_solver{solver::LinearSolverParameters{}};
    AffineConstraints<double>     newton;
    TrilinosWrappers::MPI::Vector u, u_committed, u_previous, start, increment;
    double                        last_dt = 0.;
    double                        time = 0., violation = 0., reference = 0.;
    double                        largest_reference = 0.;
  };

  constexpr double mu = 0.3, delta = 0.002;

  /**
   * The die motion of the oblique slide: press by delta (t in [0, 1]), slide by 0.0006 along e_s
   * (t in [1, 2], below the slip limit), slide on at 0.04 per unit t (t in [2, 6], full slip;
   * the elastic transient of the start of sliding decays by ~0.2 per step of 0.01), release by
   * 2 delta (t in [6, 7]).
   */
  std::string slide_translation(const double phi_degrees)
  {
    const double c = std::cos(phi_degrees * M_PI / 180.), s = std::sin(phi_degrees * M_PI / 180.);
    const std::string a = "(0.0006 * min(max(t - 1, 0), 1) + 0.04 * min(max(t - 2, 0), 4))";
    char              text[512];
    std::snprintf(text,
                  sizeof(text),
                  "%.17g * %s; %.17g * %s; %g * min(t, 1) - %g * max(t - 6, 0)",
                  c,
                  a.c_str(),
                  s,
                  a.c_str(),
                  delta,
                  2 * delta);
    return text;
  }

  std::string plane_die(const std::string &strategy, const std::string &translation)
  {
    return "subsection Contact\nset Number of dies = 1\nset Strategy = " + strategy
           + "\nsubsection Die 0\nset Name = plate\nset Shape = plane\nset Friction = Coulomb\n"
             "subsection Coulomb\nset Friction coefficient = "
           + std::to_string(mu)
           + "\nend\nset Candidate boundaries = 4\nsubsection Plane\nset Point = 0, 0, 0\n"
             "set Normal = 0, 0, 1\nend\nsubsection Motion\nset Type = prescribed\n"
             "subsection Prescribed\nset Translation = "
           + translation + "\nend\nend\nend\nend\n";
  }

  const std::string held_top = "subsection Boundary conditions\nset Number of conditions = 1\n"
                               "subsection Condition 0\nset Boundary id = 5\nset Type = fixed\n"
                               "end\nend\n";

  void block_mesh(Triangulation<3> &tria)
  {
    GridGenerator::subdivided_hyper_rectangle(
        tria, {3, 3, 2}, Point<3>(0., 0., 0.), Point<3>(2., 2., 1.), true);
  }
} // namespace

// The oblique slide (30 degrees from x) with the active set and the nested active set: stick
// before slip, then the friction force vector mu F_n e_s (1e-9), balanced by the top reaction
// (1e-9), nothing left after release. (The load-increment ratio stalls here: the direction
// changes of the slipping edge nodes at the start of the slide shrink its sub-steps to ~1e-5 of a
// step; it is run on the plane-strain slab below.)
TEST(Contact3d, ObliqueSlideUnderPlaneIsotropicCone)
{
  const double       phi = 30. * M_PI / 180.;
  const Tensor<1, 3> e_s({std::cos(phi), std::sin(phi), 0.});
  for (const std::string strategy : {"active set", "nested active set"})
  {
    BlockOnDie<3> block(block_mesh, plane_die(strategy, slide_translation(30.)), held_top, 5);
    const auto    records = block.run(0.25, 7.);
    ASSERT_FALSE(records.empty());
    double worst_slip = 0., worst_balance = 0., stick_ratio = 0.;
    bool   saw_stick = false;
    for (const auto &r : records)
    {
      const double Fn = r.die_force[2];
      Tensor<1, 3> FT = r.die_force;
      FT[2] = 0.;
      if (std::abs(r.t - 2.) < 1e-12) // after the small slide
      {
        saw_stick = r.n_stick > 0;
        stick_ratio = FT.norm() / (mu * Fn);
      }
      if (r.t > 5.25 - 1e-12 && r.t < 6. + 1e-12) // full slip, after the transient
      {
        EXPECT_EQ(r.n_stick, 0u) << strategy << ", t = " << r.t;
        worst_slip = std::max(worst_slip, (FT - mu * Fn * e_s).norm() / (mu * Fn));
        worst_balance
            = std::max(worst_balance, (r.die_force + r.top_force).norm() / r.die_force.norm());
      }
    }
    const auto &last = records.back();
    std::printf(
        "[ contact3d ] %s: %zu steps; t = 2: %u sticking, |F_T| / mu F_n = %.4f; full slip: "
        "|F_T - mu F_n e_s| / mu F_n = %.1e, |F_die + F_top| / |F_die| = %.1e; released: "
        "%u closed, |F| = %.1e, max |u| = %.1e\n",
        strategy.c_str(),
        records.size(),
        saw_stick ? 1u : 0u,
        stick_ratio,
        worst_slip,
        worst_balance,
        last.n_stick + last.n_slip,
        last.die_force.norm(),
        last.max_u);
    EXPECT_TRUE(saw_stick) << strategy;
    EXPECT_GT(stick_ratio, 0.05) << strategy;
    EXPECT_LT(stick_ratio, 0.9) << strategy;
    EXPECT_LT(worst_slip, 1e-9) << strategy;
    EXPECT_LT(worst_balance, 1e-9) << strategy;
    EXPECT_EQ(last.n_stick + last.n_slip, 0u) << strategy;
    EXPECT_EQ(last.die_force.norm(), 0.) << strategy;
    EXPECT_LT(last.max_u, 1e-12) << strategy;
  }
}

namespace
{
  /** Friction coefficient of the slab: no node slips while it is pressed (the largest
      |R_t| / R_n then is 0.42, at the corners), so the slide starts from sticking nodes (a
      corner node that slid outward while pressed and reverses at the start of the slide is
      where the 2D sign rule and the 3D direction rule differ: the 3D direction follows the slip
      of the previous step, the 2D sign is kept). */
  constexpr double slab_mu = 0.5;

  /** The die force per step of a block [0, 2] x [0, 1] (x [0, 0.5]) pressed by delta and slid
      along x by 0.04 per unit t (t in [1, 3]) by a flat (2D) / plane (3D) die at y = 0; top
      y = 1 held; 3D: u_z = 0 on both faces z = 0, 0.5 (plane strain). */
  template <int dim>
  std::vector<StepRecord<dim>> slab(const std::string &strategy)
  {
    const std::string slide = "0.04 * min(max(t - 1, 0), 4)";
    const std::string press = std::to_string(delta) + " * min(t, 1)";
    std::string contact = "subsection Contact\nset Number of dies = 1\nset Strategy = " + strategy
                          + "\nsubsection Die 0\nset Name = plate\nset Friction = Coulomb\n"
                            "subsection Coulomb\nset Friction coefficient = "
                          + std::to_string(slab_mu) + "\nend\nset Candidate boundaries = 2\n";
    std::string conditions = "subsection Boundary conditions\nset Number of conditions = "
                             + std::string(dim == 2 ? "1" : "3")
                             + "\nsubsection Condition 0\nset Boundary id = 3\nset Type = fixed\n"
                               "end\n";
    if constexpr (dim == 2)
      contact
          += "set Shape = flat\nsubsection Flat\nset Point = 0, 0\nset Normal = 0, 1\nend\n"
             "subsection Motion\nset Type = prescribed\nsubsection Prescribed\nset Translation = "
             + slide + "; " + press + "\nend\nend\nend\nend\n";
    else
    {
      contact += "set Shape = plane\nsubsection Plane\nset Point = 0, 0, 0\nset Normal = 0, 1, 0\n"
                 "end\nsubsection Motion\nset Type = prescribed\nsubsection Prescribed\n"
                 "set Translation = "
                 + slide + "; " + press + "; 0\nend\nend\nend\nend\n";
      for (const unsigned int id : {4u, 5u})
        conditions += "subsection Condition " + std::to_string(id - 3)
                      + "\nset Boundary id = " + std::to_string(id)
                      + "\nset Type = displacement\nset Components = z\nset Value = 0\nend\n";
    }
    conditions += "end\n";
    const auto mesh = [](Triangulation<dim> &tria)
    {
      if constexpr (dim == 2)
        GridGenerator::subdivided_hyper_rectangle(
            tria, {4, 2}, Point<2>(0., 0.), Point<2>(2., 1.), true);
      else
        GridGenerator::subdivided_hyper_rectangle(
            tria, {4, 2, 1}, Point<3>(0., 0., 0.), Point<3>(2., 1., 0.5), true);
    };
    BlockOnDie<dim> block(mesh, contact, conditions, 3);
    return block.run(0.25, 5.);
  }
} // namespace

// 2D == 3D: the plane-strain slab against the 2D run. Active set and load-increment ratio: die
// force per unit thickness (3D / 0.5) equal to 1e-10 of |F| in every step, twice the sticking and
// slipping nodes; in full slip F_x = mu F_y (1e-9). Nested active set: equal while the slab is
// pressed (t <= 1); once it slides, the 3D rule that a sticking node whose (unsolved) reaction
// leaves the cone slips before it may open lets every node slip (F_x = mu F_y, 1e-9), while the
// 2D rule (tension first) keeps the leading corner node sticking (F_x / F_y = 0.465 < mu).
TEST(Contact3d, PlaneStrainSlabEqualsTwoDimensionalRun)
{
  for (const std::string strategy : {"active set", "nested active set", "load increment ratio"})
  {
    const auto two = slab<2>(strategy);
    const auto three = slab<3>(strategy);
    ASSERT_EQ(two.size(), three.size()) << strategy;
    const bool same_rules = strategy != "nested active set";
    double     worst = 0., worst_slip = 0.;
    bool       slipped = false;
    for (unsigned int i = 0; i < two.size(); ++i)
    {
      EXPECT_NEAR(two[i].t, three[i].t, 1e-12) << strategy;
      EXPECT_NEAR(three[i].die_force[2], 0., 1e-10 * two[i].die_force.norm()) << strategy;
      if (!same_rules && two[i].t > 1. + 1e-12)
      {
        if (three[i].n_stick == 0)
        {
          slipped = true;
          worst_slip = std::max(worst_slip,
                                std::abs(three[i].die_force[0] - slab_mu * three[i].die_force[1])
                                    / three[i].die_force[1]);
        }
        continue;
      }
      EXPECT_EQ(2 * two[i].n_stick, three[i].n_stick) << strategy << ", t = " << two[i].t;
      EXPECT_EQ(2 * two[i].n_slip, three[i].n_slip) << strategy << ", t = " << two[i].t;
      const Tensor<1, 2> f3({three[i].die_force[0] / 0.5, three[i].die_force[1] / 0.5});
      worst = std::max(worst, (f3 - two[i].die_force).norm() / two[i].die_force.norm());
      if (two[i].n_stick == 0 && two[i].n_slip > 0)
      {
        slipped = true;
        worst_slip = std::max(worst_slip,
                              std::abs(two[i].die_force[0] - slab_mu * two[i].die_force[1])
                                  / two[i].die_force[1]);
      }
    }
    std::printf("[ contact3d ] slab, %s: %zu steps, max |F_3D / w - F_2D| / |F_2D| = %.1e%s, "
                "full slip |F_x - mu F_y| / F_y = %.1e\n",
                strategy.c_str(),
                two.size(),
                worst,
                same_rules ? "" : " (t <= 1)",
                worst_slip);
    EXPECT_LT(worst, 1e-10) << strategy;
    if (strategy != "active set") // the active set keeps a sticking corner node in 2D and 3D
    {
      EXPECT_TRUE(slipped) << strategy;
      EXPECT_LT(worst_slip, 1e-9) << strategy;
    }
  }
}

// The tangent of a slipping node's friction force -mu R_n d with d = s / |s| following the slip
// s of the step (contact::SlipDirectionTangent): the oblique slide in full slip
// (t = 4), evaluated a quarter step later (the die has moved 0.01 along e_s, each bottom node has
// slipped 0.01 > slip_length = 5e-3 relative to it). The elastic block is linear, so the only
// nonlinear terms are the contact ones: central differences (h = 1e-6, truncation ~ (h/|s|)^2
// = 1e-8, round-off ~ 1e-13) must match the assembled tangent to 1e-6 of its largest entry of
// K w; without the direction term the tangent misses T / |s| (P - d (x) d) (a few per cent).
// The active set, whose directions follow the slip at every iterate; the nested active set adds
// the same term once a node's direction follows (after its first turn at a converged state of
// the step: at the first iterate of a step, as here, its directions are held and have no
// derivative, which the check confirms with the term and without it).
TEST(Contact3d, SlipDirectionTangentMatchesFiniteDifferences)
{
  for (const std::string strategy : {"active set", "nested active set"})
  {
    BlockOnDie<3> block(block_mesh, plane_die(strategy, slide_translation(30.)), held_top, 5);
    const auto    records = block.run(0.25, 4.);
    ASSERT_FALSE(records.empty());
    ASSERT_EQ(records.back().n_stick, 0u) << strategy;
    ASSERT_GT(records.back().n_slip, 0u) << strategy;
    const double with = block.tangent_error(4.25, 1e-6, 7);
    block.direction_tangent = false;
    const double without = block.tangent_error(4.25, 1e-6, 7);
    std::printf("[ contact3d ] %s: slip direction tangent, finite-difference error %.1e (without "
                "the direction term %.1e)\n",
                strategy.c_str(),
                with,
                without);
    EXPECT_LT(with, 1e-6) << strategy;
    if (strategy == "active set")
      EXPECT_GT(without, 1e-3) << strategy;
    else
      EXPECT_LT(without, 1e-6) << strategy;
  }
}
