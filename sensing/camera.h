#pragma once
// A pinhole camera on a UAV that flies at an altitude (issue 53): its ground footprint follows
// from the altitude, the two fields of view and the pitch; its range-bearing noise grows with
// the slant distance. Used only by agents whose scenario gives an altitude (`uavs[].z`, a
// `camera`, altitude limits): every other agent keeps the paper's fixed footprint and eq. 2.
#include "core/types.h"
#include "sensing/footprint.h"

namespace canopy::sensing {

/// m, the altitude at which a UAV flies when its scenario gives none, and at which a UAV's
/// `fov.size` is its footprint: a camera without explicit angles has the fields of view that
/// make its nadir footprint `fov.size` at this altitude.
inline constexpr double kDefaultAltitude = 20.0;
/// m, the height of a walker's head, the point a camera must see (3-D line of sight).
inline constexpr double kTargetHeight = 1.7;
/// m, the height of a ground robot's camera.
inline constexpr double kGroundCameraHeight = 0.5;
/// rad, the largest pitch + half the along-heading field of view: the footprint's far edge then
/// lies at most tan(80°) ≈ 5.7 altitudes ahead (at 90° it would not meet the ground at all).
inline constexpr double kMaxFarEdgeAngle = 80.0 * 3.14159265358979323846 / 180.0;

/// A pinhole camera's angles.
struct CameraDef {
  double fov_along = 0.0;   // rad, full field of view along the heading (the image's vertical)
  double fov_across = 0.0;  // rad, full field of view across the heading (the image's horizontal)
  double pitch = 0.0;       // rad, the optical axis tilted forward from nadir (0: looking down)
  // m, its nadir footprint [along, across] at kDefaultAltitude: 2 h_ref tan(fov/2), kept so that
  // a camera made from `fov.size` has exactly that footprint at the default altitude.
  Vec2 nadir_size = Vec2::Zero();
};

/// The camera whose nadir footprint at the default altitude is the rectangle `size`
/// [along, across]: fov = 2 atan(size / (2 h_ref)).
CameraDef cameraForFootprint(const Vec2& size);
/// The camera of the given full fields of view (rad) and pitch (rad).
CameraDef cameraWithAngles(double fov_along, double fov_across, double pitch);

/// The ground footprint of `camera` at `altitude` (m, > 0) above the ground, relative to the
/// UAV's ground point in its heading frame. Nadir (pitch 0): the rectangle
/// nadir_size · altitude / h_ref, i.e. 2·altitude·tan(fov/2) per axis. Pitched by θ with
/// half-angles a (along) and b (across): the corner rays
/// (sin θ ± tan a cos θ, ± tan b, −cos θ ± tan a sin θ) meet the ground at x = altitude · tan(θ ± a)
/// and |y| = altitude · cos a · tan b / cos(θ ± a): a trapezoid whose short side is the one nearest
/// the UAV. Requires θ + a ≤ kMaxFarEdgeAngle.
FootprintDef groundFootprint(const CameraDef& camera, double altitude);

/// The slant distance ℓ from a camera at `altitude` above the ground point p to the ground point
/// z: √(|z − p|² + altitude²) (m).
double slantDistance(const Vec2& z, const Vec2& p, double altitude);

/// The stated noise model of a camera at an altitude (docs/design-notes.md, "Height"): eq. 2's
/// covariance scaled by the ratio of slant distances to the measured point,
///   R_h(z, p) = (ℓ(h) / ℓ(h_ref)) · R(z, p),  ℓ(h) = √(|z − p|² + h²),
/// with h_ref = kDefaultAltitude: a camera's ground sample distance grows in proportion to the
/// slant distance, and at the default altitude the factor is exactly 1 (the paper's model).
double slantNoiseFactor(const Vec2& z, const Vec2& p, double altitude);

}  // namespace canopy::sensing
