#pragma once
// (cos θ, sin θ) of a swarm heading θ ∈ [0, 2π] in one inline evaluation, for the planner's
// decode a = s (cos θ, sin θ) (algorithms.md §6), which runs for every action of every particle.
// glibc's cos and sin are correctly rounded in nearly all cases but cost a call each; this is
// within 2.3e-16 of them in absolute terms (about 2 ulp of 1; tests/agents/planning/
// heading_test.cpp), so plans differ from a libm decode only in the last bits of the actions
// (docs/design-notes.md).
#include <cstddef>
#include <cstdint>
#include <iterator>

#include "core/types.h"

namespace canopy::agents::planning {

/// The constants of unitHeading, shared with its four-lane form (swarm_kernels.cpp).
namespace heading_series {
constexpr double kTwoOverPi = 0.63661977236758134308;     // 2/π
constexpr double kHalfPi1 = 1.57079632673412561417e+00;   // π/2, 33 bits: 0x3FF921FB54400000
constexpr double kHalfPi1t = 6.07710050650619224932e-11;  // π/2 − kHalfPi1: 0x3DD0B4611A626331
// Taylor coefficients in r², innermost first: sin r = r + r·r²·(−1/3! + r²(1/5! + …)),
// cos r = 1 + r²·(−1/2! + r²(1/4! + …)).
constexpr double kSin[] = {1.0 / 355687428096000,
                           -1.0 / 1307674368000,
                           1.0 / 6227020800,
                           -1.0 / 39916800,
                           1.0 / 362880,
                           -1.0 / 5040,
                           1.0 / 120,
                           -1.0 / 6};  // 1/17!, −1/15!, …, −1/3!
constexpr double kCos[] = {-1.0 / 6402373705728000,
                           1.0 / 20922789888000,
                           -1.0 / 87178291200,
                           1.0 / 479001600,
                           -1.0 / 3628800,
                           1.0 / 40320,
                           -1.0 / 720,
                           1.0 / 24,
                           -0.5};  // −1/18!, …
}  // namespace heading_series

/// (cos θ, sin θ) for 0 ≤ θ ≤ 2π (a heading of the swarm's box; other θ lose accuracy as |θ|
/// grows, but stay well below 2²⁰ · π/2 exact in the reduction).
///   n = round(θ / (π/2)),  r = θ − n π/2 ∈ [−π/4, π/4]  (Cody–Waite: π/2 = P1 + P1t, where P1
///   holds 33 significant bits, so n·P1 and θ − n·P1 are exact),
///   sin r = r − r³/3! + … − r¹⁷/17!,  cos r = 1 − r²/2! + … + r¹⁸/18!  (Taylor; the remainders
///   are below 10⁻¹⁹ on |r| ≤ π/4; the reduction's own error, π/2 − P1 − P1t = 3.5·10⁻²⁷ per
///   quarter, is absolute),
///   then (cos θ, sin θ) = (cos r, sin r) rotated by n quarter turns.
inline Vec2 unitHeading(double theta) {
  using namespace heading_series;
  const double scaled = theta * kTwoOverPi;
  const std::int64_t n = static_cast<std::int64_t>(scaled >= 0.0 ? scaled + 0.5 : scaled - 0.5);
  const double nd = static_cast<double>(n);
  const double r = (theta - nd * kHalfPi1) - nd * kHalfPi1t;  // θ − n π/2, |r| ≤ π/4
  const double r2 = r * r;
  // Horner in r², both series at once in the two lanes of a pair (each lane the scalar steps in
  // the same order, so the same bits); cos has one coefficient more, taken first.
  using Pair = double __attribute__((vector_size(16)));
  static_assert(std::size(kCos) == std::size(kSin) + 1);
  Pair tail = {kSin[0], kCos[1] + r2 * kCos[0]};  // (sin tail, cos tail)
  for (std::size_t k = 1; k < std::size(kSin); ++k) {
    const Pair coefficient = {kSin[k], kCos[k + 1]};
    tail = coefficient + r2 * tail;
  }
  const double sin_r = r + r * r2 * tail[0];
  const double cos_r = 1.0 + r2 * tail[1];
  switch (n & 3) {  // θ = r + n π/2
    case 0:
      return {cos_r, sin_r};
    case 1:
      return {-sin_r, cos_r};
    case 2:
      return {-cos_r, -sin_r};
    default:
      return {sin_r, -cos_r};
  }
}

}  // namespace canopy::agents::planning
