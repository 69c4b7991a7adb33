#include "replay/replay_data.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <tuple>

#include "analysis/behaviours.h"
#include "core/enum_names.h"
#include "render/colour.h"
#include "replay/columns.h"
#include "replay/packed_json.h"
#include "replay/replay_changes.h"
#include "sensing/visibility.h"

namespace canopy::replay {
namespace {

constexpr double kAssociationCutoff = 50.0;  // m, the OSPA cut-off c of summary.json
constexpr double kCentimetres = 100.0;       // fixedPoint's scale: m → cm
constexpr double kMilliradians = 1000.0;     // rad → mrad

std::string hexColour(int agent) {
  const render::Rgba c = render::uavColour(agent);
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", c.r, c.g, c.b);
  return buffer;
}

void writeModel(const RunFolder& run, Writer& w, Columns& columns) {
  const spec::ScenarioSpec& spec = run.spec;
  w.raw("\"format\":3,\"scenario\":");
  w.string(spec.name);
  w.raw(",\"seed\":");
  w.integer(static_cast<long long>(spec.seed));
  w.raw(",\"dt\":");
  w.significant(spec.dt);
  w.raw(",\"steps\":");
  w.integer(static_cast<long long>(run.steps.size()));
  const bool plans = spec.planner.algorithm != agents::PlannerAlgorithm::none;
  w.raw(",\"plan_steps\":");
  w.integer(std::max(1L, std::lround(spec.planner.plan_period / spec.dt)));
  w.raw(",\"plans\":");
  w.raw(plans ? "true" : "false");
  w.raw(",\"algorithm\":");
  w.string(std::string(nameOf(agents::kPlannerAlgorithmNames, spec.planner.algorithm)));
  w.raw(",\"aoi\":[");
  bool first = true;
  for (double x : {spec.aoi.lo.x(), spec.aoi.lo.y(), spec.aoi.hi.x(), spec.aoi.hi.y()}) {
    w.comma(first);
    w.position(x);
  }
  w.raw("],\"occlusion_model\":");
  w.string(std::string(nameOf(sensing::kOcclusionModelNames, spec.sensing.occlusion_model)));
  w.raw(",\"comm_range\":");
  if (std::isfinite(spec.fusion.comm_range)) {
    w.significant(spec.fusion.comm_range);
  } else {
    w.raw("null");
  }
  w.raw(",\"comm_latency\":");
  w.integer(spec.fusion.comm_latency);
  w.raw(",\"comm_drop\":");
  w.significant(spec.fusion.comm_drop);
  w.raw(",\"m\":");
  w.integer(spec.analysis.m);
  w.raw(",\"agents\":[");
  first = true;
  for (std::size_t i = 0; i < spec.uavs.size(); ++i) {
    const spec::UavSpec& uav = spec.uavs[i];
    // A UAV at a chosen altitude (issue 53): its footprint at its start altitude.
    const sensing::FootprintDef f = sensing::footprintAt(uav.sensor, uav.body.z);
    w.comma(first);
    w.raw("{\"name\":");
    w.string(uav.name);
    w.raw(",\"kind\":");
    w.string(std::string(nameOf(world::kAgentKindNames, uav.body.kind)));
    w.raw(",\"colour\":");
    w.string(hexColour(static_cast<int>(i)));
    if (uav.sensor.camera) {  // its start altitude, the footprint's (altitude.js scales it)
      w.raw(",\"z\":");
      w.position(uav.body.z);
    }
    w.raw(",\"los\":");
    w.raw(sensing::occlusionModel(uav.sensor, spec.sensing) ==
                  sensing::OcclusionModel::line_of_sight
              ? "true"
              : "false");
    w.raw(",\"footprint\":");
    if (f.shape == sensing::FootprintShape::rectangle) {
      w.raw("{\"shape\":\"rectangle\",\"size\":[");
      w.position(f.size.x());
      w.raw(",");
      w.position(f.size.y());
      w.raw("]}");
    } else if (f.shape == sensing::FootprintShape::quad) {  // a pitched camera's trapezoid
      w.raw("{\"shape\":\"quad\",\"radius\":");
      w.position(sensing::circumradius(f));
      w.raw(",\"corners\":[");
      for (std::size_t c = 0; c < f.corners.size(); ++c) {
        w.raw(c == 0 ? "[" : ",[");
        w.position(f.corners[c].x());
        w.raw(",");
        w.position(f.corners[c].y());
        w.raw("]");
      }
      w.raw("]}");
    } else {
      w.raw(f.shape == sensing::FootprintShape::disc ? "{\"shape\":\"disc\",\"radius\":"
                                                     : "{\"shape\":\"sector\",\"radius\":");
      w.position(f.radius);
      if (f.shape == sensing::FootprintShape::sector) {
        w.raw(",\"angle\":");
        w.significant(f.angle);
      }
      w.raw("}");
    }
    w.raw("}");
  }
  w.raw("],\"targets\":[");
  first = true;
  for (const spec::TargetSpec& target : spec.targets) {
    w.comma(first);
    w.raw("{\"name\":");
    w.string(target.name);
    w.raw(",\"label\":");
    w.string(spec.labels.at(static_cast<std::size_t>(target.label)));
    w.raw("}");
  }
  // The crowns (discs): centre and radius in cm, a column each.
  std::vector<std::int32_t> tx, ty, tr;
  for (const world::TreeDef& tree : spec.trees) {
    if (tree.shape != world::TreeShape::disc) continue;
    tx.push_back(fixedPoint(tree.centre.x(), kCentimetres));
    ty.push_back(fixedPoint(tree.centre.y(), kCentimetres));
    tr.push_back(fixedPoint(tree.radius, kCentimetres));
  }
  columns.int32("tree_x", tx);
  columns.int32("tree_y", ty);
  columns.int32("tree_r", tr);
  w.raw("],\"polygons\":[");
  first = true;
  for (const world::TreeDef& tree : spec.trees) {
    if (tree.shape != world::TreeShape::polygon) continue;
    w.comma(first);
    w.raw("[");
    bool first_vertex = true;
    for (const Vec2& v : tree.vertices) {
      w.comma(first_vertex);
      w.position(v.x());
      w.raw(",");
      w.position(v.y());
    }
    w.raw("]");
  }
  w.raw("]");
}

// Poses and positions over time, per agent or person (its whole run, then the next one's), in
// cm and mrad, each value after the first stored as the change since the step before.
void writeTruth(const RunFolder& run, Writer& w, Columns& c) {
  const std::size_t S = run.steps.size(), A = run.spec.uavs.size(), T = run.spec.targets.size();
  std::vector<std::int32_t> x(S * A), y(S * A), yaw(S * A);
  for (std::size_t k = 0; k < S; ++k) {
    for (std::size_t i = 0; i < A; ++i) {
      const RecordedAgent& a = run.steps[k].agents[i];
      x[i * S + k] = fixedPoint(a.position.x(), kCentimetres);
      y[i * S + k] = fixedPoint(a.position.y(), kCentimetres);
      yaw[i * S + k] = fixedPoint(a.yaw, kMilliradians);
    }
  }
  c.int32("uav_x", x, S);
  c.int32("uav_y", y, S);
  c.int32("uav_yaw", yaw, S);
  // Altitudes in cm, only when some UAV has one (issue 53; kMissing for the others).
  bool altitudes = false;
  for (std::size_t k = 0; k < S && !altitudes; ++k)
    for (std::size_t i = 0; i < A; ++i) altitudes = altitudes || std::isfinite(run.steps[k].agents[i].z);
  if (altitudes) {
    std::vector<std::int32_t> z(S * A);
    for (std::size_t k = 0; k < S; ++k)
      for (std::size_t i = 0; i < A; ++i)
        z[i * S + k] = fixedPoint(run.steps[k].agents[i].z, kCentimetres);
    c.int32("uav_z", z, S);
  }
  x.assign(S * T, 0);
  y.assign(S * T, 0);
  for (std::size_t k = 0; k < S; ++k) {
    for (std::size_t t = 0; t < T; ++t) {
      const Vec2& p = run.steps[k].targets[t];
      x[t * S + k] = fixedPoint(p.x(), kCentimetres);
      y[t * S + k] = fixedPoint(p.y(), kCentimetres);
    }
  }
  c.int32("target_x", x, S);
  c.int32("target_y", y, S);
  // Contacts, at the steps that have any: [k, agent, "wall:3", …].
  w.raw(",\"contacts\":[");
  bool first = true;
  for (std::size_t k = 0; k < run.steps.size(); ++k) {
    const std::vector<RecordedAgent>& agents = run.steps[k].agents;
    for (std::size_t i = 0; i < agents.size(); ++i) {
      if (agents[i].contacts.empty()) continue;
      w.comma(first);
      w.raw("[");
      w.integer(static_cast<long long>(k));
      w.raw(",");
      w.integer(static_cast<long long>(i));
      for (const std::string& contact : agents[i].contacts) {
        w.raw(",");
        w.string(contact);
      }
      w.raw("]");
    }
  }
  w.raw("]");
}

void writeIndexLists(const std::vector<std::vector<std::vector<int>>>& lists, Writer& w) {
  w.raw("[");
  bool first_step = true;
  for (const auto& per_agent : lists) {
    w.comma(first_step);
    w.raw("[");
    bool first_agent = true;
    for (const std::vector<int>& list : per_agent) {
      w.comma(first_agent);
      w.raw("[");
      bool first = true;
      for (int t : list) {
        w.comma(first);
        w.integer(t);
      }
      w.raw("]");
    }
    w.raw("]");
  }
  w.raw("]");
}

// Scans and m-Ownership (analysis/behaviours.h on the recorded visible sets).
void writeSensing(const RunFolder& run, Writer& w) {
  const std::size_t agents = run.spec.uavs.size();
  std::vector<std::vector<std::vector<int>>> in_fp, visible, owned;
  analysis::SetHistory sets;
  for (const RecordedStep& s : run.steps) {
    auto& f = in_fp.emplace_back();
    auto& v = visible.emplace_back();
    auto& bits = sets.emplace_back();
    for (const RecordedAgent& a : s.agents) {
      f.push_back(a.in_footprint);
      v.push_back(a.visible);
      analysis::TargetSet set = 0;
      for (int t : a.visible) {
        if (t < analysis::kMaxAnalysedTargets) set |= analysis::bit(t);
      }
      bits.push_back(set);
    }
  }
  w.raw(",\"in_footprint\":");
  writeIndexLists(in_fp, w);
  w.raw(",\"visible\":");
  writeIndexLists(visible, w);
  w.raw(",\"owned\":");
  if (run.spec.targets.size() > static_cast<std::size_t>(analysis::kMaxAnalysedTargets)) {
    w.raw("null");
  } else {
    const analysis::SetHistory M = analysis::mOwnership(sets, run.spec.analysis.m);
    for (const auto& per_agent : M) {
      auto& o = owned.emplace_back();
      for (std::size_t i = 0; i < agents; ++i) {
        std::vector<int>& list = o.emplace_back();
        for (int t = 0; t < static_cast<int>(run.spec.targets.size()); ++t) {
          if (per_agent[i] & analysis::bit(t)) list.push_back(t);
        }
      }
    }
    writeIndexLists(owned, w);
  }
  w.raw(",\"ospa\":[");
  bool first = true;
  for (const std::vector<double>& values : run.ospa) {
    w.comma(first);
    w.raw("[");
    bool first_value = true;
    for (double x : values) {
      w.comma(first_value);
      w.significant(x);
    }
    w.raw("]");
  }
  w.raw("]");
}

// Per step, agent and target: the index of the agent's track that stands for the target — pairs
// of the same label taken greedily, nearest first, up to the OSPA cut-off — or −1.
std::vector<int> associate(const RecordedStep& s, const RecordedAgent& a,
                           const spec::ScenarioSpec& spec) {
  struct Pair {
    double d;
    int target, track;
  };
  std::vector<Pair> pairs;
  for (int t = 0; t < static_cast<int>(s.targets.size()); ++t) {
    const std::string& label =
        spec.labels.at(static_cast<std::size_t>(spec.targets[static_cast<std::size_t>(t)].label));
    for (int j = 0; j < static_cast<int>(a.tracks.size()); ++j) {
      const RecordedTrack& track = a.tracks[static_cast<std::size_t>(j)];
      const double d = (track.position - s.targets[static_cast<std::size_t>(t)]).norm();
      if (track.label == label && d <= kAssociationCutoff) pairs.push_back({d, t, j});
    }
  }
  std::sort(pairs.begin(), pairs.end(), [](const Pair& x, const Pair& y) {
    return std::tie(x.d, x.target, x.track) < std::tie(y.d, y.target, y.track);
  });
  std::vector<int> of_target(s.targets.size(), -1);
  std::vector<bool> taken(a.tracks.size(), false);
  for (const Pair& p : pairs) {
    if (of_target[static_cast<std::size_t>(p.target)] >= 0 ||
        taken[static_cast<std::size_t>(p.track)])
      continue;
    of_target[static_cast<std::size_t>(p.target)] = p.track;
    taken[static_cast<std::size_t>(p.track)] = true;
  }
  return of_target;
}

// The tracks of every agent at every step, in order (step, agent, track): how many each agent
// holds at each step, then a column per field (key and label as indices into the tables; the
// person the track stands for, associate()'s pairing, or -1; position and velocity in cm and
// cm/s; the covariance's position block as Float32s).
void writeTracks(const RunFolder& run, Table& keys, Table& labels, Columns& c) {
  std::vector<std::int32_t> count, key, label, target, x, y, vx, vy;
  std::vector<float> pxx, pxy, pyy;
  for (const RecordedStep& s : run.steps) {
    for (const RecordedAgent& a : s.agents) {
      count.push_back(static_cast<std::int32_t>(a.tracks.size()));
      std::vector<std::int32_t> of_track(a.tracks.size(), -1);
      const std::vector<int> of_target = associate(s, a, run.spec);
      for (std::size_t t = 0; t < of_target.size(); ++t) {
        if (of_target[t] >= 0)
          of_track[static_cast<std::size_t>(of_target[t])] = static_cast<std::int32_t>(t);
      }
      for (std::size_t j = 0; j < a.tracks.size(); ++j) {
        const RecordedTrack& t = a.tracks[j];
        key.push_back(keys.index(t.key));
        label.push_back(labels.index(t.label));
        target.push_back(of_track[j]);
        x.push_back(fixedPoint(t.position.x(), kCentimetres));
        y.push_back(fixedPoint(t.position.y(), kCentimetres));
        vx.push_back(fixedPoint(t.velocity.x(), kCentimetres));
        vy.push_back(fixedPoint(t.velocity.y(), kCentimetres));
        pxx.push_back(significantFloat(t.P_pos.x()));
        pxy.push_back(significantFloat(t.P_pos.y()));
        pyy.push_back(significantFloat(t.P_pos.z()));
      }
    }
  }
  c.int32("track_count", count);
  c.int32("track_key", key);
  c.int32("track_label", label);
  c.int32("track_target", target);
  c.int32("track_x", x);
  c.int32("track_y", y);
  c.int32("track_vx", vx);
  c.int32("track_vy", vy);
  c.float32("track_pxx", pxx);
  c.float32("track_pxy", pxy);
  c.float32("track_pyy", pyy);
}

void writeTable(const char* name, const Table& table, Writer& w) {
  w.raw(",\"");
  w.raw(name);
  w.raw("\":[");
  bool first = true;
  for (const std::string& s : table.names()) {
    w.comma(first);
    w.string(s);
  }
  w.raw("]");
}

}  // namespace

std::string replayData(const RunFolder& run) {
  Writer w;
  Columns c;
  w.raw("{");
  writeModel(run, w, c);
  writeTruth(run, w, c);
  writeSensing(run, w);
  Table keys, labels;
  writeTracks(run, keys, labels, c);
  writeMaps(run, keys, c);
  writePlans(run, c);
  writeTable("keys", keys, w);
  writeTable("labels", labels, w);
  c.describe(w);
  w.raw("}");
  // The header's length (4 bytes, little-endian), the header, spaces to a multiple of 4 bytes
  // (so that every column starts 4-byte aligned), the columns.
  std::string header = std::move(w.text);
  while ((4 + header.size()) % 4 != 0) header += ' ';
  std::string out;
  const auto n = static_cast<std::uint32_t>(header.size());
  for (int shift = 0; shift < 32; shift += 8) out += static_cast<char>(n >> shift & 0xffu);
  out += header;
  out += c.bytes();
  return out;
}

}  // namespace canopy::replay
