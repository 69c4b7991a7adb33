// docs/output-formats.md names every key a run writes to record.jsonl and summary.json, its
// record table is what `canopy schema --record-markdown` prints today, and
// docs/scenario-reference.md is what `canopy schema --markdown` prints today.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "core/text_file.h"
#include "sim/record_fields.h"
#include "sim/run.h"
#include "spec/loader.h"
#include "spec/schema.h"
#include "tests/sim/json_key_paths.h"

namespace canopy::sim {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

const fs::path kDocs = fs::path(CANOPY_SOURCE_DIR) / "docs";

using test::keysOf;

TEST(OutputFormats, EveryKeyARunWritesIsDocumented) {
  const std::string page = readTextFile(kDocs / "output-formats.md").value();
  // Scripted (demo: trees in the maps, tree observations) and planned with limited range
  // (resource_allocation: plans, intention messages, planning times).
  const std::vector<std::pair<std::string, std::vector<std::string>>> runs = {
      {"demo", {"clock.duration=1"}},
      {"resource_allocation", {"clock.duration=2", "fusion.comm_range=30"}}};
  std::set<std::string> record, summary;
  for (const auto& [name, overrides] : runs) {
    spec::LoadOptions load;
    load.overrides = overrides;
    RunOptions options;
    options.out_dir = fs::temp_directory_path() / ("canopy_formats_" + std::to_string(::getpid()));
    runScenario(spec::loadScenario(name, load), options);
    std::stringstream lines(readTextFile(options.out_dir / "record.jsonl").value());
    for (std::string line; std::getline(lines, line);) keysOf(Json::parse(line), "", record);
    keysOf(Json::parse(readTextFile(options.out_dir / "summary.json").value()), "", summary);
    fs::remove_all(options.out_dir);
  }
  EXPECT_TRUE(record.count("plan.messages[].from"));  // the runs reach every part
  EXPECT_TRUE(record.count("agents[].map[].P"));
  EXPECT_TRUE(summary.count("messages.intentions.late"));
  for (const std::set<std::string>* keys : {&record, &summary}) {
    for (const std::string& key : *keys)
      EXPECT_NE(page.find("| `" + key + "` |"), std::string::npos) << key << " is undocumented";
  }
}

TEST(OutputFormats, TheRecordTableIsTheFieldTables) {
  const std::string page = readTextFile(kDocs / "output-formats.md").value();
  const std::size_t begin = page.find(kRecordFieldsBegin);
  const std::size_t end = page.find(kRecordFieldsEnd);
  ASSERT_NE(begin, std::string::npos);
  ASSERT_NE(end, std::string::npos);
  EXPECT_EQ(page.substr(begin, end + std::string(kRecordFieldsEnd).size() + 1 - begin),
            recordFieldsMarkdown())
      << "regenerate the part of docs/output-formats.md between its markers with "
         "build/release/app/canopy schema --record-markdown";
}

TEST(ScenarioReference, TheCheckedInPageIsCurrent) {
  EXPECT_EQ(readTextFile(kDocs / "scenario-reference.md").value_or(""),
            spec::scenarioReferenceMarkdown())
      << "regenerate: build/release/app/canopy schema --markdown > docs/scenario-reference.md";
}

TEST(ScenarioReference, EveryFieldTheLoaderReadsIsDocumentedAndNoOther) {
  EXPECT_NO_THROW(spec::documentedFields());
}

// The schema's numbers are the loader's: checked against the config structs' own defaults and
// the loader's bounds as the code states them.
TEST(ScenarioReference, SchemaCarriesTypesRangesDefaultsAndUnits) {
  const Json schema = Json::parse(spec::scenarioSchemaJson());
  const Json& v_max = schema["properties"]["uavs"]["items"]["properties"]["v_max"];
  EXPECT_EQ(v_max["type"], "number");
  EXPECT_EQ(v_max["default"], 5.0);  // world/defs.h: UavDef::v_max
  EXPECT_EQ(v_max["exclusiveMinimum"], 0);
  EXPECT_EQ(v_max["x-unit"], "m/s");
  const Json& dt = schema["properties"]["clock"]["properties"]["dt"];
  EXPECT_EQ(dt["default"], spec::ScenarioSpec{}.dt);
  const Json& gate = schema["properties"]["tracking"]["properties"]["gate_probability"];
  EXPECT_EQ(gate["default"], 0.98);  // agents/config.h
  EXPECT_EQ(gate["exclusiveMinimum"], 0.0);
  EXPECT_EQ(gate["exclusiveMaximum"], 1.0);
  EXPECT_EQ(schema["properties"]["fusion"]["properties"]["method"]["enum"],
            Json({"ci", "hcmci", "observer_average"}));
  const Json& horizon = schema["properties"]["planner"]["properties"]["horizon"];
  EXPECT_EQ(horizon["minimum"], 1.0);
  EXPECT_EQ(horizon["maximum"], 50.0);
  EXPECT_EQ(schema["required"], Json({"aoi", "uavs"}));
  // Lists of alternatives in any order (the order of first use in the library's files).
  const auto sorted = [](Json list) {
    std::sort(list.begin(), list.end());
    return list;
  };
  EXPECT_EQ(sorted(schema["properties"]["occluders"]["items"]["properties"]["radius"]["type"]),
            Json({"array", "number"}));
  // Variants: one per occluder type and include, each with its own required members, told apart
  // by "type"; a footprint is a radius, a size or a ground robot's sector, never two of them.
  const Json& occluder = schema["properties"]["occluders"]["items"];
  ASSERT_EQ(occluder["oneOf"].size(), 6u);
  EXPECT_EQ(occluder["oneOf"][0]["properties"]["type"]["enum"], Json({"disc"}));
  EXPECT_EQ(occluder["oneOf"][0]["required"], Json({"centre", "radius", "type"}));
  const Json& fov = schema["properties"]["uavs"]["items"]["properties"]["fov"];
  EXPECT_FALSE(fov.contains("required"));
  ASSERT_EQ(fov["oneOf"].size(), 3u);
  EXPECT_EQ(fov["oneOf"][1]["required"], Json({"radius"}));
  EXPECT_EQ(fov["oneOf"][1]["additionalProperties"], false);
  // A numeric yaw or the one spelling "velocity".
  EXPECT_EQ(
      sorted(schema["properties"]["uavs"]["items"]["properties"]["yaw"]["anyOf"]),
      sorted(Json::parse(R"([{"type": "string", "enum": ["velocity"]}, {"type": "number"}])")));
}

}  // namespace
}  // namespace canopy::sim
