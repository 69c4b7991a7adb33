#pragma once
// Named, seeded random streams. Every random draw in canopy comes from a RandomStream created
// from (trial seed, purpose, index), so a trial is bit-for-bit reproducible whatever the
// thread count, and adding a draw for one purpose never shifts the draws of another.
#include <bit>
#include <cstdint>
#include <span>
#include <string_view>

#include "core/types.h"

namespace canopy {

/// xoshiro256** (Blackman & Vigna 2018) seeded through SplitMix64. The distributions are our
/// own (not <random>'s) so that the same seed gives the same numbers with any standard library.
class RandomStream {
 public:
  /// trial_seed: the trial's seed; purpose: e.g. "sensing", "pso"; index: e.g. the agent.
  RandomStream(std::uint64_t trial_seed, std::string_view purpose, std::uint64_t index = 0);

  std::uint64_t nextU64();               // inline below: the swarm draws millions per call
  double uniform();                      // [0, 1), 53 random bits
  double uniform(double lo, double hi);  // [lo, hi)
  /// out[k] = uniform() for k = 0, 1, …: the same numbers in the same order as one call each.
  void fillUniform(std::span<double> out);
  double normal();                        // N(0, 1), Marsaglia's polar method
  double exponential(double rate);        // Exp(rate), mean 1/rate
  int poisson(double mean);               // exact: counts Exp(mean) arrivals in [0, 1)
  bool bernoulli(double p);               // true with probability p
  Vec2 gaussian(const Mat2& covariance);  // N(0, covariance), via Cholesky (LDLᵀ if singular)

 private:
  std::uint64_t s_[4];
  double spare_normal_ = 0.0;
  bool has_spare_normal_ = false;
};

inline std::uint64_t RandomStream::nextU64() {
  const std::uint64_t result = std::rotl(s_[1] * 5, 7) * 9;  // the ** scrambler
  const std::uint64_t t = s_[1] << 17;
  s_[2] ^= s_[0];
  s_[3] ^= s_[1];
  s_[1] ^= s_[2];
  s_[0] ^= s_[3];
  s_[2] ^= t;
  s_[3] = std::rotl(s_[3], 45);
  return result;
}

inline double RandomStream::uniform() {
  // The top 53 bits, · 2⁻⁵³. Below 2⁵³ the signed conversion is exact and equals the unsigned
  // one (g++ 12 -O3 emits the same single cvtsi2sd for both here: it knows the range).
  return static_cast<double>(static_cast<std::int64_t>(nextU64() >> 11)) * 0x1.0p-53;
}

inline double RandomStream::uniform(double lo, double hi) {
  return lo + (hi - lo) * uniform();
}

inline void RandomStream::fillUniform(std::span<double> out) {
  for (double& u : out) u = uniform();
}

/// 64-bit FNV-1a of a string: stable across platforms (used to name streams and hash configs).
std::uint64_t fnv1a64(std::string_view text);

}  // namespace canopy
