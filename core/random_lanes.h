#pragma once
// Four random streams side by side, one per lane of a vector (core/lanes.h), for the particle
// swarm's r1, r2: a planning call draws about 2.7·10⁵ of them, which one scalar stream produced
// at 19 instructions each, a third of the swarm's own work. Four xoshiro256+ streams (Blackman &
// Vigna 2018; the "+" scrambler is the authors' choice for floating point, whose upper bits it
// leaves sound) advance in one vector step each: a few instructions per number. The streams are
// seeded from a named RandomStream, so a trial's numbers still follow from its seed alone, on any
// CPU and at any thread count (integer arithmetic; the baseline lowers it to SSE2 pairs).
#include <cstddef>
#include <cstdint>

#include "core/lanes.h"
#include "core/random.h"

namespace canopy::lanes {

using U4 = std::uint64_t __attribute__((vector_size(32)));  // four 64-bit words

/// The state of four xoshiro256+ streams: word k of every lane in s[k]. Aligned to 32 bytes
/// explicitly: outside an AVX translation unit GCC gives a 32-byte vector type only 16, so a
/// RandomLanes inside a heap object (ParticleSwarm's, in a std::vector of PlanOptimizer) could sit
/// at an odd 16, and the AVX2 kernel's aligned loads of it (vmovdqa) fault.
struct alignas(32) RandomLanes {
  U4 s[4];

  /// Four streams whose sixteen state words are the next sixteen draws of `source` (a lane whose
  /// words are all zero, the one state xoshiro cannot leave, gets 1 for its first word).
  static RandomLanes from(RandomStream& source) {
    RandomLanes r;
    for (int lane = 0; lane < 4; ++lane) {
      bool all_zero = true;
      for (int k = 0; k < 4; ++k) {
        r.s[k][lane] = source.nextU64();
        all_zero = all_zero && r.s[k][lane] == 0;
      }
      if (all_zero) r.s[0][lane] = 1;
    }
    return r;
  }
};

/// One step of the four streams, returned as four uniforms on [0, 1) with 52 random bits each
/// (the top 52 bits of each output as the mantissa of a double in [1, 2), minus 1: exact).
///   out = s0 + s3;  t = s1 << 17;  s2 ^= s0;  s3 ^= s1;  s1 ^= s2;  s0 ^= s3;  s2 ^= t;
///   s3 = rotl(s3, 45).
/// The state is passed as four locals so that a kernel keeps it in registers.
[[gnu::always_inline]] inline V4 nextUniform(U4& s0, U4& s1, U4& s2, U4& s3) {
  const U4 out = s0 + s3;
  const U4 t = s1 << 17;
  s2 ^= s0;
  s3 ^= s1;
  s1 ^= s2;
  s0 ^= s3;
  s2 ^= t;
  s3 = (s3 << 45) | (s3 >> 19);
  constexpr std::uint64_t kOne = 0x3FF0000000000000;  // the bits of 1.0
  return (V4)((out >> 12) | kOne) - 1.0;
}

/// The four streams moved on by `steps` steps of nextUniform, the draws discarded: where a later
/// part of a sequence of draws starts, so that it can be drawn apart from the parts before it.
inline void advance(RandomLanes& random, std::size_t steps) {
  U4 s0 = random.s[0], s1 = random.s[1], s2 = random.s[2], s3 = random.s[3];
  for (std::size_t k = 0; k < steps; ++k) nextUniform(s0, s1, s2, s3);
  random.s[0] = s0;
  random.s[1] = s1;
  random.s[2] = s2;
  random.s[3] = s3;
}

}  // namespace canopy::lanes
