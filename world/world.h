#pragma once
// The Box2D world: agents as dynamic bodies, targets as kinematic ones, trees as fixtures of one
// static body. The only code in canopy that includes Box2D. Box2D serves as the integrator, the
// spatial database (broad-phase AABB queries and ray casts) and the contact solver: a ground
// robot is stopped by trunks, walls and other robots and slides along them, UAVs keep their
// separation; targets and crowns touch nothing (docs/design-notes.md, "Bodies that collide").
#include <memory>
#include <optional>
#include <vector>

#include "core/types.h"
#include "world/defs.h"
#include "world/snapshot.h"

namespace canopy::world {

class World {
 public:
  explicit World(WorldDef def);
  ~World();
  World(World&&) noexcept;
  World& operator=(World&&) noexcept;
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  /// Sets UAV uav's velocity command for the next steps, clamped to |v| ≤ v_max (m/s). A ground
  /// robot follows it as a unicycle (world/unicycle.h): turning toward it, then driving along it.
  void commandUav(int uav, const Vec2& velocity);
  const Vec2& commandedVelocity(int uav) const { return commands_[uav]; }
  /// Sets UAV uav's climb command (m/s, up positive) for the next steps, clamped to
  /// |ż| ≤ climb_rate; a step then moves its altitude by ż·dt, kept within [z_min, z_max].
  void commandClimb(int uav, double climb);
  double commandedClimb(int uav) const { return climb_commands_[uav]; }

  /// Advances time by dt (s): targets move to their scripted position at t + dt, UAVs by their
  /// commanded velocity, ground robots by unicycleMove over dt, as far as the contact solver lets
  /// them. Sub-steps Box2D so that no body exceeds Box2D's per-step motion limits and no two
  /// agents that collide and could meet close by more than half the smaller radius in one
  /// sub-step (so none passes through another); continuous collision stops a robot at a trunk or
  /// wall, and two agents with bodies (bullets) at each other, at the time of impact. Each
  /// sub-step drives every agent at its command again (the solver removes only the part into
  /// what it touches).
  void step(double dt);

  WorldSnapshot snapshot() const;
  double time() const { return time_; }
  int stepIndex() const { return step_; }
  const WorldDef& def() const { return def_; }
  const std::vector<TreeDef>& trees() const { return def_.trees; }

  /// Bodies whose Box2D fixture bounds overlap box (a superset: callers test exact geometry);
  /// crowns, not solid parts. Appends to out, in a deterministic order.
  void queryAabb(const Aabb& box, std::vector<BodyRef>& out) const;
  /// How many trunks and walls the stepped Box2D world holds now: those near a ground robot with
  /// a body (docs/design-notes.md, "Only solids near a robot are stepped").
  int steppedSolidCount() const;

  /// True when p is strictly inside some tree crown.
  bool insideOccluder(const Vec2& p) const;
  /// True when some crown's volume hides (b, hb) from (a, ha) (world/tree.h, blocksSight;
  /// heights in m above the ground).
  bool sightBlocked(const Vec2& a, double ha, const Vec2& b, double hb) const;
  /// The tree the segment a → b enters first (nearest a), or none.
  std::optional<int> firstOccluderOnSegment(const Vec2& a, const Vec2& b) const;

 private:
  struct Box2d;  // Box2D objects, hidden from the header
  /// Before a step: brings into the stepped world the trunks and walls a ground robot may reach
  /// during it, and takes out those none can reach any longer.
  void keepSolidsNear(double dt);
  WorldDef def_;
  std::unique_ptr<Box2d> b2_;
  std::vector<Vec2> commands_;                  // clamped UAV velocity commands (m/s)
  std::vector<Vec2> uav_velocity_;              // last applied (m/s)
  std::vector<double> climb_commands_;          // clamped climb commands (m/s)
  std::vector<double> altitude_;                // m, each UAV's z
  std::vector<double> climb_;                   // m/s, each UAV's last applied climb
  std::vector<Vec2> target_velocity_;           // last applied (m/s)
  std::vector<std::vector<BodyRef>> contacts_;  // per agent: touched during the last step
  std::vector<int> contacts_begun_;             // per agent: of those, new at the last step
  double time_ = 0.0;
  int step_ = 0;
};

}  // namespace canopy::world
