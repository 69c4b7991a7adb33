#include "sim/finite_check.h"

#include <cmath>
#include <cstdio>

namespace canopy::sim {
namespace {

template <typename Matrix>
bool finite(const Matrix& m) {
  return m.allFinite();
}
bool finite(double x) {
  return std::isfinite(x);
}

std::string shown(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}
template <typename Matrix>
std::string shown(const Matrix& m) {
  std::string text;
  for (int i = 0; i < m.size() && i < 4; ++i) text += (i ? ", " : "") + shown(m.data()[i]);
  return "(" + text + (m.size() > 4 ? ", …" : "") + ")";
}

class Checker {
 public:
  Checker(const StepRecord& record, const std::vector<std::string>& names)
      : step_(record.step), names_(names) {}

  template <typename Value>
  void check(const Value& value, const std::string& body, const char* quantity,
             const char* source) const {
    if (finite(value)) return;
    throw NonFiniteState("step " + std::to_string(step_) + ": " + body + " " + quantity +
                         " is not finite " + shown(value) + ": " + source +
                         " produced it; the run stops here and keeps none of its files");
  }
  std::string agent(std::size_t i) const {
    return "agent " + std::to_string(i) + (i < names_.size() ? " (" + names_[i] + ")" : "");
  }

 private:
  int step_;
  const std::vector<std::string>& names_;
};

}  // namespace

void checkFinite(const StepRecord& record, const std::vector<std::string>& names) {
  const Checker c(record, names);
  constexpr const char* kWorld = "the world's step";
  for (std::size_t i = 0; i < record.uavs.size(); ++i) {
    const UavRecord& uav = record.uavs[i];
    const std::string body = c.agent(i);
    c.check(uav.position, body, "position", kWorld);
    c.check(uav.yaw, body, "yaw", kWorld);
    c.check(uav.velocity, body, "velocity", kWorld);
    c.check(uav.command, body, "command", "its planner or path");
  }
  for (std::size_t t = 0; t < record.targets.size(); ++t) {
    const std::string body = "target " + std::to_string(t);
    c.check(record.targets[t].position, body, "position", kWorld);
    c.check(record.targets[t].velocity, body, "velocity", kWorld);
  }
  for (std::size_t i = 0; i < record.beliefs.size(); ++i) {
    const agents::AgentBelief& belief = record.beliefs[i];
    const std::string body = c.agent(i);
    for (const agents::TrackEstimate& track : belief.tracks) {
      c.check(track.belief.x, body, "track mean", "its tracker or fusion");
      c.check(track.belief.P, body, "track covariance", "its tracker or fusion");
    }
    for (const agents::TreeEstimate& tree : belief.trees) {
      c.check(tree.belief.x, body, "tree estimate", "its occlusion map");
      c.check(tree.belief.P, body, "tree covariance", "its occlusion map");
    }
    for (const Vec2& p : belief.planned_path) c.check(p, body, "planned path", "its planner");
  }
}

}  // namespace canopy::sim
