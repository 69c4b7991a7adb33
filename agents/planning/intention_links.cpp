#include "agents/planning/intention_links.h"

#include <algorithm>

namespace canopy::agents::planning {

IntentionLinks::IntentionLinks(const LinkConfig& config, int agents, std::uint64_t seed)
    : config_(config), agents_(agents), inbox_(static_cast<std::size_t>(agents) * agents) {
  for (int i = 0; i < agents; ++i) loss_.emplace_back(seed, "intention.loss", i);
}

void IntentionLinks::beginEpoch(int epoch, std::span<const UavState> uavs) {
  epoch_ = epoch;
  positions_.resize(uavs.size());
  for (std::size_t i = 0; i < uavs.size(); ++i) positions_[i] = uavs[i].position;
  // Deliver, in the order sent, every message due by now; keep the rest in flight.
  std::size_t kept = 0;
  for (std::size_t k = 0; k < in_flight_.size(); ++k) {
    if (in_flight_[k].arrival_epoch <= epoch) {
      ++counts_.late;
      deliver(in_flight_[k].receiver, in_flight_[k].message);
    } else {
      if (kept != k) in_flight_[kept] = std::move(in_flight_[k]);  // never a self-move
      ++kept;
    }
  }
  in_flight_.resize(kept);
}

void IntentionLinks::send(const IntentionMessage& message, int to) {
  route(message.from, to, routes_);
  post(routes_, message);
}

void IntentionLinks::route(int from, int to, std::vector<Route>& out) {
  out.clear();
  // The first epoch whose step is at least latency_steps after this one's:
  // ⌈latency / steps_per_epoch⌉ epochs later.
  const int delay =
      (config_.latency_steps + config_.steps_per_epoch - 1) / std::max(1, config_.steps_per_epoch);
  for (int r = 0; r < agents_; ++r) {
    if (r == from || (to >= 0 && r != to)) continue;
    // As in fusion's communication graph: a link exists within range (no message otherwise);
    // a message on a link is lost with probability drop.
    const double d2 = (positions_[r] - positions_[from]).squaredNorm();
    if (d2 > config_.range * config_.range) continue;  // ∞ stays ∞
    ++counts_.sent;
    if (config_.drop > 0.0 && loss_[r].bernoulli(config_.drop)) {
      ++counts_.lost;
      out.push_back({r, -1});
      continue;
    }
    out.push_back({r, epoch_ + delay});
  }
}

void IntentionLinks::post(std::span<const Route> routes, const IntentionMessage& message) {
  for (const Route& route : routes) {
    if (route.arrival_epoch < 0) continue;  // lost
    if (route.arrival_epoch == epoch_) {
      deliver(route.receiver, message);
    } else {
      in_flight_.push_back({route.receiver, route.arrival_epoch, message});
    }
  }
}

void IntentionLinks::deliver(int receiver, const IntentionMessage& message) {
  IntentionMessage& held = inbox_[static_cast<std::size_t>(receiver) * agents_ + message.agent];
  if (message.epoch >= held.epoch) held = message;  // never replace a newer plan by an older one
}

}  // namespace canopy::agents::planning
