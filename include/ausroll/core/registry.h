/**
 * @file registry.h
 * One registry per pluggable kind (die shapes of each dimension, friction laws, ...): name ->
 * {subsection, description, declare_parameters() of its own subsection, a factory of its
 * parameters object}. The parameters object parses its subsection (`parse()`) and creates the
 * thing (its `create()`, whose arguments the kind defines). The `Selection` list of the kind's
 * `.prm` entry, the subsections and therefore doc/parameters.md come from the registry.
 *
 * A class registers itself with AUSROLL_REGISTER at the end of its own `.cc` (as ASPECT's
 * `ASPECT_REGISTER_*` and MOOSE's `registerMooseObject`): a static object whose constructor adds
 * the entry before main(). `ausroll_core` is an OBJECT library (CMakeLists.txt), so every object
 * file, and with it every registration, is linked into each executable that links the core (a
 * static library would let the linker drop a file nobody references). The entries are kept in
 * name order, whatever the order of static initialisation: the selection lists and the
 * documentation do not depend on the link order.
 */
#pragma once

#include <ausroll/core/exceptions.h>

#include <deal.II/base/parameter_handler.h>

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace ausroll
{
  /**
   * A base for the parameters of a pluggable kind whose members may have no entries: parse() of
   * the member's own subsection does nothing unless the member overrides it (contact strategies,
   * step controls, friction laws).
   */
  class RegisteredParameters
  {
  public:
    virtual ~RegisteredParameters() = default;

    /** Read the member's subsection (entered by the caller; @p path its full path with a
        trailing slash, for InputErrors naming the entry). Default: no entries. */
    virtual void parse(dealii::ParameterHandler &prm,
                       const std::string        &path,
                       const std::string        &input_directory)
    {
      (void)prm;
      (void)path;
      (void)input_directory;
    }
  };

  /**
   * The registry of one pluggable kind whose parameters objects derive from @p Parameters, which
   * has `virtual void parse(dealii::ParameterHandler &, const std::string &path, const std::string
   * &input_directory)`; @p path is the full path of the entered subsection with a trailing slash
   * ("Contact/Die 0/Circle/"), for InputErrors naming the entry.
   */
  template <class Parameters>
  class Registry
  {
  public:
    /** One registered class. */
    struct Entry
    {
      std::string name;        ///< its value in the kind's selection entry
      std::string subsection;  ///< its own subsection ("": it has no entries)
      std::string description; ///< one sentence for the help text of the selection entry
      void (*declare)(dealii::ParameterHandler &) = nullptr; ///< declare its subsection's entries
      std::unique_ptr<Parameters> (*make)() = nullptr;       ///< a default parameters object
    };

    /** The one registry of this kind. */
    static Registry &instance()
    {
      static Registry registry;
      return registry;
    }

    /** Add @p entry; a name registered twice is a programming error (std::logic_error). */
    bool add(Entry entry)
    {
      const std::string name = entry.name;
      if (!entries.emplace(name, std::move(entry)).second)
        throw std::logic_error("Registry: '" + name + "' is registered twice");
      return true;
    }

    /** True if @p name is registered. */
    bool contains(const std::string &name) const { return entries.count(name) != 0; }

    /** The registered names in name order. */
    std::vector<std::string> names() const
    {
      std::vector<std::string> result;
      for (const auto &[name, entry] : entries)
        result.push_back(name);
      return result;
    }

    /** The names joined by '|' (a Patterns::Selection). */
    std::string selection() const
    {
      std::string result;
      for (const auto &[name, entry] : entries)
        result += (result.empty() ? "" : "|") + name;
      return result;
    }

    /** "name: description; name: description" for the help text of the selection entry. */
    std::string descriptions() const
    {
      std::string result;
      for (const auto &[name, entry] : entries)
        result += (result.empty() ? "" : "; ") + name + ": " + entry.description;
      return result;
    }

    /** The entry of @p name; InputError naming @p entry_path (the selection entry) if unknown. */
    const Entry &get(const std::string &name, const std::string &entry_path) const
    {
      const auto it = entries.find(name);
      if (it == entries.end())
        throw InputError(entry_path + ": unknown value '" + name + "' (expected one of "
                         + selection() + ")");
      return it->second;
    }

    /** Declare every registered subsection inside the current subsection. */
    void declare_subsections(dealii::ParameterHandler &prm) const
    {
      for (const auto &[name, entry] : entries)
        if (!entry.subsection.empty())
        {
          prm.enter_subsection(entry.subsection);
          if (entry.declare != nullptr)
            entry.declare(prm);
          prm.leave_subsection();
        }
    }

    /** Full path of @p name's subsection below @p parent_path ("Contact/Die 0/" -> ".../Circle/").
     */
    std::string path(const std::string &name, const std::string &parent_path) const
    {
      const Entry &e = get(name, parent_path);
      return e.subsection.empty() ? parent_path : parent_path + e.subsection + "/";
    }

    /**
     * The parameters of @p name read from its subsection of the current subsection, whose full
     * path is @p parent_path; @p selection_entry names the selection entry for an unknown name.
     */
    std::unique_ptr<Parameters> parse(const std::string        &name,
                                      dealii::ParameterHandler &prm,
                                      const std::string        &parent_path,
                                      const std::string        &input_directory,
                                      const std::string        &selection_entry) const
    {
      const Entry                &e = get(name, parent_path + selection_entry);
      std::unique_ptr<Parameters> parameters = e.make();
      if (e.subsection.empty())
        parameters->parse(prm, parent_path, input_directory);
      else
      {
        prm.enter_subsection(e.subsection);
        parameters->parse(prm, parent_path + e.subsection + "/", input_directory);
        prm.leave_subsection();
      }
      return parameters;
    }

  private:
    Registry() = default;
    std::map<std::string, Entry> entries;
  };

  namespace internal
  {
    /** Adds one entry to a registry when constructed (the static object of AUSROLL_REGISTER). */
    template <class Parameters, class Class>
    struct Registration
    {
      Registration(const char *name, const char *subsection, const char *description)
      {
        Registry<Parameters>::instance().add({name,
                                              subsection,
                                              description,
                                              &Class::declare_parameters,
                                              []() -> std::unique_ptr<Parameters>
                                              { return std::make_unique<Class>(); }});
      }
    };
  } // namespace internal
} // namespace ausroll

#define AUSROLL_REGISTRY_CONCAT_(a, b) a##b
#define AUSROLL_REGISTRY_CONCAT(a, b) AUSROLL_REGISTRY_CONCAT_(a, b)

/**
 * Register the parameters class @p Class (derived from @p Kind, with a static
 * `declare_parameters(dealii::ParameterHandler &)` and a default constructor) under @p name with
 * its subsection @p subsection ("" if it has no entries) and a one-sentence @p description. Put it
 * at the end of the class's own `.cc`, at namespace scope.
 */
#define AUSROLL_REGISTER(Kind, Class, name, subsection, description)                             \
  namespace                                                                                      \
  {                                                                                              \
    const ::ausroll::internal::Registration<Kind, Class>                                         \
        AUSROLL_REGISTRY_CONCAT(ausroll_registration_, __LINE__){name, subsection, description}; \
  }
