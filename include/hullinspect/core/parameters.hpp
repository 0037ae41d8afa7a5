#pragma once
// Declared parameters (docs/architecture.md, "Parameters and registries"): every planner,
// partitioner, TSP solver and scenario declares each of its options once — name (kebab-case), type,
// default, range, description — bound to a field of its plain options struct. The declaration
// parses an OptionMap into the struct (typed, range-checked, unknown keys refused with a hint),
// writes the effective options back as canonical text (defaults included) and lists itself for
// --help, `hullinspect list`, the manifest and Python. There is no global state besides the
// registries (core/registry.hpp), which only hold these declarations.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/options.hpp"

namespace hullinspect {

enum class ParamType { kInt, kDouble, kBool, kString, kEnum, kNested };

/// "int", "double", "bool", "string", "enum", "options".
std::string_view param_type_name(ParamType type);

/// One declared option, as shown to users.
struct ParamSpec {
  std::string name;           ///< kebab-case; "tsp.<key>" for a nested group
  ParamType type = ParamType::kString;
  std::string default_value;  ///< canonical text of the default
  std::string range;          ///< "[0, 1]", "true|false", "darp|stripes", "" (any text)
  std::string description;
};

/// "name = default" lines with ranges, for help texts: "  r1 (int, default 2, [0, 1048576]): …".
std::string describe_params(const std::vector<ParamSpec>& specs, std::string_view indent = "  ");

/// Parsers shared by every declaration (and the CLI). `owner_key` names the option in errors
/// ("part-tsp.r1"); the messages say what was expected and what was given.
long long parse_int_param(const std::string& owner_key, const std::string& text, long long min,
                          long long max);
double parse_double_param(const std::string& owner_key, const std::string& text, double min,
                          double max);
bool parse_bool_param(const std::string& owner_key, const std::string& text);
/// Canonical text of a value (shortest round-trip form for doubles).
std::string param_text(double value);
std::string param_text(long long value);
std::string param_text(bool value);

/// The unknown-key error: names the known keys and, when one is close (same letters with '_' for
/// '-', or a small typo), suggests it: "unknown option 'time_limit' (did you mean time-limit?)".
[[noreturn]] void throw_unknown_param(const std::string& owner, const std::string& key,
                                      const std::vector<std::string>& known);
/// The closest of `known` to `key` ("" when none is close).
std::string closest_name(std::string_view key, const std::vector<std::string>& known);

/// The declaration of a stage's options, bound to the fields of `Options`. Defaults are the values
/// of the `defaults` object (normally `Options{}`, i.e. the struct's member initialisers), so a
/// default is written exactly once.
template <class Options>
class Params {
 public:
  /// Resolves a nested group: (the options read so far, the group's keys without prefix) →
  /// the group's effective options (validated, defaults filled). Throws ParameterError.
  using NestedResolver = std::function<OptionMap(const Options&, const OptionMap&)>;

  explicit Params(std::string owner, Options defaults = {})
      : owner_(std::move(owner)), defaults_(std::move(defaults)) {}

  const std::string& owner() const { return owner_; }
  const Options& defaults() const { return defaults_; }

  template <class Int>
  Params& integer(std::string name, Int Options::*field, long long min, long long max,
                  std::string description) {
    Param p;
    p.spec = {name, ParamType::kInt, param_text(static_cast<long long>(defaults_.*field)),
              "[" + param_text(min) + ", " + param_text(max) + "]", std::move(description)};
    const std::string key = owner_ + "." + name;
    p.parse = [field, key, min, max](Options& o, const std::string& text) {
      o.*field = static_cast<Int>(parse_int_param(key, text, min, max));
    };
    p.write = [field](const Options& o) { return param_text(static_cast<long long>(o.*field)); };
    params_.push_back(std::move(p));
    return *this;
  }

  Params& number(std::string name, double Options::*field, double min, double max,
                 std::string description) {
    Param p;
    p.spec = {name, ParamType::kDouble, param_text(defaults_.*field),
              "[" + param_text(min) + ", " + param_text(max) + "]", std::move(description)};
    const std::string key = owner_ + "." + name;
    p.parse = [field, key, min, max](Options& o, const std::string& text) {
      o.*field = parse_double_param(key, text, min, max);
    };
    p.write = [field](const Options& o) { return param_text(o.*field); };
    params_.push_back(std::move(p));
    return *this;
  }

  Params& flag(std::string name, bool Options::*field, std::string description) {
    Param p;
    p.spec = {name, ParamType::kBool, param_text(defaults_.*field), "true|false",
              std::move(description)};
    const std::string key = owner_ + "." + name;
    p.parse = [field, key](Options& o, const std::string& text) {
      o.*field = parse_bool_param(key, text);
    };
    p.write = [field](const Options& o) { return param_text(o.*field); };
    params_.push_back(std::move(p));
    return *this;
  }

  Params& text(std::string name, std::string Options::*field, std::string description) {
    Param p;
    p.spec = {name, ParamType::kString, defaults_.*field, "", std::move(description)};
    p.parse = [field](Options& o, const std::string& text) { o.*field = text; };
    p.write = [field](const Options& o) { return o.*field; };
    params_.push_back(std::move(p));
    return *this;
  }

  /// A name from a list that may grow (e.g. the registered TSP solvers): `choices` is asked each
  /// time, so the range always lists what is registered now.
  Params& choice(std::string name, std::string Options::*field,
                 std::function<std::vector<std::string>()> choices, std::string description) {
    Param p;
    p.spec = {name, ParamType::kEnum, defaults_.*field, "", std::move(description)};
    p.choices = choices;
    const std::string key = owner_ + "." + name;
    p.parse = [field, key, choices](Options& o, const std::string& text) {
      const auto names = choices();
      for (const auto& n : names) {
        if (n == text) {
          o.*field = text;
          return;
        }
      }
      std::string list;
      for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
      throw ParameterError(key, "unknown name '" + text + "' (known: " + list + ")");
    };
    p.write = [field](const Options& o) { return o.*field; };
    params_.push_back(std::move(p));
    return *this;
  }

  /// A group of options passed on to another stage, spelled "<prefix>.<key>" (e.g. "tsp.kicks");
  /// `resolve` validates them against that stage and returns its effective options.
  Params& nested(std::string prefix, OptionMap Options::*field, NestedResolver resolve,
                 std::string description) {
    Param p;
    p.spec = {prefix + ".<key>", ParamType::kNested, "", "", std::move(description)};
    p.prefix = prefix + ".";
    p.assign = [field](Options& o, OptionMap m) { o.*field = std::move(m); };
    p.resolve = std::move(resolve);
    p.write_nested = [field](const Options& o) { return o.*field; };
    params_.push_back(std::move(p));
    return *this;
  }

  /// The declared options, in declaration order (ranges of choices as currently registered).
  std::vector<ParamSpec> specs() const {
    std::vector<ParamSpec> out;
    for (const auto& p : params_) {
      ParamSpec s = p.spec;
      if (p.choices) {
        for (const auto& n : p.choices()) s.range += (s.range.empty() ? "" : "|") + n;
      }
      out.push_back(std::move(s));
    }
    return out;
  }

  /// Reads `options` over the defaults. Throws ParameterError("<owner>.<key>", …) for a bad value
  /// or an unknown key (with a did-you-mean hint).
  Options read(const OptionMap& options) const {
    Options o = defaults_;
    std::vector<OptionMap> groups(params_.size());
    for (const auto& [key, value] : options) {
      bool used = false;
      for (std::size_t i = 0; i < params_.size() && !used; ++i) {
        const Param& p = params_[i];
        if (!p.prefix.empty()) {
          if (key.size() > p.prefix.size() && key.compare(0, p.prefix.size(), p.prefix) == 0) {
            groups[i][key.substr(p.prefix.size())] = value;
            used = true;
          }
        } else if (p.spec.name == key) {
          p.parse(o, value);
          used = true;
        }
      }
      if (!used) throw_unknown_param(owner_, key, known_names());
    }
    for (std::size_t i = 0; i < params_.size(); ++i) {
      const Param& p = params_[i];
      if (!p.prefix.empty()) p.assign(o, p.resolve(o, groups[i]));
    }
    return o;
  }

  /// The effective options of `o` as canonical text, every declared option included; a nested
  /// group contributes "<prefix>.<key>" entries.
  OptionMap write(const Options& o) const {
    OptionMap out;
    for (const auto& p : params_) {
      if (!p.prefix.empty()) {
        for (const auto& [k, v] : p.write_nested(o)) out[p.prefix + k] = v;
      } else {
        out[p.spec.name] = p.write(o);
      }
    }
    return out;
  }

  /// write(read(options)): validated, defaults filled in, canonical.
  OptionMap resolve(const OptionMap& options) const { return write(read(options)); }

 private:
  struct Param {
    ParamSpec spec;
    std::function<std::vector<std::string>()> choices;
    std::function<void(Options&, const std::string&)> parse;
    std::function<std::string(const Options&)> write;
    std::string prefix;  // non-empty for a nested group
    std::function<void(Options&, OptionMap)> assign;
    NestedResolver resolve;
    std::function<OptionMap(const Options&)> write_nested;
  };

  std::vector<std::string> known_names() const {
    std::vector<std::string> names;
    for (const auto& p : params_) names.push_back(p.spec.name);
    return names;
  }

  std::string owner_;
  Options defaults_;
  std::vector<Param> params_;
};

}  // namespace hullinspect
