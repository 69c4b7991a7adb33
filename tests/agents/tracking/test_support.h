#pragma once
// Small builders shared by the tracking tests.
#include <cmath>
#include <numbers>

#include "agents/occlusion_map.h"
#include "sensing/footprint.h"
#include "sensing/observation.h"

namespace canopy::agents::tracking::test {

inline sensing::Observation targetObservation(const Vec2& z, const Mat2& R,
                                              sensing::LabelId label = 1) {
  sensing::Observation o;
  o.label = label;
  o.z = z;
  o.R = R;
  return o;
}

inline sensing::Observation treeObservation(const Vec2& z, const Mat2& R, double radius,
                                            double radius_variance) {
  sensing::Observation o;
  o.label = sensing::kTreeLabel;
  o.z = z;
  o.R = R;
  o.radius = radius;
  o.radius_variance = radius_variance;
  return o;
}

/// A disc footprint (m) centred at `centre`.
inline sensing::Footprint discFootprint(const Vec2& centre, double radius) {
  sensing::FootprintDef def;
  def.shape = sensing::FootprintShape::disc;
  def.radius = radius;
  return sensing::Footprint::place(def, centre, 0.0);
}

/// N(ν; 0, S) for a 2-D innovation, written out from the density's definition.
inline double gaussianDensity(const Vec2& nu, const Mat2& S) {
  const double det = S(0, 0) * S(1, 1) - S(0, 1) * S(1, 0);
  const Mat2 S_inv = Mat2{{S(1, 1), -S(0, 1)}, {-S(1, 0), S(0, 0)}} / det;
  return std::exp(-0.5 * nu.dot(S_inv * nu)) / (2.0 * std::numbers::pi * std::sqrt(det));
}

}  // namespace canopy::agents::tracking::test
