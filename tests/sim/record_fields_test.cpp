// A new field of the record is one entry in one place (sim/record_fields.h): added to a copy of the
// record's schema and nowhere else, it is written into the JSON line in its key's place, read back
// by the one line reader, documented, and carried losslessly by the compact record's columns. The
// steps are a real run's (demo: trees, tracks, scans, tree observations).
#include "sim/record_fields.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sim/record_line.h"
#include "sim/record_step_reader.h"
#include "sim/simulation.h"
#include "sim/step_columns.h"
#include "spec/loader.h"

namespace canopy::sim::record_fields_test {  // named: the sanitizer's unity build merges files
namespace {

using nlohmann::json;

struct DemoRun {
  spec::ScenarioSpec spec;
  std::vector<StepRecord> steps;
};

DemoRun demo(int steps) {
  spec::LoadOptions options;
  options.seed = 3;
  DemoRun run{spec::loadScenario("demo", options), {}};
  Simulation sim(run.spec);
  for (int k = 0; k < steps; ++k) run.steps.push_back(sim.tick());
  return run;
}

// UavRecord::climb, which the record does not hold: one entry.
RecordSchema withClimb() {
  RecordSchema schema = recordSchema();
  schema.uavs.add(field<UavRecord>(
      "climb", [](auto& u) -> auto& { return u.climb; }, codec::Number{}, "m/s", kGenericPacking,
      "the climb flown over the step (m/s)"));
  return schema;
}

TEST(RecordFields, ANewFieldIsWrittenReadAndDocumentedFromItsOneEntry) {
  DemoRun run = demo(12);
  const RecordSchema schema = withClimb();
  const RecordShape shape = shapeOf(run.spec);
  for (std::size_t k = 0; k < run.steps.size(); ++k) {
    StepRecord& s = run.steps[k];
    for (std::size_t i = 0; i < s.uavs.size(); ++i)
      s.uavs[i].climb = 0.25 * static_cast<double>(k + 1) * (i % 2 == 0 ? 1.0 : -1.0);
    const std::string line = recordLine(run.spec.labels, s, schema);
    const std::string plain = recordLine(run.spec.labels, s);  // the record's own line
    // Written: the line is the record's own plus "climb" in every UAV, first of its keys
    // ("climb" < "cmd" byte by byte).
    json with = json::parse(line);
    ASSERT_EQ(with["uavs"].size(), s.uavs.size());
    for (std::size_t i = 0; i < s.uavs.size(); ++i) {
      EXPECT_EQ(with["uavs"][i]["climb"].get<double>(), s.uavs[i].climb);
      EXPECT_EQ(with["uavs"][i].begin().key(), "climb");
      with["uavs"][i].erase("climb");
    }
    EXPECT_EQ(with, json::parse(plain));
    if (k == 0) {
      EXPECT_NE(line.find("\"uavs\":[{\"climb\":0.25,\"cmd\":"), std::string::npos);
    }
    // Read: the reader with the entry gets the value back and writes the same line; the record's
    // own reader takes the line and leaves the field out.
    StepRecord read;
    readStepLine(line, "record.jsonl", 1, shape, read, schema);
    for (std::size_t i = 0; i < s.uavs.size(); ++i) EXPECT_EQ(read.uavs[i].climb, s.uavs[i].climb);
    EXPECT_EQ(recordLine(run.spec.labels, read, schema), line);
    readStepLine(line, "record.jsonl", 1, shape, read);
    EXPECT_EQ(recordLine(run.spec.labels, read), plain);
  }
  // Documented: its row, in the place of its table.
  const std::string row =
      "| `uavs[].climb` | number | m/s | structure: its JSON text | the climb flown over the step "
      "(m/s) |\n";
  EXPECT_NE(recordFieldsMarkdown(schema).find("| `uavs[].contacts` |"), std::string::npos);
  EXPECT_LT(recordFieldsMarkdown(schema).find("| `uavs[].contacts` |"),
            recordFieldsMarkdown(schema).find(row));
  EXPECT_LT(recordFieldsMarkdown(schema).find(row),
            recordFieldsMarkdown(schema).find("| `targets` |"));
  EXPECT_EQ(recordFieldsMarkdown().find("uavs[].climb"), std::string::npos);
  // Compact: the columns decode to the same lines, the new field with them.
  StepColumnEncoder encoder(run.spec.labels, schema);
  for (const StepRecord& s : run.steps) encoder.add(s);
  std::string block;
  encoder.take(block);
  StepColumnDecoder decoder(block, schema);
  StepRecord decoded;
  for (const StepRecord& s : run.steps) {
    ASSERT_TRUE(decoder.next(decoded));
    EXPECT_EQ(recordLine(run.spec.labels, decoded, schema), recordLine(run.spec.labels, s, schema));
  }
  EXPECT_FALSE(decoder.next(decoded));
}

// A new field of a track counts in the compact record's rule for unchanged entries: a track whose
// recorded values keep their bits but whose new field changes is not written as "the same".
TEST(RecordFields, ANewTrackFieldCountsInTheRuleForUnchangedEntries) {
  const DemoRun run = demo(30);
  RecordSchema schema = recordSchema();
  schema.tracks.add(field<agents::TrackEstimate>(
      "confirmed", [](auto& t) -> auto& { return t.confirmed; }, codec::Bool{}, "", kGenericPacking,
      "the track is confirmed"));
  StepRecord before = run.steps.back();
  std::size_t tracks = 0;
  for (agents::AgentBelief& b : before.beliefs) {
    for (agents::TrackEstimate& t : b.tracks) t.confirmed = false, ++tracks;
  }
  ASSERT_GT(tracks, 0u) << "the demo holds tracks after 30 steps";
  StepRecord after = before;  // the same values, bit for bit; every track confirmed
  after.step += 1;
  for (agents::AgentBelief& b : after.beliefs) {
    for (agents::TrackEstimate& t : b.tracks) t.confirmed = true;
  }
  StepColumnEncoder encoder(run.spec.labels, schema);
  encoder.add(before);
  encoder.add(after);
  std::string block;
  encoder.take(block);
  StepColumnDecoder decoder(block, schema);
  StepRecord decoded;
  ASSERT_TRUE(decoder.next(decoded));
  EXPECT_NE(recordLine(run.spec.labels, decoded, schema).find("\"confirmed\":false"),
            std::string::npos);
  ASSERT_TRUE(decoder.next(decoded));
  const std::string line = recordLine(run.spec.labels, decoded, schema);
  EXPECT_EQ(line, recordLine(run.spec.labels, after, schema));
  EXPECT_EQ(line.find("\"confirmed\":false"), std::string::npos);
}

// The one reader names the file, the line and the field of a fault, with the ranges the scenario
// gives (2 UAVs, so agent indices below 2).
TEST(RecordFields, TheReaderNamesTheFieldOfAFault) {
  const DemoRun run = demo(2);
  const RecordShape shape = shapeOf(run.spec);
  json line = json::parse(recordLine(run.spec.labels, run.steps[1]));
  auto errorOf = [&](const json& edited) {
    StepRecord read;
    try {
      readStepLine(edited.dump(), "record.jsonl", 7, shape, read);
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_EQ(errorOf(line), "(no error)");
  json bad = line;
  bad["scans"][1]["uav"] = 2;
  EXPECT_NE(errorOf(bad).find("record.jsonl: line 7: scans.1.uav: expected an agent index below 2"),
            std::string::npos)
      << errorOf(bad);
  bad = line;
  bad["uavs"][0]["p"] = json::array({1.0});
  EXPECT_NE(errorOf(bad).find("line 7: uavs.0.p: expected [x, y] (two numbers)"), std::string::npos)
      << errorOf(bad);
  bad = line;
  bad["agents"].erase(1);
  EXPECT_NE(errorOf(bad).find("line 7: agents: expected a list of 2 entries"), std::string::npos)
      << errorOf(bad);
  bad = line;
  bad["uavs"][1]["contacts"] = json::array({"wall:x"});
  EXPECT_NE(errorOf(bad).find("line 7: uavs.1.contacts: expected \"wall:K\""), std::string::npos)
      << errorOf(bad);
}

}  // namespace
}  // namespace canopy::sim::record_fields_test
