#include "agents/planning/swarm_kernels.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include "agents/planning/heading.h"
#include "core/random.h"
#include "core/random_lanes.h"

namespace canopy::agents::planning {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

std::uint64_t bitsOf(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

// The kernel sets this CPU can run: baseline always, avx2 where present.
std::vector<InstructionSet> runnableSets() {
  std::vector<InstructionSet> sets = {InstructionSet::baseline};
  if (instructionSet() == InstructionSet::avx2) sets.push_back(InstructionSet::avx2);
  return sets;
}

// xoshiro256+ one stream at a time, as Blackman & Vigna publish it: an independent rendering of
// what core/random_lanes.h computes four lanes at a time.
struct ScalarStreams {
  std::uint64_t s[4][4];  // [lane][word]

  explicit ScalarStreams(const lanes::RandomLanes& r) {
    for (int lane = 0; lane < 4; ++lane) {
      for (int k = 0; k < 4; ++k) s[lane][k] = r.s[k][lane];
    }
  }
  double next(int lane) {
    std::uint64_t* q = s[lane];
    const std::uint64_t result = q[0] + q[3];
    const std::uint64_t t = q[1] << 17;
    q[2] ^= q[0];
    q[3] ^= q[1];
    q[1] ^= q[2];
    q[0] ^= q[3];
    q[2] ^= t;
    q[3] = std::rotl(q[3], 45);
    return static_cast<double>(result >> 12) * 0x1.0p-52;  // the top 52 bits, exactly
  }
};

// A swarm of `count` coordinates in boxes like the planner's (speeds [0, v_max], headings
// [0, 2π]), with velocities that sometimes jump more than a box's width, and a few degenerate
// coordinates: an empty box, a NaN velocity, an infinite one.
struct SwarmState {
  std::vector<double> own, best, lo, hi, width, x, v, moved;
  lanes::RandomLanes random;

  explicit SwarmState(std::size_t count, std::uint64_t seed, bool degenerate) {
    RandomStream rng(seed, "swarm-kernels-test");
    for (std::size_t i = 0; i < count; ++i) {
      lo.push_back(0.0);
      hi.push_back(i % 2 == 0 ? rng.uniform(0.5, 8.0) : kTwoPi);
      width.push_back(hi[i] - lo[i]);
      x.push_back(rng.uniform(lo[i], hi[i]));
      own.push_back(rng.uniform(lo[i], hi[i]));
      best.push_back(rng.uniform(lo[i], hi[i]));
      const double reach = rng.bernoulli(0.1) ? 6.0 : 0.6;  // |v| up to 6 widths, now and then
      v.push_back(rng.uniform(-reach, reach) * width[i]);
    }
    random = lanes::RandomLanes::from(rng);
    moved.assign(count, 0.0);
    if (degenerate && count > 7) {
      hi[3] = lo[3] = 1.5;  // an empty box: wrap returns lo
      width[3] = 0.0;
      v[5] = std::numeric_limits<double>::quiet_NaN();
      v[6] = std::numeric_limits<double>::infinity();
    }
  }
  SwarmMove move() {
    return {x.size(),  0.9,       0.5,          0.3,      &random,  own.data(),  best.data(),
            lo.data(), hi.data(), width.data(), x.data(), v.data(), moved.data()};
  }
};

// The update as particle_swarm.h states it, one coordinate at a time, with r1 and r2 drawn in
// swarm_kernels.h's order: per group of four coordinates, one draw of each stream for r1, then r2.
void moveByTheFormula(SwarmState& s, ScalarStreams& streams) {
  double r1[4], r2[4];
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    const int lane = static_cast<int>(i % 4);
    if (lane == 0) {
      for (int l = 0; l < 4; ++l) r1[l] = streams.next(l);
      for (int l = 0; l < 4; ++l) r2[l] = streams.next(l);
    }
    s.v[i] = 0.9 * s.v[i] + 0.5 * r1[lane] * shortestDisplacement(s.own[i] - s.x[i], s.width[i]) +
             0.3 * r2[lane] * shortestDisplacement(s.best[i] - s.x[i], s.width[i]);
    s.x[i] = wrapPeriodic(s.x[i] + s.v[i], s.lo[i], s.hi[i]);
  }
}

TEST(SwarmKernels, MoveHasTheBitsOfTheScalarUpdate) {
  for (const InstructionSet set : runnableSets()) {
    for (const std::size_t count : {1u, 4u, 10u, 998u, 1000u, 1003u}) {
      for (const bool degenerate : {false, true}) {
        SwarmState kernel(count, count, degenerate), formula(count, count, degenerate);
        ScalarStreams streams(formula.random);
        for (int iteration = 0; iteration < 5; ++iteration) {
          moveParticles(kernel.move(), set);
          moveByTheFormula(formula, streams);
        }
        for (std::size_t i = 0; i < count; ++i) {
          ASSERT_EQ(bitsOf(kernel.x[i]), bitsOf(formula.x[i])) << count << " " << i;
          ASSERT_EQ(bitsOf(kernel.v[i]), bitsOf(formula.v[i])) << count << " " << i;
        }
      }
    }
  }
}

// By hand, in the unit box, with streams whose first two outputs are known: a lane seeded
// (s0, s1, s2, s3) = (a, 0, 0, b) first gives a + b, then (after s0 ^= s3 and s3 = rotl(s3, 45))
// (a ^ b) + rotl(b, 45). With a = 2⁶³ and b = 0: r1 = 2⁶³ >> 12 · 2⁻⁵² = 0.5 and r2 = 0.5 too.
// δ1 = 0.4 − 0.2 = 0.2; 0.9 − 0.2 = 0.7 is more than half the box, so δ2 = 0.7 − 1 = −0.3 (the
// short way round); v = 0.9·(−0.5) + 0.5·0.5·0.2 + 0.3·0.5·(−0.3) = −0.445, and x = 0.2 − 0.445
// is below 0, so it re-enters below 1: 0.755.
TEST(SwarmKernels, MoveByHand) {
  for (const InstructionSet set : runnableSets()) {
    std::vector<double> own(4, 0.4), best(4, 0.9), lo(4, 0.0), hi(4, 1.0), width(4, 1.0), x(4, 0.2),
        v(4, -0.5), moved(4);
    lanes::RandomLanes random{};
    for (int lane = 0; lane < 4; ++lane) random.s[0][lane] = std::uint64_t{1} << 63;
    moveParticles({4, 0.9, 0.5, 0.3, &random, own.data(), best.data(), lo.data(), hi.data(),
                   width.data(), x.data(), v.data(), moved.data()},
                  set);
    for (int k = 0; k < 4; ++k) {
      EXPECT_NEAR(v[k], -0.445, 1e-15);
      EXPECT_NEAR(x[k], 0.755, 1e-15);
    }
  }
}

// The four streams give uniforms on [0, 1) with the moments of U[0, 1): mean 1/2 and variance
// 1/12, each within 5 standard errors over 4·10⁵ draws, in every lane.
TEST(RandomLanes, UniformMoments) {
  RandomStream source(5, "random-lanes-test");
  lanes::RandomLanes r = lanes::RandomLanes::from(source);
  constexpr int kDraws = 100000;
  double sum[4] = {}, sum_sq[4] = {};
  for (int k = 0; k < kDraws; ++k) {
    const lanes::V4 u = lanes::nextUniform(r.s[0], r.s[1], r.s[2], r.s[3]);
    for (int lane = 0; lane < 4; ++lane) {
      ASSERT_GE(u[lane], 0.0);
      ASSERT_LT(u[lane], 1.0);
      sum[lane] += u[lane];
      sum_sq[lane] += u[lane] * u[lane];
    }
  }
  for (int lane = 0; lane < 4; ++lane) {
    const double mean = sum[lane] / kDraws, variance = sum_sq[lane] / kDraws - mean * mean;
    EXPECT_NEAR(mean, 0.5, 5 * std::sqrt(1.0 / 12 / kDraws)) << lane;
    // Var of u² is 1/5 − 1/9 = 4/45, so the variance's standard error is about √(4/45/n).
    EXPECT_NEAR(variance, 1.0 / 12, 5 * std::sqrt(4.0 / 45 / kDraws)) << lane;
  }
}

// Lanes seeded alike would repeat each other; RandomLanes::from gives each its own words.
TEST(RandomLanes, LanesDiffer) {
  RandomStream source(6, "random-lanes-test");
  lanes::RandomLanes r = lanes::RandomLanes::from(source);
  const lanes::V4 u = lanes::nextUniform(r.s[0], r.s[1], r.s[2], r.s[3]);
  EXPECT_NE(u[0], u[1]);
  EXPECT_NE(u[1], u[2]);
  EXPECT_NE(u[2], u[3]);
}

TEST(SwarmKernels, DecodeHasTheBitsOfUnitHeading) {
  RandomStream rng(3, "swarm-kernels-decode");
  for (const InstructionSet set : runnableSets()) {
    for (const std::size_t count : {1u, 3u, 4u, 5u, 500u, 503u}) {
      for (const bool out_of_range : {false, true}) {
        std::vector<double> x;
        for (std::size_t k = 0; k < count; ++k) {
          x.push_back(rng.uniform(0.0, 10.0));
          // The box's ends and quarter turns, where the reduction's rounding decides n.
          const double special[] = {0.0,
                                    kTwoPi,
                                    std::numbers::pi / 2,
                                    std::numbers::pi,
                                    3 * std::numbers::pi / 2,
                                    std::numbers::pi / 4};
          x.push_back(k < 6 ? special[k] : rng.uniform(0.0, kTwoPi));
        }
        if (out_of_range) x[2 * (count / 2) + 1] = count % 2 ? 3.0e9 : -1.0e12;
        std::vector<Vec2> actions(count);
        decodeActions(x, actions, set);
        for (std::size_t k = 0; k < count; ++k) {
          const Vec2 expected = x[2 * k] * unitHeading(x[2 * k + 1]);
          ASSERT_EQ(bitsOf(actions[k].x()), bitsOf(expected.x())) << count << " " << k;
          ASSERT_EQ(bitsOf(actions[k].y()), bitsOf(expected.y())) << count << " " << k;
        }
      }
    }
  }
}

}  // namespace
}  // namespace canopy::agents::planning
