#pragma once
// Which solid parts (trunks and walls) the stepped Box2D world holds: only those a ground robot
// with a body could reach before it is next looked at, not the forest's every trunk
// (docs/design-notes.md, "Only solids near a robot are stepped"). Internal to world/: World
// creates and destroys the fixtures this names.
#include <vector>

#include "core/types.h"
#include "world/solid_index.h"
#include "world/tree.h"

namespace canopy::world {

class NearSolids {
 public:
  /// Indexes the solid part of every tree that has one (a wall, or a trunk of positive radius).
  explicit NearSolids(const std::vector<TreeDef>& trees);

  /// Called before each step for robot `robot` (radius m) at p, when no body can move more than
  /// `travel` m during the step. While its last neighbourhood still holds its every reach
  /// (|p − anchor| + travel ≤ skin) nothing changes; otherwise the neighbourhood is re-centred
  /// on p: the solids whose bounds meet the box of half-width radius + skin + kFloatMargin
  /// around p, with skin = max(kMinSkin, 2·travel). Appends to `added` the solids no robot's
  /// neighbourhood held before, to `removed` those none holds now, each in increasing index.
  void update(int robot, const Vec2& p, double radius, double travel, std::vector<int>& added,
              std::vector<int>& removed);

  /// True when some robot's neighbourhood holds solid `tree` (the stepped world should hold it).
  bool holds(int tree) const { return users_[tree] > 0; }
  /// How many solids some robot's neighbourhood holds.
  int heldCount() const { return held_; }

  /// The least skin, m: a robot re-centres its neighbourhood after moving about skin − travel.
  static constexpr double kMinSkin = 8.0;
  /// m: the fixtures' coordinates are floats, 1 m coarse at the largest a scenario may use.
  static constexpr double kFloatMargin = 1.0;

 private:
  struct Neighbourhood {
    bool valid = false;
    Vec2 anchor = Vec2::Zero();  // m, where it was centred
    double skin = 0.0;           // m
    std::vector<int> solids;     // tree indices, increasing
  };
  SolidIndex index_;
  std::vector<Neighbourhood> near_;  // per robot index
  std::vector<int> users_;           // per tree: neighbourhoods that hold it
  std::vector<int> scratch_;
  int held_ = 0;
};

}  // namespace canopy::world
