#pragma once
// Small builders shared by the tracking tests.
#include <cmath>
#include <numbers>

#include "agents/occlusion_map.h"
#include "agents/tracking/tracker.h"
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

/// A confirmed track of a person the scenario does not name (key {0, serial}, not a known
/// person's kKnownOrigin), with existence 1 and P = P₀.
inline TargetTrack unknownTrack(int serial, const Vec4& x, const Mat4& P) {
  TargetTrack track;
  track.key = {0, serial};
  track.posterior = {x, P};
  track.prior = track.posterior;
  track.status = TrackStatus::confirmed;
  return track;
}

/// Adds `tracks` after the tracker's own, as fusion would hand them over.
inline void addUnknown(Tracker& tracker, std::vector<TargetTrack> tracks) {
  std::vector<TreeTrack> trees;
  tracks.insert(tracks.begin(), tracker.targets().begin(), tracker.targets().end());
  tracker.adopt(std::move(tracks), std::move(trees));
}

}  // namespace canopy::agents::tracking::test
