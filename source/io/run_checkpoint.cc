#include <ausroll/core/exceptions.h>
#include <ausroll/io/checkpoint.h>
#include <ausroll/io/run_checkpoint.h>

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/solution_transfer.h>

#include <filesystem>
#include <iostream>
#include <sstream>

namespace ausroll::io
{
  using namespace dealii;

  template <int dim>
  void write_checkpoint(mechanics::MechanicalSystem<dim>         &system,
                        adaptivity::MaterialPointTransfer<dim>   &points,
                        const RunState                           &state,
                        const std::map<std::string, std::string> &entries,
                        const std::string                        &output_directory,
                        thermal::ThermalSystem<dim>              *thermal)
  {
    using Vector = TrilinosWrappers::MPI::Vector;
    const CheckpointDirectory checkpoints(output_directory, system.comm);
    // Room for it, checked before p4est writes (p4est aborts when it cannot write its file).
    // The estimate is a lower bound: the material points' and the two vectors' values per cell
    // (deal.II adds a few bytes per cell, the temperature field more), the mesh file's 12 bytes
    // per cell.
    {
      unsigned int n_q = 0;
      for (const auto &cell : system.triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
        {
          n_q = system.material_points.get_data(cell).size();
          break;
        }
      n_q = Utilities::MPI::max(n_q, system.comm);
      const std::uintmax_t n_cells = system.triangulation.n_global_active_cells();
      const std::uintmax_t data
          = n_cells * sizeof(double)
            * (n_q * material::MaterialState::n_packed_values + 2 * system.fe.n_dofs_per_cell());
      std::string error;
      if (Utilities::MPI::this_mpi_process(system.comm) == 0)
        try
        {
          require_room(output_directory, data + 12 * n_cells, data);
        }
        catch (const std::exception &e)
        {
          error = "step " + std::to_string(state.step) + ": " + e.what();
        }
      error = Utilities::MPI::broadcast(system.comm, error, 0);
      if (!error.empty())
        throw RunFailure(error);
    }
    const std::string dir = checkpoints.begin_write();

    parallel::distributed::SolutionTransfer<dim, Vector> transfer(system.dof_handler);
    // the converged solution before this one too: the predictor of the next step needs it
    Vector previous_ghosted(system.owned_dofs, system.relevant_dofs, system.comm);
    previous_ghosted = system.previous_start;
    transfer.prepare_for_serialization(
        std::vector<const Vector *>{&system.solution_ghosted, &previous_ghosted});
    points.prepare();
    if (thermal != nullptr)
      thermal->prepare_serialization();
    system.triangulation.save(dir + "/mesh");

    CheckpointMetadata meta;
    meta.values["time"] = {state.time};
    meta.values["step"] = {double(state.step)};
    meta.values["dt"] = {state.step_size};
    meta.values["last_step_size"] = {state.last_step_size};
    meta.values["previous_solution"] = {1.};
    meta.values["temperature"] = {thermal != nullptr ? 1. : 0.};
    meta.set_parameters(entries);
    meta.values["output_counter"] = {double(state.output_counter)};
    meta.values["last_output_step"] = {double(state.last_output_step)};
    meta.values["largest_reference_force"] = {state.largest_reference_force};
    meta.values["contact"] = state.contact;
    // generalized plane strain: lambda of the converged state and of the one before it
    if (system.out_of_plane.active)
      meta.values["out_of_plane_stretch"]
          = {system.out_of_plane.step_start, system.out_of_plane.previous_start};
    std::vector<double> output_times;
    std::string         output_files;
    for (const auto &[t, file] : state.vtu_records)
    {
      output_times.push_back(t);
      output_files += (output_files.empty() ? "" : " ") + file;
    }
    meta.values["output_times"] = output_times;
    meta.strings["output_files"] = output_files;
    // every rank has closed its part of the mesh files
    MPI_Barrier(system.comm);
    std::string error;
    if (Utilities::MPI::this_mpi_process(system.comm) == 0)
      try
      {
        const std::string incomplete = incomplete_cell_data(
            dir + "/mesh_fixed.data", system.triangulation.n_global_active_cells());
        if (!incomplete.empty())
          throw RunFailure(incomplete);
        meta.record_files(dir);
        meta.write(dir + "/metadata.txt");
      }
      catch (const std::exception &e)
      {
        error = "step " + std::to_string(state.step) + ": " + e.what()
                + " (the previous checkpoint is kept)";
        std::error_code ec;
        std::filesystem::remove_all(dir, ec); // give back the space of the incomplete one
      }
    // a checkpoint that could not be completed is not swapped in: the previous one stays
    error = Utilities::MPI::broadcast(system.comm, error, 0);
    if (!error.empty())
      throw RunFailure(error);
    checkpoints.commit();
  }

  template <int dim>
  std::string load_checkpoint_mesh(mechanics::MechanicalSystem<dim>         &system,
                                   const std::map<std::string, std::string> &entries,
                                   const std::string                        &output_directory)
  {
    const std::string  directory = CheckpointDirectory(output_directory, system.comm).latest();
    CheckpointMetadata meta;
    meta.read(directory + "/metadata.txt");
    // Every file is checked before p4est or deal.II sees it (an emptied p4est file aborts in
    // p4est, an emptied data file crashes, a bit flip loads and gives NaN later).
    std::string damaged;
    if (Utilities::MPI::this_mpi_process(system.comm) == 0)
      damaged = meta.damaged_file(directory);
    damaged = Utilities::MPI::broadcast(system.comm, damaged, 0);
    if (!damaged.empty())
      throw InputError("--resume: " + damaged);
    for (const std::string &warning : compare_resume_parameters(meta, entries, directory))
      if (Utilities::MPI::this_mpi_process(system.comm) == 0)
        std::cerr << "ausroll: warning: " << warning << std::endl;
    system.triangulation.load(directory + "/mesh");
    return directory;
  }

  template <int dim>
  void load_checkpoint_vectors(mechanics::MechanicalSystem<dim>       &system,
                               adaptivity::MaterialPointTransfer<dim> &points,
                               const std::string                      &directory,
                               thermal::ThermalSystem<dim>            *thermal)
  {
    CheckpointMetadata meta;
    meta.read(directory + "/metadata.txt");
    // Same order as in write_checkpoint(): solution first, then the material points.
    parallel::distributed::SolutionTransfer<dim, TrilinosWrappers::MPI::Vector> transfer(
        system.dof_handler);
    // with the converged solution before it (the predictor's), if the checkpoint has it
    std::vector<TrilinosWrappers::MPI::Vector *> vectors{&system.solution};
    if (meta.values.count("previous_solution") > 0)
      vectors.push_back(&system.previous_start);
    transfer.deserialize(vectors);
    system.solution_ghosted = system.solution;
    system.step_start = system.solution;
    if (system.out_of_plane.active)
    {
      const auto stretch = meta.values.find("out_of_plane_stretch");
      if (stretch == meta.values.end() || stretch->second.size() != 2)
        throw InputError(directory
                         + ": the checkpoint has no out-of-plane stretch (it was written by a run "
                           "without Model/Planar model = generalized plane strain, which must "
                           "match the run that wrote it)");
      system.out_of_plane.stretch = system.out_of_plane.step_start = stretch->second[0];
      system.out_of_plane.previous_start = stretch->second[1];
    }
    points.prepare();
    points.unpack();
    if (thermal != nullptr)
    {
      if (meta.values.count("temperature") == 0 || meta.get("temperature") != 1.)
        throw InputError(
            directory
            + ": the checkpoint has no temperature field (it was written "
              "by an isothermal run; Thermal/Enabled must match the run that wrote it)");
      thermal->deserialize();
    }
  }

  RunState read_run_state(const std::string &directory)
  {
    CheckpointMetadata meta;
    meta.read(directory + "/metadata.txt");
    RunState state;
    state.time = meta.get("time");
    state.step = static_cast<unsigned int>(meta.get("step"));
    state.step_size = meta.get("dt");
    state.output_counter = static_cast<unsigned int>(meta.get("output_counter"));
    state.last_output_step = static_cast<int>(meta.get("last_output_step"));
    state.largest_reference_force = meta.get("largest_reference_force");
    if (meta.values.count("last_step_size") > 0)
      state.last_step_size = meta.get("last_step_size");
    state.contact = meta.values["contact"];
    std::istringstream files(meta.strings["output_files"]);
    for (const double t : meta.values["output_times"])
    {
      std::string file;
      files >> file;
      state.vtu_records.emplace_back(t, file);
    }
    return state;
  }

  template void        write_checkpoint(mechanics::MechanicalSystem<2> &,
                                        adaptivity::MaterialPointTransfer<2> &,
                                        const RunState &,
                                        const std::map<std::string, std::string> &,
                                        const std::string &,
                                        thermal::ThermalSystem<2> *);
  template void        write_checkpoint(mechanics::MechanicalSystem<3> &,
                                        adaptivity::MaterialPointTransfer<3> &,
                                        const RunState &,
                                        const std::map<std::string, std::string> &,
                                        const std::string &,
                                        thermal::ThermalSystem<3> *);
  template std::string load_checkpoint_mesh(mechanics::MechanicalSystem<2> &,
                                            const std::map<std::string, std::string> &,
                                            const std::string &);
  template std::string load_checkpoint_mesh(mechanics::MechanicalSystem<3> &,
                                            const std::map<std::string, std::string> &,
                                            const std::string &);
  template void        load_checkpoint_vectors(mechanics::MechanicalSystem<2> &,
                                               adaptivity::MaterialPointTransfer<2> &,
                                               const std::string &,
                                               thermal::ThermalSystem<2> *);
  template void        load_checkpoint_vectors(mechanics::MechanicalSystem<3> &,
                                               adaptivity::MaterialPointTransfer<3> &,
                                               const std::string &,
                                               thermal::ThermalSystem<3> *);
} // namespace ausroll::io
