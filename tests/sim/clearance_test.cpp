// Plans that keep clear (issue 27), the cases quick enough for every build: validate's check of
// scripted paths through solids (spec/solid_paths.h) and two UAVs with bodies closing on one
// person. The corridor and mixed_team trials over 40 seeds are in clearance_trials_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "sim/run_report.h"
#include "sim/simulation.h"
#include "sim/summary.h"
#include "spec/loader.h"
#include "spec/solid_paths.h"

namespace canopy::sim {
namespace {

TEST(SolidPaths, ATargetWalkingThroughAWallOrATrunkIsNamedWithItsWaypoints) {
  const spec::ScenarioSpec spec = spec::loadScenarioText(R"({
    "name": "through", "aoi": [-20, -20, 20, 20],
    "uavs": [{"start": [0, 0]}],
    "targets": [
      {"name": "ok", "path": {"waypoints": [{"t": 0, "p": [-10, 10]}, {"t": 10, "p": [10, 10]}]}},
      {"name": "W", "path": {"waypoints": [{"t": 0, "p": [-10, 0]}, {"t": 5, "p": [-6, 0]},
                                           {"t": 10, "p": [-1, 0]}]}},
      {"name": "V", "path": {"start": [5, -10], "velocity": [0, 1]}}
    ],
    "occluders": [
      {"type": "polygon", "vertices": [[-4, -1], [-3, -1], [-3, 1], [-4, 1]]},
      {"type": "disc", "centre": [5, 0], "radius": 2, "trunk_radius": 0.3},
      {"type": "disc", "centre": [5.5, 5], "radius": 2}
    ]
  })",
                                                         "through.json");
  const std::vector<spec::SolidCrossing> found = spec::solidCrossings(spec);
  // W's second leg (waypoint 1 → 2, x from −6 to −1) crosses the wall x ∈ [−4, −3]; V walks up
  // x = 5 for 20 s (y from −10 to 10) through the trunk at (5, 0); the default trunk of the tree
  // at (5.5, 5) is 0.2 m, 0.5 m off V's line: clear.
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].target, 1);
  EXPECT_EQ(found[0].leg, 1);
  EXPECT_EQ(found[0].tree, 0);
  EXPECT_NE(found[0].message.find("target \"W\""), std::string::npos) << found[0].message;
  EXPECT_NE(found[0].message.find("from waypoint 1"), std::string::npos) << found[0].message;
  EXPECT_NE(found[0].message.find("wall 0"), std::string::npos) << found[0].message;
  EXPECT_EQ(found[1].target, 2);
  EXPECT_EQ(found[1].tree, 1);
  EXPECT_NE(found[1].message.find("trunk of tree 1"), std::string::npos) << found[1].message;
}

// A ground robot's scripted path into a wall is named as a target's is (issue 51: a rover drove
// into a wall and stayed there for 170 steps, and validate said nothing), with its body's radius
// as clearance; a UAV's path over the same wall is not (UAVs fly above walls), nor a robot's when
// a planner runs (the path is not followed). A constant-velocity path is named once ("its path
// (constant velocity, …)", not "its path its constant-velocity path").
TEST(SolidPaths, AGroundRobotsPathIntoAWallIsNamedAndAUavsIsNot) {
  const std::string text = R"({
    "name": "rover_wall", "aoi": [-20, -20, 20, 20], "clock": {"duration": 10},
    "uavs": [{"name": "rover", "kind": "ground", "radius": 0.5,
              "path": {"start": [-10, 0], "velocity": [1, 0]}},
             {"name": "edge", "kind": "ground", "radius": 0.5,
              "path": {"waypoints": [{"t": 0, "p": [-10, 1.4]}, {"t": 10, "p": [0, 1.4]}]}},
             {"name": "flyer", "path": {"start": [-10, 0], "velocity": [1, 0]}}],
    "targets": [{"name": "T", "path": {"start": [-10, -10], "velocity": [0, 0]}}],
    "occluders": [{"type": "polygon", "vertices": [[-4, -1], [-3, -1], [-3, 1], [-4, 1]]}]
  })";
  const std::vector<spec::SolidCrossing> found =
      spec::solidCrossings(spec::loadScenarioText(text, "rover_wall.json"));
  // rover drives along y = 0 through the wall; edge passes 0.4 m above it, within its 0.5 m body.
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].agent, 0);
  EXPECT_EQ(found[0].target, -1);
  EXPECT_EQ(found[0].tree, 0);
  EXPECT_EQ(found[0].message,
            "ground robot \"rover\": its path (constant velocity, from its start to its position "
            "at the end of the run) runs into wall 0 (centre (-3.5, 0)); the robot is stopped "
            "there and stays");
  EXPECT_EQ(found[1].agent, 1);
  EXPECT_NE(found[1].message.find("from waypoint 0 (t = 0 s) to waypoint 1"), std::string::npos)
      << found[1].message;
  spec::LoadOptions planned;
  planned.overrides = {"planner.algorithm=sma"};
  EXPECT_TRUE(
      spec::solidCrossings(spec::loadScenarioText(text, "rover_wall.json", planned)).empty());
}

// The run says so when an agent stays against a wall (issue 51: 170 steps, and nothing on the
// terminal): the rover above reaches the wall at x = -4.5 (its 0.5 m body) after 5.5 s and stays
// there for the remaining 14.5 s of 20; the summary counts the longest run of steps in contact and
// runWarnings (what `canopy run` prints to stderr) names the rover. Without the wall: no warning.
std::vector<std::string> warningsOfRover(bool wall) {
  const std::string text =
      std::string(R"({
    "name": "rover_stuck", "aoi": [-20, -20, 20, 20], "clock": {"dt": 0.2, "duration": 20},
    "uavs": [{"name": "rover", "kind": "ground", "radius": 0.5,
              "path": {"start": [-10, 0], "velocity": [1, 0]}}],
    "targets": [{"name": "T", "path": {"start": [-10, -10], "velocity": [0, 0]}}],
    "occluders": [)") +
      (wall ? R"({"type": "polygon", "vertices": [[-4, -1], [-3, -1], [-3, 1], [-4, 1]]})" : "") +
      "]}";
  const spec::ScenarioSpec spec = spec::loadScenarioText(text, "rover_stuck.json");
  Simulation sim(spec);
  SummaryBuilder summary(spec);
  while (!sim.done()) summary.onStep(sim.tick());
  const SummaryBuilder::UavTally& rover = summary.uavs()[0];
  if (wall) {
    EXPECT_GE(rover.longest_contact, 70);  // 14.5 s / 0.2 s, give or take the step of impact
    EXPECT_LE(rover.longest_contact, 74);
    EXPECT_EQ(rover.longest_contact, rover.steps_in_contact);
    EXPECT_EQ(rover.longest_contact_from + rover.longest_contact, 101);  // to the last step, 100
  } else {
    EXPECT_EQ(rover.longest_contact, 0);
  }
  return runWarnings(summary.json(0.0));
}

TEST(StuckAgents, ARoverAgainstAWallForSecondsIsNamedOnTheTerminal) {
  const std::vector<std::string> stuck = warningsOfRover(true);
  ASSERT_EQ(stuck.size(), 1u);
  EXPECT_EQ(stuck[0].rfind("rover: against something solid for ", 0), 0u) << stuck[0];
  EXPECT_NE(stuck[0].find("steps in a row"), std::string::npos) << stuck[0];
  EXPECT_NE(stuck[0].find("stuck?"), std::string::npos) << stuck[0];
  EXPECT_TRUE(warningsOfRover(false).empty());
}

// Two UAVs with bodies (r = 1 m each) close on one person from either side: the world stops them
// at their time of impact, and their plans charge every interval on which they would come within
// 2r + c = 2.2 m of each other (closest approach between samples included), so over 20 seeds
// they never touch and their centres stay at least 2r apart. The control, UAVs without bodies,
// shows that the chase does bring them within 2 m.
std::string twoUavsOnOnePerson(double radius) {
  const std::string r = std::to_string(radius);
  return R"({
    "name": "two_uavs", "aoi": [-30, -30, 30, 30], "clock": {"dt": 0.2, "duration": 20},
    "uavs": [{"name": "west", "start": [-12, 0], "v_max": 5, "radius": )" +
         r + R"(,
              "fov": {"radius": 4}},
             {"name": "east", "start": [12, 0], "v_max": 5, "radius": )" +
         r + R"(,
              "fov": {"radius": 4}}],
    "targets": [{"name": "P", "path": {"waypoints": [{"t": 0, "p": [0, -3]},
                                                   {"t": 20, "p": [0, 3]}]}}],
    "tracking": {"preseed": true},
    "planner": {"algorithm": "sma", "horizon": 3}
  })";
}

struct Closeness {
  long contacts = 0;     // contacts begun, both UAVs
  double closest = 1e9;  // m, between the centres at any step
};

Closeness closeIn(double radius, int seeds) {
  Closeness out;
  for (int seed = 1; seed <= seeds; ++seed) {
    spec::LoadOptions options;
    options.overrides = {"seed=" + std::to_string(seed)};
    Simulation sim(spec::loadScenarioText(twoUavsOnOnePerson(radius), "two_uavs.json", options));
    while (!sim.done()) {
      const StepRecord& step = sim.tick();
      for (const UavRecord& uav : step.uavs) out.contacts += uav.contacts_begun;
      out.closest = std::min(out.closest, (step.uavs[0].position - step.uavs[1].position).norm());
    }
  }
  return out;
}

TEST(Clearance, TwoUavsWithBodiesOnOnePersonNeverTouchOver20Seeds) {
  const Closeness bodies = closeIn(1.0, 20);
  EXPECT_EQ(bodies.contacts, 0);
  EXPECT_GE(bodies.closest, 2.0);
  EXPECT_LT(closeIn(0.0, 5).closest, 2.0);  // the control: without bodies they come closer
}

}  // namespace
}  // namespace canopy::sim
