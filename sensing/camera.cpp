#include "sensing/camera.h"

#include <cmath>

namespace canopy::sensing {

CameraDef cameraForFootprint(const Vec2& size) {
  CameraDef camera;
  camera.fov_along = 2.0 * std::atan(0.5 * size.x() / kDefaultAltitude);   // 2 atan(w / 2h_ref)
  camera.fov_across = 2.0 * std::atan(0.5 * size.y() / kDefaultAltitude);  // 2 atan(h / 2h_ref)
  camera.nadir_size = size;
  return camera;
}

CameraDef cameraWithAngles(double fov_along, double fov_across, double pitch) {
  CameraDef camera;
  camera.fov_along = fov_along;
  camera.fov_across = fov_across;
  camera.pitch = pitch;
  // 2 h_ref tan(fov/2) per axis.
  camera.nadir_size = 2.0 * kDefaultAltitude *
                      Vec2(std::tan(0.5 * fov_along), std::tan(0.5 * fov_across));
  return camera;
}

FootprintDef groundFootprint(const CameraDef& camera, double altitude) {
  FootprintDef def;
  const double a = 0.5 * camera.fov_along;   // half-angle along the heading
  const double b = 0.5 * camera.fov_across;  // half-angle across it
  if (camera.pitch == 0.0) {
    def.shape = FootprintShape::rectangle;
    def.size = camera.nadir_size * (altitude / kDefaultAltitude);  // 2 h tan(fov/2) per axis
    return def;
  }
  def.shape = FootprintShape::quad;
  const double theta = camera.pitch;
  const double tan_a = std::tan(a), tan_b = std::tan(b);
  const double c = std::cos(theta), s = std::sin(theta);
  // Edge s_v = −1 (near) and +1 (far): the ray (s + s_v tan a · c, ± tan b, −c + s_v tan a · s)
  // from (0, 0, h) meets the ground at t = h / (c − s_v tan a · s).
  const auto edge = [&](double side) {
    const double t = altitude / (c - side * tan_a * s);
    return Vec2(t * (s + side * tan_a * c), t * tan_b);  // (x, half-width)
  };
  const Vec2 near = edge(-1.0), far = edge(1.0);
  // Counter-clockwise in the heading frame (x forward, y left).
  def.corners = {Vec2(near.x(), -near.y()), Vec2(far.x(), -far.y()), Vec2(far.x(), far.y()),
                 Vec2(near.x(), near.y())};
  return def;
}

double slantDistance(const Vec2& z, const Vec2& p, double altitude) {
  return std::sqrt((z - p).squaredNorm() + altitude * altitude);  // √(|z − p|² + h²)
}

double slantNoiseFactor(const Vec2& z, const Vec2& p, double altitude) {
  // ℓ(h) / ℓ(h_ref): exactly 1 at h = h_ref (the same operations on the same numbers).
  return slantDistance(z, p, altitude) / slantDistance(z, p, kDefaultAltitude);
}

}  // namespace canopy::sensing
