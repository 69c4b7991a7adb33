// Reading UAVs, targets and their scripted paths.
#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/angles.h"
#include "core/progress.h"
#include "spec/internal/referenced_file.h"
#include "spec/internal/sections.h"
#include "spec/track_csv.h"
#include "world/footpaths.h"

namespace canopy::spec::internal {
namespace {

std::string aoiText(const Aabb& aoi) {
  std::ostringstream text;
  text << "[" << aoi.lo.x() << ", " << aoi.lo.y() << ", " << aoi.hi.x() << ", " << aoi.hi.y()
       << "]";
  return text.str();
}

void requireInside(const Field& field, const Vec2& p, const Aabb& aoi, const std::string& what) {
  if (!aoi.contains(p)) {
    std::ostringstream text;
    text << "expected " << what << " inside the AOI " << aoiText(aoi) << ", got (" << p.x() << ", "
         << p.y() << ")";
    field.fail(text.str());
  }
}

// Strictly increasing times, each a finite number.
void requireIncreasing(const std::vector<world::TimedPoint>& points,
                       const std::vector<Field>& times) {
  for (std::size_t i = 1; i < points.size(); ++i) {
    if (!(points[i].t > points[i - 1].t)) {
      std::ostringstream text;
      text << "expected a time greater than the previous point's (" << points[i - 1].t
           << " s): times must increase strictly, got " << points[i].t;
      times[i].fail(text.str());
    }
  }
}

// A recorded track from a CSV file the scenario names (spec/track_csv.h).
std::vector<world::TimedPoint> readTrackCsv(const Field& field) {
  const ReferencedFile file = readReferencedFile(field, "track file");
  try {
    return parseTrackCsv(file.text, file.shown);
  } catch (const ScenarioError& e) {
    field.fail(std::string("in the track file ") + e.what());
  }
}

double shortestLeg(const world::FootpathNetwork& network) {
  double shortest = 1e300;
  for (const auto& [a, b] : network.segments()) shortest = std::min(shortest, (b - a).norm());
  return shortest;
}

// A walk over a layout's footpath network (world/footpaths.h): the shortest route from "from" to
// "to", or without "to" a random walk drawn from "seed", at "speed".
std::vector<world::TimedPoint> readFootpathWalk(ObjectReader& reader, const Aabb& aoi,
                                                double duration, bool check_inside) {
  const Field layout = reader.required("footpaths");
  const world::FootpathNetwork network(readLayoutFootpaths(layout));
  if (network.edgeCount() == 0)
    layout.fail("expected footpaths with at least one segment of two distinct points");
  const Field from_field = reader.required("from");
  const Vec2 from = from_field.vec2();
  const double speed = reader.number("speed", 1.4, Bound::positive);
  if (speed > 1e3) reader.required("speed").fail("expected at most 1000 m/s");
  std::vector<world::TimedPoint> points;
  if (auto to_field = reader.optional("to")) {
    const Vec2 to = to_field->vec2();
    try {
      points = network.route(from, to, speed);
    } catch (const std::invalid_argument& e) {
      to_field->fail(std::string("expected a point the start's footpaths lead to: ") + e.what());
    }
  } else {
    const auto seed = static_cast<std::uint64_t>(reader.integer("seed", 1, 0, 2147483647));
    // At most 10⁶ legs: a network of legs far shorter than the walk is refused.
    const double legs = duration * speed / std::max(1e-9, shortestLeg(network));
    if (legs > 1e6) {
      from_field.fail("expected a walk of at most 10⁶ legs; the network's shortest segment makes "
                      "this one's up to " + std::to_string(legs));
    }
    points = network.randomWalk(from, speed, duration, seed, 0);
  }
  if (check_inside) {
    for (const world::TimedPoint& q : points)
      requireInside(from_field, q.p, aoi, "every point of the walk");
  }
  return points;
}

}  // namespace

world::Path readPath(const Field& field, const Aabb& aoi, double duration, bool check_inside,
                     std::vector<ScriptedAltitude>* altitudes) {
  ObjectReader reader = field.object();
  const std::string kind = reader.oneOf({"waypoints", "velocity", "track", "footpaths"});
  world::Path path;
  if (kind == "waypoints") {
    const Field list = reader.required("waypoints");
    std::vector<world::TimedPoint> points;
    std::vector<Field> times, positions;
    for (const Field& element : list.elements(1)) {
      ObjectReader waypoint = element.object();
      times.push_back(waypoint.required("t"));
      positions.push_back(waypoint.required("p"));
      points.push_back({times.back().number(Bound::non_negative), positions.back().vec2()});
      if (altitudes) {
        if (auto z = waypoint.optional("z"))
          altitudes->push_back({{points.back().t, z->number(Bound::positive)}, *z});
      }
      waypoint.finish();
    }
    requireIncreasing(points, times);
    if (check_inside) {
      for (std::size_t i = 0; i < points.size(); ++i)
        requireInside(positions[i], points[i].p, aoi, "a waypoint");
    }
    path = world::Path::throughPoints(std::move(points));
  } else if (kind == "velocity") {
    const Field start = reader.required("start");
    const Vec2 p0 = start.vec2();
    const Vec2 v = reader.required("velocity").vec2();
    if (check_inside) {
      requireInside(start, p0, aoi, "a start");
      requireInside(field, p0 + v * duration, aoi,
                    "the position at the end of the run (start + velocity · duration)");
    }
    path = world::Path::constantVelocity(p0, v);
  } else if (kind == "track") {
    const Field track = reader.required("track");
    std::vector<world::TimedPoint> points;
    if (track.json().is_string()) {
      points = readTrackCsv(track);
    } else {
      std::vector<Field> times;
      for (const Field& row : track.elements(1)) {
        const std::vector<Field> txy = row.elements(3, altitudes ? 4 : 3);  // [t, x, y(, z)]
        times.push_back(txy[0]);
        points.push_back(
            {txy[0].number(Bound::non_negative), Vec2(txy[1].number(), txy[2].number())});
        if (txy.size() == 4)
          altitudes->push_back({{points.back().t, txy[3].number(Bound::positive)}, txy[3]});
      }
      requireIncreasing(points, times);
    }
    if (check_inside) {
      for (const world::TimedPoint& q : points) requireInside(track, q.p, aoi, "every track point");
    }
    path = world::Path::throughPoints(std::move(points));
  } else if (kind == "footpaths") {
    path = world::Path::throughPoints(readFootpathWalk(reader, aoi, duration, check_inside));
  } else {
    field.fail(
        "expected a path: {\"waypoints\": [{\"t\": …, \"p\": [x, y]}, …]}, "
        "{\"start\": [x, y], \"velocity\": [vx, vy]}, {\"track\": \"file.csv\"} or "
        "{\"footpaths\": \"layout.json\", \"from\": [x, y], …}");
  }
  reader.finish();
  return path;
}

// A ground robot's forward camera: {"range": r, "angle": θ}, a sector of radius r opening θ about
// the heading.
void readSector(ObjectReader& robot, sensing::FootprintDef& footprint) {
  footprint.shape = sensing::FootprintShape::sector;
  footprint.radius = 25.0;      // m, default range
  footprint.angle = 0.5 * kPi;  // rad, default field of view (90°)
  auto fov_field = robot.optional("fov");
  if (!fov_field) {
    (*robot.field().out())["fov"] = Json{{"range", footprint.radius}, {"angle", footprint.angle}};
    return;
  }
  ObjectReader fov = fov_field->object();
  footprint.radius = fov.number("range", footprint.radius, Bound::positive);
  if (footprint.radius > 1e7) fov.required("range").fail("expected at most 1e7 m");
  footprint.angle = fov.number("angle", footprint.angle, Bound::positive);
  if (footprint.angle > kTwoPi) fov.required("angle").fail("expected at most 2π rad (a full turn)");
  fov.finish();
}

namespace {

// A UAV's downward camera footprint: {"size": [w, h]} or {"radius": r}.
void readFov(const Field& fov_field, sensing::FootprintDef& footprint) {
  ObjectReader fov = fov_field.object();
  const std::string kind = fov.oneOf({"size", "radius"});
  if (kind == "radius") {
    footprint.shape = sensing::FootprintShape::disc;
    footprint.radius = fov.required("radius").number(Bound::positive);
    if (footprint.radius > 1e7) fov.required("radius").fail("expected at most 1e7 m");
  } else if (kind == "size") {
    footprint.size = fov.required("size").vec2(Bound::positive);
    if (footprint.size.maxCoeff() > 2e7) fov.required("size").fail("expected at most 2e7 m a side");
  } else {
    fov_field.fail("expected {\"size\": [w, h]} or {\"radius\": r}");
  }
  fov.finish();
}

// Height (issue 53): a UAV whose scenario gives any of z, z_min, z_max, climb_rate or camera flies
// at a chosen altitude with a pinhole camera (sensing/camera.h); without them it keeps the fixed
// footprint and eq. 2, and none of these fields is written to the effective configuration.
// A scripted path's altitudes (its waypoints' z) make the UAV one at an altitude too: z defaults to
// the profile's at t = 0 and [z_min, z_max] to the span of z and the profile; a profile outside
// the limits given, or a changing one without a climb rate, is refused.
void readAltitude(ObjectReader& reader, UavSpec& uav, const std::vector<ScriptedAltitude>& path_z) {
  const bool any = reader.has("z") || reader.has("z_min") || reader.has("z_max") ||
                   reader.has("climb_rate") || reader.has("camera") || !path_z.empty();
  if (!any) return;
  constexpr double kMaxAltitude = 1e4;  // m: a footprint stays within the loader's 2e7 m
  world::UavDef& body = uav.body;
  const auto altitude = [&](const char* key, double fallback) {
    const double z = reader.number(key, fallback, Bound::positive);
    if (z > kMaxAltitude) reader.required(key).fail("expected at most 1e4 m");
    return z;
  };
  std::vector<world::TimedAltitude> points;
  for (const ScriptedAltitude& a : path_z) {
    if (a.point.z > kMaxAltitude) a.field.fail("expected at most 1e4 m");
    points.push_back(a.point);
  }
  std::optional<world::AltitudeProfile> profile;
  if (!points.empty()) profile.emplace(std::move(points));
  body.z = altitude("z", profile ? profile->altitudeAt(0.0) : sensing::kDefaultAltitude);
  double lowest = body.z, highest = body.z;
  for (const ScriptedAltitude& a : path_z) {
    lowest = std::min(lowest, a.point.z);
    highest = std::max(highest, a.point.z);
  }
  body.z_min = altitude("z_min", lowest);
  body.z_max = altitude("z_max", highest);
  if (body.z_min > body.z) reader.required("z_min").fail("expected z_min ≤ z");
  if (body.z_max < body.z) reader.required("z_max").fail("expected z_max ≥ z");
  body.climb_rate = reader.number("climb_rate", 2.0, Bound::non_negative);
  for (const ScriptedAltitude& a : path_z) {
    if (a.point.z < body.z_min || a.point.z > body.z_max) {
      std::ostringstream text;
      text << "expected an altitude within the UAV's [z_min, z_max] = [" << body.z_min << ", "
           << body.z_max << "] m, got " << a.point.z;
      a.field.fail(text.str());
    }
    if (body.climb_rate == 0.0 && a.point.z != body.z) {
      std::ostringstream text;
      text << "expected the UAV's altitude z = " << body.z
           << " m: its climb_rate is 0, so it cannot fly a path that changes altitude";
      a.field.fail(text.str());
    }
  }
  uav.altitude_profile = std::move(profile);
  if (uav.sensor.footprint.shape != sensing::FootprintShape::rectangle) {
    reader.required("fov").fail(
        "expected a rectangular footprint {\"size\": [w, h]} for a UAV at an altitude (its "
        "footprint at the default altitude of 20 m)");
  }
  // Its angles default to those that make fov.size its nadir footprint at the default altitude.
  sensing::CameraDef camera = sensing::cameraForFootprint(uav.sensor.footprint.size);
  if (auto camera_field = reader.optional("camera")) {
    ObjectReader fields = camera_field->object();
    const auto angle = [&](const char* key, double fallback) {
      const double a = fields.number(key, fallback, Bound::positive);
      if (a >= kPi) fields.required(key).fail("expected a field of view below π rad (180°)");
      return a;
    };
    const double hfov = angle("hfov", camera.fov_across);
    const double vfov = angle("vfov", camera.fov_along);
    const double pitch = fields.number("pitch", 0.0, Bound::non_negative);
    if (pitch + 0.5 * vfov > sensing::kMaxFarEdgeAngle) {
      fields.required("pitch").fail(
          "expected pitch + vfov/2 ≤ 80° (1.396 rad): the footprint's far edge must meet the "
          "ground within 5.7 altitudes");
    }
    fields.finish();
    // Angles equal to the defaults (as the effective configuration writes them back) keep the
    // camera made from fov.size, so that a run read back from its manifest has the same bits.
    if (hfov != camera.fov_across || vfov != camera.fov_along || pitch != 0.0)
      camera = sensing::cameraWithAngles(vfov, hfov, pitch);
  }
  uav.sensor.camera = camera;
}

}  // namespace

void readUavs(ObjectReader& root, ScenarioSpec& spec) {
  const Field list = root.required("uavs");
  std::set<std::string> names;
  const std::vector<Field> elements = list.elements(1, kMaxUavs);
  for (std::size_t i = 0; i < elements.size(); ++i) {
    ObjectReader reader = elements[i].object();
    UavSpec uav;
    uav.name = reader.string("name", "uav" + std::to_string(i + 1));
    if (!names.insert(uav.name).second) {
      reader.required("name").fail("expected a unique UAV name, got \"" + uav.name + "\" twice");
    }
    uav.body.kind = reader.enumeration("kind", world::kAgentKindNames, uav.body.kind);
    const bool ground = uav.body.kind == world::AgentKind::ground;
    std::vector<ScriptedAltitude> path_z;  // a UAV's waypoints may give altitudes (issue 53)
    reader.attempt([&] {
      if (auto path = reader.optional("path"))
        uav.path = readPath(*path, spec.aoi, spec.duration, true, ground ? nullptr : &path_z);
    });
    reader.attempt([&] {
      if (auto start = reader.optional("start")) {
        uav.body.start = start->vec2();
        requireInside(*start, uav.body.start, spec.aoi, "a start");
      } else if (uav.path) {
        uav.body.start = uav.path->positionAt(0.0);
      } else {
        reader.required("start");
      }
    });
    reader.attempt([&] {
      if (auto yaw = reader.optional("yaw"); yaw && yaw->json().is_string()) {
        yaw->choice({"velocity"});
        uav.body.yaw_mode = world::YawMode::velocity;
      } else if (yaw) {
        uav.body.yaw = yaw->number();
      } else {
        reader.number("yaw", 0.0);
      }
    });
    if (ground) {  // its heading is its body's: it always faces the way it drives
      uav.body.yaw_mode = world::YawMode::velocity;
      uav.body.turn_rate = reader.number("turn_rate", uav.body.turn_rate, Bound::positive);
    }
    uav.body.v_max = reader.number("v_max", uav.body.v_max, Bound::positive);
    // A robot has a body by default; UAVs pass over one another unless given one (the paper's
    // scenarios have them cross: docs/design-notes.md).
    uav.body.radius = reader.number("radius", ground ? 0.5 : 0.0, Bound::non_negative);
    if (uav.body.radius > world::kMaxAgentRadius) {
      reader.required("radius").fail("expected at most 100 m");
    } else if (uav.body.radius > 0.0 && uav.body.radius < world::kMinAgentRadius) {
      // world/defs.h: Box2D's skin; a smaller body's mass overflows and its position turns NaN.
      reader.required("radius").fail(
          "expected 0 (no body) or at least 0.01 m (Box2D's b2_polygonRadius; a smaller body "
          "cannot be simulated), got " +
          describe(reader.required("radius").json()));
    }

    uav.sensor.ground_level = ground;
    if (ground) {
      readSector(reader, uav.sensor.footprint);
    } else if (auto fov_field = reader.optional("fov")) {
      reader.attempt([&] { readFov(*fov_field, uav.sensor.footprint); });
    } else {
      const Vec2& size = uav.sensor.footprint.size;  // sensing/footprint.h's default
      (*reader.field().out())["fov"] = Json{{"size", {size.x(), size.y()}}};
    }
    uav.sensor.quality.alpha = reader.number("quality", uav.sensor.quality.alpha, Bound::positive);
    uav.sensor.quality.r0 = reader.number("r0", uav.sensor.quality.r0, Bound::positive);
    if (!ground) reader.attempt([&] { readAltitude(reader, uav, path_z); });
    reader.finish();
    spec.uavs.push_back(std::move(uav));
  }
}

std::vector<std::string> readTargets(ObjectReader& root, ScenarioSpec& spec) {
  std::vector<std::string> labels;
  const auto list = root.optional("targets");
  if (!list) {
    (*root.field().out())["targets"] = Json::array();
    return labels;
  }
  std::set<std::string> names;
  const std::vector<Field> elements = list->elements(0, kMaxTargets);
  ProgressCounter progress("reading targets", static_cast<double>(elements.size()), 1024);
  for (std::size_t i = 0; i < elements.size(); ++i) {
    progress.add();
    ObjectReader reader = elements[i].object();
    TargetSpec target;
    target.name = reader.string("name", "T" + std::to_string(i + 1));
    if (!names.insert(target.name).second) {
      reader.required("name").fail("expected a unique target name, got \"" + target.name +
                                   "\" twice");
    }
    const std::string label = reader.string("label", "human");
    if (label == "tree" || label.empty()) {
      reader.required("label").fail(
          "expected a target label other than \"tree\" (reserved for "
          "occluders) and not empty");
    }
    reader.attempt(
        [&] { target.path = readPath(reader.required("path"), spec.aoi, spec.duration, true); });
    reader.finish();
    labels.push_back(label);
    spec.targets.push_back(std::move(target));
  }
  return labels;
}

int uavIndex(const Field& field, const ScenarioSpec& spec) {
  if (field.json().is_string()) {
    const std::string name = field.string();
    for (std::size_t i = 0; i < spec.uavs.size(); ++i) {
      if (spec.uavs[i].name == name) return static_cast<int>(i);
    }
    field.fail("expected the name of a UAV, got \"" + name + "\"");
  }
  return field.integer(0, static_cast<int>(spec.uavs.size()) - 1);
}

int targetIndex(const Field& field, const ScenarioSpec& spec) {
  if (field.json().is_string()) {
    const std::string name = field.string();
    for (std::size_t t = 0; t < spec.targets.size(); ++t) {
      if (spec.targets[t].name == name) return static_cast<int>(t);
    }
    field.fail("expected the name of a target, got \"" + name + "\"");
  }
  return field.integer(0, static_cast<int>(spec.targets.size()) - 1);
}

}  // namespace canopy::spec::internal
