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
                    "its constant-velocity path (start to the position at the end of the run)"});
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
  ProgressCounter progress("checking target paths", static_cast<double>(spec.targets.size()), 1024);
  for (int t = 0; t < static_cast<int>(spec.targets.size()); ++t) {
    progress.add();
    const std::vector<Leg> legs = legsOf(spec.targets[t].path, spec.duration);
    for (int leg = 0; leg < static_cast<int>(legs.size()); ++leg) {
      const Vec2& a = legs[leg].a;
      const Vec2& b = legs[leg].b;
      near.clear();
      index.near(Aabb{a.cwiseMin(b), a.cwiseMax(b)}, near);
      for (const int k : near) {
        const world::TreeDef& tree = spec.trees[k];
        if (world::solidDistance(tree, a, b) > 0.0) continue;
        std::ostringstream text;
        text << "target \"" << spec.targets[t].name << "\": its path " << legs[leg].words
             << " runs into " << (world::isWall(tree) ? "wall " : "the trunk of tree ") << k
             << " (centre (" << tree.centre.x() << ", " << tree.centre.y()
             << ")); the target passes through it as scripted";
        out.push_back({t, leg, k, text.str()});
      }
    }
  }
  return out;
}

}  // namespace canopy::spec
