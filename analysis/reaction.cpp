#include "analysis/reaction.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/random.h"

namespace canopy::analysis {
namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

// The first step at which the mean over `chosen` trials (indices, with repeats) of the target's
// coverage is below level, as k·dt; +∞ when it never is.
double crossing(const ConfigStatistics& s, int target, double level,
                const std::vector<int>& chosen) {
  const std::size_t steps = s.trial_coverage.front()[target].size();
  const double bound = level * static_cast<double>(chosen.size());  // Σ < level·n ⇔ mean < level
  for (std::size_t k = 0; k < steps; ++k) {
    double sum = 0.0;
    for (const int trial : chosen) sum += s.trial_coverage[trial][target][k];
    if (sum < bound) return static_cast<double>(k) * s.dt;
  }
  return kNever;
}

// The p-quantile of sorted values by the nearest-rank rule (the ⌈p·n⌉-th smallest).
double nearestRank(const std::vector<double>& sorted, double p) {
  const auto rank = static_cast<std::size_t>(std::ceil(p * static_cast<double>(sorted.size())));
  return sorted[std::clamp<std::size_t>(rank, 1, sorted.size()) - 1];
}

}  // namespace

CrossingTime firstCrossing(const ConfigStatistics& s, int target, double level,
                           std::uint64_t seed, int resamples) {
  CrossingTime result;
  result.ci = {-kNever, kNever};
  const int n = static_cast<int>(s.trial_coverage.size());
  if (n == 0) return result;
  std::vector<int> chosen(n);
  for (int i = 0; i < n; ++i) chosen[i] = i;
  const double all = crossing(s, target, level, chosen);
  if (std::isfinite(all)) result.time_s = all;
  if (n < 2 || resamples < 1) return result;
  RandomStream rng(seed, "bootstrap");
  std::vector<double> times(resamples);
  for (double& t : times) {
    for (int& i : chosen) i = static_cast<int>(rng.uniform() * n);  // with replacement
    t = crossing(s, target, level, chosen);
  }
  std::sort(times.begin(), times.end());
  const ConfidenceInterval ci{nearestRank(times, 0.025), nearestRank(times, 0.975)};
  // Agreeing trials, too few to say the spread is nil: no interval ("too few trials").
  if (ci.low == ci.high && n < kMinTrialsForPoint) return result;
  result.ci = ci;
  return result;
}

}  // namespace canopy::analysis
