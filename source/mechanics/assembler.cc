#include <ausroll/core/exceptions.h>
#include <ausroll/mechanics/assembler.h>
#include <ausroll/mechanics/terms/face_loads.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/work_stream.h>
#include <deal.II/grid/filtered_iterator.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <Epetra_CrsMatrix.h>
#include <Epetra_FEVector.h>

#include <algorithm>
#include <cstring>

namespace ausroll::mechanics
{
  using namespace dealii;

  template <int dim>
  Assembler<dim>::Assembler(const Mapping<dim>                &mapping,
                            const FiniteElement<dim>          &fe,
                            const unsigned int                 n_q_points_1d,
                            const PlanarKinematics<dim>       &kinematics,
                            const material::ConstitutiveModel &model,
                            const BoundaryConditions<dim>     &boundary_conditions,
                            const VolumetricLocking            locking)
      : mapping(mapping)
      , fe(fe)
      , cell_quadrature(n_q_points_1d)
      , face_quadrature(n_q_points_1d)
      , kinematics(kinematics)
      , model(model)
      , boundary_conditions(boundary_conditions)
      , locking(locking)
      , out_of_plane(kinematics.is_generalized_plane_strain())
      , layout(fe, cell_quadrature.size(), face_quadrature.size())
  {
    // The term list, in the order the terms add to a cell: the cached cell part first. A new
    // term is one file pair in mechanics/terms/ and one line here.
    auto internal = InternalForce<dim>::create(
        layout, mapping, fe, cell_quadrature, kinematics, model, locking);
    internal_force = internal.get();
    terms.push_back(std::move(internal));
    terms.push_back(FaceLoads<dim>::create(layout,
                                           mapping,
                                           fe,
                                           face_quadrature,
                                           kinematics,
                                           boundary_conditions,
                                           !model.is_small_strain()));
    // the cached terms lead the list
    for (unsigned int t = 0; t < terms.size(); ++t)
    {
      AssertThrow(!terms[t]->cached() || t == n_cached_terms, ExcInternalError());
      if (terms[t]->cached())
        ++n_cached_terms;
    }
  }

  template <int dim>
  Assembler<dim>::~Assembler() = default;

  template <int dim>
  struct Assembler<dim>::Setup
  {
    AssemblyInputs<dim>              inputs; // what the terms read
    const AffineConstraints<double> *hanging = nullptr;
    const AffineConstraints<double> *newton = nullptr;
    const RowTransforms<dim>        *row_transforms = nullptr;
    const AssemblyTargets           *targets = nullptr;
    // the cache to read the cell part from (reuse) or to write it to (store)
    AssemblyCache *cache = nullptr;
    bool           reuse = false;
    bool           store = false;
    // the slot tables of the matrix (AssemblyCache::slot_rows) and the local values of the
    // target vectors (same map), or nullptr
    const AssemblyCache *slots = nullptr;
    double *residual_values = nullptr, *external_values = nullptr, *free_values = nullptr,
           *rhs_values = nullptr;

    // generalized plane strain: int P_zz dV and k_ee, summed by the copier in cell order
    double axial_work = 0., axial_stiffness = 0.;
    // outcome, gathered by the copier in cell order
    bool        ok = true;
    double      min_jacobian = 1e300;
    std::string message;
    // the copier's work vector (-r of the free equations of one cell)
    Vector<double> cell_rhs;
  };

  // The scratch data of the terms (WorkStream copies the whole ScratchData once per thread;
  // FEValues cannot be copied, so each term makes its scratch anew).
  template <int dim>
  struct Assembler<dim>::ScratchData
  {
    explicit ScratchData(const std::vector<std::unique_ptr<const AssemblyTerm<dim>>> &terms)
        : terms(terms)
    {
      for (const auto &term : terms)
        parts.push_back(term->create_scratch());
    }

    ScratchData(const ScratchData &other)
        : ScratchData(other.terms)
    {
    }

    const std::vector<std::unique_ptr<const AssemblyTerm<dim>>> &terms;
    std::vector<std::unique_ptr<TermScratch>>                    parts; // by term
  };

  // ------------------------------------------------------------------ row-transform part

  template <int dim>
  void Assembler<dim>::apply_row_transforms(const Setup &setup, CopyData &copy) const
  {
    // Row transforms (friction) act on the equations of whole nodes.
    copy.cell_free = copy.cell_residual;
    const RowTransforms<dim> *row_transforms = setup.row_transforms;
    if (row_transforms == nullptr || row_transforms->empty())
      return;
    const auto &node_dofs = layout.node_dofs;
    for (unsigned int b = 0; b < layout.n_base; ++b)
    {
      const auto it = row_transforms->find(copy.dofs[node_dofs[b][0]]);
      if (it == row_transforms->end())
        continue;
      const Tensor<2, dim> &T = it->second.matrix;
      // the node's rows of a local vector or matrix column: its row c becomes
      // sum_d T[c][d] source(d) (source: the same entries, or the residual for the free one)
      const auto transform = [&](const auto &entry, const auto &source)
      {
        std::array<double, dim> old;
        for (unsigned int c = 0; c < dim; ++c)
          old[c] = source(node_dofs[b][c]);
        for (unsigned int c = 0; c < dim; ++c)
        {
          double s = 0.;
          for (unsigned int d = 0; d < dim; ++d)
            s += T[c][d] * old[d];
          entry(node_dofs[b][c]) = s;
        }
      };
      transform([&](const unsigned int i) -> double & { return copy.cell_free(i); },
                [&](const unsigned int i) { return copy.cell_residual(i); });
      if (!setup.inputs.need_matrix)
        continue;
      // the column k_ue of generalized plane strain is transformed as the matrix rows it borders
      if (copy.column.size() > 0)
        transform([&](const unsigned int i) -> double & { return copy.column(i); },
                  [&](const unsigned int i) { return copy.column(i); });
      for (unsigned int j = 0; j < layout.n_dofs; ++j)
        transform([&](const unsigned int i) -> double & { return copy.cell_matrix(i, j); },
                  [&](const unsigned int i) { return copy.cell_matrix(i, j); });
    }
  }

  template <int dim>
  void Assembler<dim>::add_row_transform_offsets(const DoFHandler<dim> &dof_handler,
                                                 const Setup           &setup) const
  {
    // Constant parts of the row transforms (shear friction), once per node by its owner.
    const RowTransforms<dim> *row_transforms = setup.row_transforms;
    const AssemblyTargets    &targets = *setup.targets;
    if (row_transforms == nullptr
        || (targets.free_residual == nullptr && !setup.inputs.need_matrix))
      return;
    const IndexSet                      &owned = dof_handler.locally_owned_dofs();
    Vector<double>                       node_offset(dim);
    std::vector<types::global_dof_index> node_dofs_global(dim);
    for (const auto &[key, transform] : *row_transforms)
    {
      if (transform.offset.norm_square() == 0. || !owned.is_element(key))
        continue;
      for (unsigned int c = 0; c < dim; ++c)
      {
        node_offset(c) = transform.offset[c];
        node_dofs_global[c] = transform.dofs[c];
      }
      if (targets.free_residual != nullptr)
        setup.newton->distribute_local_to_global(
            node_offset, node_dofs_global, *targets.free_residual);
      if (setup.inputs.need_matrix)
      {
        node_offset *= -1.;
        setup.newton->distribute_local_to_global(node_offset, node_dofs_global, *targets.rhs);
      }
    }
  }

  // ------------------------------------------------------------------ copier

  template <int dim>
  void Assembler<dim>::copy_local_to_global(const CopyData &copy, Setup &setup) const
  {
    // The copier runs serially and in cell order: it owns the outcome in Setup.
    if (!setup.ok)
      return; // after a failure nothing more is added (the assembly is discarded)
    setup.min_jacobian = std::min(setup.min_jacobian, copy.min_jacobian);
    if (!copy.ok)
    {
      setup.ok = false;
      setup.message = copy.message;
      return;
    }
    const AssemblyTargets &targets = *setup.targets;
    if (targets.out_of_plane != nullptr)
    {
      // generalized plane strain: the column condensed as the residual is (homogeneous Newton
      // constraints), the row with the hanging nodes only (it is dotted with distributed
      // increments, Dirichlet parts included)
      setup.axial_work += copy.axial_work;
      if (setup.inputs.need_matrix)
      {
        setup.axial_stiffness += copy.axial_stiffness;
        setup.newton->distribute_local_to_global(
            copy.column, copy.dofs, targets.out_of_plane->column);
        setup.hanging->distribute_local_to_global(copy.row, copy.dofs, targets.out_of_plane->row);
      }
    }
    if (setup.slots != nullptr)
    {
      // A cell without constrained DoFs whose rows are all owned here: its entries straight into
      // the value arrays of the vectors and the matrix (what distribute_local_to_global adds for
      // such a cell, one sum per entry in the same cell order, without its row sorting and
      // Epetra's searches).
      const AssemblyCache &slots = *setup.slots;
      const std::size_t    n = layout.n_dofs;
      const std::size_t    base = copy.cell_index * n;
      bool                 direct = slots.slot_rows[base] != nullptr;
      for (unsigned int i = 0; direct && i < n; ++i)
        direct = !setup.newton->is_constrained(copy.dofs[i]);
      if (direct)
      {
        for (unsigned int i = 0; i < n; ++i)
        {
          const std::int32_t k = slots.slot_rhs[base + i];
          setup.residual_values[k] += copy.cell_residual(i);
          setup.external_values[k] += copy.cell_external(i);
          if (setup.free_values != nullptr)
            setup.free_values[k] += copy.cell_free(i);
          if (!setup.inputs.need_matrix)
            continue;
          double *const             row = slots.slot_rows[base + i];
          const std::int32_t *const position = &slots.slot_columns[(base + i) * n];
          const double *const       local = &copy.cell_matrix(i, 0);
          for (unsigned int j = 0; j < n; ++j)
            row[position[j]] += local[j];
          setup.rhs_values[k] += -copy.cell_free(i);
        }
        return;
      }
    }
    setup.hanging->distribute_local_to_global(copy.cell_residual, copy.dofs, *targets.residual);
    setup.hanging->distribute_local_to_global(
        copy.cell_external, copy.dofs, *targets.external_force);
    if (targets.free_residual != nullptr)
      setup.newton->distribute_local_to_global(copy.cell_free, copy.dofs, *targets.free_residual);
    if (setup.inputs.need_matrix)
    {
      // -r of the free equations (the copier's own work vector: copies run one at a time)
      Vector<double> &cell_rhs = setup.cell_rhs;
      cell_rhs = copy.cell_free;
      cell_rhs *= -1.;
      setup.newton->distribute_local_to_global(
          copy.cell_matrix, cell_rhs, copy.dofs, *targets.matrix, *targets.rhs, true);
    }
  }

  // ------------------------------------------------------------------ driver

  template <int dim>
  void Assembler<dim>::assemble_one_cell(const typename DoFHandler<dim>::active_cell_iterator &cell,
                                         const Setup &setup,
                                         ScratchData &scratch,
                                         CopyData    &copy) const
  {
    copy.ok = true;
    copy.min_jacobian = 1e300;
    cell->get_dof_indices(copy.dofs);
    const std::size_t n_dofs = layout.n_dofs;
    const std::size_t index = cell->active_cell_index();
    copy.cell_index = index;
    if (setup.reuse)
    {
      // the cell part of the cached assembly at this very state (AssemblyCache)
      const AssemblyCache &cache = *setup.cache;
      if (setup.inputs.need_matrix)
        std::copy_n(cache.matrices.begin() + index * n_dofs * n_dofs,
                    n_dofs * n_dofs,
                    &copy.cell_matrix(0, 0));
      std::copy_n(cache.residuals.begin() + index * n_dofs, n_dofs, copy.cell_residual.begin());
      copy.cell_external = 0.;
      copy.min_jacobian = cache.min_jacobian[index];
      if (out_of_plane)
      {
        const double *const part = cache.out_of_plane.data() + index * (2 * n_dofs + 2);
        std::copy_n(part, n_dofs, copy.column.begin());
        std::copy_n(part + n_dofs, n_dofs, copy.row.begin());
        copy.axial_work = part[2 * n_dofs];
        copy.axial_stiffness = part[2 * n_dofs + 1];
      }
    }
    else
    {
      copy.cell_matrix = 0.;
      copy.cell_residual = 0.;
      copy.cell_external = 0.;
      if (out_of_plane)
      {
        copy.column = 0.;
        copy.row = 0.;
        copy.axial_work = 0.;
        copy.axial_stiffness = 0.;
      }
      for (unsigned int t = 0; t < n_cached_terms; ++t)
      {
        terms[t]->execute(cell, setup.inputs, *scratch.parts[t], copy);
        if (!copy.ok)
          return;
      }
      if (setup.store)
      {
        // each cell writes its own slots: safe on WorkStream's threads
        AssemblyCache &cache = *setup.cache;
        if (setup.inputs.need_matrix)
          std::copy_n(&copy.cell_matrix(0, 0),
                      n_dofs * n_dofs,
                      cache.matrices.begin() + index * n_dofs * n_dofs);
        std::copy_n(copy.cell_residual.begin(), n_dofs, cache.residuals.begin() + index * n_dofs);
        cache.min_jacobian[index] = copy.min_jacobian;
        if (out_of_plane)
        {
          double *const part = cache.out_of_plane.data() + index * (2 * n_dofs + 2);
          std::copy_n(copy.column.begin(), n_dofs, part);
          std::copy_n(copy.row.begin(), n_dofs, part + n_dofs);
          part[2 * n_dofs] = copy.axial_work;
          part[2 * n_dofs + 1] = copy.axial_stiffness;
        }
      }
    }
    for (unsigned int t = n_cached_terms; t < terms.size(); ++t)
    {
      terms[t]->execute(cell, setup.inputs, *scratch.parts[t], copy);
      if (!copy.ok)
        return;
    }
    copy.cell_residual -= copy.cell_external;
    apply_row_transforms(setup, copy);
  }

  template <int dim>
  AssemblyStatus Assembler<dim>::assemble(const DoFHandler<dim>               &dof_handler,
                                          const TrilinosWrappers::MPI::Vector &solution,
                                          const double                         time,
                                          MaterialPointStorage<dim>           &material_points,
                                          const AffineConstraints<double>     &hanging,
                                          const AffineConstraints<double>     &newton,
                                          const RowTransforms<dim>            *row_transforms,
                                          const AssemblyTargets               &targets,
                                          AssemblyCache                       *cache) const
  {
    Assert(targets.residual != nullptr && targets.external_force != nullptr, ExcInternalError());

    Setup setup;
    setup.inputs.solution = &solution;
    setup.inputs.time = time;
    setup.inputs.material_points = &material_points;
    setup.inputs.check_inversion = !model.is_small_strain();
    setup.cell_rhs.reinit(layout.n_dofs);
    setup.hanging = &hanging;
    setup.newton = &newton;
    setup.row_transforms = row_transforms;
    setup.targets = &targets;
    setup.inputs.need_matrix = targets.matrix != nullptr;
    prepare_cache(dof_handler, solution, time, cache, setup);
    if (cache != nullptr)
    {
      // the owner changes `state` whenever the material points may have been replaced
      const std::size_t n_cells = dof_handler.get_triangulation().n_active_cells();
      if (!cache->points_valid || cache->points_state != cache->state
          || cache->points.size() != n_cells * layout.n_q)
      {
        cache->points.assign(n_cells * layout.n_q, nullptr);
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
          {
            const auto shared = material_points.get_data(cell);
            AssertDimension(shared.size(), layout.n_q);
            for (unsigned int q = 0; q < layout.n_q; ++q)
              cache->points[cell->active_cell_index() * layout.n_q + q] = shared[q].get();
          }
        cache->points_state = cache->state;
        cache->points_valid = true;
      }
      setup.inputs.point_table = cache->points.data();
    }

    prepare_slots(dof_handler, cache, setup);

    // The cell loop on the threads of DEAL_II_NUM_THREADS (step-44): the worker fills one cell's
    // CopyData, the copier adds it to the targets in cell order. On one thread the same in a
    // plain loop with the kept scratch (what WorkStream does then, without building the scratch
    // and its three FEValues anew for every assembly).
    if (MultithreadInfo::n_threads() == 1)
    {
      if (!kept_scratch)
      {
        kept_scratch = std::make_unique<ScratchData>(terms);
        kept_copy = std::make_unique<CopyData>(layout.n_dofs, out_of_plane);
      }
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          assemble_one_cell(cell, setup, *kept_scratch, *kept_copy);
          copy_local_to_global(*kept_copy, setup);
        }
    }
    else
    {
      using CellFilter = FilteredIterator<typename DoFHandler<dim>::active_cell_iterator>;
      WorkStream::run(
          CellFilter(IteratorFilters::LocallyOwnedCell(), dof_handler.begin_active()),
          CellFilter(IteratorFilters::LocallyOwnedCell(), dof_handler.end()),
          [this, &setup](const typename DoFHandler<dim>::active_cell_iterator &cell,
                         ScratchData                                          &scratch,
                         CopyData &copy) { assemble_one_cell(cell, setup, scratch, copy); },
          [this, &setup](const CopyData &copy) { copy_local_to_global(copy, setup); },
          ScratchData(terms),
          CopyData(layout.n_dofs, out_of_plane));
    }

    add_row_transform_offsets(dof_handler, setup);
    if (setup.store)
    {
      // a failed assembly is never reused; a successful one is the state of the next reuse
      cache->valid = setup.ok;
      cache->with_matrix = setup.inputs.need_matrix;
    }

    targets.residual->compress(VectorOperation::add);
    targets.external_force->compress(VectorOperation::add);
    if (targets.free_residual != nullptr)
      targets.free_residual->compress(VectorOperation::add);
    if (setup.inputs.need_matrix)
    {
      targets.matrix->compress(VectorOperation::add);
      targets.rhs->compress(VectorOperation::add);
    }
    if (targets.out_of_plane != nullptr)
    {
      GeneralizedPlaneStrain &border = *targets.out_of_plane;
      const MPI_Comm          comm = dof_handler.get_communicator();
      border.axial_work = Utilities::MPI::sum(setup.axial_work, comm);
      if (setup.inputs.need_matrix)
      {
        border.stiffness = Utilities::MPI::sum(setup.axial_stiffness, comm);
        border.column.compress(VectorOperation::add);
        border.row.compress(VectorOperation::add);
      }
    }

    // Agree on the outcome across ranks; the message comes from the lowest failing rank.
    const MPI_Comm     comm = dof_handler.get_communicator();
    const unsigned int my_rank = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const unsigned int bad_rank = Utilities::MPI::min(setup.ok ? n_ranks : my_rank, comm);
    AssemblyStatus     status;
    status.min_jacobian = Utilities::MPI::min(setup.min_jacobian, comm);
    if (bad_rank < n_ranks)
    {
      status.ok = false;
      status.message = Utilities::MPI::broadcast(comm, setup.message, bad_rank);
    }
    return status;
  }

  template <int dim>
  void Assembler<dim>::prepare_cache(const DoFHandler<dim>               &dof_handler,
                                     const TrilinosWrappers::MPI::Vector &solution,
                                     const double                         time,
                                     AssemblyCache                       *cache,
                                     Setup                               &setup) const
  {
    setup.cache = cache;
    if (cache == nullptr)
      return;
    const std::size_t n_cells = dof_handler.get_triangulation().n_active_cells();
    const std::size_t n_dofs = layout.n_dofs;
    if (n_cells * (n_dofs * n_dofs + n_dofs + 1) * sizeof(double) > cache->max_bytes)
    {
      cache->valid = false;
      cache->solution = {};
      cache->matrices = {};
      cache->residuals = {};
      cache->min_jacobian = {};
      return;
    }
    // the displacement with its ghost entries, compared bit for bit
    const Epetra_MultiVector &values = solution.trilinos_vector();
    const std::size_t         n_values = values.MyLength();
    const double             *first = values[0];
    setup.reuse = cache->valid && cache->cached_state == cache->state
                  && cache->min_jacobian.size() == n_cells && cache->time == time
                  && cache->stretch == kinematics.out_of_plane_stretch()
                  && (cache->with_matrix || !setup.inputs.need_matrix)
                  && cache->solution.size() == n_values
                  && std::memcmp(cache->solution.data(), first, n_values * sizeof(double)) == 0;
    if (setup.reuse)
    {
      ++cache->hits;
      return;
    }
    ++cache->misses;
    setup.store = true;
    cache->valid = false;
    cache->cached_state = cache->state;
    cache->time = time;
    cache->stretch = kinematics.out_of_plane_stretch();
    cache->solution.assign(first, first + n_values);
    cache->residuals.resize(n_cells * n_dofs);
    cache->min_jacobian.resize(n_cells);
    cache->out_of_plane.resize(out_of_plane ? n_cells * (2 * n_dofs + 2) : 0);
    cache->matrices.resize(setup.inputs.need_matrix ? n_cells * n_dofs * n_dofs : 0);
  }

  template <int dim>
  void Assembler<dim>::prepare_slots(const DoFHandler<dim> &dof_handler,
                                     AssemblyCache         *cache,
                                     Setup                 &setup) const
  {
    if (cache == nullptr)
      return;
    const AssemblyTargets &targets = *setup.targets;
    const std::size_t      n_cells = dof_handler.get_triangulation().n_active_cells();
    const std::size_t      n = layout.n_dofs;
    Epetra_FEVector       &residual = targets.residual->trilinos_vector();
    // the target vectors share one map (their local indices are those of the table)
    const auto same_map = [&](const TrilinosWrappers::MPI::Vector *v)
    { return v == nullptr || v->trilinos_vector().Map().SameAs(residual.Map()); };
    if (!same_map(targets.external_force) || !same_map(targets.free_residual)
        || !same_map(targets.rhs))
      return;
    if (!setup.inputs.need_matrix)
    {
      // residual only: the tables of the last matrix assembly on this pattern, if any
      if (!cache->slots_valid || cache->slots_pattern != cache->pattern
          || cache->slot_rows.size() != n_cells * n)
        return;
      setup.slots = cache;
      setup.residual_values = residual[0];
      setup.external_values = targets.external_force->trilinos_vector()[0];
      setup.free_values = targets.free_residual != nullptr
                              ? targets.free_residual->trilinos_vector()[0]
                              : nullptr;
      return;
    }
    const Epetra_CrsMatrix &matrix = targets.matrix->trilinos_matrix();
    Epetra_FEVector        &rhs = targets.rhs->trilinos_vector();
    if (!cache->slots_valid || cache->slots_pattern != cache->pattern
        || cache->slots_matrix != &matrix || cache->slot_rows.size() != n_cells * n)
    {
      cache->slots_valid = false;
      cache->slot_rows = {};
      cache->slot_columns = {};
      cache->slot_rhs = {};
      const std::size_t bytes
          = n_cells * n * (sizeof(double *) + 2 * sizeof(std::int32_t) * (1 + n));
      if (bytes > cache->max_bytes || !matrix.Filled())
        return;
      cache->slot_rows.assign(n_cells * n, nullptr);
      cache->slot_columns.assign(n_cells * n * n, 0);
      cache->slot_rhs.assign(n_cells * n, 0);
      using IndexType = TrilinosWrappers::types::int_type;
      std::vector<types::global_dof_index> dofs(n);
      std::vector<int>                     columns(n);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          const std::size_t base = cell->active_cell_index() * n;
          bool              found = true;
          for (unsigned int j = 0; found && j < n; ++j)
          {
            columns[j] = matrix.ColMap().LID(static_cast<IndexType>(dofs[j]));
            found = columns[j] >= 0;
          }
          for (unsigned int i = 0; found && i < n; ++i)
          {
            const int row = matrix.RowMap().LID(static_cast<IndexType>(dofs[i]));
            const int rhs_row = rhs.Map().LID(static_cast<IndexType>(dofs[i]));
            int       n_entries = 0;
            double   *values = nullptr;
            int      *indices = nullptr;
            found = row >= 0 && rhs_row >= 0
                    && matrix.ExtractMyRowView(row, n_entries, values, indices) == 0;
            if (!found)
              break;
            cache->slot_rows[base + i] = values;
            cache->slot_rhs[base + i] = rhs_row;
            int *const end = indices + n_entries;
            const bool sorted = std::is_sorted(indices, end);
            for (unsigned int j = 0; found && j < n; ++j)
            {
              const int *const at = sorted ? std::lower_bound(indices, end, columns[j])
                                           : std::find(indices, end, columns[j]);
              found = at != end && *at == columns[j];
              cache->slot_columns[(base + i) * n + j] = static_cast<std::int32_t>(at - indices);
            }
          }
          if (!found)
            std::fill_n(cache->slot_rows.begin() + base, n, nullptr); // deal.II's path
        }
      cache->slots_pattern = cache->pattern;
      cache->slots_matrix = &matrix;
      cache->slots_valid = true;
    }
    setup.slots = cache;
    setup.residual_values = residual[0];
    setup.external_values = targets.external_force->trilinos_vector()[0];
    setup.free_values
        = targets.free_residual != nullptr ? targets.free_residual->trilinos_vector()[0] : nullptr;
    setup.rhs_values = rhs[0];
  }

  template <int dim>
  std::vector<Tensor<2, 3>> Assembler<dim>::material_deformation_gradients(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      const TrilinosWrappers::MPI::Vector                  &solution) const
  {
    return internal_force->material_deformation_gradients(cell, solution);
  }

  template class Assembler<2>;
  template class Assembler<3>;
} // namespace ausroll::mechanics
