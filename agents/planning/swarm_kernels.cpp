#include "agents/planning/swarm_kernels.h"

#include <cstdint>

#include "agents/planning/heading.h"
#include "core/cpu.h"
#include "core/lanes.h"
#include "core/random_lanes.h"

namespace canopy::agents::planning {
namespace {

using lanes::allLanes;
using lanes::I4;
using lanes::load;
using lanes::M4;
using lanes::store;
using lanes::U4;
using lanes::V4;

[[gnu::always_inline]] inline void moveOne(const SwarmMove& m, std::size_t i, double r1,
                                           double r2) {
  m.v[i] = m.w * m.v[i] + m.c1 * r1 * shortestDisplacement(m.own_best[i] - m.x[i], m.width[i]) +
           m.c2 * r2 * shortestDisplacement(m.swarm_best[i] - m.x[i], m.width[i]);
  m.x[i] = wrapPeriodic(m.x[i] + m.v[i], m.lo[i], m.hi[i]);
}

[[gnu::always_inline]] inline void moveParticlesBody(const SwarmMove& m) {
  // Locals: a store through x or v could alias the struct's own doubles and pointers as far as
  // the compiler knows, so it would reload every one of them for each vector.
  const double w = m.w, c1 = m.c1, c2 = m.c2;
  const double *own_best = m.own_best, *swarm_best = m.swarm_best;
  const double *lo_of = m.lo, *hi_of = m.hi, *width_of = m.width;
  double *xs = m.x, *vs = m.v, *moved_of = m.moved;
  const std::size_t count = m.count;
  U4 s0 = m.random->s[0], s1 = m.random->s[1], s2 = m.random->s[2], s3 = m.random->s[3];
  M4 near_all = M4{} - 1;  // every lane so far within one width of its box
  std::size_t i = 0;
  for (; i + 4 <= count; i += 4) {
    const V4 r1 = lanes::nextUniform(s0, s1, s2, s3);  // one per lane: coordinates i..i+3
    const V4 r2 = lanes::nextUniform(s0, s1, s2, s3);
    const V4 x = load(xs + i), width = load(width_of + i), lo = load(lo_of + i),
             hi = load(hi_of + i);
    const V4 half = 0.5 * width, minus_half = -0.5 * width;  // the bounds of δ's three cases
    // δ(d): d − width above width/2, d + width below −width/2, else d.
    const V4 d1 = load(own_best + i) - x, d2 = load(swarm_best + i) - x;
    const V4 toward_own = d1 > half ? d1 - width : (d1 < minus_half ? d1 + width : d1);
    const V4 toward_best = d2 > half ? d2 - width : (d2 < minus_half ? d2 + width : d2);
    const V4 v = w * load(vs + i) + c1 * r1 * toward_own + c2 * r2 * toward_best;
    const V4 moved = x + v;
    store(vs + i, v);
    store(moved_of + i, moved);
    // wrap: within one width of the box fmod(a, width) = a exactly, so the re-entry is one
    // addition; the lanes where that does not hold are redone below.
    near_all &= (width > 0.0) & (moved - hi < width) & (lo - moved < width);
    store(xs + i, moved > hi ? lo + (moved - hi) : (moved < lo ? hi - (lo - moved) : moved));
  }
  // An empty box, a jump longer than the box or a NaN: the scalar form for the whole swarm's
  // vectors (rare: |v| grows beyond the box's width only after many pushes the same way).
  if (!allLanes(near_all)) [[unlikely]] {
    for (std::size_t k = 0; k < i; ++k) xs[k] = wrapPeriodic(moved_of[k], lo_of[k], hi_of[k]);
  }
  if (i < count) {  // the last count mod 4 coordinates take the first lanes of one more draw
    const V4 r1 = lanes::nextUniform(s0, s1, s2, s3);
    const V4 r2 = lanes::nextUniform(s0, s1, s2, s3);
    for (int lane = 0; i < count; ++i, ++lane) moveOne(m, i, r1[lane], r2[lane]);
  }
  m.random->s[0] = s0, m.random->s[1] = s1, m.random->s[2] = s2, m.random->s[3] = s3;
}

// unitHeading (heading.h) in four lanes: the same reduction, polynomial and quarter turns, each
// lane the scalar operations in the same order. The lanes' n = round(θ·2/π) is converted through
// 32 bits, exact where |θ| < 2³⁰; if any heading is larger (or NaN), the scalar form redoes all.
[[gnu::always_inline]] inline void decodeActionsBody(std::span<const double> x,
                                                     std::span<Vec2> actions) {
  using namespace heading_series;
  constexpr double kLimit = 1.0e9;  // |θ| below this: n fits 32 bits
  const std::size_t count = actions.size();
  const double* in = x.data();
  double* out = reinterpret_cast<double*>(actions.data());
  static_assert(sizeof(Vec2) == 2 * sizeof(double));
  M4 in_range = M4{} - 1;  // every heading so far within ±kLimit
  std::size_t k = 0;
  for (; k + 4 <= count; k += 4, in += 8, out += 8) {
    const V4 a = load(in), b = load(in + 4);  // (s0, θ0, s1, θ1), (s2, θ2, s3, θ3)
    const V4 speed = __builtin_shufflevector(a, b, 0, 2, 4, 6);
    const V4 theta = __builtin_shufflevector(a, b, 1, 3, 5, 7);
    in_range &= (theta < kLimit) & (theta > -kLimit);
    const V4 scaled = theta * kTwoOverPi;
    const V4 rounded = scaled >= 0.0 ? scaled + 0.5 : scaled - 0.5;
    const I4 n = __builtin_convertvector(rounded, I4);  // truncation, as the scalar int64 cast
    const V4 nd = __builtin_convertvector(n, V4);
    const V4 r = (theta - nd * kHalfPi1) - nd * kHalfPi1t;
    const V4 r2 = r * r;
    V4 sin_tail = V4{} + kSin[0];
    V4 cos_tail = kCos[1] + r2 * kCos[0];
    for (std::size_t c = 1; c < sizeof kSin / sizeof kSin[0]; ++c) {
      sin_tail = kSin[c] + r2 * sin_tail;
      cos_tail = kCos[c + 1] + r2 * cos_tail;
    }
    const V4 sin_r = r + r * r2 * sin_tail;
    const V4 cos_r = 1.0 + r2 * cos_tail;
    // Quarter turns: n & 3 = 0: (cos, sin), 1: (−sin, cos), 2: (−cos, −sin), 3: (sin, −cos).
    const M4 quarter = __builtin_convertvector(n & 3, M4);
    const M4 odd = (quarter & 1) != 0;
    const V4 first = odd ? sin_r : cos_r, second = odd ? cos_r : sin_r;
    const M4 sign = M4{} + INT64_MIN;  // the sign bit
    const M4 flip_cos = (quarter == 1) | (quarter == 2), flip_sin = quarter >= 2;
    const V4 c = (V4)((M4)first ^ (flip_cos & sign));
    const V4 s = (V4)((M4)second ^ (flip_sin & sign));
    const V4 ax = speed * c, ay = speed * s;
    store(out, __builtin_shufflevector(ax, ay, 0, 4, 1, 5));
    store(out + 4, __builtin_shufflevector(ax, ay, 2, 6, 3, 7));
  }
  if (!allLanes(in_range))
    k = 0;  // a heading out of range (or NaN): all of them by the scalar form
  for (; k < count; ++k) actions[k] = x[2 * k] * unitHeading(x[2 * k + 1]);
}

#if defined(__x86_64__)
[[gnu::target("avx2")]] void moveParticlesAvx2(const SwarmMove& move) {
  moveParticlesBody(move);
}
[[gnu::target("avx2")]] void decodeActionsAvx2(std::span<const double> x, std::span<Vec2> a) {
  decodeActionsBody(x, a);
}
#else
void moveParticlesAvx2(const SwarmMove& move) {
  moveParticlesBody(move);
}
void decodeActionsAvx2(std::span<const double> x, std::span<Vec2> a) {
  decodeActionsBody(x, a);
}
#endif
void moveParticlesBaseline(const SwarmMove& move) {
  moveParticlesBody(move);
}
void decodeActionsBaseline(std::span<const double> x, std::span<Vec2> a) {
  decodeActionsBody(x, a);
}

}  // namespace

void moveParticles(const SwarmMove& move, InstructionSet set) {
  set == InstructionSet::avx2 ? moveParticlesAvx2(move) : moveParticlesBaseline(move);
}

void decodeActions(std::span<const double> x, std::span<Vec2> actions, InstructionSet set) {
  set == InstructionSet::avx2 ? decodeActionsAvx2(x, actions) : decodeActionsBaseline(x, actions);
}

}  // namespace canopy::agents::planning
