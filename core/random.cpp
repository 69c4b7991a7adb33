#include "core/random.h"

#include <Eigen/Cholesky>
#include <cmath>

namespace canopy {
namespace {

std::uint64_t splitMix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

}  // namespace

std::uint64_t fnv1a64(std::string_view text) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  return h;
}

RandomStream::RandomStream(std::uint64_t trial_seed, std::string_view purpose,
                           std::uint64_t index) {
  std::uint64_t state = trial_seed;
  state ^= splitMix64(state) ^ fnv1a64(purpose);
  state ^= splitMix64(state) ^ (index * 0xd1b54a32d192ed03ULL);
  for (std::uint64_t& word : s_) word = splitMix64(state);
}

double RandomStream::normal() {
  if (has_spare_normal_) {
    has_spare_normal_ = false;
    return spare_normal_;
  }
  double u = 0.0, v = 0.0, s = 0.0;
  do {
    u = 2.0 * uniform() - 1.0;
    v = 2.0 * uniform() - 1.0;
    s = u * u + v * v;
  } while (s >= 1.0 || s == 0.0);
  const double scale = std::sqrt(-2.0 * std::log(s) / s);
  spare_normal_ = v * scale;
  has_spare_normal_ = true;
  return u * scale;
}

double RandomStream::exponential(double rate) {
  return -std::log1p(-uniform()) / rate;
}

int RandomStream::poisson(double mean) {
  if (!(mean > 0.0)) return 0;
  // Arrivals of a unit-rate Poisson process in [0, mean] (inter-arrival times Exp(1)).
  int count = 0;
  for (double t = exponential(1.0); t <= mean; t += exponential(1.0)) ++count;
  return count;
}

bool RandomStream::bernoulli(double p) {
  return uniform() < p;
}

Vec2 RandomStream::gaussian(const Mat2& covariance) {
  const Vec2 w(normal(), normal());
  const Eigen::LLT<Mat2> llt(covariance);
  if (llt.info() == Eigen::Success) return llt.matrixL() * w;
  // Positive semi-definite (e.g. a zero variance): x = P L √D w.
  const Eigen::LDLT<Mat2> ldlt(covariance);
  const Vec2 d = ldlt.vectorD().cwiseMax(0.0).cwiseSqrt();
  Vec2 x = ldlt.matrixL() * d.cwiseProduct(w);
  return ldlt.transpositionsP().transpose() * x;
}

}  // namespace canopy
