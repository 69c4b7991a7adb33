#pragma once
// The links intention messages travel (SMA-NBO's plans, the centralised leader's orders), under
// the same rule as the consensus messages of fusion (FusionConfig): a message reaches a teammate
// only within comm_range of the sender (UAV positions when it is sent), is lost with probability
// comm_drop, and arrives comm_latency simulation steps after it was sent; the receiver reads it at
// its first planning epoch at least that late (exactly k steps later when it plans every step).
// A receiver keeps, per UAV, the latest plan that has reached it.
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "agents/planning/plan.h"
#include "agents/planning/uav_state.h"
#include "core/random.h"

namespace canopy::agents::planning {

/// A plan as published to the team.
struct IntentionMessage {
  int from = -1;   // the agent that published it
  int agent = -1;  // the UAV whose actions it holds (= from, except for centralised planning)
  int epoch = -1;  // the planning epoch it was published in
  Plan plan;
};

struct LinkConfig {
  double range = std::numeric_limits<double>::infinity();  // m
  double drop = 0.0;                                        // probability a message is lost
  int latency_steps = 0;                                    // simulation steps in flight
  int steps_per_epoch = 1;                                  // replan_period / dt
};

/// Messages of one kind since the start. As for consensus (FusionDiagnostics), a message is sent
/// on a link, i.e. to a teammate within range; every (sender, receiver) pair counts once.
struct MessageCounts {
  long sent = 0;
  long lost = 0;  // of which dropped (comm_drop)
  long late = 0;  // of the others, delivered by now at a later epoch than the one sent in
};

class IntentionLinks {
 public:
  /// agents: team size; seed: the trial's seed (receiver i draws its losses from the stream
  /// "intention.loss", index i, only when drop > 0).
  IntentionLinks() = default;
  IntentionLinks(const LinkConfig& config, int agents, std::uint64_t seed);

  /// Starts planning epoch `epoch` with the UAVs where they are: delivers what is due by now.
  void beginEpoch(int epoch, std::span<const UavState> uavs);
  /// Sends `message` to one agent `to`, or to every agent but its sender (to = −1), now:
  /// post(route(message.from, to), message).
  void send(const IntentionMessage& message, int to = -1);

  /// Where a message from `from` sent now goes (to one agent `to`, or to all but `from`): per
  /// receiver in range, ascending, the epoch it arrives in (−1: lost). Draws the losses and counts
  /// the messages exactly as send() does; what a message holds plays no part in where it goes, so
  /// a planner can route this epoch's messages before it knows their plans.
  struct Route {
    int receiver = 0;
    int arrival_epoch = -1;  // this epoch: delivered at once; later: in flight; −1: lost
  };
  void route(int from, int to, std::vector<Route>& out);
  /// Delivers (or puts in flight) `message` along routes from route(message.from, …).
  void post(std::span<const Route> routes, const IntentionMessage& message);
  int epoch() const { return epoch_; }
  /// The latest plan about UAV `about` that agent `receiver` holds (epoch −1: none yet).
  const IntentionMessage& latest(int receiver, int about) const {
    return inbox_[static_cast<std::size_t>(receiver) * agents_ + about];
  }
  const MessageCounts& counts() const { return counts_; }

 private:
  struct InFlight {
    int receiver = 0;
    int arrival_epoch = 0;
    IntentionMessage message;
  };
  void deliver(int receiver, const IntentionMessage& message);

  LinkConfig config_;
  int agents_ = 0;
  int epoch_ = -1;
  std::vector<Vec2> positions_;
  std::vector<RandomStream> loss_;
  std::vector<IntentionMessage> inbox_;  // [receiver · agents + about]
  std::vector<InFlight> in_flight_;      // in the order sent
  MessageCounts counts_;
  std::vector<Route> routes_;  // send()'s scratch
};

}  // namespace canopy::agents::planning
