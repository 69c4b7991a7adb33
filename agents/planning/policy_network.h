#pragma once
// The learned planner's network (issue 54; docs/imitation.md): a Deep Sets policy, invariant to
// the order of an agent's tracks and of its teammates. Each track's features go through the track
// encoder φ_T, each teammate's through the teammate encoder φ_M (dense layers, ReLU after every
// one); each set is pooled by its mean and its elementwise max (zeros for an empty set); the head
// ρ maps [self, mean φ_T, max φ_T, mean φ_M, max φ_M] through dense layers (ReLU after all but the
// last) to two numbers, and u = tanh(ρ) is the command as a fraction of v_max per axis.
// Evaluated in double precision with Eigen: the same bits for the same input.
#include <string>
#include <vector>

#include "agents/planning/observation.h"
#include "core/types.h"

namespace canopy::agents::planning {

struct DenseLayer {
  Eigen::MatrixXd weight;  // out × in
  Eigen::VectorXd bias;    // out
};

struct PolicyNetwork {
  std::vector<DenseLayer> track, mate, head;
  std::string file;  // where it was read from (messages, the effective config)

  /// Empty when the layers chain (each layer's input is the previous one's output; the encoders
  /// take kTrackFeatures and kMateFeatures, the head kSelfFeatures + 2·(track width) + 2·(mate
  /// width) and gives 2), else what is wrong, naming the layer ("layers.head[1].weight: …").
  std::string shapeError() const;
  /// u = tanh(ρ(…)) ∈ (−1, 1)²; the observation must have the feature counts above.
  Vec2 output(const Observation& observation) const;
  /// The command (m/s): v_max·u, scaled down to |a| = v_max when longer.
  Vec2 command(const Observation& observation, double v_max) const;
};

}  // namespace canopy::agents::planning
