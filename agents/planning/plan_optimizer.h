#pragma once
// NBO for a set of UAVs: the particle swarm over their speeds and headings, the cost over the
// joint plan with every other UAV held to a given plan (algorithms.md §6).
#include <span>
#include <vector>

#include "agents/config.h"
#include "agents/planning/nominal_cost.h"
#include "agents/planning/particle_swarm.h"
#include "agents/planning/plan.h"
#include "core/random.h"
#include "core/task_pool.h"

namespace canopy::agents::planning {

struct PlanSearch {
  std::vector<Plan> plans;    // one per free UAV, in the order given; each carries `cost`
  double cost = 0.0;          // J of the best joint plan found
  int iterations = 0;         // swarm iterations
  long long evaluations = 0;  // cost evaluations
};

/// The swarm's social structure beyond the paper's global best (particle_swarm.h).
struct SwarmShape {
  SwarmTopology topology = SwarmTopology::global_best;
  int neighbours = 1;     // ring: particles on each side
  int restart_after = 0;  // > 0: restart a particle after this many iterations without progress
  int particles_per_step = 0;  // > 0: instead of pso.particles_per_step
  int max_iterations = 0;      // > 0: instead of pso.max_iterations
};

/// Decision variables, per free UAV f and step m (agent-major): x[2(f·H + m)] = speed ∈ [0,
/// v_max_f] (m/s), x[2(f·H + m) + 1] = heading ∈ [0, 2π] (rad); a_{f,m} = speed · (cos heading, sin
/// heading). Height (issue 53): then, for each free UAV whose altitude is free (altitudeFree), in
/// order, its H climb rates x[2·n_free·H + c·H + m] ∈ [−climb_rate, climb_rate] (m/s), returned as
/// its plan's `climbs`; without such a UAV the vector is the paper's. Keeps its buffers between
/// calls; one instance per thread.
///
/// With a shared evaluation (share), a swarm whose batches are large enough (particles · tracks
/// ≥ kSharedWork) has each iteration's particles moved and evaluated side by side on its pool: the
/// particles split into one block per thread (multiples of four, the cost's lanes), each block
/// moved (its r1, r2 from the swarm's streams advanced past the blocks before it: SwarmBlocks),
/// decoded and evaluated by its own copy of the prepared cost. The swarm's best is chosen on the
/// calling thread in particle order and every candidate's cost has the bits it has alone, so the
/// search is the same bits at any thread count (docs/design-notes.md, "Threads inside one run").
class PlanOptimizer {
 public:
  /// particles · tracks of one batch from which it is shared out: below, the hand-off costs more
  /// than it gains (bench/RESULTS.md, "One agent's swarm on two threads").
  static constexpr std::size_t kSharedWork = 2000;

  /// A pool and one cost per block to evaluate on: the copies are made once per search and
  /// reused by every optimiser given the same SharedEvaluation, so the optimisers that share it
  /// must run one at a time, and the pool must be idle while they do (not one of its tasks).
  struct SharedEvaluation {
    TaskPool* pool = nullptr;
    std::vector<NominalCost> costs;
  };
  /// Evaluates large batches with `shared` (nullptr, no pool or one thread: on the calling
  /// thread); it must outlive its use.
  void share(SharedEvaluation* shared) { shared_ = shared; }
  /// Batches evaluated on the pool since construction.
  long long sharedBatches() const { return shared_batches_; }

  /// free_agents: the UAVs to optimise (SMA: the planning agent; Dec-POMDP: all). assumed: one
  /// plan per UAV, used for the others. warm_start: empty, or k joint starts of one plan per free
  /// UAV each (k·free_agents.size() plans, start-major; the first is the previous plan already
  /// shifted), given to particles 0 … k − 1 when pso.warm_start is on.
  PlanSearch optimise(const PlanningProblem& problem, const PsoConfig& pso,
                      std::span<const int> free_agents, std::span<const Plan> assumed,
                      std::span<const Plan> warm_start, RandomStream& rng,
                      const SwarmShape& shape = {});

 private:
  // swarm_actions_ and swarm_climbs_ sized for n particles.
  void resizeDecoded(std::size_t n, std::size_t n_climbs);
  // Particles [first, last) (`positions` holds theirs only) into their entries of
  // swarm_actions_ (and swarm_climbs_ when n_climbs > 0); blocks may decode side by side.
  void decode(std::span<const double> positions, std::size_t first, std::size_t last,
              std::size_t n_moves, std::size_t n_climbs);

  NominalCost cost_;
  ParticleSwarm swarm_;
  std::vector<double> lo_, hi_, warm_;
  std::vector<Vec2> actions_;        // m/s, the free UAVs' actions of one particle
  std::vector<Vec2> swarm_actions_;  // m/s, every particle's actions (particle-major)
  std::vector<double> swarm_climbs_;  // m/s, every particle's climb rates (particle-major)
  SharedEvaluation* shared_ = nullptr;
  std::vector<char> copied_;  // per block: its cost holds this search's preparation
  long long shared_batches_ = 0;
};

}  // namespace canopy::agents::planning
