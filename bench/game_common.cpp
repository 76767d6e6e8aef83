#include "game_common.hpp"

#include <algorithm>
#include <numeric>

namespace edgeland::bench {

std::size_t game_repeats() {
  return std::max<std::size_t>(1, env_count("EDGELAND_GAME_REPEATS", 5));
}

void Series::add_repeat(const std::vector<double>& seconds) {
  if (fastest.empty())
    fastest = seconds;
  else
    for (std::size_t i = 0; i < seconds.size(); ++i) fastest[i] = std::min(fastest[i], seconds[i]);
  repeat_median.push_back(quantile(seconds, 0.5));
}

void report_series(benchmark::State& state, const std::string& name, const Series& s) {
  const std::vector<double>& v = s.fastest;
  state.counters[name + "_median_us"] = quantile(v, 0.5) * 1e6;
  state.counters[name + "_p99_us"] = quantile(v, 0.99) * 1e6;
  state.counters[name + "_max_us"] = v.empty() ? 0 : *std::max_element(v.begin(), v.end()) * 1e6;
  state.counters[name + "_mean_us"] =
      v.empty() ? 0
                : std::accumulate(v.begin(), v.end(), 0.0) * 1e6 / static_cast<double>(v.size());
}

}  // namespace edgeland::bench
