#pragma once
// One registry template for every stage chosen by name: planners, partitioners, TSP solvers and
// corrosion scenarios. An entry holds a name, a description, its declared options (ParamSpec) and
// two functions built from one Params<Options> declaration: resolve (validate, fill defaults) and
// make (build the product). Built-in entries are added when the registry is first used; user code
// adds its own with add() (examples/ planners, Python planners). Lookups and additions are
// thread-safe; entries are never removed, so references stay valid.

#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/parameters.hpp"

namespace hullinspect {

template <class Product>
struct RegistryEntry {
  std::string name;
  std::string description;
  /// The entry reads the ground truth (an oracle or bound): never a fair planner.
  bool sees_truth = false;
  std::vector<ParamSpec> options;  ///< as declared (refreshed by Registry::entries())
  std::function<std::vector<ParamSpec>()> specs;  ///< current specs (choice ranges can grow)
  std::function<OptionMap(const OptionMap&)> resolve;
  std::function<std::unique_ptr<Product>(const OptionMap&)> make;
};

/// An entry whose options are declared by `params` and whose product is built by `build` from the
/// options struct.
template <class Product, class Options>
RegistryEntry<Product> make_entry(std::string name, std::string description, Params<Options> params,
                                  std::function<std::unique_ptr<Product>(const Options&)> build,
                                  bool sees_truth = false) {
  auto shared = std::make_shared<const Params<Options>>(std::move(params));
  RegistryEntry<Product> e;
  e.name = std::move(name);
  e.description = std::move(description);
  e.sees_truth = sees_truth;
  e.options = shared->specs();
  e.specs = [shared] { return shared->specs(); };
  e.resolve = [shared](const OptionMap& o) { return shared->resolve(o); };
  e.make = [shared, build = std::move(build)](const OptionMap& o) { return build(shared->read(o)); };
  return e;
}

template <class Product>
class Registry {
 public:
  using Entry = RegistryEntry<Product>;

  /// `kind` names an entry in messages ("planner", "TSP solver"); `parameter` is the name of the
  /// option that selects one ("algorithm", "tsp-solver"); `builtins` adds the built-in entries on
  /// first use.
  Registry(std::string kind, std::string parameter, std::function<void(Registry&)> builtins)
      : kind_(std::move(kind)), parameter_(std::move(parameter)), builtins_(std::move(builtins)) {}

  const std::string& kind() const { return kind_; }

  /// Adds an entry; a name already registered is a LogicError (names are never replaced, so a
  /// running experiment keeps its planners).
  void add(Entry entry) {
    std::lock_guard lock(mutex_);
    load_locked();
    add_locked(std::move(entry));
  }

  bool contains(std::string_view name) const {
    std::lock_guard lock(mutex_);
    load_locked();
    for (const auto& e : entries_) {
      if (e.name == name) return true;
    }
    return false;
  }

  /// Throws ParameterError(parameter, "unknown <kind> '<name>' (known: …)").
  const Entry& get(std::string_view name) const {
    std::lock_guard lock(mutex_);
    load_locked();
    std::vector<std::string> names;
    for (const auto& e : entries_) {
      if (e.name == name) return e;
      names.push_back(e.name);
    }
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    std::string message = "unknown " + kind_ + " '" + std::string(name) + "'";
    if (auto near = closest_name(name, names); !near.empty()) message += " (did you mean " + near + "?)";
    throw ParameterError(parameter_, message + " (known: " + (list.empty() ? "none" : list) + ")");
  }

  /// A snapshot of every entry, in registration order, with current option specs.
  std::vector<Entry> entries() const {
    std::lock_guard lock(mutex_);
    load_locked();
    std::vector<Entry> out(entries_.begin(), entries_.end());
    for (auto& e : out) e.options = e.specs();
    return out;
  }

  std::vector<std::string> names() const {
    std::lock_guard lock(mutex_);
    load_locked();
    std::vector<std::string> out;
    for (const auto& e : entries_) out.push_back(e.name);
    return out;
  }

  std::unique_ptr<Product> make(std::string_view name, const OptionMap& options = {}) const {
    return get(name).make(options);
  }
  /// The effective options (validated, every default filled in, canonical text).
  OptionMap resolve(std::string_view name, const OptionMap& options = {}) const {
    return get(name).resolve(options);
  }

 private:
  void load_locked() const {
    if (loaded_) return;
    loaded_ = true;
    builtins_(const_cast<Registry&>(*this));
  }
  void add_locked(Entry entry) {
    for (const auto& e : entries_) {
      if (e.name == entry.name) {
        throw LogicError(kind_ + " '" + entry.name + "' is registered twice");
      }
    }
    if (!entry.specs) {
      auto fixed = entry.options;
      entry.specs = [fixed] { return fixed; };
    }
    entries_.push_back(std::move(entry));
  }

  std::string kind_;
  std::string parameter_;
  std::function<void(Registry&)> builtins_;
  mutable std::recursive_mutex mutex_;
  mutable bool loaded_ = false;
  std::deque<Entry> entries_;

 public:
  /// For the builtins function only (called with the lock held).
  void add_builtin(Entry entry) { add_locked(std::move(entry)); }
};

}  // namespace hullinspect
