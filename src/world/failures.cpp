#include "hullinspect/world/failures.hpp"

#include <fmt/format.h>

#include <charconv>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/world/random.hpp"

namespace hullinspect::world {

namespace {

/// Stream ids of the failure draws: one per UAV for the rate (so a UAV's draws do not depend on
/// when the others fail), one for the "one random UAV" draw.
std::uint64_t rate_stream(int uav) {
  return (static_cast<std::uint64_t>(Stream::kFailures) << 32) + static_cast<std::uint64_t>(uav);
}
constexpr std::uint64_t kOneRandomStream =
    (static_cast<std::uint64_t>(Stream::kFailures) << 32) - 1;

bool parse_int(std::string_view s, int& out) {
  if (s.empty()) return false;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && end == s.data() + s.size() && out >= 0;
}

}  // namespace

std::string FailurePlan::text() const {
  std::string out;
  for (const auto& f : at) out += fmt::format("{}{}@{}", out.empty() ? "" : ",", f.uav, f.time);
  if (rate > 0) out += fmt::format("{}rate={}", out.empty() ? "" : ";", rate);
  if (one_within > 0) out += fmt::format("{}one<{}", out.empty() ? "" : ";", one_within);
  return out;
}

UavFailure parse_uav_failure(std::string_view text) {
  const auto at = text.find('@');
  UavFailure f;
  if (at == std::string_view::npos || !parse_int(text.substr(0, at), f.uav) ||
      !parse_int(text.substr(at + 1), f.time)) {
    throw ParameterError("fail",
                         fmt::format("expects UAV@STEP with two integers >= 0 (got '{}')", text));
  }
  return f;
}

void validate(const FailurePlan& plan, int uavs) {
  for (const auto& f : plan.at) {
    if (f.uav < 0 || f.uav >= uavs) {
      throw ParameterError("fail", fmt::format("UAV {} does not exist (the fleet has UAVs 0 to {})",
                                               f.uav, uavs - 1));
    }
    if (f.time < 0) throw ParameterError("fail", fmt::format("step {} is negative", f.time));
  }
  if (!(plan.rate >= 0 && plan.rate <= 1)) {
    throw ParameterError("fail-rate", fmt::format("must be in [0, 1] (got {})", plan.rate));
  }
  if (plan.one_within < 0) {
    throw ParameterError("fail-one-within", fmt::format("must be >= 0 (got {})", plan.one_within));
  }
}

std::vector<int> failure_times(const FailurePlan& plan, int uavs, std::uint64_t seed,
                               int time_limit) {
  std::vector<int> times(static_cast<std::size_t>(uavs), -1);
  auto fail = [&](int uav, int t) {
    auto& slot = times[static_cast<std::size_t>(uav)];
    if (t < time_limit && (slot < 0 || t < slot)) slot = t;
  };
  for (const auto& f : plan.at) fail(f.uav, f.time);
  if (plan.rate > 0) {
    // One Bernoulli draw per step while the UAV works: exactly the per-step definition. The draws
    // stop at the first failure (or the time limit), so this costs O(min(1/p, limit)) per UAV.
    for (int k = 0; k < uavs; ++k) {
      RandomStream stream(seed, rate_stream(k));
      for (int t = 0; t < time_limit; ++t) {
        if (stream.bernoulli(plan.rate)) {
          fail(k, t);
          break;
        }
      }
    }
  }
  if (plan.one_within > 0) {
    RandomStream stream(seed, kOneRandomStream);
    const auto uav = static_cast<int>(stream.below(static_cast<std::uint64_t>(uavs)));
    const auto t = static_cast<int>(stream.below(static_cast<std::uint64_t>(plan.one_within)));
    fail(uav, t);
  }
  return times;
}

}  // namespace hullinspect::world
