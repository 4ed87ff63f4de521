#include <ausroll/core/exceptions.h>
#include <ausroll/core/parse_utilities.h>
#include <ausroll/thermal/thermal_system.h>

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/numerics/vector_tools.h>

#include <limits>
#include <unordered_map>

namespace ausroll::thermal
{
  using namespace dealii;

  namespace
  {
    std::string variables(const int dim, const bool with_time)
    {
      const std::string space = dim == 2 ? "x,y" : "x,y,z";
      return with_time ? space + ",t" : space;
    }

    template <int dim>
    std::unique_ptr<FunctionParser<dim>>
    make_parser(const std::string &expression, const std::string &entry, const bool with_time)
    {
      auto parser = std::make_unique<FunctionParser<dim>>(1);
      try
      {
        parser->initialize(variables(dim, with_time),
                           expression,
                           std::map<std::string, double>{{"pi", numbers::PI}},
                           with_time);
        parser->set_time(0.);
        const double v = parser->value(Point<dim>());
        if (!std::isfinite(v))
          throw InputError(entry + ": '" + abbreviate(expression)
                           + "' is not finite at the origin");
      }
      catch (const InputError &)
      {
        throw;
      }
      catch (...)
      {
        throw InputError(entry + ": cannot parse '" + abbreviate(expression)
                         + "' (variables: " + variables(dim, with_time) + ", pi)");
      }
      return parser;
    }
  } // namespace

  template <int dim>
  ThermalSystem<dim>::ThermalSystem(const ThermalParameters                   &prm,
                                    parallel::distributed::Triangulation<dim> &tria,
                                    const Mapping<dim>                        &map,
                                    const unsigned int                         degree,
                                    const Quadrature<dim>                     &q,
                                    Kinematics                                 kin,
                                    const unsigned int                         n_dies,
                                    const MPI_Comm                             communicator)
      : parameters(prm)
      , comm(communicator)
      , fe(degree)
      , dof_handler(tria)
      , triangulation(tria)
      , mapping(map)
      , quadrature(q)
      , kinematics(std::move(kin))
  {
    conditions = parameters.conditions;
    for (unsigned int i = 0; i < parameters.conditions.size(); ++i)
      values.push_back(make_parser<dim>(parameters.conditions[i].value,
                                        "Thermal/Condition " + std::to_string(i) + "/Value",
                                        true));
    // checked now so that the error comes before anything is written
    make_parser<dim>(parameters.initial_temperature, "Thermal/Initial temperature", false);
    balance.boundary_heat.assign(parameters.conditions.size(), 0.);
    balance.die_heat.assign(n_dies, 0.);
    const auto &expressions = parameters.die_temperatures;
    require(expressions.size() == 1 || expressions.size() == n_dies,
            "Thermal/Die temperatures",
            "needs one expression per die (Contact/Number of dies = " + std::to_string(n_dies)
                + ") or one for all, found " + std::to_string(expressions.size()));
    for (unsigned int k = 0; k < n_dies; ++k)
    {
      const std::string expression = expressions[expressions.size() == 1 ? 0 : k];
      auto              parser = std::make_unique<FunctionParser<1>>(1);
      try
      {
        parser->initialize("t", expression, std::map<std::string, double>{{"pi", numbers::PI}});
      }
      catch (...)
      {
        throw InputError("Thermal/Die temperatures: cannot parse '" + abbreviate(expression)
                         + "' (variable: t, pi)");
      }
      die_temperatures.push_back(std::move(parser));
    }
  }

  template <int dim>
  void ThermalSystem<dim>::make_constraints(const double t)
  {
    constraints.clear();
    constraints.reinit(relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    for (unsigned int i = 0; i < conditions.size(); ++i)
      if (conditions[i].type == ThermalConditionType::temperature)
      {
        values[i]->set_time(t);
        VectorTools::interpolate_boundary_values(
            mapping, dof_handler, conditions[i].id, *values[i], constraints);
      }
    constraints.close();
  }

  template <int dim>
  void ThermalSystem<dim>::set_conditions(const std::vector<ThermalCondition> &stage_conditions,
                                          const std::string                   &entry)
  {
    AssertDimension(stage_conditions.size(), conditions.size());
    for (unsigned int i = 0; i < conditions.size(); ++i)
    {
      Assert(stage_conditions[i].id == conditions[i].id
                 && stage_conditions[i].type == conditions[i].type,
             ExcInternalError());
      if (stage_conditions[i].value != conditions[i].value)
        values[i] = make_parser<dim>(stage_conditions[i].value, entry, true);
    }
    conditions = stage_conditions;
  }

  template <int dim>
  void ThermalSystem<dim>::setup()
  {
    dof_handler.distribute_dofs(fe);
    owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant_dofs);
    make_constraints(0.);
    DynamicSparsityPattern dsp(relevant_dofs);
    // all couplings, so that the pattern holds for the Dirichlet values of every time
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, true);
    SparsityTools::distribute_sparsity_pattern(dsp, owned_dofs, comm, relevant_dofs);
    matrix.reinit(owned_dofs, owned_dofs, dsp, comm);
    temperature.reinit(owned_dofs, relevant_dofs, comm);
    committed_temperature.reinit(owned_dofs, relevant_dofs, comm);
    temperature_rate.reinit(owned_dofs, relevant_dofs, comm);
    rhs.reinit(owned_dofs, comm);
  }

  template <int dim>
  void ThermalSystem<dim>::check_die_temperatures(const double end_time) const
  {
    for (unsigned int k = 0; k < die_temperatures.size(); ++k)
      for (unsigned int i = 0; i <= 100; ++i)
      {
        const double t = end_time * i / 100.;
        const double T = die_temperatures[k]->value(Point<1>(t));
        if (!std::isfinite(T))
          throw InputError("Thermal/Die temperatures: the temperature of die " + std::to_string(k)
                           + " is not finite at t = " + std::to_string(t));
      }
  }

  template <int dim>
  void ThermalSystem<dim>::initialize()
  {
    const auto initial
        = make_parser<dim>(parameters.initial_temperature, "Thermal/Initial temperature", false);
    Vector owned(owned_dofs, comm);
    VectorTools::interpolate(mapping, dof_handler, *initial, owned);
    temperature = owned;
    committed_temperature = owned;
    temperature_rate = 0.;
  }

  template <int dim>
  void ThermalSystem<dim>::commit()
  {
    committed_temperature = temperature;
  }

  template <int dim>
  void ThermalSystem<dim>::restore()
  {
    temperature = committed_temperature;
  }

  template <int dim>
  void ThermalSystem<dim>::assemble(const double                t,
                                    const double                dt,
                                    const DoFHandler<dim>      &displacement_dofs,
                                    const Vector               &displacement,
                                    const PointStorage         &points,
                                    const Vector               &T_old,
                                    const std::vector<Contact> &contacts,
                                    Vector                     *residual)
  {
    const bool         matrix_wanted = residual == nullptr;
    const unsigned int n = fe.n_dofs_per_cell();
    const unsigned int n_q = quadrature.size();
    FEValues<dim>      fe_values(mapping,
                            fe,
                            quadrature,
                            update_values | update_gradients | update_quadrature_points
                                | update_JxW_values);
    FEValues<dim>      displacement_values(
        mapping, displacement_dofs.get_fe(), quadrature, update_values | update_gradients);
    const QGauss<dim - 1> face_quadrature(fe.degree + 1);
    FEFaceValues<dim>     face_values(
        mapping, fe, face_quadrature, update_values | update_quadrature_points | update_JxW_values);
    const FEValuesExtractors::Vector     u_extractor(0);
    FullMatrix<double>                   cell_matrix(n, n);
    dealii::Vector<double>               cell_rhs(n), cell_T(n), cell_T_old(n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<double>                  T_q(n_q), T_old_q(n_q);
    std::vector<Tensor<1, dim>>          grad_T_q(n_q);
    std::vector<Tensor<2, dim>>          grad_u(n_q);
    std::vector<Tensor<1, dim>>          u(n_q);
    std::vector<double>                  T_face(face_quadrature.size());
    const AffineConstraints<double>      no_constraints;
    const double                         beta = parameters.taylor_quinney;
    const double                         L_M = parameters.latent_heat_martensite;
    const double                         L_B = parameters.latent_heat_bainite;
    const bool                           latent = L_M > 0. || L_B > 0.;

    if (matrix_wanted)
    {
      matrix = 0.;
      rhs = 0.;
      balance.plastic_heat = 0.; // summed in this pass
    }
    else
    {
      *residual = 0.;
      std::fill(balance.boundary_heat.begin(), balance.boundary_heat.end(), 0.); // and in this
    }

    for (const auto &cell : dof_handler.active_cell_iterators())
    {
      if (!cell->is_locally_owned())
        continue;
      fe_values.reinit(cell);
      const typename DoFHandler<dim>::active_cell_iterator mechanical_cell(
          &triangulation, cell->level(), cell->index(), &displacement_dofs);
      const bool finite = static_cast<bool>(kinematics.deformation_gradient);
      if (finite)
      {
        displacement_values.reinit(mechanical_cell);
        displacement_values[u_extractor].get_function_gradients(displacement, grad_u);
        displacement_values[u_extractor].get_function_values(displacement, u);
      }
      fe_values.get_function_values(T_old, T_old_q);
      if (!matrix_wanted)
      {
        fe_values.get_function_values(temperature, T_q);
        fe_values.get_function_gradients(temperature, grad_T_q);
      }
      const auto material_points = points.get_data(cell);
      cell_matrix = 0.;
      cell_rhs = 0.;
      for (unsigned int q = 0; q < n_q; ++q)
      {
        const Point<dim> &X = fe_values.quadrature_point(q);
        const double      dV = fe_values.JxW(q) * kinematics.volume_factor(X);
        const double      T0 = T_old_q[q];
        const double   capacity = parameters.density.value(T0) * parameters.specific_heat.value(T0);
        const double   k = parameters.conductivity.value(T0);
        Tensor<2, dim> K;
        if (finite)
        {
          const Tensor<2, 3> F = kinematics.deformation_gradient(grad_u[q], u[q], X);
          const Tensor<2, 3> F_inv = invert(F);
          const Tensor<2, 3> K3 = k * determinant(F) * F_inv * transpose(F_inv);
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = 0; j < dim; ++j)
              K[i][j] = K3[i][j];
        }
        else
          for (unsigned int i = 0; i < dim; ++i)
            K[i][i] = k;
        const material::MaterialPoint &point = *material_points[q];
        // plastic heating of the step: the trial state is the converged one, not yet committed
        const double plastic
            = beta * (point.trial.plastic_work - point.committed.plastic_work) / dt;
        if (matrix_wanted)
          balance.plastic_heat += plastic * dV;
        // latent heat of the phases formed in the step (Phases/Latent heat; not in heat_plastic)
        const double source
            = latent ? plastic
                           + parameters.density.value(T0)
                                 * (L_M * (point.trial.martensite - point.committed.martensite)
                                    + L_B * (point.trial.bainite - point.committed.bainite))
                                 / dt
                     : plastic;
        for (unsigned int i = 0; i < n; ++i)
        {
          const double         phi_i = fe_values.shape_value(i, q);
          const Tensor<1, dim> K_grad_i = K * fe_values.shape_grad(i, q);
          if (matrix_wanted)
          {
            for (unsigned int j = 0; j < n; ++j)
              cell_matrix(i, j) += (capacity / dt * phi_i * fe_values.shape_value(j, q)
                                    + K_grad_i * fe_values.shape_grad(j, q))
                                   * dV;
            cell_rhs(i) += (capacity / dt * T0 + source) * phi_i * dV;
          }
          else // residual of the solved step (K is symmetric: K grad phi . grad T)
            cell_rhs(i)
                += (capacity / dt * (T_q[q] - T0) * phi_i + K_grad_i * grad_T_q[q] - source * phi_i)
                   * dV;
        }
      }
      // convection and prescribed flux
      for (const auto f : cell->face_indices())
      {
        if (!cell->face(f)->at_boundary())
          continue;
        for (unsigned int c = 0; c < conditions.size(); ++c)
        {
          const ThermalCondition &condition = conditions[c];
          if (cell->face(f)->boundary_id() != condition.id
              || condition.type == ThermalConditionType::temperature)
            continue;
          face_values.reinit(cell, f);
          face_values.get_function_values(matrix_wanted ? T_old : temperature, T_face);
          values[c]->set_time(t);
          for (unsigned int q = 0; q < face_quadrature.size(); ++q)
          {
            const Point<dim> &X = face_values.quadrature_point(q);
            const double      dA = face_values.JxW(q) * kinematics.volume_factor(X);
            const double      value = values[c]->value(X);
            const double      h = condition.heat_transfer_coefficient;
            for (unsigned int i = 0; i < n; ++i)
            {
              const double phi_i = face_values.shape_value(i, q);
              if (condition.type == ThermalConditionType::flux)
                cell_rhs(i) += (matrix_wanted ? 1. : -1.) * value * phi_i * dA;
              else if (matrix_wanted)
              {
                for (unsigned int j = 0; j < n; ++j)
                  cell_matrix(i, j) += h * phi_i * face_values.shape_value(j, q) * dA;
                cell_rhs(i) += h * value * phi_i * dA;
              }
              else
                cell_rhs(i) -= h * (value - T_face[q]) * phi_i * dA;
            }
            if (!matrix_wanted)
              balance.boundary_heat[c]
                  += (condition.type == ThermalConditionType::flux ? value
                                                                   : h * (value - T_face[q]))
                     * dA;
          }
        }
      }
      cell->get_dof_indices(dofs);
      if (matrix_wanted)
        constraints.distribute_local_to_global(cell_matrix, cell_rhs, dofs, matrix, rhs);
      else
        no_constraints.distribute_local_to_global(cell_rhs, dofs, *residual);
    }
    add_contact_terms(t, dt, displacement_dofs, contacts, residual);
    if (matrix_wanted)
    {
      matrix.compress(VectorOperation::add);
      rhs.compress(VectorOperation::add);
    }
    else
      residual->compress(VectorOperation::add);
  }

  template <int dim>
  void ThermalSystem<dim>::add_contact_terms(const double                t,
                                             const double                dt,
                                             const DoFHandler<dim>      &displacement_dofs,
                                             const std::vector<Contact> &contacts,
                                             Vector                     *residual)
  {
    std::fill(balance.die_heat.begin(), balance.die_heat.end(), 0.);
    // No early return on a rank without contact nodes: the die heat is summed over all ranks.
    // The temperature DoF at each contact node: the displacement x DoF of base index i of a
    // cell sits where the temperature DoF i of that cell sits (same degree, same mesh)
    std::unordered_map<types::global_dof_index, types::global_dof_index> thermal_dof;
    const FiniteElement<dim>            &mechanical_fe = displacement_dofs.get_fe();
    std::vector<types::global_dof_index> mechanical(mechanical_fe.n_dofs_per_cell()),
        own(fe.n_dofs_per_cell());
    if (!contacts.empty())
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          const typename DoFHandler<dim>::active_cell_iterator mechanical_cell(
              &triangulation, cell->level(), cell->index(), &displacement_dofs);
          mechanical_cell->get_dof_indices(mechanical);
          cell->get_dof_indices(own);
          for (unsigned int j = 0; j < mechanical.size(); ++j)
          {
            const auto [component, i] = mechanical_fe.system_to_component_index(j);
            if (component == 0)
              thermal_dof[mechanical[j]] = own[i];
          }
        }
    const double                         h = parameters.contact_conductance;
    const double                         eta = parameters.friction_heat_partition;
    FullMatrix<double>                   m(1, 1);
    dealii::Vector<double>               r(1);
    std::vector<types::global_dof_index> dof(1);
    for (const Contact &c : contacts)
    {
      const auto found = thermal_dof.find(c.dof);
      AssertThrow(found != thermal_dof.end(),
                  ExcMessage("ThermalSystem: a contact node has no temperature DoF"));
      dof[0] = found->second;
      die_temperatures[c.die]->set_time(0.);
      const double T_die = die_temperatures[c.die]->value(Point<1>(t));
      if (!std::isfinite(T_die))
        throw InputError("Thermal/Die temperatures: the temperature of die " + std::to_string(c.die)
                         + " is not finite at t = " + std::to_string(t));
      const double friction = eta * c.friction_work / dt;
      if (residual == nullptr)
      {
        m(0, 0) = h * c.area;
        r(0) = h * c.area * T_die + friction;
        constraints.distribute_local_to_global(m, r, dof, matrix, rhs);
      }
      else
      {
        const double heat = h * c.area * (T_die - temperature(dof[0])) + friction;
        r(0) = -heat;
        AffineConstraints<double>().distribute_local_to_global(r, dof, *residual);
        balance.die_heat[c.die] += heat;
      }
    }
    if (residual != nullptr)
      for (double &heat : balance.die_heat)
        heat = Utilities::MPI::sum(heat, comm);
    else
      for (unsigned int k = 0; k < balance.die_heat.size(); ++k)
        balance.die_heat[k] = 0.;
  }

  template <int dim>
  void ThermalSystem<dim>::solve_step(const double                t,
                                      const double                dt,
                                      const DoFHandler<dim>      &displacement_dofs,
                                      const Vector               &displacement,
                                      const PointStorage         &points,
                                      const std::vector<Contact> &contacts)
  {
    AssertThrow(dt > 0., ExcMessage("ThermalSystem::solve_step: step size must be positive"));
    const Vector &T_old = committed_temperature;
    Vector        previous(owned_dofs, comm);
    previous = temperature;
    make_constraints(t);
    assemble(t, dt, displacement_dofs, displacement, points, T_old, contacts, nullptr);

    Vector solution(owned_dofs, comm);
    solution = T_old;
    constraints.set_zero(solution);
    SolverControl                                     control(1000, 1e-12 * rhs.l2_norm() + 1e-300);
    TrilinosWrappers::PreconditionAMG                 amg;
    TrilinosWrappers::PreconditionAMG::AdditionalData amg_data;
    amg_data.elliptic = true;
    amg_data.higher_order_elements = fe.degree > 1;
    amg_data.smoother_sweeps = 2;
    amg.initialize(matrix, amg_data);
    SolverCG<Vector> cg(control);
    try
    {
      cg.solve(matrix, solution, rhs, amg);
    }
    catch (const SolverControl::NoConvergence &e)
    {
      throw RunFailure("the heat equation at t = " + std::to_string(t)
                       + " did not converge (CG with AMG, residual "
                       + std::to_string(e.last_residual) + " after " + std::to_string(e.last_step)
                       + " iterations)");
    }
    constraints.distribute(solution);
    temperature = solution;
    previous -= solution;
    last_change = previous.linfty_norm();
    Vector rate(owned_dofs, comm);
    rate = solution;
    Vector old_owned(owned_dofs, comm);
    old_owned = T_old;
    rate -= old_owned;
    rate /= dt;
    temperature_rate = rate;

    // heat flows of the step: boundary integrals and the reactions of prescribed temperatures
    Vector residual;
    residual.reinit(owned_dofs, relevant_dofs, comm, true);
    assemble(t, dt, displacement_dofs, displacement, points, T_old, contacts, &residual);
    Vector owned_residual(owned_dofs, comm);
    owned_residual = residual;
    std::vector<bool> counted(owned_dofs.n_elements(), false);
    for (unsigned int c = 0; c < conditions.size(); ++c)
      if (conditions[c].type == ThermalConditionType::temperature)
      {
        const IndexSet boundary_dofs
            = DoFTools::extract_boundary_dofs(dof_handler, ComponentMask(), {conditions[c].id});
        double heat = 0.;
        for (const auto i : boundary_dofs)
          if (owned_dofs.is_element(i) && !counted[owned_dofs.index_within_set(i)])
          {
            counted[owned_dofs.index_within_set(i)] = true;
            heat += owned_residual(i);
          }
        balance.boundary_heat[c] = heat;
      }
    balance.plastic_heat = Utilities::MPI::sum(balance.plastic_heat, comm);
    for (double &heat : balance.boundary_heat)
      heat = Utilities::MPI::sum(heat, comm);
  }

  template <int dim>
  template <typename Write>
  void ThermalSystem<dim>::write_point_temperatures(PointStorage &points, const Write &write) const
  {
    FEValues<dim>       fe_values(mapping, fe, quadrature, update_values);
    std::vector<double> T(quadrature.size());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        fe_values.reinit(cell);
        fe_values.get_function_values(temperature, T);
        const auto material_points = points.get_data(cell);
        for (unsigned int q = 0; q < T.size(); ++q)
          write(*material_points[q], T[q]);
      }
  }

  template <int dim>
  void ThermalSystem<dim>::set_point_temperatures(PointStorage &points,
                                                  const bool    committed_too) const
  {
    const double reference = parameters.expansion.reference_temperature;
    write_point_temperatures(
        points,
        [committed_too, reference](material::MaterialPoint &point, const double T)
        {
          point.trial.temperature = T;
          if (committed_too)
          {
            // the initial state F = I excludes no thermal stretch: that of
            // the reference (stress-free) temperature
            point.committed.temperature = T;
            point.committed.evaluation_temperature = reference;
            point.trial.evaluation_temperature = reference;
          }
        });
  }

  template <int dim>
  void ThermalSystem<dim>::hold_point_temperatures(PointStorage &points) const
  {
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &point : points.get_data(cell))
        {
          point->committed.temperature = point->committed.evaluation_temperature;
          point->trial.temperature = point->committed.evaluation_temperature;
        }
  }

  template <int dim>
  void ThermalSystem<dim>::release_point_temperatures(PointStorage &points) const
  {
    write_point_temperatures(points,
                             [](material::MaterialPoint &point, const double T)
                             {
                               point.trial.temperature = T;
                               point.committed.temperature = T;
                             });
  }

  template <int dim>
  void ThermalSystem<dim>::prepare_refinement()
  {
    transfer = std::make_unique<parallel::distributed::SolutionTransfer<dim, Vector>>(dof_handler);
    transfer->prepare_for_coarsening_and_refinement(temperature);
  }

  template <int dim>
  void ThermalSystem<dim>::finish_refinement()
  {
    Vector owned(owned_dofs, comm);
    transfer->interpolate(owned);
    transfer.reset();
    // hanging nodes only: the prescribed values of the last step stay as interpolated
    AffineConstraints<double> hanging(relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, hanging);
    hanging.close();
    hanging.distribute(owned);
    temperature = owned;
    committed_temperature = owned;
    temperature_rate = 0.;
  }

  template <int dim>
  void ThermalSystem<dim>::prepare_serialization()
  {
    transfer = std::make_unique<parallel::distributed::SolutionTransfer<dim, Vector>>(dof_handler);
    transfer->prepare_for_serialization(temperature);
  }

  template <int dim>
  void ThermalSystem<dim>::deserialize()
  {
    Vector                                               owned(owned_dofs, comm);
    parallel::distributed::SolutionTransfer<dim, Vector> loader(dof_handler);
    loader.deserialize(owned);
    temperature = owned;
    committed_temperature = owned;
    temperature_rate = 0.;
  }

  template <int dim>
  std::array<double, 3> ThermalSystem<dim>::statistics() const
  {
    double lo = std::numeric_limits<double>::max(), hi = -std::numeric_limits<double>::max();
    for (const auto i : owned_dofs)
    {
      lo = std::min(lo, temperature(i));
      hi = std::max(hi, temperature(i));
    }
    FEValues<dim> fe_values(
        mapping, fe, quadrature, update_values | update_quadrature_points | update_JxW_values);
    std::vector<double> T(quadrature.size());
    double              integral = 0., volume = 0.;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
      {
        fe_values.reinit(cell);
        fe_values.get_function_values(temperature, T);
        for (unsigned int q = 0; q < T.size(); ++q)
        {
          const double dV
              = fe_values.JxW(q) * kinematics.volume_factor(fe_values.quadrature_point(q));
          integral += T[q] * dV;
          volume += dV;
        }
      }
    return {Utilities::MPI::min(lo, comm),
            Utilities::MPI::max(hi, comm),
            Utilities::MPI::sum(integral, comm) / Utilities::MPI::sum(volume, comm)};
  }

  template class ThermalSystem<2>;
  template class ThermalSystem<3>;
} // namespace ausroll::thermal
