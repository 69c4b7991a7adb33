// The compact record's step columns (sim/step_columns.h): steps decode to the fields the record
// writes, so their JSON lines are byte-identical (recordLine of the decoded step against the
// original's); the rule for what is not repeated, counted in bytes; malformed blocks are errors.
#include "sim/step_columns.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/record_fields.h"
#include "sim/record_line.h"
#include "tests/sim/json_key_paths.h"

namespace canopy::sim::step_columns_test {  // named: the sanitizer's unity build merges files
namespace {

const std::vector<std::string> kLabels{"tree", "human", "car \"red\""};

agents::TreeEstimate tree(int origin, int serial, double cx, int vertices = 0) {
  agents::TreeEstimate t;
  t.key = {origin, serial};
  t.belief.x << cx, cx / 3, 1.25;
  t.belief.P << 0.5, 0.1, 0.0, 0.1, 0.4, 0.0, 0.0, 0.0, 0.01 * cx;
  t.outline.vertices = vertices;
  for (int v = 0; v < vertices; ++v)
    t.outline.offsets[static_cast<std::size_t>(v)] = Vec2(v, -v * 0.5);
  return t;
}

agents::TrackEstimate track(int origin, int serial, double px, int label = 1) {
  agents::TrackEstimate t;
  t.key = {origin, serial};
  t.label = label;
  t.belief.x << px, -px, 0.3, 0.1;
  t.belief.P = Eigen::Matrix4d::Identity() * (1.0 + px);
  t.belief.P(0, 2) = t.belief.P(2, 0) = 0.125;
  t.existence = 0.9;
  return t;
}

// A step with two agents, maps with and without outlines, tracks, scans, truth and (odd steps) a
// plan; `k` moves some of it.
StepRecord step(int k) {
  StepRecord r;
  r.step = k;
  r.time = 0.2 * k;
  for (int i = 0; i < 2; ++i) {
    UavRecord& u = r.uavs.emplace_back();
    u.position = Vec2(10.0 * i + k, 3.0);
    u.velocity = Vec2(1.0, -0.5 * i);
    u.command = Vec2(0.7, 0.1 * k);
    u.yaw = 0.3 * i;
    u.altitude = i == 1;
    u.z = 12.5 + k;
    if (k % 2 == 1) u.contacts = {{world::BodyKind::wall, 3}, {world::BodyKind::uav, 1 - i}};
    u.scan.uav = i;
    u.scan.in_footprint = {1, 4, 9};
    u.scan.visible = {4};
    sensing::Observation& o = u.scan.observations.emplace_back();
    o.label = 1;
    o.z = Vec2(4.5, -2.0 + k);
    o.R << 0.3, 0.01, 0.01, 0.2;
    o.truth = 4;
    sensing::Observation& w = u.scan.observations.emplace_back();
    w.label = sensing::kTreeLabel;
    w.z = Vec2(1.0, 2.0);
    w.radius = 2.5;
    w.truth = -1;
  }
  for (int t = 0; t < 3; ++t) {
    TargetRecord& target = r.targets.emplace_back();
    target.position = Vec2(t + 0.1 * k, 2.0 * t);
    target.velocity = Vec2(0.1, std::numeric_limits<double>::quiet_NaN());
  }
  agents::AgentBelief& a = r.beliefs.emplace_back();
  a.trees = {tree(0, 1, 5.0), tree(0, 2, 6.0 + k, 4), tree(1, 7, 8.0)};
  if (k >= 2) a.trees.insert(a.trees.begin(), tree(0, 0, 9.0));  // a new entry shifts the rest
  a.tracks = {track(0, 3, 1.0 + k), track(1, 1, 2.0)};
  a.planned_path = {Vec2(1, 2), Vec2(3, 4)};
  agents::AgentBelief& b = r.beliefs.emplace_back();
  b.trees = {tree(1, 7, 8.0), tree(0, 1, 5.0)};  // another order
  if (k == 3) b.trees.pop_back();
  b.tracks = {track(1, 1, 2.0, k >= 2 ? 2 : 1)};  // its label changes at step 2
  if (k % 2 == 1) {
    agents::planning::TeamPlan& plan = r.plan.emplace();
    plan.epoch = k / 2;
    for (int i = 0; i < 2; ++i) {
      auto& report = plan.reports.emplace_back();
      report.agent = i;
      report.cost = 12.5 * k + i;
      report.evaluations = 5'000'000'000LL + i;
      report.iterations = 20;
      report.joint_epoch = {plan.epoch, -1};
      report.plan.velocities = {Vec2(1, 0), Vec2(0.5, 0.5)};
      auto& m = plan.messages.emplace_back();
      m.from = m.agent = i;
      m.epoch = plan.epoch;
      m.plan.velocities = {Vec2(-1, 0)};
    }
  }
  return r;
}

TEST(StepColumns, StepsDecodeToTheSameRecordLines) {
  StepColumnEncoder encoder(kLabels);
  std::vector<std::string> lines;
  for (int k = 0; k < 5; ++k) {
    encoder.add(step(k));
    lines.push_back(recordLine(kLabels, step(k)));
  }
  EXPECT_EQ(encoder.steps(), 5u);
  std::string block;
  encoder.take(block);
  EXPECT_EQ(encoder.steps(), 0u);
  StepColumnDecoder decoder(block);
  EXPECT_EQ(decoder.labels(), kLabels);
  StepRecord r;
  for (const std::string& line : lines) {
    ASSERT_TRUE(decoder.next(r));
    EXPECT_EQ(recordLine(kLabels, r), line);
  }
  EXPECT_FALSE(decoder.next(r));
  // The next block starts whole: it decodes on its own.
  encoder.add(step(3));
  block.clear();
  encoder.take(block);
  StepColumnDecoder second(block);
  ASSERT_TRUE(second.next(r));
  EXPECT_EQ(recordLine(kLabels, r), recordLine(kLabels, step(3)));
}

// The rule: an unchanged entry is a reference (one structure byte, no values); a changed one is a
// reference and its values XORed with the entry's at the step before.
TEST(StepColumns, UnchangedEntriesAreReferencesChangedOnesXorTheirValues) {
  StepColumnEncoder encoder(kLabels);
  StepRecord r;
  r.beliefs.resize(1);
  r.beliefs[0].trees = {tree(0, 1, 5.0), tree(0, 2, 6.0)};
  r.beliefs[0].tracks = {track(0, 3, 1.0)};
  encoder.add(r);
  const std::size_t map = encoder.columnBytes(kMapColumn);
  const std::size_t tracks = encoder.columnBytes(kTrackColumn);
  EXPECT_EQ(map, 2u * 9 * 8);  // two trees whole: 6 covariance + 3 mean values
  EXPECT_EQ(tracks, 15u * 8);  // 10 + 4 + existence
  const std::size_t structure = encoder.columnBytes(kStructureColumn);
  encoder.add(r);  // nothing changed
  EXPECT_EQ(encoder.columnBytes(kMapColumn), map);
  EXPECT_EQ(encoder.columnBytes(kTrackColumn), tracks);
  // step, targets, uavs, agents, tree count, 2 references, path, track count, 1 reference, plan
  // flag: one byte each
  EXPECT_EQ(encoder.columnBytes(kStructureColumn) - structure, 11u);
  r.beliefs[0].trees[1].belief.x(2) = 1.5;  // one value of the second tree changes
  encoder.add(r);
  EXPECT_EQ(encoder.columnBytes(kMapColumn), map + 9 * 8);  // one tree's values, XORed
  std::string block;
  encoder.take(block);
  StepColumnDecoder decoder(block);
  StepRecord out;
  for (int k = 0; k < 3; ++k) ASSERT_TRUE(decoder.next(out));
  EXPECT_EQ(out.beliefs[0].trees[1].belief.x(2), 1.5);
  EXPECT_EQ(out.beliefs[0].trees[0].belief.x(0), 5.0);
}

using sim::test::keysOf;

// The record's field table (record_fields.h) names exactly the keys the line writer writes: a
// step with every optional part (outline, contacts, altitude, tree observations, a plan).
TEST(StepColumns, TheFieldTableIsWhatTheLineWriterWrites) {
  std::set<std::string> written, described;
  for (int k = 0; k < 2; ++k)
    keysOf(nlohmann::json::parse(recordLine(kLabels, step(k))), "", written);
  for (const RecordField& f : recordFields()) {
    EXPECT_TRUE(described.insert(f.path).second) << f.path << " twice";
    EXPECT_TRUE(f.type[0] != '\0' && f.packing[0] != '\0' && f.meaning[0] != '\0') << f.path;
  }
  EXPECT_EQ(written, described);
}

// A label that JSON cannot hold (invalid UTF-8) fails the step that first writes it, in either
// form.
TEST(StepColumns, ALabelJsonCannotHoldFailsTheStepThatWritesIt) {
  const std::vector<std::string> labels{"tree", "bad \xff"};
  StepRecord r;
  r.beliefs.resize(1);
  StepColumnEncoder encoder(labels);
  EXPECT_NO_THROW(encoder.add(r));
  r.beliefs[0].tracks = {track(0, 1, 1.0, 1)};
  EXPECT_ANY_THROW(recordLine(labels, r));
  EXPECT_ANY_THROW(encoder.add(r));
}

TEST(StepColumns, BytePlanesGoBothWays) {
  const std::string values = "ABCDEFGHabcdefgh12345678xyz";  // three values and a tail
  std::string planes;
  toPlanes(values, planes);
  EXPECT_EQ(planes, "Aa1Bb2Cc3Dd4Ee5Ff6Gg7Hh8xyz");
  std::string back;
  fromPlanes(planes, back);
  EXPECT_EQ(back, values);
}

// Byte planes by their definition, planes[b·n + i] = values[8i + b], for sizes on either side of
// the eight values the encoder moves at a time, and back.
TEST(StepColumns, BytePlanesAreTheValuesBytesByPosition) {
  std::mt19937 rng(20261208);
  for (const std::size_t size : {0, 7, 8, 63, 64, 65, 71, 72, 127, 128, 135, 1000, 4099}) {
    std::string values(size, '\0');
    for (char& byte : values) byte = static_cast<char>(rng() & 0xff);
    std::string planes = "prefix";  // appended after what out holds
    toPlanes(values, planes);
    const std::size_t n = size / 8;
    std::string expected = "prefix" + std::string(size, '\0');
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t b = 0; b < 8; ++b) expected[6 + b * n + i] = values[8 * i + b];
    for (std::size_t k = 8 * n; k < size; ++k) expected[6 + k] = values[k];
    EXPECT_EQ(planes, expected) << size << " bytes";
    std::string back;
    fromPlanes(std::string_view(planes).substr(6), back);
    EXPECT_EQ(back, values) << size << " bytes";
  }
}

TEST(StepColumns, MalformedBlocksAreErrors) {
  StepColumnEncoder encoder(kLabels);
  encoder.add(step(0));
  encoder.add(step(1));
  std::string block;
  encoder.take(block);
  auto decodeAll = [](const std::string& bytes) {
    StepColumnDecoder decoder(bytes);
    StepRecord r;
    while (decoder.next(r)) {
    }
  };
  EXPECT_NO_THROW(decodeAll(block));
  EXPECT_THROW(decodeAll(""), std::runtime_error);
  for (std::size_t cut : {block.size() / 3, block.size() / 2, block.size() - 1})
    EXPECT_THROW(decodeAll(block.substr(0, cut)), std::runtime_error) << cut;
  // Every single-byte change either decodes or is refused: none crashes or hangs.
  for (std::size_t i = 0; i < block.size(); ++i) {
    std::string changed = block;
    changed[i] = static_cast<char>(changed[i] ^ 0x41);
    try {
      decodeAll(changed);
    } catch (const std::runtime_error&) {
    }
  }
}

}  // namespace
}  // namespace canopy::sim::step_columns_test
