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

namespace canopy::agents::planning {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

std::uint64_t bitsOf(double x) { return std::bit_cast<std::uint64_t>(x); }

// The kernel sets this CPU can run: baseline always, avx2 where present.
std::vector<InstructionSet> runnableSets() {
  std::vector<InstructionSet> sets = {InstructionSet::baseline};
  if (instructionSet() == InstructionSet::avx2) sets.push_back(InstructionSet::avx2);
  return sets;
}

// A swarm of `count` coordinates in boxes like the planner's (speeds [0, v_max], headings
// [0, 2π]), with velocities that sometimes jump more than a box's width, and a few degenerate
// coordinates: an empty box, a NaN velocity, an infinite one.
struct SwarmState {
  std::vector<double> r1, r2, own, best, lo, hi, width, x, v, moved;

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
      r1.push_back(rng.uniform());
      r2.push_back(rng.uniform());
    }
    moved.assign(count, 0.0);
    if (degenerate && count > 7) {
      hi[3] = lo[3] = 1.5;  // an empty box: wrap returns lo
      width[3] = 0.0;
      v[5] = std::numeric_limits<double>::quiet_NaN();
      v[6] = std::numeric_limits<double>::infinity();
    }
  }
  SwarmMove move() {
    return {x.size(), 0.9,        0.5,       0.3,      r1.data(), r2.data(), own.data(),
            best.data(), lo.data(), hi.data(), width.data(), x.data(),  v.data(),  moved.data()};
  }
};

// The update as particle_swarm.h states it, one coordinate at a time.
void moveByTheFormula(SwarmState& s) {
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    s.v[i] = 0.9 * s.v[i] + 0.5 * s.r1[i] * shortestDisplacement(s.own[i] - s.x[i], s.width[i]) +
             0.3 * s.r2[i] * shortestDisplacement(s.best[i] - s.x[i], s.width[i]);
    s.x[i] = wrapPeriodic(s.x[i] + s.v[i], s.lo[i], s.hi[i]);
  }
}

TEST(SwarmKernels, MoveHasTheBitsOfTheScalarUpdate) {
  for (const InstructionSet set : runnableSets()) {
    for (const std::size_t count : {1u, 4u, 10u, 998u, 1000u, 1003u}) {
      for (const bool degenerate : {false, true}) {
        SwarmState kernel(count, count, degenerate), formula(count, count, degenerate);
        for (int iteration = 0; iteration < 5; ++iteration) {
          moveParticles(kernel.move(), set);
          moveByTheFormula(formula);
        }
        for (std::size_t i = 0; i < count; ++i) {
          ASSERT_EQ(bitsOf(kernel.x[i]), bitsOf(formula.x[i])) << count << " " << i;
          ASSERT_EQ(bitsOf(kernel.v[i]), bitsOf(formula.v[i])) << count << " " << i;
        }
      }
    }
  }
}

// By hand, in the unit box with r1 = r2 = 1: δ1 = 0.4 − 0.2 = 0.2; 0.9 − 0.2 = 0.7 is more than
// half the box, so δ2 = 0.7 − 1 = −0.3 (the short way round); a jump below 0 re-enters below 1.
TEST(SwarmKernels, MoveByHand) {
  for (const InstructionSet set : runnableSets()) {
    std::vector<double> r1(4, 1.0), r2(4, 1.0), own(4, 0.4), best(4, 0.9), lo(4, 0.0), hi(4, 1.0),
        width(4, 1.0), x(4, 0.2), v(4, -0.5), moved(4);
    moveParticles({4, 0.9, 0.5, 0.3, r1.data(), r2.data(), own.data(), best.data(), lo.data(),
                   hi.data(), width.data(), x.data(), v.data(), moved.data()},
                  set);
    // v = −0.45 + 0.5·0.2 + 0.3·(−0.3) = −0.44; x = 0.2 − 0.44 = −0.24 → 1 − 0.24 = 0.76.
    for (int k = 0; k < 4; ++k) {
      EXPECT_NEAR(v[k], -0.44, 1e-15);
      EXPECT_NEAR(x[k], 0.76, 1e-15);
    }
  }
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
          const double special[] = {0.0, kTwoPi, std::numbers::pi / 2, std::numbers::pi,
                                    3 * std::numbers::pi / 2, std::numbers::pi / 4};
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
