#pragma once
// A scenario moved as a whole: mirrored, rotated, shifted, its distances or its walking speeds
// scaled. The invariance tests use it to check that a finding does not depend on where and how
// the layout lies (a mirrored scenario must show the same behaviour within sampling error).
#include "core/types.h"
#include "spec/scenario_spec.h"

namespace canopy::experiments {

/// p ↦ A·(s·p) + b for every position (targets, UAVs, trees, the AOI); footprint sizes, crown
/// radii and polygon vertices scale with s as well. A is a rotation or a reflection; headings
/// (UAV yaws) turn with it. Target velocities are A·(s·v·speed_scale); on timed paths the times
/// divide by speed_scale, so the walkers cover the scaled distances at the scaled speeds.
struct Placement {
  Mat2 A = Mat2::Identity();    // orthogonal
  Vec2 b = Vec2::Zero();        // m
  double distance_scale = 1.0;  // s
  double speed_scale = 1.0;     // targets' speeds (and so their timing)

  static Placement mirrorX();                 // x ↦ −x
  static Placement rotation(double radians);  // counter-clockwise about the origin
};

spec::ScenarioSpec placed(const spec::ScenarioSpec& spec, const Placement& placement);

}  // namespace canopy::experiments
