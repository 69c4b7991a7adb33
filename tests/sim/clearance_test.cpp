// Plans that keep clear (issue 27): a ground robot follows a person down a corridor with a pillar
// in its middle. The NBO cost charges any nominal pose within the robot's radius + clearance of a
// mapped trunk or wall (agents/planning/nominal_cost.h), so its plans go around the pillar: over
// 40 seeds it never touches the pillar or the corridor's walls, and it gets past the pillar.
// validate's check of scripted paths is here too (spec/solid_paths.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "sim/simulation.h"
#include "spec/loader.h"
#include "spec/solid_paths.h"

namespace canopy::sim {
namespace {

// Walls along y ∈ [3, 4] and [−4, −3], a 1 m square pillar at the origin; the person walks at
// y = 1.8 past it, the robot starts on the pillar's line, 12 m before it, facing it.
std::string corridor(const std::string& map) {
  return R"({
    "name": "corridor", "aoi": [-20, -10, 20, 10], "clock": {"dt": 0.2, "duration": 16},
    "uavs": [{"name": "rover", "kind": "ground", "start": [-12, 0], "yaw": 0, "v_max": 2,
              "turn_rate": 1.5, "radius": 0.4, "fov": {"range": 6, "angle": 1.5708}}],
    "targets": [{"name": "P", "path": {"waypoints": [{"t": 0, "p": [-9, 1.8]},
                                                   {"t": 16, "p": [14, 1.8]}]}}],
    "occluders": [
      {"type": "polygon", "vertices": [[-18, 3], [18, 3], [18, 4], [-18, 4]]},
      {"type": "polygon", "vertices": [[-18, -4], [18, -4], [18, -3], [-18, -3]]},
      {"type": "polygon", "vertices": [[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]]}
    ],
    "tracking": {"preseed": true},
    "planner": {"algorithm": "sma", "horizon": 3, "occlusion_map": ")" +
         map + R"("}
  })";
}

struct Outcome {
  int contacts = 0;  // contacts begun
  double final_x = 0.0;
};

Outcome drive(const std::string& map, std::uint64_t seed) {
  spec::LoadOptions options;
  options.overrides = {"seed=" + std::to_string(seed)};
  Simulation sim(spec::loadScenarioText(corridor(map), "corridor.json", options));
  Outcome out;
  while (!sim.done()) {
    const StepRecord& step = sim.tick();
    out.contacts += step.uavs[0].contacts_begun;
  }
  out.final_x = sim.lastStep().uavs[0].position.x();
  return out;
}

TEST(Clearance, ARobotsPlanPassesThePillarWithoutContactOver40Seeds) {
  int contacts = 0, passed = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    const Outcome o = drive("a_priori", seed);
    contacts += o.contacts;
    passed += o.final_x > 0.5 + 0.4;  // beyond the pillar's far face by its radius
  }
  EXPECT_EQ(contacts, 0);
  EXPECT_EQ(passed, 40);
}

TEST(Clearance, WithoutAMapTheSamePlansRunIntoThePillar) {
  // The control: with no map the cost sees no solids, and the straight plans touch the pillar.
  int contacts = 0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) contacts += drive("none", seed).contacts;
  EXPECT_GT(contacts, 0);
}

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

}  // namespace
}  // namespace canopy::sim

namespace canopy::sim {
namespace {

// mixed_team with the a-priori map (the true trunks and walls in every agent's map): its robots
// touch nothing over 40 seeds. (With the dynamic map they may touch what they have not yet seen:
// docs/design-notes.md reports the count.)
TEST(Clearance, MixedTeamWithTheAPrioriMapHasNoContactsOver40Seeds) {
  long contacts = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    spec::LoadOptions options;
    options.overrides = {"seed=" + std::to_string(seed), "planner.occlusion_map=\"a_priori\""};
    Simulation sim(spec::loadScenario("mixed_team", options));
    while (!sim.done()) {
      for (const UavRecord& uav : sim.tick().uavs) contacts += uav.contacts_begun;
    }
  }
  EXPECT_EQ(contacts, 0);
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
    "uavs": [{"name": "west", "start": [-12, 0], "v_max": 5, "radius": )" + r + R"(,
              "fov": {"radius": 4}},
             {"name": "east", "start": [12, 0], "v_max": 5, "radius": )" + r + R"(,
              "fov": {"radius": 4}}],
    "targets": [{"name": "P", "path": {"waypoints": [{"t": 0, "p": [0, -3]},
                                                   {"t": 20, "p": [0, 3]}]}}],
    "tracking": {"preseed": true},
    "planner": {"algorithm": "sma", "horizon": 3}
  })";
}

struct Closeness {
  long contacts = 0;      // contacts begun, both UAVs
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
