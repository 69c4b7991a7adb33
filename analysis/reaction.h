#pragma once
// When a team reacts to an occlusion: the first time the mean coverage of a target over trials
// falls below a level (Joint Effect's "the curve changes at 1.6 s"), with a 95 % interval.
#include <cstdint>
#include <optional>

#include "analysis/intervals.h"
#include "analysis/sweep_statistics.h"

namespace canopy::analysis {

/// A first crossing time of a mean curve and its 95 % percentile-bootstrap interval.
struct CrossingTime {
  std::optional<double> time_s;  // none: the mean curve never falls below the level
  /// Percentiles 2.5 and 97.5 of the crossing time over resamples of the trials; a resample
  /// whose mean never falls below the level counts as +∞, so high = +∞ when more than 2.5 % of
  /// them never do. Unbounded (±∞) with fewer than two trials, and when fewer than
  /// kMinTrialsForPoint trials give a zero-width interval.
  ConfidenceInterval ci;
  bool contains(double t) const { return ci.contains(t); }
};

/// The first step k at which the mean over the trials of s.trial_coverage[·][target][k] is below
/// `level`, in seconds (k·dt), and its interval from `resamples` resamples of the trials with
/// replacement, drawn from RandomStream(seed, "bootstrap"): the same seed, the same interval.
CrossingTime firstCrossing(const ConfigStatistics& s, int target, double level,
                           std::uint64_t seed, int resamples = 2000);

}  // namespace canopy::analysis
