#include "world/altitude_profile.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace canopy::world {

AltitudeProfile::AltitudeProfile(std::vector<TimedAltitude> points) : points_(std::move(points)) {
  if (points_.empty()) throw std::invalid_argument("AltitudeProfile: no points");
}

double AltitudeProfile::altitudeAt(double t) const {
  if (t <= points_.front().t) return points_.front().z;
  if (t >= points_.back().t) return points_.back().z;
  // The first point after t; the segment [a, b] holds t.
  const auto after =
      std::upper_bound(points_.begin(), points_.end(), t,
                       [](double time, const TimedAltitude& q) { return time < q.t; });
  const TimedAltitude& a = *(after - 1);
  const TimedAltitude& b = *after;
  const double s = (t - a.t) / (b.t - a.t);  // s ∈ [0, 1)
  return a.z + s * (b.z - a.z);
}

}  // namespace canopy::world
