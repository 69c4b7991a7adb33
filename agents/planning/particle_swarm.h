#pragma once
// A particle swarm over a box with periodic boundaries (algorithms.md §6): the paper's global-best
// swarm, or a local-best (ring) swarm with restarts for the joint plan's larger search
// (docs/design-notes.md, "Dec-POMDP's joint search"). Generic: it minimises any batch cost over a
// flat vector, so it can be tested on standard functions.
#include <cmath>
#include <functional>
#include <span>
#include <vector>

#include "agents/config.h"
#include "agents/planning/swarm_kernels.h"
#include "core/random.h"
#include "core/random_lanes.h"

namespace canopy::agents::planning {

/// Who attracts a particle socially: the best position of the whole swarm (the paper's PSO), or
/// the best personal best among the particle and its `neighbours` nearest indices on each side of
/// a ring (Kennedy & Mendes 2002's lbest).
enum class SwarmTopology { global_best, ring };

struct SwarmOptions {
  int particles = 100;        // swarm size
  double inertia = 0.9;       // w
  double c1 = 0.5;            // cognitive weight (towards the particle's own best)
  double c2 = 0.3;            // social weight (towards the swarm's best)
  double ftol = 5e-4;         // a change of the best cost below ftol·(1 + |best|) is a stall
  int stall_iterations = 50;  // stop after this many stalls in a row
  int max_iterations = 1000;  // hard cap on velocity/position updates
  SwarmTopology topology = SwarmTopology::global_best;
  int neighbours = 1;  // ring: particles on each side in a particle's neighbourhood
  // > 0: a particle whose own best has not improved for this many iterations in a row is drawn
  // again (position, velocity, and its own best forgotten), unless it holds the swarm's best.
  int restart_after = 0;

  /// particles = particles_per_step · H, the rest copied.
  static SwarmOptions from(const PsoConfig& config, int horizon);
};

struct SwarmResult {
  std::vector<double> best;  // the best position found (size = dimension)
  double best_cost = 0.0;
  int iterations = 0;         // velocity/position updates performed
  long long evaluations = 0;  // cost evaluations, the initial swarm included
  bool stalled = false;       // stopped by the ftol criterion (false: max_iterations reached)
};

/// positions: particle-major, particles × dimension; costs: one per particle, to be written.
using BatchCost = std::function<void(std::span<const double> positions, std::span<double> costs)>;

/// The swarm in blocks of particles that move and are evaluated side by side (a global-best
/// swarm without restarts): block b holds particles [b·width, min((b + 1)·width, n)), width a
/// multiple of four. `run(count, task)` runs task(b) for every b < count and returns when all
/// are done (on a pool: ParticleSwarm's tasks write only their block's entries); `cost(b,
/// positions, costs)` evaluates block b's particles. Each block draws its own r1, r2: the four
/// streams are advanced past the blocks before it (core/random_lanes.h, advance), so the draws,
/// and the search, are those of the whole swarm at once, bit for bit.
struct SwarmBlocks {
  std::size_t count = 1;
  std::size_t width = 0;
  std::function<void(std::size_t count, const std::function<void(std::size_t)>& task)> run;
  std::function<void(std::size_t block, std::span<const double> positions, std::span<double> costs)>
      cost;
};

/// Synchronous PSO (global best):
///   v ← w v + c1 r1 δ(x_best,own − x) + c2 r2 δ(x_best,swarm − x),  x ← wrap(x + v),
/// r1, r2 ~ U[0, 1) per particle and coordinate. A coordinate that leaves [lo, hi] re-enters from
/// the opposite bound (periodic), and δ is the shortest periodic displacement (remainder by
/// hi − lo), so the box is a torus for the attraction too: a minimum near a bound pulls particles
/// from both sides of it rather than across the whole box. Initial positions are uniform in the
/// box, initial velocities uniform in ±kInitialVelocityFraction·(hi − lo). Draw order (fixed, so a
/// stream gives one result): per particle, per coordinate, position then velocity, from `rng`;
/// then sixteen words of `rng` seed four xoshiro256+ streams (core/random_lanes.h), which give
/// every iteration's r1, r2 in swarm_kernels.h's order.
///
/// Ring topology: the social attractor of particle p is the best own best among particles
/// p − k … p + k (indices modulo the swarm, k = neighbours; ties to the lowest index), and an
/// iteration is a stall when no particle's neighbourhood best changed by ftol·(1 + |previous|) or
/// more, so the search stops only once every neighbourhood has settled, not when the swarm's best
/// pauses. Restarts (restart_after > 0) draw, after each iteration's bookkeeping, a new position
/// and velocity for every particle due, in index order, per coordinate position then velocity,
/// from `rng`; its own best is forgotten (set to the new position, of cost +∞) and replaced by its
/// next evaluation. The global-best
/// swarm without restarts draws nothing from `rng` after the start (the paper's swarm, unchanged).
class ParticleSwarm {
 public:
  static constexpr double kInitialVelocityFraction = 0.5;

  /// warm_start: empty, or k positions (k·dimension values, k ≤ particles) given to particles
  /// 0 … k − 1 instead of their draws (which are still made, so the rest do not depend on k).
  /// Buffers are kept between calls; the cost is called once per iteration with the whole swarm.
  /// With `blocks` (global best, no restarts; otherwise ignored), every iteration after the
  /// first evaluation moves and evaluates the blocks side by side (SwarmBlocks); the result is
  /// the same bits.
  SwarmResult minimise(const BatchCost& cost, std::span<const double> lo,
                       std::span<const double> hi, const SwarmOptions& options, RandomStream& rng,
                       std::span<const double> warm_start = {},
                       const SwarmBlocks* blocks = nullptr);

 private:
  /// Ring: each particle's neighbourhood best into swarm_best_ (swarm_best where a
  /// neighbourhood has no finite own best) and neighbourhood_cost_; true when one of them
  /// improved by ftol·(1 + |previous|) or more.
  bool updateNeighbourhoods(std::size_t n, std::size_t dim, int neighbours,
                            std::span<const double> swarm_best, double ftol = 0.0);

  std::vector<double> x_, v_, own_best_, own_best_cost_, cost_;
  std::vector<double> neighbourhood_cost_;        // ring: each particle's neighbourhood best cost
  std::vector<int> since_improved_;               // restarts: iterations since own best improved
  std::vector<char> improved_;                    // blocks: own best improved at this iteration
  std::vector<lanes::RandomLanes> block_random_;  // blocks: each block's streams
  lanes::RandomLanes random_;  // four streams for r1, r2, seeded from the call's stream
  // Per particle and coordinate (particle-major, as x_), for swarm_kernels.h: the box, its width
  // and the swarm's best position, repeated once per particle.
  std::vector<double> lo_, hi_, width_, swarm_best_;
  std::vector<double> moved_;  // the kernel's scratch
};

}  // namespace canopy::agents::planning
