// Printing and freeing a parsed document with progress (spec/json_progress.h): the text is the
// JSON library's own dump(2), byte for byte (the second method), on documents made to hit each
// case of the layout, and on every built-in scenario's effective configuration.
#include "spec/json_progress.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/progress.h"
#include "spec/loader.h"

namespace canopy::spec {
namespace {

TEST(JsonProgress, DumpIsTheLibrarysIndentedDumpByteForByte) {
  const std::vector<std::string> documents = {
      R"({})",
      R"([])",
      R"(3.25)",
      R"("text")",
      R"({"a": []})",
      R"({"a": {}})",
      R"({"a": [1]})",
      R"({"a": [[], {}, [1, [2, [3]]], {"b": {"c": []}}]})",
      R"({"line\nbreak \"quoted\"": "x\ny\tz", "e": "é ✓", "z": null, "t": true})",
      R"({"occluders": [{"type": "disc", "centre": [1.5, -2e-7], "radius": 1e300},
                        {"type": "polygon", "vertices": [[0, 0], [1, 0], [0, 1]]}],
          "aoi": [0, 0, 10, 10], "n": -0.0, "big": 18446744073709551615, "neg": -5})",
  };
  for (const std::string& text : documents) {
    const Json value = Json::parse(text);
    EXPECT_EQ(dumpIndented2(value, "test"), value.dump(2)) << text;
  }
}

TEST(JsonProgress, DumpMatchesForEveryBuiltInScenarioConfiguration) {
  for (const std::string& name : libraryScenarios()) {
    const Json config = Json::parse(loadScenario(name).effective_config);
    EXPECT_EQ(dumpIndented2(config, "test"), config.dump(2)) << name;
  }
}

std::vector<double>& dones() {
  static std::vector<double> all;
  return all;
}

TEST(JsonProgress, BothCountTheTopLevelArraysElementsAndReleaseEmpties) {
  Json value = Json::object();
  value["many"] = Json::array();
  for (int i = 0; i < 3000; ++i) value["many"].push_back({{"i", i}});
  value["few"] = {1, 2};
  value["scalar"] = 7;
  const ProgressHook before = setProgressHook(
      [](const char*, double done, double total) { dones().push_back(done + 1e6 * total); });
  dones().clear();
  dumpIndented2(value, "dump");
  // Start, 1024, 2048, end: 3002 elements in all (1e6 · total carries the total).
  EXPECT_EQ(dones(), (std::vector<double>{3002e6, 1024 + 3002e6, 2048 + 3002e6, 3002 + 3002e6}));
  dones().clear();
  releaseReporting(value, "release");
  setProgressHook(before);
  EXPECT_EQ(dones(), (std::vector<double>{3002e6, 1024 + 3002e6, 2048 + 3002e6, 3002 + 3002e6}));
  EXPECT_TRUE(value.is_null());
}

}  // namespace
}  // namespace canopy::spec
