#pragma once
// Scripted paths that run into something solid (a trunk or a wall, world/tree.h): a target is
// moved along its script whatever stands in the way, and a ground robot following its path is
// stopped there for good, so such a path is most likely a mistake in the file. `canopy validate`
// warns of each (with --strict, refuses the scenario). UAVs fly above walls and trees.
#include <string>
#include <vector>

#include "spec/scenario_spec.h"

namespace canopy::spec {

/// One leg of a target's or a ground robot's path that touches or enters a solid part.
struct SolidCrossing {
  int target = 0;       // index in spec.targets (-1 for an agent's path)
  int agent = -1;       // index in spec.uavs of a ground robot whose path it is, else -1
  int leg = 0;          // waypoints (or track points): the leg from waypoint `leg` to `leg + 1`; a
                        // path of one point: 0; constant velocity: 0, start to start + v·duration
  int tree = 0;         // index in spec.trees (the record's "wall:K" / "trunk:K")
  std::string message;  // target "C": its path from waypoint 1 (t = 16 s) to waypoint 2 …
};

/// Every leg of every target's path against every trunk and wall, in target, leg, tree order;
/// then, when no planner runs (the scripted paths are followed), every leg of every ground
/// robot's path (within its body's radius of a solid part), in agent, leg, tree order.
std::vector<SolidCrossing> solidCrossings(const ScenarioSpec& spec);

}  // namespace canopy::spec
