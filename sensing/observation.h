#pragma once
// What a UAV's camera reports in one scan, and the truth behind it (for analysis only).
#include <vector>

#include "core/types.h"
#include "sensing/outline.h"

namespace canopy::sensing {

/// Semantic labels are small integers; the scenario names them. Label 0 is always "tree" (SOO).
using LabelId = int;
inline constexpr LabelId kTreeLabel = 0;

/// One labelled detection.
struct Observation {
  LabelId label = kTreeLabel;
  Vec2 z = Vec2::Zero();         // m, measured position (a tree's measured centre)
  Mat2 R = Mat2::Identity();     // m², the covariance the filter uses: R(z, p_i), paper eq. 2
  double radius = 0.0;           // m, trees only: measured crown radius (≥ 0)
  double radius_variance = 0.0;  // m², trees only: σ_r²
  int truth = -1;                // analysis only: target or tree index, −1 for clutter
  Outline outline;               // polygonal trees only: measured vertex offsets (m)
};

/// One UAV's scan at one step.
struct Scan {
  int uav = 0;
  Vec2 sensor_position = Vec2::Zero();    // m, the UAV's ground point p_i
  double sensor_height = 20.0;            // m, its camera above the ground (sensing/sensor.h
                                          // cameraHeight): the 3-D line of sight's start
  std::vector<int> in_footprint;          // targets whose true position lies in φ_i (sorted)
  std::vector<int> visible;               // V_{i,k}: in φ_i and not occluded (sorted)
  std::vector<Observation> observations;  // detected targets, then clutter, then trees

  void clear() {
    in_footprint.clear();
    visible.clear();
    observations.clear();
  }
};

}  // namespace canopy::sensing
