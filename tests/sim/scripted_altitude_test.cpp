// Scripted paths with a z (issue 53): a UAV without a planner flies its waypoints' altitudes within
// its climb rate, against an altitude profile worked by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sim/simulation.h"
#include "spec/loader.h"

namespace canopy::sim {
namespace {

// dt = 0.5 s, climb rate 2 m/s. The waypoints ask for 20 → 30 m over 0–5 s (2 m/s: flyable),
// 30 → 40 m over 5–7 s (5 m/s: too steep), 40 m held to 12 s, 40 → 30 m over 12–16 s (2.5 m/s:
// too steep). The waypoint at t = 9 s gives no z. No z, z_min or z_max in the file: they default to
// the profile's 20 m at t = 0 and its span [20, 40] m.
constexpr const char* kProfile = R"({
  "name": "scripted_altitude",
  "aoi": [0, 0, 100, 100],
  "clock": {"dt": 0.5, "duration": 18},
  "uavs": [{"name": "u", "fov": {"size": [20, 14]}, "climb_rate": 2,
            "path": {"waypoints": [{"t": 0, "p": [10, 50], "z": 20}, {"t": 5, "p": [20, 50], "z": 30},
                                   {"t": 7, "p": [24, 50], "z": 40}, {"t": 9, "p": [28, 50]},
                                   {"t": 12, "p": [34, 50], "z": 40},
                                   {"t": 16, "p": [42, 50], "z": 30}]}}]
})";

// By hand: the UAV aims at the profile one step ahead, ż = (z(t + dt) − z)/dt clamped to ±2 m/s.
// 0–5 s: on the profile, z = 20 + 2t. From 5 s the profile climbs 2.5 m a step and the UAV 1 m:
// z = 30 + 2(t − 5) until it meets 40 m at 10 s; held at 40 m to 12 s. From 12 s the profile
// descends 1.25 m a step and the UAV 1 m: z = 40 − 2(t − 12) until 30 m at 17 s; then 30 m.
double byHand(double t) {
  if (t <= 5.0) return 20.0 + 2.0 * t;
  if (t <= 12.0) return std::min(40.0, 30.0 + 2.0 * (t - 5.0));
  return std::max(30.0, 40.0 - 2.0 * (t - 12.0));
}

TEST(ScriptedAltitude, FliesTheWaypointsAltitudesWithinItsClimbRate) {
  const spec::ScenarioSpec spec = spec::loadScenarioText(kProfile, "scripted_altitude.json");
  const world::UavDef& body = spec.uavs[0].body;
  EXPECT_EQ(body.z, 20.0);
  EXPECT_EQ(body.z_min, 20.0);
  EXPECT_EQ(body.z_max, 40.0);
  Simulation sim(spec);
  int steps = 0;
  while (!sim.done()) {
    const StepRecord& step = sim.tick();
    ASSERT_TRUE(step.uavs[0].altitude);
    EXPECT_NEAR(step.uavs[0].z, byHand(step.time), 1e-9) << "t = " << step.time;
    // The path in the plane is flown as before (v = 2 m/s ≤ v_max): x from the waypoints.
    EXPECT_NEAR(step.uavs[0].position.y(), 50.0, 1e-4);
    ++steps;
  }
  EXPECT_EQ(steps, 37);  // t = 0 … 18 s
}

}  // namespace
}  // namespace canopy::sim
