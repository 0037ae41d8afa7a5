#pragma once
// Small helpers shared by the benchmark programs that parse their own options and time themselves.

#include <algorithm>
#include <cstddef>
#include <ctime>
#include <sstream>
#include <string>
#include <vector>

namespace hullinspect::bench {

/// CPU time of the calling thread, seconds: on a shared machine wall time measures the other jobs.
inline double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

/// The non-empty items of `text` between `sep`s.
inline std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, sep);) {
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

}  // namespace hullinspect::bench

namespace hullinspect::bench {

/// The median of `v` (the upper one of an even count); `v` must not be empty.
inline double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

}  // namespace hullinspect::bench
