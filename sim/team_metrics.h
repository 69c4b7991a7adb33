#pragma once
// The team's tracking figures at one step (issue 46): what the team as a whole knows of the people,
// for runs where each agent knows only its neighbourhood.
//
// The team's estimate set holds one point per distinct track key that any agent holds (all of an
// agent's tracks, as the per-agent OSPA counts them): the mean of the holder whose tr(P_pos) is
// least, the team's best-informed copy (ties: the lower agent index). Team OSPA and GOSPA
// (c = 50 m, p = 2, α = 2) compare the people's true positions with that set, so a person no agent
// tracks is missed once, and two keys on one person count one of them as false.
//
// A person is *held* when the team estimate the OSPA assignment gives it lies within
// kHeldDistance of it and the person lies inside that estimate's 99 % ellipse,
// Δpᵀ P_pos⁻¹ Δp ≤ kHeldGate (χ²₂): some agent knows where it is, and how well.
#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "agents/belief.h"
#include "metrics/ospa.h"

namespace canopy::sim {

inline constexpr double kHeldDistance = 5.0;  // m
inline constexpr double kHeldGate = 9.21;     // χ²₂ 99 % quantile

struct TeamFigures {
  double ospa = 0.0;   // m
  double gospa = 0.0;  // m
  int held = 0;        // people held
  int estimates = 0;   // distinct keys in the team's estimate set
};

/// Computes one step's team figures; keeps its buffers between calls.
class TeamMetrics {
 public:
  /// beliefs: per agent; truth: the people's true positions. held_by (optional, resized to the
  /// people): 1 for each person held.
  TeamFigures compute(std::span<const Vec2> truth, std::span<const agents::AgentBelief> beliefs,
                      std::vector<char>* held_by = nullptr);

 private:
  struct Best {
    agents::TrackKey key;
    Vec2 position;
    double trace;  // tr(P_pos), m²
    Mat2 P;        // P_pos, m²
  };
  static std::uint64_t packed(const agents::TrackKey& key) {
    return static_cast<std::uint64_t>(static_cast<std::uint32_t>(key.origin)) << 32 |
           static_cast<std::uint32_t>(key.serial);
  }
  std::vector<Best> best_;
  std::unordered_map<std::uint64_t, std::size_t> slot_of_key_;  // key → its entry of best_
  std::vector<Vec2> points_;
  metrics::CutoffAssignment assignment_{50.0, 2.0};
};

}  // namespace canopy::sim
