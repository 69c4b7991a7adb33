#include "spec/solid_paths.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <unordered_map>

#include "core/progress.h"

namespace canopy::spec {
namespace {

// A bounding box grown point by point (empty until the first).
struct Box {
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity());
  Vec2 hi = Vec2::Constant(-std::numeric_limits<double>::infinity());
  void expand(const Vec2& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
};

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

// The solid trees (trunks and walls) in a uniform grid of their bounding boxes, so that a leg is
// tested against the trees near it, not every tree: the work is (legs × cells a leg's box meets)
// at most, and never more than legs × solids (a leg whose box meets more cells than there are
// solids is tested against every solid).
class SolidIndex {
 public:
  explicit SolidIndex(const std::vector<world::TreeDef>& trees) {
    Box all;
    for (int k = 0; k < static_cast<int>(trees.size()); ++k) {
      if (!world::isWall(trees[k]) && !(trees[k].trunk_radius > 0.0)) continue;
      solids_.push_back(k);
      boxes_.push_back(boxOf(trees[k]));
      all.expand(boxes_.back().lo);
      all.expand(boxes_.back().hi);
    }
    if (solids_.empty()) return;
    // About one solid per cell on average.
    const Vec2 extent = all.hi - all.lo;
    cell_ = std::max(1.0, std::sqrt(extent.x() * extent.y() / static_cast<double>(solids_.size())));
    for (std::size_t s = 0; s < solids_.size(); ++s) {
      const auto [i0, j0, i1, j1] = cellsOf(boxes_[s]);
      if ((i1 - i0 + 1) * (j1 - j0 + 1) > kMaxCellsPerSolid) {
        wide_.push_back(solids_[s]);  // a long wall: tested against every leg
        continue;
      }
      for (long long i = i0; i <= i1; ++i)
        for (long long j = j0; j <= j1; ++j) cells_[key(i, j)].push_back(solids_[s]);
    }
  }

  // The indices (in spec.trees, ascending) of the solids whose box may meet the segment a → b.
  std::vector<int> near(const Vec2& a, const Vec2& b) const {
    if (solids_.empty()) return {};
    Box box;
    box.expand(a);
    box.expand(b);
    const auto [i0, j0, i1, j1] = cellsOf(box);
    if (static_cast<double>(i1 - i0 + 1) * static_cast<double>(j1 - j0 + 1) >
        static_cast<double>(solids_.size()))
      return solids_;
    std::vector<int> found = wide_;
    for (long long i = i0; i <= i1; ++i)
      for (long long j = j0; j <= j1; ++j)
        if (const auto it = cells_.find(key(i, j)); it != cells_.end())
          found.insert(found.end(), it->second.begin(), it->second.end());
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    return found;
  }

 private:
  static constexpr long long kMaxCellsPerSolid = 1024;

  static Box boxOf(const world::TreeDef& tree) {
    Box box;
    if (world::isWall(tree)) {
      for (const Vec2& v : tree.vertices) box.expand(v);
    } else {
      box.expand(tree.centre - Vec2(tree.trunk_radius, tree.trunk_radius));
      box.expand(tree.centre + Vec2(tree.trunk_radius, tree.trunk_radius));
    }
    return box;
  }
  std::array<long long, 4> cellsOf(const Box& box) const {
    return {static_cast<long long>(std::floor(box.lo.x() / cell_)),
            static_cast<long long>(std::floor(box.lo.y() / cell_)),
            static_cast<long long>(std::floor(box.hi.x() / cell_)),
            static_cast<long long>(std::floor(box.hi.y() / cell_))};
  }
  static std::uint64_t key(long long i, long long j) {
    return (static_cast<std::uint64_t>(i) << 32) ^ static_cast<std::uint32_t>(j);
  }

  std::vector<int> solids_;  // indices in spec.trees, ascending
  std::vector<Box> boxes_;   // per solid
  std::vector<int> wide_;    // solids spanning more than kMaxCellsPerSolid cells
  double cell_ = 1.0;        // m
  std::unordered_map<std::uint64_t, std::vector<int>> cells_;
};

}  // namespace

std::vector<SolidCrossing> solidCrossings(const ScenarioSpec& spec) {
  std::vector<SolidCrossing> out;
  const SolidIndex index(spec.trees);
  ProgressCounter progress("checking target paths", static_cast<double>(spec.targets.size()), 1024);
  for (int t = 0; t < static_cast<int>(spec.targets.size()); ++t) {
    progress.add();
    const std::vector<Leg> legs = legsOf(spec.targets[t].path, spec.duration);
    for (int leg = 0; leg < static_cast<int>(legs.size()); ++leg) {
      for (const int k : index.near(legs[leg].a, legs[leg].b)) {
        const world::TreeDef& tree = spec.trees[k];
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
