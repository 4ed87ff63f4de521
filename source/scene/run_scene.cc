#include <ausroll/scene/scene.h>

#include <exception>
#include <memory>

namespace ausroll::scene
{
  void run_scene(const std::string                    &parameter_file,
                 const MPI_Comm                        comm,
                 const bool                            resume,
                 const std::vector<ParameterOverride> &overrides)
  {
    const SceneParameters     parameters = read_parameter_file(parameter_file, overrides);
    std::unique_ptr<Scene<2>> scene = std::make_unique<Scene<2>>(parameters, comm, resume);
    try
    {
      scene->run();
    }
    catch (...)
    {
      // Destroy the scene while the exception is handled (not in flight), so that its timers
      // and output close normally; then pass the error on.
      const std::exception_ptr error = std::current_exception();
      scene.reset();
      std::rethrow_exception(error);
    }
  }

} // namespace ausroll::scene
