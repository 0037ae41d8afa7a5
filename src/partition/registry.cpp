#include "hullinspect/core/errors.hpp"
#include "hullinspect/partition/darp_partitioner.hpp"
#include "hullinspect/partition/partitioner.hpp"
#include "hullinspect/partition/stripes_partitioner.hpp"
#include "hullinspect/partition/transfer_partitioner.hpp"

namespace hullinspect::partition {

namespace {

struct StripesOptions {};

void add_builtins(PartitionerRegistry& r) {
  r.add_builtin(make_entry<Partitioner, DarpOptions>(
      "darp", "DARP (docs/partition.md): connected, balanced regions grown from the start cells",
      darp_params(), [](const DarpOptions& o) { return std::make_unique<DarpPartitioner>(o); }));
  r.add_builtin(make_entry<Partitioner, StripesOptions>(
      "stripes", "equal-area vertical bands, in the order of the start cells' x",
      Params<StripesOptions>("stripes"),
      [](const StripesOptions&) { return std::make_unique<StripesPartitioner>(); }));
  r.add_builtin(make_entry<Partitioner, TransferOptions>(
      "transfer",
      "geodesic Voronoi regions balanced exactly by connectivity-keeping boundary transfers "
      "(docs/partition.md); fast for large fleets",
      transfer_params(),
      [](const TransferOptions& o) { return std::make_unique<TransferPartitioner>(o); }));
}

}  // namespace

PartitionerRegistry& partitioners() {
  static PartitionerRegistry registry("partitioner", "partitioner", &add_builtins);
  return registry;
}

std::vector<PartitionerInfo> partitioner_registry() {
  return partitioners().entries();
}

std::unique_ptr<Partitioner> make_partitioner(std::string_view name, const OptionMap& options) {
  return partitioners().make(name, options);
}

OptionMap resolve_partitioner_options(std::string_view name, const OptionMap& options) {
  return partitioners().resolve(name, options);
}

}  // namespace hullinspect::partition
