#include <fmt/format.h>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/partition/darp_partitioner.hpp"
#include "hullinspect/partition/partitioner.hpp"
#include "hullinspect/partition/stripes_partitioner.hpp"

namespace hullinspect::partition {

namespace {

std::unique_ptr<Partitioner> make_stripes(const OptionMap& options) {
  OptionReader reader(options, "stripes");
  reader.reject_unknown();
  return std::make_unique<StripesPartitioner>();
}

std::unique_ptr<Partitioner> make_darp(const OptionMap& options) {
  return std::make_unique<DarpPartitioner>(read_darp_options(options));
}

const std::vector<PartitionerInfo>& registry() {
  static const std::vector<PartitionerInfo> entries = {
      {"darp", "DARP (model.md §5.1): connected, balanced regions grown from the start cells",
       darp_option_specs(), &make_darp},
      {"stripes", "equal-area vertical bands, in the order of the start cells' x", {}, &make_stripes},
  };
  return entries;
}

}  // namespace

std::span<const PartitionerInfo> partitioner_registry() { return registry(); }

std::unique_ptr<Partitioner> make_partitioner(std::string_view name, const OptionMap& options) {
  std::string names;
  for (const auto& info : registry()) {
    if (info.name == name) return info.make(options);
    names += (names.empty() ? "" : ", ") + info.name;
  }
  throw ParameterError("partitioner", fmt::format("unknown partitioner '{}' (known: {})", name, names));
}

}  // namespace hullinspect::partition
