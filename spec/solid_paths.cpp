#include "spec/solid_paths.h"

#include <sstream>
#include <vector>

#include "core/progress.h"
#include "world/solid_index.h"

namespace canopy::spec {
namespace {

// A leg of a target's path as a segment, with the words that name it.
struct Leg {
  Vec2 a, b;
  std::string words;
};

std::vector<Leg> legsOf(const world::Path& path, double duration) {
  std::vector<Leg> legs;
  if (path.isConstantVelocity()) {
    legs.push_back({path.start(), path.start() + path.velocity() * duration,
                    "(constant velocity, from its start to its position at the end of the run)"});
    return legs;
  }
  const std::vector<world::TimedPoint>& p = path.points();
  auto name = [&](std::size_t i) {
    std::ostringstream text;
    text << "waypoint " << i << " (t = " << p[i].t << " s)";
    return text.str();
  };
  if (p.size() == 1) legs.push_back({p[0].p, p[0].p, name(0)});
  for (std::size_t i = 0; i + 1 < p.size(); ++i)
    legs.push_back({p[i].p, p[i + 1].p, "from " + name(i) + " to " + name(i + 1)});
  return legs;
}

}  // namespace

std::vector<SolidCrossing> solidCrossings(const ScenarioSpec& spec) {
  std::vector<SolidCrossing> out;
  const world::SolidIndex index(spec.trees);
  std::vector<int> near;
  // The legs of one path against the solid parts within `clearance` of them.
  auto check = [&](const world::Path& path, double clearance, const std::string& who,
                   const char* consequence, int target, int agent) {
    const std::vector<Leg> legs = legsOf(path, spec.duration);
    for (int leg = 0; leg < static_cast<int>(legs.size()); ++leg) {
      const Vec2& a = legs[leg].a;
      const Vec2& b = legs[leg].b;
      near.clear();
      index.near(Aabb{a.cwiseMin(b) - Vec2::Constant(clearance),
                      a.cwiseMax(b) + Vec2::Constant(clearance)},
                 near);
      for (const int k : near) {
        const world::TreeDef& tree = spec.trees[k];
        if (world::solidDistance(tree, a, b) > clearance) continue;
        std::ostringstream text;
        text << who << ": its path " << legs[leg].words << " runs into "
             << (world::isWall(tree) ? "wall " : "the trunk of tree ") << k << " (centre ("
             << tree.centre.x() << ", " << tree.centre.y() << ")); " << consequence;
        out.push_back({target, agent, leg, k, text.str()});
      }
    }
  };
  ProgressCounter progress("checking target paths", static_cast<double>(spec.targets.size()), 1024);
  for (int t = 0; t < static_cast<int>(spec.targets.size()); ++t) {
    progress.add();
    check(spec.targets[t].path, 0.0, "target \"" + spec.targets[t].name + "\"",
          "the target passes through it as scripted", t, -1);
  }
  for (int i = 0; i < static_cast<int>(spec.uavs.size()); ++i) {
    const UavSpec& uav = spec.uavs[i];
    // Only a path it follows: with a planner, the plan moves it and the path is not read.
    if (uav.body.kind != world::AgentKind::ground || !uav.path ||
        spec.planner.algorithm != agents::PlannerAlgorithm::none)
      continue;
    check(*uav.path, uav.body.radius, "ground robot \"" + uav.name + "\"",
          "the robot is stopped there and stays", -1, i);
  }
  return out;
}

}  // namespace canopy::spec
