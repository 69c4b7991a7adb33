#include "sim/record_line.h"

namespace canopy::sim {
namespace {

// Keys are written in the order dump() of a std::map-backed object gives: sorted by byte.

void vec(JsonLine& j, const Vec2& v) {
  j.beginArray();
  j.number(v.x());
  j.number(v.y());
  j.endArray();
}
void sym(JsonLine& j, const Mat2& m) {  // upper triangle
  j.beginArray();
  j.number(m(0, 0));
  j.number(m(0, 1));
  j.number(m(1, 1));
  j.endArray();
}
template <typename Vector>
void values(JsonLine& j, const Vector& x) {
  j.beginArray();
  for (int r = 0; r < x.size(); ++r) j.number(x(r));
  j.endArray();
}
template <typename Matrix>
void upperTriangle(JsonLine& j, const Matrix& P) {  // row by row: P00, P01, …, P0n, P11, …
  j.beginArray();
  for (int r = 0; r < P.rows(); ++r) {
    for (int c = r; c < P.cols(); ++c) j.number(P(r, c));
  }
  j.endArray();
}
void key(JsonLine& j, const agents::TrackKey& k) {
  j.beginArray();
  j.integer(k.origin);
  j.integer(k.serial);
  j.endArray();
}
void integers(JsonLine& j, const std::vector<int>& list) {
  j.beginArray();
  for (int i : list) j.integer(i);
  j.endArray();
}
// A body touched, as the record names it: "trunk:K" or "wall:K" (the occluder's index among the
// scenario's trees), "uav:I" (the agent's index), with the quotes of a JSON string.
std::string contactName(const world::BodyRef& c) {
  const char* kind = c.kind == world::BodyKind::trunk  ? "trunk"
                     : c.kind == world::BodyKind::wall ? "wall"
                     : c.kind == world::BodyKind::uav  ? "uav"
                     : c.kind == world::BodyKind::tree ? "tree"
                                                       : "target";
  return "\"" + std::string(kind) + ":" + std::to_string(c.index) + "\"";
}
void velocities(JsonLine& j, const agents::planning::Plan& plan) {
  j.beginArray();
  for (const Vec2& v : plan.velocities) vec(j, v);
  j.endArray();
}

}  // namespace

void RecordLineWriter::belief(JsonLine& j, const agents::AgentBelief& belief) {
  j.beginObject();
  j.key("map");
  j.beginArray();
  for (const agents::TreeEstimate& t : belief.trees) {
    j.beginObject();
    j.key("P");
    upperTriangle(j, t.belief.P);
    j.key("key");
    key(j, t.key);
    if (t.outline.vertices > 0) {  // a polygonal crown or wall: its vertex offsets
      j.key("outline");
      j.beginArray();
      for (int v = 0; v < t.outline.vertices; ++v) vec(j, t.outline.offsets[v]);
      j.endArray();
    }
    j.key("x");
    values(j, t.belief.x);
    j.endObject();
  }
  j.endArray();
  j.key("planned_path");
  j.beginArray();
  for (const Vec2& p : belief.planned_path) vec(j, p);
  j.endArray();
  j.key("tracks");
  j.beginArray();
  for (const agents::TrackEstimate& t : belief.tracks) {
    j.beginObject();
    j.key("P");
    upperTriangle(j, t.belief.P);
    j.key("existence");
    j.number(t.existence);
    j.key("key");
    key(j, t.key);
    j.key("label");
    j.escapedString(label(t.label));
    j.key("x");
    values(j, t.belief.x);
    j.endObject();
  }
  j.endArray();
  j.endObject();
}

void RecordLineWriter::scan(JsonLine& j, const sensing::Scan& scan) {
  j.beginObject();
  j.key("in_footprint");
  integers(j, scan.in_footprint);
  j.key("obs");
  j.beginArray();
  for (const sensing::Observation& o : scan.observations) {
    j.beginObject();
    j.key("R");
    sym(j, o.R);
    j.key("label");
    j.escapedString(label(o.label));
    if (o.label == sensing::kTreeLabel) {
      j.key("radius");
      j.number(o.radius);
    }
    j.key("truth");
    j.integer(o.truth);
    j.key("z");
    vec(j, o.z);
    j.endObject();
  }
  j.endArray();
  j.key("uav");
  j.integer(scan.uav);
  j.key("visible");
  integers(j, scan.visible);
  j.endObject();
}

namespace {

void plan(JsonLine& j, const agents::planning::TeamPlan& plan) {
  j.beginObject();
  j.key("agents");
  j.beginArray();
  for (const auto& report : plan.reports) {
    j.beginObject();
    j.key("agent");
    j.integer(report.agent);
    j.key("cost");
    j.number(report.cost);
    j.key("evaluations");
    j.integer(report.evaluations);
    j.key("iterations");
    j.integer(report.iterations);
    j.key("joint_epoch");
    integers(j, report.joint_epoch);
    j.key("velocities");
    velocities(j, report.plan);
    j.endObject();
  }
  j.endArray();
  j.key("epoch");
  j.integer(plan.epoch);
  j.key("messages");
  j.beginArray();
  for (const auto& m : plan.messages) {
    j.beginObject();
    j.key("agent");
    j.integer(m.agent);
    j.key("epoch");
    j.integer(m.epoch);
    j.key("from");
    j.integer(m.from);
    j.key("velocities");
    velocities(j, m.plan);
    j.endObject();
  }
  j.endArray();
  j.endObject();
}

}  // namespace

void RecordLineWriter::write(const StepRecord& record, std::string& out) {
  JsonLine j(out, &numbers_);
  j.beginObject();
  j.key("agents");
  j.beginArray();
  for (const agents::AgentBelief& b : record.beliefs) belief(j, b);
  j.endArray();
  j.key("k");
  j.integer(record.step);
  if (record.plan) {
    j.key("plan");
    plan(j, *record.plan);
  }
  j.key("scans");
  j.beginArray();
  for (const UavRecord& uav : record.uavs) scan(j, uav.scan);
  j.endArray();
  j.key("t");
  j.number(record.time);
  j.key("targets");
  j.beginArray();
  for (const TargetRecord& target : record.targets) {
    j.beginObject();
    j.key("p");
    vec(j, target.position);
    j.key("v");
    vec(j, target.velocity);
    j.endObject();
  }
  j.endArray();
  j.key("uavs");
  j.beginArray();
  for (const UavRecord& uav : record.uavs) {
    j.beginObject();
    j.key("cmd");
    vec(j, uav.command);
    if (!uav.contacts.empty()) {  // what its body touched over the step: "wall:3", "uav:1", …
      j.key("contacts");
      j.beginArray();
      for (const world::BodyRef& c : uav.contacts) j.escapedString(contactName(c));
      j.endArray();
    }
    j.key("p");
    vec(j, uav.position);
    j.key("v");
    vec(j, uav.velocity);
    j.key("yaw");
    j.number(uav.yaw);
    if (uav.altitude) {  // a UAV at a chosen altitude (issue 53)
      j.key("z");
      j.number(uav.z);
    }
    j.endObject();
  }
  j.endArray();
  j.endObject();
}

std::string recordLine(const std::vector<std::string>& labels, const StepRecord& record) {
  RecordLineWriter writer(labels);
  std::string line;
  writer.write(record, line);
  return line;
}

}  // namespace canopy::sim
