// The compact record's step columns read back (the encoder, its rule and the layout:
// step_columns.h). Each read is checked: counts against the bytes left, references against the
// step before, labels and outline sizes against their ranges.
#include <limits>

#include "sim/step_columns.h"
#include "sim/step_values.h"

namespace canopy::sim {
namespace {

constexpr long long kIntMin = std::numeric_limits<int>::min();
constexpr long long kIntMax = std::numeric_limits<int>::max();
constexpr const char* kColumnNames[kColumnCount] = {"structure", "truth", "map",
                                                    "tracks",    "scans", "plans"};

}  // namespace

StepColumnDecoder::StepColumnDecoder(std::string_view block, const RecordSchema& schema)
    : schema_(schema) {
  ColumnIn header(block, "header");
  const std::size_t labels = header.count();
  for (std::size_t i = 0; i < labels; ++i) {
    const std::size_t length = header.count();
    const std::size_t at = block.size() - header.remaining();
    labels_.emplace_back(block.substr(at, length));
    header = ColumnIn(block.substr(at + length), "header");
  }
  extras_.emplace(schema_, labels_);
  const std::size_t columns = header.count();
  if (columns != kColumnCount) header.fail("6 columns");
  std::array<std::size_t, kColumnCount> sizes{};
  std::size_t total = 0;
  for (std::size_t& size : sizes) {
    size = header.count();
    total += size;
  }
  if (total != header.remaining()) header.fail("columns that fill the block");
  std::size_t at = block.size() - header.remaining();
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const std::string_view bytes = block.substr(at, sizes[i]);
    at += sizes[i];
    if (i == kStructureColumn) {
      columns_[i] = ColumnIn(bytes, kColumnNames[i]);
    } else {
      fromPlanes(bytes, planes_[i]);
      columns_[i] = ColumnIn(planes_[i], kColumnNames[i]);
    }
  }
}

bool StepColumnDecoder::next(StepRecord& record) {
  if (columns_[kStructureColumn].remaining() == 0) {
    for (const ColumnIn& c : columns_) {
      if (c.remaining() != 0) c.fail("bytes after the last step");
    }
    return false;
  }
  truth(record);
  ColumnIn& s = columns_[kStructureColumn];
  const std::size_t agents = s.count();
  record.beliefs.resize(agents);
  for (std::size_t i = 0; i < agents; ++i) belief(static_cast<int>(i), record.beliefs[i]);
  scans(record);
  plans(record);
  extra(schema_.step, record);
  previous_ = record.beliefs;
  return true;
}

void StepColumnDecoder::belief(int agent, agents::AgentBelief& b) {
  ColumnIn& s = columns_[kStructureColumn];
  ColumnIn& map = columns_[kMapColumn];
  static const agents::AgentBelief kNone;
  const agents::AgentBelief& before = static_cast<std::size_t>(agent) < previous_.size()
                                          ? previous_[static_cast<std::size_t>(agent)]
                                          : kNone;
  auto entry = [&s](std::size_t entries) {  // (j, changed) of a reference, j = −1 for a new one
    const std::uint64_t ref = s.u();
    if (ref == 0) return std::pair<long long, bool>{-1, false};
    const std::uint64_t j = (ref - 1) / 2;
    if (j >= entries) s.fail("a reference to an entry the step before did not have");
    return std::pair<long long, bool>{static_cast<long long>(j), ref % 2 == 0};
  };
  const std::size_t trees = s.count();
  b.trees.clear();
  TreeValues v{}, w{};
  for (std::size_t i = 0; i < trees; ++i) {
    const auto [j, changed] = entry(before.trees.size());
    if (j >= 0) {
      b.trees.push_back(before.trees[static_cast<std::size_t>(j)]);
      if (changed) {
        const int n = gather(b.trees.back(), w);
        for (int k = 0; k < n; ++k)
          v[static_cast<std::size_t>(k)] = map.dx(w[static_cast<std::size_t>(k)]);
        scatter(v, b.trees.back());
        extra(schema_.map, b.trees.back());
      }
      continue;
    }
    agents::TreeEstimate& t = b.trees.emplace_back();
    t.key.origin = s.bounded(kIntMin, kIntMax, "key");
    t.key.serial = s.bounded(kIntMin, kIntMax, "key");
    const auto vertices = s.u();
    if (vertices > sensing::Outline::kMaxVertices) s.fail("an outline of at most 8 vertices");
    t.outline.vertices = static_cast<int>(vertices);
    const int n = 9 + 2 * t.outline.vertices;
    for (int k = 0; k < n; ++k) v[static_cast<std::size_t>(k)] = map.d();
    scatter(v, t);
    extra(schema_.map, t);
  }
  ColumnIn& plan = columns_[kPlanColumn];
  const std::size_t path = s.countOf(plan, 16);
  b.planned_path.clear();
  for (std::size_t i = 0; i < path; ++i) {
    const double x = plan.d();
    b.planned_path.emplace_back(x, plan.d());
  }
  ColumnIn& track = columns_[kTrackColumn];
  const int labels = static_cast<int>(labels_.size()) - 1;
  const std::size_t tracks = s.count();
  b.tracks.clear();
  TrackValues x{}, y{};
  for (std::size_t i = 0; i < tracks; ++i) {
    const auto [j, changed] = entry(before.tracks.size());
    if (j >= 0) {
      b.tracks.push_back(before.tracks[static_cast<std::size_t>(j)]);
      if (changed) {
        agents::TrackEstimate& t = b.tracks.back();
        t.label = s.bounded(0, labels, "label");
        gather(t, y);
        for (std::size_t k = 0; k < x.size(); ++k) x[k] = track.dx(y[k]);
        scatter(x, t);
        extra(schema_.tracks, t);
      }
      continue;
    }
    agents::TrackEstimate& t = b.tracks.emplace_back();
    t.key.origin = s.bounded(kIntMin, kIntMax, "key");
    t.key.serial = s.bounded(kIntMin, kIntMax, "key");
    t.label = s.bounded(0, labels, "label");
    for (double& value : x) value = track.d();
    scatter(x, t);
    extra(schema_.tracks, t);
  }
  extra(schema_.agents, b);
}

void StepColumnDecoder::truth(StepRecord& record) {
  ColumnIn& s = columns_[kStructureColumn];
  ColumnIn& c = columns_[kTruthColumn];
  record.step = s.bounded(kIntMin, kIntMax, "step");
  record.time = c.d();
  const std::size_t targets = s.count();
  record.targets.resize(targets);
  targets_.resize(targets, std::array<double, 4>{});
  for (std::size_t i = 0; i < targets; ++i) {
    std::array<double, 4>& now = targets_[i];
    for (double& value : now) value = c.dx(value);
    record.targets[i].position = Vec2(now[0], now[1]);
    record.targets[i].velocity = Vec2(now[2], now[3]);
    extra(schema_.targets, record.targets[i]);
  }
  const std::size_t uavs = s.count();
  record.uavs.resize(uavs);
  uavs_.resize(uavs, std::array<double, 8>{});
  for (std::size_t i = 0; i < uavs; ++i) {
    std::array<double, 8>& now = uavs_[i];
    for (std::size_t k = 0; k < 7; ++k) now[k] = c.dx(now[k]);
    UavRecord& u = record.uavs[i];
    u.command = Vec2(now[0], now[1]);
    u.position = Vec2(now[2], now[3]);
    u.velocity = Vec2(now[4], now[5]);
    u.yaw = now[6];
    u.altitude = s.u() != 0;
    if (u.altitude) now[7] = c.dx(now[7]);
    u.z = u.altitude ? now[7] : 0.0;
    const std::size_t contacts = s.count(2);
    u.contacts.clear();
    for (std::size_t k = 0; k < contacts; ++k) {
      world::BodyRef& r = u.contacts.emplace_back();
      r.kind = static_cast<world::BodyKind>(s.bounded(0, 4, "body kind"));
      r.index = s.bounded(kIntMin, kIntMax, "body index");
    }
    extra(schema_.uavs, u);
  }
}

void StepColumnDecoder::scans(StepRecord& record) {
  ColumnIn& s = columns_[kStructureColumn];
  ColumnIn& c = columns_[kScanColumn];
  auto list = [&s](std::vector<int>& values) {
    const std::size_t n = s.count();
    values.clear();
    long long last = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const std::int64_t difference = s.i();  // of two ints: within ±2³²
      if (difference < 2 * kIntMin || difference > 2 * kIntMax) s.fail("an index out of range");
      last += difference;
      if (last < kIntMin || last > kIntMax) s.fail("an index out of range");
      values.push_back(static_cast<int>(last));
    }
  };
  const int labels = static_cast<int>(labels_.size()) - 1;
  for (UavRecord& u : record.uavs) {
    sensing::Scan& scan = u.scan;
    scan.uav = s.bounded(kIntMin, kIntMax, "uav");
    list(scan.in_footprint);
    list(scan.visible);
    const std::size_t n = s.count(2);
    scan.observations.clear();
    for (std::size_t i = 0; i < n; ++i) {
      sensing::Observation& o = scan.observations.emplace_back();
      o.label = s.bounded(0, labels, "label");
      o.truth = s.bounded(kIntMin, kIntMax, "truth");
      o.R(0, 0) = c.d();
      o.R(0, 1) = o.R(1, 0) = c.d();
      o.R(1, 1) = c.d();
      const double zx = c.d();
      o.z = Vec2(zx, c.d());
      if (o.label == sensing::kTreeLabel) o.radius = c.d();
      extra(schema_.observations, o);
    }
    extra(schema_.scans, scan);
  }
}

void StepColumnDecoder::plans(StepRecord& record) {
  ColumnIn& s = columns_[kStructureColumn];
  ColumnIn& c = columns_[kPlanColumn];
  record.plan.reset();
  if (s.u() == 0) return;
  auto velocities = [&](agents::planning::Plan& plan) {
    const std::size_t n = s.countOf(c, 16);
    for (std::size_t i = 0; i < n; ++i) {
      const double x = c.d();
      plan.velocities.emplace_back(x, c.d());
    }
  };
  agents::planning::TeamPlan& plan = record.plan.emplace();
  plan.epoch = s.bounded(kIntMin, kIntMax, "epoch");
  const std::size_t reports = s.count();
  for (std::size_t i = 0; i < reports; ++i) {
    auto& r = plan.reports.emplace_back();
    r.agent = s.bounded(kIntMin, kIntMax, "agent");
    r.cost = c.d();
    r.evaluations = static_cast<long long>(s.i());
    r.iterations = s.bounded(kIntMin, kIntMax, "iterations");
    const std::size_t epochs = s.count();
    for (std::size_t k = 0; k < epochs; ++k)
      r.joint_epoch.push_back(s.bounded(kIntMin, kIntMax, "epoch"));
    velocities(r.plan);
    extra(schema_.plan_agents, r);
  }
  const std::size_t messages = s.count();
  for (std::size_t i = 0; i < messages; ++i) {
    auto& m = plan.messages.emplace_back();
    m.agent = s.bounded(kIntMin, kIntMax, "agent");
    m.epoch = s.bounded(kIntMin, kIntMax, "epoch");
    m.from = s.bounded(kIntMin, kIntMax, "from");
    velocities(m.plan);
    extra(schema_.messages, m);
  }
  extra(schema_.plan, plan);
}

}  // namespace canopy::sim
