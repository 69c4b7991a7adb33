#pragma once
// A scripted UAV's altitude over time (issue 53): the `z` its waypoints (or track rows) give,
// linear in time between them. The world flies it within the UAV's climb rate and [z_min, z_max]
// (World::commandClimb), so a profile steeper than the climb rate is followed late.
#include <vector>

namespace canopy::world {

/// Be at altitude z (m) at time t (s).
struct TimedAltitude {
  double t = 0.0;
  double z = 0.0;
};

class AltitudeProfile {
 public:
  /// points: at least one, with strictly increasing t (validated by the scenario loader).
  explicit AltitudeProfile(std::vector<TimedAltitude> points);

  /// z(t) = z_i + (t − t_i)/(t_{i+1} − t_i) · (z_{i+1} − z_i) on [t_i, t_{i+1}); before the first
  /// point its z, after the last the last one's.
  double altitudeAt(double t) const;
  const std::vector<TimedAltitude>& points() const { return points_; }

 private:
  std::vector<TimedAltitude> points_;
};

}  // namespace canopy::world
