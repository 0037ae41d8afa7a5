#include "hullinspect/experiment/shard.hpp"

#include <fmt/format.h>

#include <charconv>

#include "hullinspect/core/errors.hpp"

namespace hullinspect::experiment {

namespace {

std::optional<long long> parse_integer(std::string_view s) {
  long long v = 0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || s.empty()) return std::nullopt;
  return v;
}

}  // namespace

std::string Shard::text() const { return fmt::format("{}/{}", index, count); }

Shard parse_shard(std::string_view text) {
  const auto slash = text.find('/');
  std::optional<long long> k;
  std::optional<long long> n;
  if (slash != std::string_view::npos) {
    k = parse_integer(text.substr(0, slash));
    n = parse_integer(text.substr(slash + 1));
  }
  if (!k || !n || *n < 1 || *n > 1000000 || *k < 1 || *k > *n) {
    throw ParameterError("shard", fmt::format("must be K/N with 1 <= K <= N (got '{}')", text));
  }
  return Shard{static_cast<int>(*k), static_cast<int>(*n)};
}

std::optional<Shard> shard_from_slurm(const EnvLookup& getenv) {
  const char* id_text = getenv("SLURM_ARRAY_TASK_ID");
  const char* count_text = getenv("SLURM_ARRAY_TASK_COUNT");
  if (id_text == nullptr || count_text == nullptr) return std::nullopt;
  const char* min_text = getenv("SLURM_ARRAY_TASK_MIN");
  const char* step_text = getenv("SLURM_ARRAY_TASK_STEP");
  const auto id = parse_integer(id_text);
  const auto count = parse_integer(count_text);
  const auto min = min_text ? parse_integer(min_text) : std::optional<long long>(0);
  const auto step = step_text ? parse_integer(step_text) : std::optional<long long>(1);
  if (!id || !count || !min || !step || *step < 1 || *id < *min || (*id - *min) % *step != 0) {
    throw ParameterError(
        "shard", fmt::format("cannot derive a shard from SLURM_ARRAY_TASK_ID={} "
                             "SLURM_ARRAY_TASK_COUNT={} SLURM_ARRAY_TASK_MIN={} "
                             "SLURM_ARRAY_TASK_STEP={}",
                             id_text, count_text, min_text ? min_text : "(unset)",
                             step_text ? step_text : "(unset)"));
  }
  return parse_shard(fmt::format("{}/{}", (*id - *min) / *step + 1, *count));
}

}  // namespace hullinspect::experiment
