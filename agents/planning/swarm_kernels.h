#pragma once
// The particle swarm's arithmetic per coordinate, over the whole swarm at once (algorithms.md §6):
// the velocity/position update with its random weights, and the decode of speeds and headings
// into actions. Both run four coordinates (or actions) per step in vectors of four doubles; each
// lane performs the scalar formula's IEEE operations in the same order (no FMA), so the result
// has the bits of the scalar loop (tests/agents/planning/swarm_kernels_test.cpp). They were most
// of a planning call's overhead around the cost: two random numbers, one update and one decode
// per coordinate per iteration.
#include <cmath>
#include <cstddef>
#include <span>

#include "core/cpu.h"
#include "core/random_lanes.h"
#include "core/types.h"

namespace canopy::agents::planning {

/// The swarm's arrays over all particles, particle-major (index i = p·dim + d), so that lo, hi,
/// width and the swarm's best are repeated once per particle.
struct SwarmMove {
  std::size_t count = 0;                 // particles × dimension
  double w = 0.0, c1 = 0.0, c2 = 0.0;    // inertia, cognitive and social weights
  lanes::RandomLanes* random = nullptr;  // r1, r2 ~ U[0, 1): advanced by the move
  const double* own_best = nullptr;      // each particle's best position
  const double* swarm_best = nullptr;    // the swarm's best, repeated per particle
  const double* lo = nullptr;            // the box, repeated per particle
  const double* hi = nullptr;
  const double* width = nullptr;  // hi − lo
  double* x = nullptr;            // positions, updated
  double* v = nullptr;            // velocities, updated
  double* moved = nullptr;        // scratch: x + v before the wrap
};

/// For every i < count:
///   v_i ← w v_i + c1 r1_i δ(own_i − x_i) + c2 r2_i δ(best_i − x_i),  x_i ← wrap(x_i + v_i),
/// δ the shortest periodic displacement and wrap the periodic re-entry of particle_swarm.h.
/// Draw order: for each group of four coordinates i = 4g..4g+3 (the last group possibly short),
/// one draw of the four streams gives r1 (lane i − 4g), the next gives r2.
void moveParticles(const SwarmMove& move, InstructionSet set = instructionSet());

/// a_k = x[2k] · (cos x[2k+1], sin x[2k+1]) for k < actions.size() (x holds 2·actions.size()
/// values: speed, heading per action), by unitHeading (heading.h).
void decodeActions(std::span<const double> x, std::span<Vec2> actions,
                   InstructionSet set = instructionSet());

/// The scalar forms the kernels reproduce lane by lane (and use for a remainder shorter than a
/// vector). The shortest periodic displacement d mod width, in [−width/2, width/2]: both ends of a
/// swarm displacement lie in the box, so |d| ≤ width and one shift suffices.
inline double shortestDisplacement(double d, double width) {
  if (d > 0.5 * width) return d - width;
  if (d < -0.5 * width) return d + width;
  return d;
}

/// x wrapped periodically into the closed interval [lo, hi]: above hi it re-enters at lo, below lo
/// at hi.
inline double wrapPeriodic(double x, double lo, double hi) {
  const double width = hi - lo;
  if (!(width > 0.0)) return lo;
  if (x > hi) return lo + std::fmod(x - hi, width);
  if (x < lo) return hi - std::fmod(lo - x, width);
  return x;
}

}  // namespace canopy::agents::planning
