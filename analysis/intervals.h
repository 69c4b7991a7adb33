#pragma once
// 95 % confidence intervals for the numbers `analyze` and the report print: the Wilson score
// interval for a proportion k/n, the Student-t interval for a mean of independent trials, and a
// Student-t interval on the logit scale for a mean of values that lie in a known range.
#include <string>
#include <vector>

namespace canopy::analysis {

/// z_{0.975}, the standard normal quantile of a two-sided 95 % interval.
constexpr double kZ95 = 1.959963984540054;

/// A closed interval [low, high]; unbounded (±∞) where the sample cannot bound it.
struct ConfidenceInterval {
  double low = 0.0;
  double high = 0.0;
  double width() const { return high - low; }
  bool bounded() const;
  bool contains(double x) const { return low <= x && x <= high; }
};

/// The 95 % Wilson score interval of a proportion with k successes in n trials (Wilson 1927):
///   centre = (p̂ + z²/2n) / (1 + z²/n),  half = z / (1 + z²/n) · √(p̂(1 − p̂)/n + z²/4n²).
/// n = 0 gives [0, 1]; k = 0 gives low = 0 and k = n gives high = 1 exactly.
ConfidenceInterval wilsonInterval(int k, int n);

/// The p-quantile of Student's t distribution with df ≥ 1 degrees of freedom, for 0.5 ≤ p < 1,
/// by Boost.Math's students_t.
double studentTQuantile(double p, int df);

/// Count, mean and variance of a sample, accumulated one value at a time (Welford 1962), so that
/// per-step means over trials need no per-trial storage.
class SampleMoments {
 public:
  void add(double x);
  int count() const { return n_; }
  double mean() const { return mean_; }
  /// The unbiased sample variance s² (0 for fewer than two values).
  double variance() const;

 private:
  int n_ = 0;
  double mean_ = 0.0;
  double m2_ = 0.0;  // Σ (x − mean)²
};

/// Fewer trials than this cannot give a zero-width interval: two or three agreeing trials say
/// little about the spread, so such an interval is refused ("too few trials") rather than printed
/// as a point.
constexpr int kMinTrialsForPoint = 5;

/// The 95 % Student-t interval of the mean, mean ± t_{0.975, n−1} · s / √n; unbounded for n < 2
/// and for s = 0 with n < kMinTrialsForPoint.
ConfidenceInterval meanInterval(const SampleMoments& sample);
ConfidenceInterval meanInterval(const std::vector<double>& values);

/// `ci` cut to [lo, hi], the range the estimated quantity can take (a fraction, a footprint count);
/// an unbounded interval stays unbounded, so that "no interval" remains visible.
ConfidenceInterval clipped(const ConfidenceInterval& ci, double lo, double hi);

/// The 95 % interval of the mean of values known to lie in [lo, hi] (a fraction of columns, the
/// footprints of N UAVs on a target), always inside (lo, hi): Student t on the logit scale by the
/// delta method. With u = (x̄ − lo)/(hi − lo), s_u = s/(hi − lo) and σ(y) = 1/(1 + e^{−y}):
///   η = ln(u/(1 − u)),  se_η = s_u / (√n · u(1 − u)),
///   [lo + (hi − lo) · σ(η − t_{0.975,n−1} se_η),  lo + (hi − lo) · σ(η + t_{0.975,n−1} se_η)].
/// Every value at one bound gives that point (with n ≥ kMinTrialsForPoint); unbounded as
/// meanInterval is (n < 2, or s = 0 with n < kMinTrialsForPoint).
ConfidenceInterval boundedMeanInterval(const SampleMoments& sample, double lo, double hi);

/// A number, its 95 % interval, and the trials behind it.
struct Estimate {
  double value = 0.0;
  ConfidenceInterval ci;
  int trials = 0;
};
/// k/n with its Wilson interval (value 0 for n = 0).
Estimate proportion(int k, int n);
/// The mean of `values` with its Student-t interval.
Estimate meanOf(const std::vector<double>& values);
/// The mean of `values`, each in [lo, hi], with boundedMeanInterval.
Estimate boundedMeanOf(const std::vector<double>& values, double lo, double hi);

/// `x` as a CSV field in the stream's default format, or an empty field when it is not finite:
/// the ends of an interval too few trials bound are ±inf, which pandas and matplotlib would read
/// as numbers and draw as bands of infinite height (docs/output-formats.md).
std::string csvNumber(double x);

}  // namespace canopy::analysis
