#include "sim/step_columns.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <utility>

#include "sim/json_line.h"
#include "sim/step_values.h"

namespace canopy::sim {
namespace {

// The entry of `previous` with `key`: first the one after the last found (lists kept in key order
// find every entry there), else by a sorted index of the list built on the first miss.
template <typename Entry>
class PreviousEntries {
 public:
  explicit PreviousEntries(const std::vector<Entry>* previous) : previous_(previous) {}
  int find(const agents::TrackKey& key) {
    if (previous_ == nullptr) return -1;
    const std::vector<Entry>& p = *previous_;
    if (guess_ < p.size() && p[guess_].key == key) return found(guess_);
    if (sorted_.empty() && !p.empty()) {
      for (std::size_t j = 0; j < p.size(); ++j) sorted_.emplace_back(p[j].key, j);
      std::sort(sorted_.begin(), sorted_.end());
    }
    const auto it = std::lower_bound(sorted_.begin(), sorted_.end(),
                                     std::pair<agents::TrackKey, std::size_t>{key, 0});
    if (it == sorted_.end() || !(it->first == key)) return -1;
    return found(it->second);
  }

 private:
  int found(std::size_t j) {
    guess_ = j + 1;
    return static_cast<int>(j);
  }
  const std::vector<Entry>* previous_;
  std::size_t guess_ = 0;
  std::vector<std::pair<agents::TrackKey, std::size_t>> sorted_;
};

}  // namespace

void StepColumnEncoder::label(sensing::LabelId id) {
  const std::string& name = labels_.at(static_cast<std::size_t>(id));  // out_of_range if not one
  const auto at = static_cast<std::size_t>(id);
  if (!written_[at]) {  // as the line writer does: a label dump() refuses fails the run here
    JsonLine::escaped(name);
    written_[at] = true;
  }
  columns_[kStructureColumn].i(id);
}

std::size_t StepColumnEncoder::bytes() const {
  std::size_t n = 0;
  for (const ColumnOut& c : columns_) n += c.size();
  return n;
}

void StepColumnEncoder::add(const StepRecord& record) {
  truth(record);
  ColumnOut& s = columns_[kStructureColumn];
  s.u(record.beliefs.size());
  for (std::size_t i = 0; i < record.beliefs.size(); ++i)
    belief(static_cast<int>(i), record.beliefs[i]);
  scans(record);
  plans(record);
  extras_.encode(extras_.schema().step, record, s);
  previous_ = record.beliefs;
  previous_agents_ = previous_.size();
  ++steps_;
}

// References (structure column): 0 a new entry (its key, label or outline size, then its values
// whole); 2j + 1 the same as entry j of the step before; 2j + 2 entry j's key with changed values
// (a track's label, then its values XORed with entry j's).
void StepColumnEncoder::belief(int agent, const agents::AgentBelief& b) {
  ColumnOut& s = columns_[kStructureColumn];
  const agents::AgentBelief* before = static_cast<std::size_t>(agent) < previous_agents_
                                          ? &previous_[static_cast<std::size_t>(agent)]
                                          : nullptr;
  ColumnOut& map = columns_[kMapColumn];
  s.u(b.trees.size());
  PreviousEntries<agents::TreeEstimate> trees(before ? &before->trees : nullptr);
  const RecordSchema& schema = extras_.schema();
  const bool map_extras = !schema.map.generic().empty();
  const bool track_extras = !schema.tracks.generic().empty();
  TreeValues v{}, w{};
  for (const agents::TreeEstimate& t : b.trees) {
    const int n = gather(t, v);
    const int j = trees.find(t.key);
    const auto ref = static_cast<std::uint64_t>(j);
    const std::string extra = map_extras ? extras_.text(schema.map, t) : std::string();
    if (j >= 0 && gather(before->trees[ref], w) == n) {
      if (sameBits(v, w, n) &&
          (!map_extras || extra == extras_.text(schema.map, before->trees[ref]))) {
        s.u(2 * ref + 1);
        continue;
      }
      s.u(2 * ref + 2);
      for (int k = 0; k < n; ++k)
        map.dx(v[static_cast<std::size_t>(k)], w[static_cast<std::size_t>(k)]);
      s.bytes() += extra;
      continue;
    }
    s.u(0);
    s.i(t.key.origin);
    s.i(t.key.serial);
    s.u(static_cast<std::uint64_t>(t.outline.vertices));
    for (int k = 0; k < n; ++k) map.d(v[static_cast<std::size_t>(k)]);
    s.bytes() += extra;
  }
  ColumnOut& plan = columns_[kPlanColumn];
  s.u(b.planned_path.size());
  for (const Vec2& p : b.planned_path) {
    plan.d(p.x());
    plan.d(p.y());
  }
  ColumnOut& track = columns_[kTrackColumn];
  s.u(b.tracks.size());
  PreviousEntries<agents::TrackEstimate> tracks(before ? &before->tracks : nullptr);
  TrackValues x{}, y{};
  for (const agents::TrackEstimate& t : b.tracks) {
    gather(t, x);
    const int j = tracks.find(t.key);
    const auto ref = static_cast<std::uint64_t>(j);
    const std::string extra = track_extras ? extras_.text(schema.tracks, t) : std::string();
    if (j >= 0) {
      const agents::TrackEstimate& was = before->tracks[ref];
      gather(was, y);
      if (was.label == t.label && sameBits(x, y, kTrackValues) &&
          (!track_extras || extra == extras_.text(schema.tracks, was))) {
        s.u(2 * ref + 1);
        continue;
      }
      s.u(2 * ref + 2);
      label(t.label);
      for (std::size_t k = 0; k < x.size(); ++k) track.dx(x[k], y[k]);
      s.bytes() += extra;
      continue;
    }
    s.u(0);
    s.i(t.key.origin);
    s.i(t.key.serial);
    label(t.label);
    for (const double value : x) track.d(value);
    s.bytes() += extra;
  }
  extras_.encode(schema.agents, b, s);
}

void StepColumnEncoder::truth(const StepRecord& record) {
  ColumnOut& s = columns_[kStructureColumn];
  ColumnOut& c = columns_[kTruthColumn];
  s.i(record.step);
  c.d(record.time);
  s.u(record.targets.size());
  targets_.resize(record.targets.size(), std::array<double, 4>{});
  for (std::size_t i = 0; i < record.targets.size(); ++i) {
    const TargetRecord& t = record.targets[i];
    const std::array<double, 4> now{t.position.x(), t.position.y(), t.velocity.x(), t.velocity.y()};
    for (std::size_t k = 0; k < now.size(); ++k) c.dx(now[k], targets_[i][k]);
    targets_[i] = now;
    extras_.encode(extras_.schema().targets, t, s);
  }
  s.u(record.uavs.size());
  uavs_.resize(record.uavs.size(), std::array<double, 8>{});
  for (std::size_t i = 0; i < record.uavs.size(); ++i) {
    const UavRecord& u = record.uavs[i];
    const std::array<double, 8> now{
        u.command.x(),  u.command.y(),  u.position.x(), u.position.y(),
        u.velocity.x(), u.velocity.y(), u.yaw,          u.altitude ? u.z : uavs_[i][7]};
    for (std::size_t k = 0; k < 7; ++k) c.dx(now[k], uavs_[i][k]);
    s.u(u.altitude ? 1 : 0);
    if (u.altitude) c.dx(now[7], uavs_[i][7]);
    uavs_[i] = now;
    s.u(u.contacts.size());
    for (const world::BodyRef& r : u.contacts) {
      s.i(static_cast<int>(r.kind));
      s.i(r.index);
    }
    extras_.encode(extras_.schema().uavs, u, s);
  }
}

void StepColumnEncoder::scans(const StepRecord& record) {
  ColumnOut& s = columns_[kStructureColumn];
  ColumnOut& c = columns_[kScanColumn];
  auto list = [&s](const std::vector<int>& values) {  // differences: the lists are sorted
    s.u(values.size());
    long long last = 0;
    for (const int v : values) {
      s.i(v - last);
      last = v;
    }
  };
  for (const UavRecord& u : record.uavs) {
    const sensing::Scan& scan = u.scan;
    s.i(scan.uav);
    list(scan.in_footprint);
    list(scan.visible);
    s.u(scan.observations.size());
    for (const sensing::Observation& o : scan.observations) {
      label(o.label);
      s.i(o.truth);
      c.d(o.R(0, 0));
      c.d(o.R(0, 1));
      c.d(o.R(1, 1));
      c.d(o.z.x());
      c.d(o.z.y());
      if (o.label == sensing::kTreeLabel) c.d(o.radius);
      extras_.encode(extras_.schema().observations, o, s);
    }
    extras_.encode(extras_.schema().scans, scan, s);
  }
}

void StepColumnEncoder::plans(const StepRecord& record) {
  ColumnOut& s = columns_[kStructureColumn];
  ColumnOut& c = columns_[kPlanColumn];
  s.u(record.plan ? 1 : 0);
  if (!record.plan) return;
  auto velocities = [&](const agents::planning::Plan& plan) {
    s.u(plan.velocities.size());
    for (const Vec2& v : plan.velocities) {
      c.d(v.x());
      c.d(v.y());
    }
  };
  const agents::planning::TeamPlan& plan = *record.plan;
  s.i(plan.epoch);
  s.u(plan.reports.size());
  for (const auto& r : plan.reports) {
    s.i(r.agent);
    c.d(r.cost);
    s.i(r.evaluations);
    s.i(r.iterations);
    s.u(r.joint_epoch.size());
    for (const int e : r.joint_epoch) s.i(e);
    velocities(r.plan);
    extras_.encode(extras_.schema().plan_agents, r, s);
  }
  s.u(plan.messages.size());
  for (const auto& m : plan.messages) {
    s.i(m.agent);
    s.i(m.epoch);
    s.i(m.from);
    velocities(m.plan);
    extras_.encode(extras_.schema().messages, m, s);
  }
  extras_.encode(extras_.schema().plan, plan, s);
}

void StepColumnEncoder::take(std::string& out) {
  ColumnOut header;
  header.u(labels_.size());
  for (const std::string& label : labels_) {
    header.u(label.size());
    header.bytes() += label;
  }
  header.u(kColumnCount);
  for (ColumnOut& c : columns_) header.u(c.bytes().size());
  out += header.bytes();
  for (int i = 0; i < kColumnCount; ++i) {
    std::string& bytes = columns_[static_cast<std::size_t>(i)].bytes();
    if (i == kStructureColumn) {
      out += bytes;
    } else {
      toPlanes(bytes, out);
    }
    bytes.clear();
  }
  steps_ = 0;
  previous_agents_ = 0;
  uavs_.clear();
  targets_.clear();
}

namespace {

// The 8 × 8 byte matrix whose row i is word[i] (byte k in column k, little-endian) transposed in
// place: afterwards byte i of word[k] is what byte k of word[i] was. Three rounds swap the
// off-diagonal blocks of 4 × 4, then 2 × 2, then 1 × 1 bytes (each a masked XOR swap).
void transposeBytes(std::uint64_t (&word)[8]) {
  for (int i = 0; i < 4; ++i) {
    const std::uint64_t t = ((word[i] >> 32) ^ word[i + 4]) & 0x00000000FFFFFFFFULL;
    word[i] ^= t << 32;
    word[i + 4] ^= t;
  }
  for (const int i : {0, 1, 4, 5}) {
    const std::uint64_t t = ((word[i] >> 16) ^ word[i + 2]) & 0x0000FFFF0000FFFFULL;
    word[i] ^= t << 16;
    word[i + 2] ^= t;
  }
  for (const int i : {0, 2, 4, 6}) {
    const std::uint64_t t = ((word[i] >> 8) ^ word[i + 1]) & 0x00FF00FF00FF00FFULL;
    word[i] ^= t << 8;
    word[i + 1] ^= t;
  }
}

// Plane b of n values, planes[b·n + i] = values[8i + b], and back (inverse = true): eight values
// at a time through transposeBytes (a value's byte b is its b-th in memory), the rest one byte
// at a time.
void transposePlanes(const char* from, char* to, std::size_t n, bool inverse) {
  std::size_t i = 0;
  if constexpr (std::endian::native == std::endian::little) {
    for (; i + 8 <= n; i += 8) {
      std::uint64_t word[8];
      for (std::size_t r = 0; r < 8; ++r)
        std::memcpy(&word[r], inverse ? from + r * n + i : from + 8 * (i + r), 8);
      transposeBytes(word);
      for (std::size_t r = 0; r < 8; ++r)
        std::memcpy(inverse ? to + 8 * (i + r) : to + r * n + i, &word[r], 8);
    }
  }
  for (; i < n; ++i) {
    for (std::size_t b = 0; b < 8; ++b) {
      if (inverse) {
        to[8 * i + b] = from[b * n + i];
      } else {
        to[b * n + i] = from[8 * i + b];
      }
    }
  }
}

}  // namespace

void toPlanes(std::string_view values, std::string& out) {
  const std::size_t n = values.size() / 8;
  const std::size_t start = out.size();
  out.resize(start + values.size());
  char* planes = out.data() + start;
  transposePlanes(values.data(), planes, n, false);
  for (std::size_t k = 8 * n; k < values.size(); ++k) planes[k] = values[k];
}

void fromPlanes(std::string_view planes, std::string& out) {
  const std::size_t n = planes.size() / 8;
  out.resize(planes.size());
  transposePlanes(planes.data(), out.data(), n, true);
  for (std::size_t k = 8 * n; k < planes.size(); ++k) out[k] = planes[k];
}

}  // namespace canopy::sim
