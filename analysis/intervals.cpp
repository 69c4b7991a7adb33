#include "analysis/intervals.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <sstream>

#include <boost/math/distributions/students_t.hpp>

namespace canopy::analysis {

bool ConfidenceInterval::bounded() const {
  return std::isfinite(low) && std::isfinite(high);
}

ConfidenceInterval wilsonInterval(int k, int n) {
  assert(0 <= k && k <= n);
  if (n == 0) return {0.0, 1.0};
  const double z2 = kZ95 * kZ95;
  const double p = static_cast<double>(k) / n;
  const double denominator = 1.0 + z2 / n;
  const double centre = (p + z2 / (2.0 * n)) / denominator;  // (p̂ + z²/2n) / (1 + z²/n)
  const double half =
      kZ95 / denominator * std::sqrt(p * (1.0 - p) / n + z2 / (4.0 * n * n));  // z/(1+z²/n)·√…
  return {k == 0 ? 0.0 : std::max(0.0, centre - half), k == n ? 1.0 : std::min(1.0, centre + half)};
}

double studentTQuantile(double p, int df) {
  assert(df >= 1 && p >= 0.5 && p < 1.0);
  // Boost.Math (Debian libboost-dev): the inverse of the regularised incomplete beta function.
  return boost::math::quantile(boost::math::students_t(static_cast<double>(df)), p);
}

void SampleMoments::add(double x) {
  ++n_;
  const double delta = x - mean_;
  mean_ += delta / n_;         // mean_n = mean_{n−1} + (x − mean_{n−1}) / n
  m2_ += delta * (x - mean_);  // M2_n = M2_{n−1} + (x − mean_{n−1})(x − mean_n)
}

double SampleMoments::variance() const {
  return n_ < 2 ? 0.0 : m2_ / (n_ - 1);
}

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

// No interval: a single trial, or agreeing trials too few to say the spread is zero.
bool tooFewTrials(const SampleMoments& sample) {
  return sample.count() < 2 || (sample.variance() == 0.0 && sample.count() < kMinTrialsForPoint);
}
}  // namespace

ConfidenceInterval meanInterval(const SampleMoments& sample) {
  const int n = sample.count();
  if (tooFewTrials(sample)) return {-kInf, kInf};
  const double half = studentTQuantile(0.975, n - 1) * std::sqrt(sample.variance() / n);
  return {sample.mean() - half, sample.mean() + half};
}

ConfidenceInterval boundedMeanInterval(const SampleMoments& sample, double lo, double hi) {
  assert(hi > lo);
  if (tooFewTrials(sample)) return {-kInf, kInf};
  const double n = sample.count();
  const double u = std::clamp((sample.mean() - lo) / (hi - lo), 0.0, 1.0);
  if (u == 0.0 || u == 1.0) return {sample.mean(), sample.mean()};  // every value at that bound
  const double s_u = std::sqrt(sample.variance()) / (hi - lo);
  const double eta = std::log(u / (1.0 - u));              // η = logit(u)
  const double se = s_u / (std::sqrt(n) * u * (1.0 - u));  // se_η = s_u / (√n u(1 − u))
  const double half = studentTQuantile(0.975, sample.count() - 1) * se;
  const auto back = [&](double y) { return lo + (hi - lo) / (1.0 + std::exp(-y)); };  // σ
  return {back(eta - half), back(eta + half)};
}

ConfidenceInterval meanInterval(const std::vector<double>& values) {
  return meanOf(values).ci;
}

ConfidenceInterval clipped(const ConfidenceInterval& ci, double lo, double hi) {
  if (!ci.bounded()) return ci;
  return {std::clamp(ci.low, lo, hi), std::clamp(ci.high, lo, hi)};
}

Estimate proportion(int k, int n) {
  return {n ? static_cast<double>(k) / n : 0.0, wilsonInterval(k, n), n};
}

Estimate meanOf(const std::vector<double>& values) {
  SampleMoments sample;
  for (const double x : values) sample.add(x);
  return {sample.mean(), meanInterval(sample), sample.count()};
}

Estimate boundedMeanOf(const std::vector<double>& values, double lo, double hi) {
  SampleMoments sample;
  for (const double x : values) sample.add(x);
  return {sample.mean(), boundedMeanInterval(sample, lo, hi), sample.count()};
}

std::string csvNumber(double x) {
  if (!std::isfinite(x)) return {};
  std::ostringstream text;
  text << x;
  return text.str();
}

}  // namespace canopy::analysis
