#include "world/path.h"

#include <algorithm>
#include <utility>

namespace canopy::world {

Path Path::throughPoints(std::vector<TimedPoint> points) {
  Path path;
  path.points_ = std::move(points);
  return path;
}

Path Path::constantVelocity(const Vec2& start, const Vec2& velocity) {
  Path path;
  path.start_ = start;
  path.velocity_ = velocity;
  return path;
}

namespace {
// Index of the last point with t_i <= t (or 0 before the first point).
std::size_t segmentIndex(const std::vector<TimedPoint>& points, double t) {
  const auto after = std::upper_bound(points.begin(), points.end(), t,
                                      [](double time, const TimedPoint& q) { return time < q.t; });
  return after == points.begin() ? 0 : static_cast<std::size_t>(after - points.begin()) - 1;
}
}  // namespace

Vec2 Path::positionAt(double t) const {
  if (isConstantVelocity()) return start_ + velocity_ * t;
  if (t <= points_.front().t) return points_.front().p;
  if (t >= points_.back().t) return points_.back().p;
  const std::size_t i = segmentIndex(points_, t);
  const TimedPoint& a = points_[i];
  const TimedPoint& b = points_[i + 1];
  const double s = (t - a.t) / (b.t - a.t);  // linear interpolation, s ∈ [0, 1)
  return a.p + s * (b.p - a.p);
}

Vec2 Path::velocityAt(double t) const {
  if (isConstantVelocity()) return velocity_;
  if (t < points_.front().t || t >= points_.back().t) return Vec2::Zero();
  const std::size_t i = segmentIndex(points_, t);
  const TimedPoint& a = points_[i];
  const TimedPoint& b = points_[i + 1];
  return (b.p - a.p) / (b.t - a.t);
}

}  // namespace canopy::world
