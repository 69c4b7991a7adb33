#include "experiments/placement.h"

#include <algorithm>
#include <cmath>

namespace canopy::experiments {

Placement Placement::mirrorX() {
  Placement p;
  p.A << -1.0, 0.0, 0.0, 1.0;
  return p;
}

Placement Placement::rotation(double radians) {
  Placement p;
  const double c = std::cos(radians), s = std::sin(radians);
  p.A << c, -s, s, c;
  return p;
}

spec::ScenarioSpec placed(const spec::ScenarioSpec& spec, const Placement& placement) {
  const Mat2& A = placement.A;
  const double s = placement.distance_scale;
  auto point = [&](const Vec2& p) -> Vec2 { return A * (s * p) + placement.b; };
  auto velocity = [&](const Vec2& v) -> Vec2 { return A * (s * placement.speed_scale * v); };
  auto heading = [&](double yaw) {  // the direction (cos ψ, sin ψ) turned by A
    const Vec2 d = A * Vec2(std::cos(yaw), std::sin(yaw));
    return std::atan2(d.y(), d.x());
  };
  auto path = [&](const world::Path& p) {
    if (p.isConstantVelocity())
      return world::Path::constantVelocity(point(p.start()), velocity(p.velocity()));
    std::vector<world::TimedPoint> points;
    for (const world::TimedPoint& q : p.points()) {
      points.push_back({q.t / placement.speed_scale, point(q.p)});
    }
    return world::Path::throughPoints(points);
  };

  spec::ScenarioSpec out = spec;
  const Vec2 a = point(spec.aoi.lo), b = point(spec.aoi.hi);
  const Vec2 c = point(Vec2(spec.aoi.lo.x(), spec.aoi.hi.y()));
  const Vec2 d = point(Vec2(spec.aoi.hi.x(), spec.aoi.lo.y()));
  out.aoi.lo = a.cwiseMin(b).cwiseMin(c).cwiseMin(d);
  out.aoi.hi = a.cwiseMax(b).cwiseMax(c).cwiseMax(d);
  for (spec::UavSpec& u : out.uavs) {
    u.body.start = point(u.body.start);
    u.body.yaw = heading(u.body.yaw);
    u.sensor.footprint.size *= s;
    u.sensor.footprint.radius *= s;
    // A camera at an altitude (issue 53): its nadir footprint at the default altitude scales too.
    if (u.sensor.camera) u.sensor.camera->nadir_size *= s;
    if (u.path) u.path = path(*u.path);
    if (u.altitude_profile) {  // its times follow the path's; altitudes are not plane distances
      std::vector<world::TimedAltitude> points = u.altitude_profile->points();
      for (world::TimedAltitude& q : points) q.t /= placement.speed_scale;
      u.altitude_profile.emplace(std::move(points));
    }
  }
  for (spec::TargetSpec& t : out.targets) t.path = path(t.path);
  for (world::TreeDef& tree : out.trees) {
    const double base = tree.base, top = tree.top;  // heights are not distances of the plane
    if (tree.shape == world::TreeShape::disc) {
      tree = world::TreeDef::disc(point(tree.centre), s * tree.radius);
    } else {
      std::vector<Vec2> vertices;
      for (const Vec2& v : tree.vertices) vertices.push_back(point(v));
      tree = world::TreeDef::polygon(std::move(vertices));  // re-oriented counter-clockwise
    }
    tree.base = base;
    tree.top = top;
  }
  out.duration = spec.duration / placement.speed_scale;
  return out;
}

}  // namespace canopy::experiments
