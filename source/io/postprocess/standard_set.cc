#include <ausroll/io/postprocess/standard_set.h>

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>

namespace ausroll::io
{
  template <int dim>
  std::unique_ptr<PostprocessorSet<dim>>
  make_standard_postprocessors(const PostprocessorContext &context, const MPI_Comm comm)
  {
    // The registered postprocessors in the order of their positions (the history columns).
    const auto &registry = PostprocessorRegistry::instance();
    std::vector<std::pair<unsigned int, std::unique_ptr<PostprocessorFactory>>> factories;
    for (const std::string &name : registry.names())
    {
      std::unique_ptr<PostprocessorFactory> factory = registry.get(name, "postprocessor").make();
      const unsigned int                    position = factory->position();
      factories.emplace_back(position, std::move(factory));
    }
    std::sort(factories.begin(),
              factories.end(),
              [](const auto &a, const auto &b) { return a.first < b.first; });
    auto set = std::make_unique<PostprocessorSet<dim>>(context.output, comm);
    for (unsigned int i = 0; i < factories.size(); ++i)
    {
      if (i > 0 && factories[i].first == factories[i - 1].first)
        throw std::logic_error("two postprocessors are registered at position "
                               + std::to_string(factories[i].first));
      std::unique_ptr<Postprocessor<dim>> postprocessor;
      if constexpr (dim == 2)
        postprocessor = factories[i].second->create_2d(context);
      else
        postprocessor = factories[i].second->create_3d(context);
      if (postprocessor)
        set->add(std::move(postprocessor));
    }
    return set;
  }

  template std::unique_ptr<PostprocessorSet<2>>
  make_standard_postprocessors(const PostprocessorContext &, const MPI_Comm);
  template std::unique_ptr<PostprocessorSet<3>>
  make_standard_postprocessors(const PostprocessorContext &, const MPI_Comm);
} // namespace ausroll::io
