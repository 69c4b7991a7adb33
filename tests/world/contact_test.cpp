// Bodies that collide (issue 27): a ground robot against a wall and a trunk, sliding along a wall,
// two UAVs keeping their separation, and what each body is said to have touched. The answers are
// worked by hand from the geometry and Box2D's documented tolerances: the position solver leaves a
// body sunk by at most b2_linearSlop (5 mm) into what it touches, a polygon carries a skin of
// b2_polygonRadius (10 mm), and a frictionless contact removes only the normal part of a velocity.
#include <box2d/b2_common.h>
#include <gtest/gtest.h>

#include <cmath>

#include "world/world.h"

namespace canopy::world {
namespace {

constexpr double kSlop = b2_linearSlop;  // m
constexpr double kTol = 1e-3;            // m, float bodies and the solver's last iterations

WorldDef emptyWorld() {
  WorldDef def;
  def.aoi = {Vec2(-100, -100), Vec2(100, 100)};
  return def;
}

UavDef robot(const Vec2& start, double yaw, double radius = 0.5) {
  UavDef r;
  r.start = start;
  r.yaw = yaw;
  r.yaw_mode = YawMode::velocity;
  r.v_max = 2.0;
  r.turn_rate = 1.0;
  r.kind = AgentKind::ground;
  r.radius = radius;
  return r;
}

// A wall whose west face is the line x = 2, from y = −20 to 20, 1.5 m thick.
TreeDef wallAtX2() {
  return TreeDef::polygon({Vec2(2, -20), Vec2(3.5, -20), Vec2(3.5, 20), Vec2(2, 20)});
}

TEST(Contacts, RobotDrivenIntoAWallStopsWithItsSurfaceOnTheFace) {
  WorldDef def = emptyWorld();
  def.uavs.push_back(robot(Vec2(0, 0), 0.0));
  def.trees.push_back(wallAtX2());
  World world(def);
  for (int k = 0; k < 15; ++k) {  // 3 s at 2 m/s: 6 m of command for 1.5 m of room
    world.commandUav(0, Vec2(2, 0));
    world.step(0.2);
  }
  const UavState s = world.snapshot().uavs[0];
  // The surface x + r on the face x = 2, within the slop; it stayed on its line.
  EXPECT_NEAR(s.position.x() + 0.5, 2.0, kSlop + kTol);
  EXPECT_NEAR(s.position.y(), 0.0, 1e-6);
  EXPECT_NEAR(s.velocity.norm(), 0.0, kTol / 0.2);  // pressed against it, not moving
  ASSERT_EQ(s.contacts.size(), 1u);
  EXPECT_EQ(s.contacts[0], (BodyRef{BodyKind::wall, 0}));
  EXPECT_EQ(s.contacts_begun, 0);  // it has been touching since an earlier step
}

TEST(Contacts, RobotAt45DegreesSlidesAlongTheWallAtTheTangentialSpeed) {
  WorldDef def = emptyWorld();
  const double diagonal = std::sqrt(0.5);  // cos 45° = sin 45°
  def.uavs.push_back(robot(Vec2(0, 0), 0.25 * M_PI));
  def.trees.push_back(wallAtX2());
  World world(def);
  const Vec2 command(2 * diagonal, 2 * diagonal);
  int first_contact = -1;
  for (int k = 1; k <= 30; ++k) {
    world.commandUav(0, command);
    world.step(0.2);
    const UavState s = world.snapshot().uavs[0];
    if (s.contacts.empty()) continue;
    if (first_contact < 0) {
      first_contact = k;
      EXPECT_EQ(s.contacts_begun, 1);
      continue;
    }
    if (k < first_contact + 2) continue;  // the step that sank it in, and the one pushing it out
    EXPECT_EQ(s.contacts_begun, 0) << "k=" << k;
    // Along the face: 2·sin 45° = √2 m/s; into it: nothing; the surface on the face.
    EXPECT_NEAR(s.velocity.y(), 2 * diagonal, 1e-3) << "k=" << k;
    EXPECT_NEAR(s.velocity.x(), 0.0, 1e-3) << "k=" << k;
    EXPECT_NEAR(s.position.x() + 0.5, 2.0, kSlop + kTol) << "k=" << k;
  }
  // The robot meets the face after (2 − 0.5)/√2 = 1.06 s of driving: in step 6 (1.0–1.2 s).
  EXPECT_EQ(first_contact, 6);
}

TEST(Contacts, RobotPassesUnderACrownAndStopsAtTheTrunk) {
  WorldDef def = emptyWorld();
  TreeDef tree = TreeDef::disc(Vec2(6, 0), 3.0);
  tree.trunk_radius = 0.3;
  def.trees.push_back(tree);
  def.uavs.push_back(robot(Vec2(0, 0), 0.0));    // straight at the trunk
  def.uavs.push_back(robot(Vec2(0, 1.5), 0.0));  // 1.5 m off its line: clear of 0.3 + 0.5
  World world(def);
  for (int k = 0; k < 25; ++k) {
    world.commandUav(0, Vec2(2, 0));
    world.commandUav(1, Vec2(2, 0));
    world.step(0.2);
  }
  const WorldSnapshot snap = world.snapshot();
  // Circles meet at centre distance 0.3 + 0.5 = 0.8 (no skin), less at most the slop.
  EXPECT_NEAR(6.0 - snap.uavs[0].position.x(), 0.8, kSlop + kTol);
  ASSERT_EQ(snap.uavs[0].contacts.size(), 1u);
  EXPECT_EQ(snap.uavs[0].contacts[0], (BodyRef{BodyKind::trunk, 0}));
  // The other drove under the crown and past the trunk untouched: 5 s at 2 m/s.
  EXPECT_NEAR(snap.uavs[1].position.x(), 10.0, 1e-4);
  EXPECT_NEAR(snap.uavs[1].position.y(), 1.5, 1e-6);
  EXPECT_TRUE(snap.uavs[1].contacts.empty());
}

TEST(Contacts, UavsCommandedAtEachOtherStopAtTheirSeparation) {
  WorldDef def = emptyWorld();
  def.uavs.push_back({Vec2(-5, 0), 0.0, YawMode::fixed, 5.0});
  def.uavs.push_back({Vec2(5, 0), 0.0, YawMode::fixed, 5.0});
  def.uavs[0].radius = 0.5;
  def.uavs[1].radius = 0.7;
  World world(def);
  for (int k = 0; k < 20; ++k) {  // 4 s at 2 m/s each: they meet after 2.2 s
    world.commandUav(0, Vec2(2, 0));
    world.commandUav(1, Vec2(-2, 0));
    world.step(0.2);
  }
  const WorldSnapshot snap = world.snapshot();
  const double gap = snap.uavs[1].position.x() - snap.uavs[0].position.x();
  EXPECT_NEAR(gap, 0.5 + 0.7, kSlop + kTol);
  // Every agent weighs the same, so equal and opposite commands stop both where they meet: their
  // surfaces close at 4 m/s from 10 − 1.2 m, after 2.2 s, at x = −5 + 2·2.2 + 0.5 = −0.1.
  EXPECT_NEAR(snap.uavs[0].position.x() + 0.5, -0.1, kSlop + kTol);
  EXPECT_EQ(snap.uavs[0].contacts, (std::vector<BodyRef>{{BodyKind::uav, 1}}));
  EXPECT_EQ(snap.uavs[1].contacts, (std::vector<BodyRef>{{BodyKind::uav, 0}}));
}

UavDef uavWithBody(const Vec2& start, double radius) {
  UavDef u{start, 0.0, YawMode::fixed, 5.0};
  u.radius = radius;
  return u;
}

// The closest two bodies' centres came at the end of any step, and the step it was.
struct Closest {
  double distance = 1e9;  // m
  int step = -1;
};

// Agents 0 and 1 commanded at each other along x at 2 m/s for `steps` steps of 0.2 s: the
// closest their centres came and the first step agent 0 touched something.
struct HeadOn {
  Closest closest;
  int first_contact = -1;
};
HeadOn driveHeadOn(World& world, int steps) {
  HeadOn out;
  for (int k = 1; k <= steps; ++k) {
    world.commandUav(0, Vec2(2, 0));
    world.commandUav(1, Vec2(-2, 0));
    world.step(0.2);
    const WorldSnapshot snap = world.snapshot();
    const double d = (snap.uavs[1].position - snap.uavs[0].position).norm();
    if (d < out.closest.distance) out.closest = {d, k};
    if (out.first_contact < 0 && !snap.uavs[0].contacts.empty()) out.first_contact = k;
  }
  return out;
}

TEST(Contacts, UavsMeetingInsideAStepNeverOverlap) {
  // Two UAVs of r = 1 m, 10.3 m apart, commanded at each other at 2 m/s: their surfaces close at
  // 4 m/s from 8.3 m and meet after 2.075 s, inside step 11 (2.0–2.2 s) and inside one of its
  // sub-steps (closing 0.8 m per step, half a radius per sub-step: 2 sub-steps). They stop there:
  // centres 2r apart at x = ∓(5.15 − 2·2.075) = ∓1.0, at every later step.
  WorldDef def = emptyWorld();
  def.uavs.push_back(uavWithBody(Vec2(-5.15, 0), 1.0));
  def.uavs.push_back(uavWithBody(Vec2(5.15, 0), 1.0));
  World world(def);
  const HeadOn run = driveHeadOn(world, 25);
  EXPECT_EQ(run.first_contact, 11);
  EXPECT_GE(run.closest.distance, 2.0 - kSlop - kTol) << "at step " << run.closest.step;
  const WorldSnapshot snap = world.snapshot();
  EXPECT_NEAR(snap.uavs[0].position.x(), -1.0, kSlop + kTol);
  EXPECT_NEAR(snap.uavs[1].position.x(), 1.0, kSlop + kTol);
  EXPECT_NEAR(snap.uavs[0].position.y(), 0.0, 1e-6);
}

TEST(Contacts, RobotsMeetingInsideAStepNeverOverlap) {
  // The same for two ground robots (r = 0.5 m) facing each other, 5.15 m apart, driven at 2 m/s
  // along their headings (no turning): surfaces close at 4 m/s from 4.15 m and meet after
  // 1.0375 s, inside step 6 (1.0–1.2 s) and inside one of its 4 sub-steps; they stop with
  // centres 1 m apart at x = ∓(2.575 − 2·1.0375) = ∓0.5.
  WorldDef def = emptyWorld();
  def.uavs.push_back(robot(Vec2(-2.575, 0), 0.0));
  def.uavs.push_back(robot(Vec2(2.575, 0), M_PI));
  World world(def);
  const HeadOn run = driveHeadOn(world, 15);
  EXPECT_EQ(run.first_contact, 6);
  EXPECT_GE(run.closest.distance, 1.0 - kSlop - kTol) << "at step " << run.closest.step;
  const WorldSnapshot snap = world.snapshot();
  EXPECT_NEAR(snap.uavs[0].position.x(), -0.5, kSlop + kTol);
  EXPECT_NEAR(snap.uavs[1].position.x(), 0.5, kSlop + kTol);
}

TEST(Contacts, AUavDrivenIntoAHoveringOnePushesItAtHalfItsSpeed) {
  // A (r = 1 m) at x = −5.1 driven at 2 m/s at B (r = 1 m) hovering at 0: A's surface meets B's
  // after (5.1 − 2)/2 = 1.55 s, inside step 8. From then on each sub-step the frictionless,
  // inelastic contact between equal masses leaves both at (2 + 0)/2 = 1 m/s: at t = 4 s, B is
  // at 1·(4 − 1.55) = 2.45 m and A 2 m behind it.
  WorldDef def = emptyWorld();
  def.uavs.push_back(uavWithBody(Vec2(-5.1, 0), 1.0));
  def.uavs.push_back(uavWithBody(Vec2(0, 0), 1.0));
  World world(def);
  Closest closest;
  for (int k = 1; k <= 20; ++k) {
    world.commandUav(0, Vec2(2, 0));
    world.commandUav(1, Vec2(0, 0));
    world.step(0.2);
    const WorldSnapshot snap = world.snapshot();
    const double d = (snap.uavs[1].position - snap.uavs[0].position).norm();
    if (d < closest.distance) closest = {d, k};
  }
  EXPECT_GE(closest.distance, 2.0 - kSlop - kTol) << "at step " << closest.step;
  const WorldSnapshot snap = world.snapshot();
  EXPECT_NEAR(snap.uavs[1].position.x(), 2.45, kSlop + kTol);
  EXPECT_NEAR(snap.uavs[0].position.x(), 0.45, 2 * (kSlop + kTol));
  EXPECT_NEAR(snap.uavs[0].velocity.x(), 1.0, kTol / 0.2);
  EXPECT_NEAR(snap.uavs[1].velocity.x(), 1.0, kTol / 0.2);
}

TEST(Contacts, UavsFlyOverWallsAndRobotsAndTargetsTouchNothing) {
  WorldDef def = emptyWorld();
  def.uavs.push_back({Vec2(0, 1), 0.0, YawMode::fixed, 5.0});  // a UAV across the wall
  def.uavs.push_back(robot(Vec2(0, 1), 0.0));                  // a robot under the UAV
  def.targets.push_back({Path::constantVelocity(Vec2(0, -1), Vec2(2, 0))});  // a person through it
  def.trees.push_back(wallAtX2());
  World world(def);
  for (int k = 0; k < 20; ++k) {
    world.commandUav(0, Vec2(2, 0));
    world.step(0.2);
  }
  const WorldSnapshot snap = world.snapshot();
  EXPECT_NEAR(snap.uavs[0].position.x(), 8.0, 1e-4);
  EXPECT_TRUE(snap.uavs[0].contacts.empty());
  EXPECT_NEAR(snap.targets[0].position.x(), 8.0, 1e-4);
  EXPECT_NEAR(snap.uavs[1].position.x(), 0.0, 1e-6);  // the robot was not pushed by the UAV
}

TEST(Contacts, ARobotFromFarAwayStillStopsOnTheWall) {
  // The wall is not in the stepped world while the robot is 100 m away (only solids near a robot
  // are); it must be there by the time the robot arrives, at 2 m/s and at 30 m/s.
  for (const double speed : {2.0, 30.0}) {
    WorldDef def = emptyWorld();
    def.aoi = {Vec2(-200, -100), Vec2(100, 100)};
    UavDef r = robot(Vec2(-100, 0), 0.0);
    r.v_max = speed;
    def.uavs.push_back(r);
    def.trees.push_back(wallAtX2());
    World world(def);
    world.commandUav(0, Vec2(speed, 0));
    world.step(0.5);
    EXPECT_EQ(world.steppedSolidCount(), 0) << speed;  // the wall is out of reach
    for (int k = 0; k < static_cast<int>(2 * 110 / speed) + 4; ++k) {
      world.commandUav(0, Vec2(speed, 0));
      world.step(0.5);
    }
    const UavState s = world.snapshot().uavs[0];
    EXPECT_NEAR(s.position.x() + 0.5, 2.0, kSlop + kTol) << speed;
    EXPECT_EQ(world.steppedSolidCount(), 1) << speed;
  }
}

TEST(Contacts, AmongAThousandTrunksOnlyThoseNearTheRobotAreStepped) {
  // A trunk every 10 m on a 32 × 32 grid; the robot drives 60 m along y = 5 (between rows).
  WorldDef def = emptyWorld();
  def.aoi = {Vec2(0, 0), Vec2(320, 320)};
  for (int i = 0; i < 32; ++i)
    for (int j = 0; j < 32; ++j) {
      TreeDef tree = TreeDef::disc(Vec2(10.0 * i, 10.0 * j), 2.0);
      tree.trunk_radius = 0.3;
      def.trees.push_back(tree);
    }
  def.uavs.push_back(robot(Vec2(100, 5), 0.0));
  World world(def);
  for (int k = 0; k < 150; ++k) {
    world.commandUav(0, Vec2(2, 0));
    world.step(0.2);
    // The neighbourhood is a box 2 · (0.5 + 8 + 1) = 19 m wide around a point within 8 m of the
    // robot along its line: it meets the trunks (0.6 m wide) of 1 or 2 columns, 10 m apart, and
    // of the rows y = 0 and 10 only (y from −4.5 to 14.5).
    EXPECT_LE(world.steppedSolidCount(), 4) << "step " << k;
    EXPECT_GE(world.steppedSolidCount(), 2) << "step " << k;
  }
  // Between the rows, 4.7 m from each trunk's rim: it touched nothing and drove 60 m.
  EXPECT_NEAR(world.snapshot().uavs[0].position.x(), 160.0, 1e-3);
  EXPECT_TRUE(world.snapshot().uavs[0].contacts.empty());
}

TEST(Contacts, SameCommandsSameBits) {
  auto run = [] {
    WorldDef def = emptyWorld();
    def.trees.push_back(wallAtX2());
    for (int i = 0; i < 4; ++i) def.uavs.push_back(robot(Vec2(0, 1.1 * i), 0.3 * i));
    World world(def);
    std::vector<Vec2> out;
    for (int k = 0; k < 40; ++k) {
      for (int i = 0; i < 4; ++i)
        world.commandUav(i, Vec2(2 * std::cos(0.4 * i), std::sin(0.7 * i)));
      world.step(0.2);
      for (const UavState& u : world.snapshot().uavs) out.push_back(u.position);
    }
    return out;
  };
  const std::vector<Vec2> a = run(), b = run();
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].x(), b[k].x());
    EXPECT_EQ(a[k].y(), b[k].y());
  }
}

}  // namespace
}  // namespace canopy::world
