#include "spec/solid_paths.h"

#include <sstream>

namespace canopy::spec {
std::vector<SolidCrossing> solidCrossings(const ScenarioSpec& spec) {
  std::vector<SolidCrossing> out;
  for (int t = 0; t < static_cast<int>(spec.targets.size()); ++t) {
    const world::Path& path = spec.targets[t].path;
    // The legs as segments, each with the words that name it.
    struct Leg {
      Vec2 a, b;
      std::string words;
    };
    std::vector<Leg> legs;
    if (path.isConstantVelocity()) {
      legs.push_back({path.start(), path.start() + path.velocity() * spec.duration,
                      "its constant-velocity path (start to the position at the end of the run)"});
    } else {
      const std::vector<world::TimedPoint>& p = path.points();
      auto name = [&](std::size_t i) {
        std::ostringstream text;
        text << "waypoint " << i << " (t = " << p[i].t << " s)";
        return text.str();
      };
      if (p.size() == 1) legs.push_back({p[0].p, p[0].p, name(0)});
      for (std::size_t i = 0; i + 1 < p.size(); ++i)
        legs.push_back({p[i].p, p[i + 1].p, "from " + name(i) + " to " + name(i + 1)});
    }
    for (int leg = 0; leg < static_cast<int>(legs.size()); ++leg) {
      for (int k = 0; k < static_cast<int>(spec.trees.size()); ++k) {
        const world::TreeDef& tree = spec.trees[k];
        if (!world::isWall(tree) && !(tree.trunk_radius > 0.0)) continue;
        if (world::solidDistance(tree, legs[leg].a, legs[leg].b) > 0.0) continue;
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
