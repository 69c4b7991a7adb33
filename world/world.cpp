#include "world/world.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/angles.h"
#include "core/progress.h"
#include "world/near_solids.h"
#include "world/substeps.h"
#include "world/unicycle.h"

namespace canopy::world {
namespace {

constexpr float kTargetBodyRadius = 0.05f;  // m, only gives the body a broad-phase box
constexpr float kNoBodyRadius = 0.25f;      // m, likewise for an agent of radius 0
// The sub-step limits (world/substeps.h) are half of Box2D's per-step motion limits.
static_assert(kMaxSubstepTranslation == 0.5 * b2_maxTranslation);
static_assert(kMaxSubstepRotation - 0.5 * b2_maxRotation < 1e-6 &&
              0.5 * b2_maxRotation - kMaxSubstepRotation < 1e-6);
// Box2D's solver iterations per sub-step (its recommended 8 and 3). They act on contacts only, so
// a body that touches nothing moves as with any other count.
constexpr int kVelocityIterations = 8;
constexpr int kPositionIterations = 3;

// Collision categories: ground robots collide with robots and solids, UAVs with UAVs only.
constexpr uint16 kGroundCategory = 0x1;
constexpr uint16 kUavCategory = 0x2;
constexpr uint16 kSolidCategory = 0x4;

// A fixture's user data encodes our id: (index << 3) | (kind + 1), never 0.
uintptr_t encode(BodyKind kind, int index) {
  return (static_cast<uintptr_t>(index) << 3) | (static_cast<uintptr_t>(kind) + 1);
}
BodyRef decode(uintptr_t data) {
  return {static_cast<BodyKind>((data & 7u) - 1), static_cast<int>(data >> 3)};
}

b2Vec2 toB2(const Vec2& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y())};
}
Vec2 fromB2(const b2Vec2& v) {
  return {v.x, v.y};
}

b2FixtureDef nonCollidingFixture(const b2Shape* shape, BodyKind kind, int index) {
  b2FixtureDef fixture;
  fixture.shape = shape;
  fixture.density = 0.0f;
  fixture.isSensor = true;
  fixture.filter.maskBits = 0;  // nothing collides
  fixture.userData.pointer = encode(kind, index);
  return fixture;
}

// A fixture the contact solver acts on: frictionless (a body slides along what it touches) and
// without restitution (it stops rather than bounces).
b2FixtureDef solidFixture(const b2Shape* shape, BodyKind kind, int index, uint16 category,
                          uint16 mask) {
  b2FixtureDef fixture;
  fixture.shape = shape;
  fixture.density = 1.0f;
  fixture.friction = 0.0f;
  fixture.restitution = 0.0f;
  fixture.filter.categoryBits = category;
  fixture.filter.maskBits = mask;
  fixture.userData.pointer = encode(kind, index);
  return fixture;
}

// Collects every fixture whose broad-phase box overlaps the query box.
class CollectCallback final : public b2QueryCallback {
 public:
  explicit CollectCallback(std::vector<BodyRef>& out) : out_(out) {}
  bool ReportFixture(b2Fixture* fixture) override {
    const BodyRef ref = decode(fixture->GetUserData().pointer);
    if (ref.kind != BodyKind::trunk && ref.kind != BodyKind::wall) out_.push_back(ref);
    return true;
  }

 private:
  std::vector<BodyRef>& out_;
};

// Stops at the first tree that strictly contains the point.
class PointInTreeCallback final : public b2QueryCallback {
 public:
  PointInTreeCallback(const std::vector<TreeDef>& trees, const Vec2& p) : trees_(trees), p_(p) {}
  bool ReportFixture(b2Fixture* fixture) override {
    const BodyRef ref = decode(fixture->GetUserData().pointer);
    if (ref.kind == BodyKind::tree && strictlyInside(trees_[ref.index], p_)) {
      hit = ref.index;
      return false;
    }
    return true;
  }
  std::optional<int> hit;

 private:
  const std::vector<TreeDef>& trees_;
  Vec2 p_;
};

// Broad-phase ray cast: candidates along the segment, exact entry fraction in double; the ray is
// clipped at the nearest entry found so far.
class FirstTreeOnSegment {
 public:
  FirstTreeOnSegment(const b2BroadPhase& broad_phase, const std::vector<TreeDef>& trees,
                     const Vec2& a, const Vec2& b)
      : broad_phase_(broad_phase), trees_(trees), a_(a), b_(b) {}
  float RayCastCallback(const b2RayCastInput& input, int32 proxy_id) {
    const auto* proxy = static_cast<const b2FixtureProxy*>(broad_phase_.GetUserData(proxy_id));
    const BodyRef ref = decode(proxy->fixture->GetUserData().pointer);
    if (ref.kind != BodyKind::tree) return input.maxFraction;
    const double s = segmentEntry(trees_[ref.index], a_, b_);
    if (s >= 0.0 && s < best_fraction) {
      best_fraction = s;
      hit = ref.index;
    }
    // Keep searching up to (slightly past) the best entry; broad-phase boxes are float.
    return hit ? std::min(1.0f, static_cast<float>(best_fraction) + 1e-4f) : input.maxFraction;
  }
  std::optional<int> hit;
  double best_fraction = 2.0;

 private:
  const b2BroadPhase& broad_phase_;
  const std::vector<TreeDef>& trees_;
  Vec2 a_, b_;
};

// The first crown (in the broad phase's order) that strictly contains p.
std::optional<int> crownContaining(const b2World& crowns, const std::vector<TreeDef>& trees,
                                   const Vec2& p) {
  PointInTreeCallback callback(trees, p);
  b2AABB query;
  query.lowerBound = toB2(p);
  query.upperBound = toB2(p);
  crowns.QueryAABB(&callback, query);
  return callback.hit;
}

// A polygon tree's vertices as Box2D's shape (box2dProblem() has checked that Box2D takes them).
b2PolygonShape polygonOf(const TreeDef& tree) {
  std::vector<b2Vec2> vertices;
  for (const Vec2& v : tree.vertices) vertices.push_back(toB2(v));
  b2PolygonShape polygon;
  polygon.Set(vertices.data(), static_cast<int32>(vertices.size()));
  return polygon;
}

// Tree k's solid part as a fixture of the static body `solids`: a wall's polygon or a trunk's disc.
b2Fixture* createSolid(b2Body& solids, const TreeDef& tree, int k) {
  if (isWall(tree)) {
    const b2PolygonShape polygon = polygonOf(tree);
    const b2FixtureDef fixture =
        solidFixture(&polygon, BodyKind::wall, k, kSolidCategory, kGroundCategory);
    return solids.CreateFixture(&fixture);
  }
  b2CircleShape trunk;
  trunk.m_p = toB2(tree.centre);
  trunk.m_radius = static_cast<float>(tree.trunk_radius);
  const b2FixtureDef fixture =
      solidFixture(&trunk, BodyKind::trunk, k, kSolidCategory, kGroundCategory);
  return solids.CreateFixture(&fixture);
}

}  // namespace

struct World::Box2d {
  b2World world{b2Vec2(0.0f, 0.0f)};
  // The tree crowns, in a world of their own that is queried and never stepped: in `world` the
  // first Step would pair-test every new static proxy, 10⁶ crowns taking tens of seconds with no
  // output (issue 34), to find contacts crowns never have.
  b2World crowns{b2Vec2(0.0f, 0.0f)};
  std::vector<b2Body*> uavs;
  std::vector<b2Body*> targets;
  b2Body* forest = nullptr;  // one static body holding every tree as a fixture
  // The trunks and walls near some ground robot with a body, as fixtures of one static body, and
  // which those are: the stepped world holds no other, so its broad phase grows with the robots'
  // surroundings and not with the forest (docs/design-notes.md, "Only solids near a robot are
  // stepped").
  b2Body* solids = nullptr;
  std::optional<NearSolids> near_solids;
  double ground_v_max = 0.0;  // m/s, the fastest ground robot with a body
  std::vector<b2Fixture*> solid_fixture;  // per tree: its solid part in `world`, or null
  std::vector<int> solids_added, solids_removed;
  // step()'s per-agent scratch, kept to reuse its memory: the command each sub-step drives at,
  // the turn rate (rad/s), the position at the step's start (m), what it touched.
  std::vector<b2Vec2> velocity;
  std::vector<float> omega;
  std::vector<int> bodied;  // the agents with a body, by x
  std::vector<Vec2> start;
  std::vector<std::vector<BodyRef>> touched;
};

// `new Box2d`, not make_unique: value-initialising would first zero its two b2Worlds (each holds
// Box2D's 100 KB stack allocator inline), 200 KB written for every world built.
World::World(WorldDef def) : def_(std::move(def)), b2_(new Box2d) {
  b2World& w = b2_->world;
  w.SetAllowSleeping(false);
  // Box2D's continuous collision: a dynamic body moving into a static shape (a robot into a
  // trunk or wall) stops at the time of impact within a sub-step, rather than sinking in and
  // being pushed out over the following ones. It acts on those contacts only.
  w.SetContinuousPhysics(true);

  // Agents are dynamic bodies driven at their command: the contact solver can stop them (a
  // kinematic body goes wherever its velocity takes it). Nothing else acts on them (no gravity,
  // no damping, fixed rotation), so a body that touches nothing moves exactly as commanded.
  bool any_ground = false;
  for (int i = 0; i < static_cast<int>(def_.uavs.size()); ++i) {
    const UavDef& agent = def_.uavs[i];
    if (agent.radius != 0.0 &&
        !(agent.radius >= kMinAgentRadius && agent.radius <= kMaxAgentRadius))
      throw std::invalid_argument("agent " + std::to_string(i) + ": radius " +
                                  std::to_string(agent.radius) + " m, expected 0 or " +
                                  std::to_string(kMinAgentRadius) + " to " +
                                  std::to_string(kMaxAgentRadius) + " m");
    const bool ground = agent.kind == AgentKind::ground;
    if (ground && agent.radius > 0.0) {
      any_ground = true;
      b2_->ground_v_max = std::max(b2_->ground_v_max, agent.v_max);
    }
    b2BodyDef body;
    body.type = b2_dynamicBody;
    body.fixedRotation = true;  // the heading is the command's, never the contacts'
    // An agent with a body is a bullet: Box2D's continuous collision then stops two agents at
    // their time of impact within a sub-step, as it stops a robot at a trunk or wall. Without it
    // two dynamic bodies touch only once they overlap at the end of a sub-step, by up to the
    // sub-step's closing distance (half a radius), and are pushed apart over the next ones.
    body.bullet = agent.radius > 0.0;
    body.position = toB2(agent.start);
    body.angle = static_cast<float>(agent.yaw);
    b2Body* b = w.CreateBody(&body);
    b2CircleShape shape;
    if (agent.radius > 0.0) {
      shape.m_radius = static_cast<float>(agent.radius);
      b2FixtureDef fixture =
          ground ? solidFixture(&shape, BodyKind::uav, i, kGroundCategory,
                                kGroundCategory | kSolidCategory)
                 : solidFixture(&shape, BodyKind::uav, i, kUavCategory, kUavCategory);
      // Every agent weighs 1 kg: two pressing on each other at equal speeds stop, neither pushes.
      fixture.density = static_cast<float>(1.0 / (std::numbers::pi * agent.radius * agent.radius));
      b->CreateFixture(&fixture);
    } else {  // no body: it touches nothing, its fixture only gives it a broad-phase box
      shape.m_radius = kNoBodyRadius;
      const b2FixtureDef fixture = nonCollidingFixture(&shape, BodyKind::uav, i);
      b->CreateFixture(&fixture);
    }
    b2_->uavs.push_back(b);
  }

  b2CircleShape target_shape;
  target_shape.m_radius = kTargetBodyRadius;
  for (int t = 0; t < static_cast<int>(def_.targets.size()); ++t) {
    b2BodyDef body;
    body.type = b2_kinematicBody;
    body.position = toB2(def_.targets[t].path.positionAt(0.0));
    b2Body* b = w.CreateBody(&body);
    const b2FixtureDef fixture = nonCollidingFixture(&target_shape, BodyKind::target, t);
    b->CreateFixture(&fixture);
    b2_->targets.push_back(b);
  }

  b2BodyDef forest_def;
  forest_def.type = b2_staticBody;
  b2_->forest = b2_->crowns.CreateBody(&forest_def);
  ProgressCounter progress("building the world (trees)", static_cast<double>(def_.trees.size()));
  for (int k = 0; k < static_cast<int>(def_.trees.size()); ++k) {
    progress.add();
    const TreeDef& tree = def_.trees[k];
    // The loader refuses these with their field; a world built from elsewhere (Python, tests)
    // gets an exception here instead of Box2D's assertion aborting the process.
    if (const std::string problem = box2dProblem(tree); !problem.empty())
      throw std::invalid_argument("tree " + std::to_string(k) + ": " + problem);
    if (tree.shape == TreeShape::disc) {
      b2CircleShape circle;
      circle.m_p = toB2(tree.centre);
      circle.m_radius = static_cast<float>(tree.radius);
      const b2FixtureDef fixture = nonCollidingFixture(&circle, BodyKind::tree, k);
      b2_->forest->CreateFixture(&fixture);
    } else {
      const b2PolygonShape polygon = polygonOf(tree);
      const b2FixtureDef fixture = nonCollidingFixture(&polygon, BodyKind::tree, k);
      b2_->forest->CreateFixture(&fixture);
    }
  }

  // Trunks and walls, only when a ground robot with a body can touch them (UAVs fly above them);
  // step() brings each into the world when a robot comes near it.
  if (any_ground) {
    b2BodyDef solids_def;
    solids_def.type = b2_staticBody;
    b2_->solids = w.CreateBody(&solids_def);
    b2_->near_solids.emplace(def_.trees);
    b2_->solid_fixture.assign(def_.trees.size(), nullptr);
  }

  commands_.assign(def_.uavs.size(), Vec2::Zero());
  contacts_.assign(def_.uavs.size(), {});
  contacts_begun_.assign(def_.uavs.size(), 0);
  uav_velocity_.assign(def_.uavs.size(), Vec2::Zero());
  climb_commands_.assign(def_.uavs.size(), 0.0);
  climb_.assign(def_.uavs.size(), 0.0);
  for (const UavDef& uav : def_.uavs) altitude_.push_back(uav.z);
  target_velocity_.assign(def_.targets.size(), Vec2::Zero());
}

World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

void World::commandUav(int uav, const Vec2& velocity) {
  const double v_max = def_.uavs[uav].v_max;
  const double speed = velocity.norm();
  commands_[uav] = speed > v_max ? Vec2(velocity * (v_max / speed)) : velocity;  // |v| ≤ v_max
}

void World::commandClimb(int uav, double climb) {
  const double rate = def_.uavs[uav].climb_rate;
  climb_commands_[uav] = std::clamp(climb, -rate, rate);  // |ż| ≤ climb_rate
}

void World::keepSolidsNear(double dt) {
  // No body moves more than twice the fastest robot's command in one step: a robot pushed by
  // another of equal mass moves at most at the pusher's speed, the solver's corrections add
  // millimetres (tests/world/contact_test.cpp).
  const double travel = 2.0 * b2_->ground_v_max * dt;  // m
  std::vector<int>& added = b2_->solids_added;
  std::vector<int>& removed = b2_->solids_removed;
  added.clear();
  removed.clear();
  for (std::size_t i = 0; i < b2_->uavs.size(); ++i) {
    const UavDef& agent = def_.uavs[i];
    if (agent.kind != AgentKind::ground || !(agent.radius > 0.0)) continue;
    b2_->near_solids->update(static_cast<int>(i), fromB2(b2_->uavs[i]->GetPosition()),
                             agent.radius, travel, added, removed);
  }
  // A solid one robot left and another reached in the same call stays where it is.
  for (const int k : removed) {
    b2Fixture*& fixture = b2_->solid_fixture[k];
    if (fixture != nullptr && !b2_->near_solids->holds(k)) {
      b2_->solids->DestroyFixture(fixture);
      fixture = nullptr;
    }
  }
  for (const int k : added) {
    b2Fixture*& fixture = b2_->solid_fixture[k];
    if (fixture == nullptr && b2_->near_solids->holds(k))
      fixture = createSolid(*b2_->solids, def_.trees[k], k);
  }
}

int World::steppedSolidCount() const {
  return b2_->near_solids ? b2_->near_solids->heldCount() : 0;
}

void World::step(double dt) {
  double max_translation = 0.0;  // m over this step, any body
  double max_rotation = 0.0;     // rad over this step, any UAV
  int substeps = 1;

  for (std::size_t t = 0; t < b2_->targets.size(); ++t) {
    b2Body* body = b2_->targets[t];
    // Aim at the scripted position at t + dt from where the body actually is, so that float
    // rounding never accumulates: the target passes its waypoints at the scripted times.
    const Vec2 goal = def_.targets[t].path.positionAt(time_ + dt);
    const Vec2 v = (goal - fromB2(body->GetPosition())) / dt;
    body->SetLinearVelocity(toB2(v));
    target_velocity_[t] = v;
    max_translation = std::max(max_translation, v.norm() * dt);
  }

  const std::size_t n = b2_->uavs.size();
  std::vector<b2Vec2>& velocity = b2_->velocity;
  std::vector<float>& omega = b2_->omega;
  std::vector<Vec2>& start = b2_->start;
  std::vector<std::vector<BodyRef>>& touched = b2_->touched;
  velocity.resize(n);
  omega.resize(n);
  start.resize(n);
  touched.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    b2Body* body = b2_->uavs[i];
    const UavDef& agent = def_.uavs[i];
    Vec2 v = commands_[i];
    double w = 0.0;  // rad/s
    start[i] = fromB2(body->GetPosition());
    if (agent.kind == AgentKind::ground) {
      // The unicycle's pose at t + dt from where the body actually is (world/unicycle.h).
      const Pose2 now{start[i], body->GetAngle()};
      const Pose2 next = unicycleMove(now, v, agent.turn_rate, dt);
      v = (next.position - now.position) / dt;
      w = wrapAngle(next.heading - now.heading) / dt;
    } else if (agent.yaw_mode == YawMode::velocity && v.squaredNorm() > 1e-12) {
      const double heading = std::atan2(v.y(), v.x());
      w = wrapAngle(heading - body->GetAngle()) / dt;
    }
    velocity[i] = toB2(v);
    omega[i] = static_cast<float>(w);
    uav_velocity_[i] = v;
    max_translation = std::max(max_translation, v.norm() * dt);
    max_rotation = std::max(max_rotation, std::abs(w) * dt);
  }
  if (b2_->near_solids) keepSolidsNear(dt);
  // Two agents that collide with each other (two robots, or two UAVs with bodies) and could meet
  // during the step: sub-steps short enough that neither passes through the other. Agents far
  // apart keep the sub-steps they had (a robot meeting a trunk or wall is stopped at the time of
  // impact by continuous collision, whatever the sub-step).
  // Only pairs closer along x than the widest reach are tested: the agents with bodies sorted by
  // x, each against those after it within that distance (O(n log n) for a spread-out team).
  std::vector<int>& bodied = b2_->bodied;
  bodied.clear();
  double widest = b2_aabbExtension;  // m: no two agents farther apart than this can meet
  double fastest = 0.0, largest = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(def_.uavs[i].radius > 0.0)) continue;  // no body
    bodied.push_back(static_cast<int>(i));
    fastest = std::max(fastest, uav_velocity_[i].norm());
    largest = std::max(largest, def_.uavs[i].radius);
  }
  widest += 2.0 * (largest + fastest * dt);
  std::sort(bodied.begin(), bodied.end(), [&](int i, int j) {
    return start[i].x() < start[j].x() || (start[i].x() == start[j].x() && i < j);
  });
  for (std::size_t a = 0; a < bodied.size(); ++a) {
    const int i = bodied[a];
    for (std::size_t b = a + 1; b < bodied.size(); ++b) {
      const int j = bodied[b];
      if (start[j].x() - start[i].x() >= widest) break;
      if (def_.uavs[j].kind != def_.uavs[i].kind) continue;
      const double closing = (uav_velocity_[i].norm() + uav_velocity_[j].norm()) * dt;  // m
      const double reach = def_.uavs[i].radius + def_.uavs[j].radius + closing + b2_aabbExtension;
      if ((start[i] - start[j]).squaredNorm() >= reach * reach) continue;
      const double smaller = std::min(def_.uavs[i].radius, def_.uavs[j].radius);
      substeps =
          std::max(substeps, static_cast<int>(std::ceil(closing / (kMaxSubstepRadii * smaller))));
    }
  }

  substeps =
      std::max({substeps, static_cast<int>(std::ceil(max_translation / kMaxSubstepTranslation)),
                static_cast<int>(std::ceil(max_rotation / kMaxSubstepRotation))});
  const float h = static_cast<float>(dt / substeps);
  for (int s = 0; s < substeps; ++s) {
    for (std::size_t i = 0; i < n; ++i) {
      b2_->uavs[i]->SetLinearVelocity(velocity[i]);
      b2_->uavs[i]->SetAngularVelocity(omega[i]);
    }
    b2_->world.Step(h, kVelocityIterations, kPositionIterations);
    for (b2Contact* c = b2_->world.GetContactList(); c != nullptr; c = c->GetNext()) {
      if (!c->IsTouching()) continue;
      const BodyRef a = decode(c->GetFixtureA()->GetUserData().pointer);
      const BodyRef b = decode(c->GetFixtureB()->GetUserData().pointer);
      if (a.kind == BodyKind::uav) touched[a.index].push_back(b);
      if (b.kind == BodyKind::uav) touched[b.index].push_back(a);
    }
  }

  for (std::size_t i = 0; i < n; ++i) {
    std::vector<BodyRef>& now = touched[i];
    std::sort(now.begin(), now.end());
    now.erase(std::unique(now.begin(), now.end()), now.end());
    const std::vector<BodyRef>& before = contacts_[i];
    contacts_begun_[i] =
        static_cast<int>(std::count_if(now.begin(), now.end(), [&](const BodyRef& r) {
          return !std::binary_search(before.begin(), before.end(), r);
        }));
    // A body that touched something went where the solver let it: its velocity is what it moved.
    if (!now.empty()) uav_velocity_[i] = (fromB2(b2_->uavs[i]->GetPosition()) - start[i]) / dt;
    contacts_[i].swap(now);  // the old list's memory is the next step's scratch
    now.clear();
  }

  // Altitude: z ← clamp(z + ż dt, z_min, z_max), the climb flown what it moved.
  for (std::size_t i = 0; i < n; ++i) {
    const UavDef& agent = def_.uavs[i];
    const double z = std::clamp(altitude_[i] + climb_commands_[i] * dt, agent.z_min, agent.z_max);
    climb_[i] = (z - altitude_[i]) / dt;
    altitude_[i] = z;
  }

  time_ += dt;
  ++step_;
}

WorldSnapshot World::snapshot() const {
  WorldSnapshot snap;
  snap.step = step_;
  snap.time = time_;
  snap.uavs.reserve(b2_->uavs.size());
  for (std::size_t i = 0; i < b2_->uavs.size(); ++i) {
    const b2Body* body = b2_->uavs[i];
    snap.uavs.push_back({fromB2(body->GetPosition()), uav_velocity_[i], wrapAngle(body->GetAngle()),
                         contacts_[i], contacts_begun_[i], altitude_[i], climb_[i]});
  }
  snap.targets.reserve(b2_->targets.size());
  for (std::size_t t = 0; t < b2_->targets.size(); ++t) {
    snap.targets.push_back({fromB2(b2_->targets[t]->GetPosition()), target_velocity_[t]});
  }
  return snap;
}

void World::queryAabb(const Aabb& box, std::vector<BodyRef>& out) const {
  const std::size_t first = out.size();
  CollectCallback callback(out);
  b2AABB query;
  query.lowerBound = toB2(box.lo);
  query.upperBound = toB2(box.hi);
  b2_->world.QueryAABB(&callback, query);
  b2_->crowns.QueryAABB(&callback, query);
  // The broad-phase order depends on the tree's history; sort so callers see a stable order.
  std::sort(out.begin() + static_cast<std::ptrdiff_t>(first), out.end());
}

bool World::insideOccluder(const Vec2& p) const {
  return crownContaining(b2_->crowns, def_.trees, p).has_value();
}

bool World::sightBlocked(const Vec2& a, double ha, const Vec2& b, double hb) const {
  std::vector<BodyRef> near;
  queryAabb({a.cwiseMin(b), a.cwiseMax(b)}, near);
  for (const BodyRef& ref : near) {
    if (ref.kind == BodyKind::tree && blocksSight(def_.trees[ref.index], a, ha, b, hb)) return true;
  }
  return false;
}

std::optional<int> World::firstOccluderOnSegment(const Vec2& a, const Vec2& b) const {
  if ((b - a).squaredNorm() < 1e-12)  // Box2D's ray cast needs a non-zero length
    return crownContaining(b2_->crowns, def_.trees, a);
  const b2BroadPhase& broad_phase = b2_->crowns.GetContactManager().m_broadPhase;
  FirstTreeOnSegment callback(broad_phase, def_.trees, a, b);
  b2RayCastInput input;
  input.p1 = toB2(a);
  input.p2 = toB2(b);
  input.maxFraction = 1.0f;
  broad_phase.RayCast(&callback, input);
  return callback.hit;
}

}  // namespace canopy::world
