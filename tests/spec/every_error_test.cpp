// One pass finds every independent error of a file, in file order, each naming the file, the
// field, what was expected and the line. The files below are written line by line, so the line
// each error must name is the line index + 1 of the planted fault, counted here by hand.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "spec/error.h"
#include "spec/json_lines.h"
#include "spec/loader.h"

namespace canopy::spec {
namespace {

// A valid scenario, one field per line; `faults` replaces whole lines (index → text).
std::string scenarioWith(const std::vector<std::pair<int, std::string>>& faults) {
  std::vector<std::string> lines = {
      "{",                                                                        // 1
      "  \"name\": \"planted\",",                                                 // 2
      "  \"aoi\": [0, 0, 100, 100],",                                             // 3
      "  \"clock\": {\"dt\": 0.2, \"duration\": 10},",                            // 4
      "  \"sensing\": {\"p_detect\": 0.9},",                                      // 5
      "  \"uavs\": [{",                                                           // 6
      "    \"start\": [10, 10],",                                                 // 7
      "    \"v_max\": 5,",                                                        // 8
      "    \"quality\": 0.3,",                                                    // 9
      "    \"fov\": {\"radius\": 10}",                                            // 10
      "  }],",                                                                    // 11
      "  \"targets\": [{\"path\": {\"start\": [5, 5], \"velocity\": [1, 0]}}],",  // 12
      "  \"tracking\": {\"sigma_a\": 1.0},",                                      // 13
      "  \"fusion\": {\"rounds\": 5}",                                            // 14
      "}"};                                                                       // 15
  for (const auto& [line, text] : faults) lines[static_cast<std::size_t>(line - 1)] = text;
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  return text;
}

std::vector<std::string> errorsOf(const std::string& text) {
  try {
    LoadOptions options;
    options.text_is_the_file = true;
    loadScenarioText(text, "planted.json", options);
  } catch (const ScenarioErrors& e) {
    std::vector<std::string> out;
    for (const ScenarioError& each : e.errors()) out.push_back(each.what());
    return out;
  } catch (const ScenarioError& e) {
    return {e.what()};
  }
  return {};
}

TEST(EveryError, TheValidBaseLoads) {
  EXPECT_TRUE(errorsOf(scenarioWith({})).empty());
}

TEST(EveryError, OneErrorInEachOfFiveSectionsGivesFiveLinesInFileOrder) {
  const std::vector<std::string> errors = errorsOf(scenarioWith({
      {4, "  \"clock\": {\"dt\": -1, \"duration\": 10},"},
      {5, "  \"sensing\": {\"p_detect\": 1.5},"},
      {8, "    \"v_max\": -3,"},
      {13, "  \"tracking\": {\"sigma_a\": \"fast\"},"},
      {14, "  \"fusion\": {\"rounds\": 5}, \"bogus\": 1"},
  }));
  ASSERT_EQ(errors.size(), 5u) << ::testing::PrintToString(errors);
  EXPECT_EQ(errors[0].rfind("planted.json: clock.dt: expected a positive number", 0), 0u);
  EXPECT_NE(errors[0].find("(line 4)"), std::string::npos) << errors[0];
  EXPECT_EQ(errors[1].rfind("planted.json: sensing.p_detect: expected", 0), 0u) << errors[1];
  EXPECT_NE(errors[1].find("(line 5)"), std::string::npos) << errors[1];
  EXPECT_EQ(errors[2].rfind("planted.json: uavs[0].v_max: expected a positive number", 0), 0u);
  EXPECT_NE(errors[2].find("(line 8)"), std::string::npos) << errors[2];
  EXPECT_EQ(errors[3].rfind("planted.json: tracking.sigma_a: expected", 0), 0u) << errors[3];
  EXPECT_NE(errors[3].find("(line 13)"), std::string::npos) << errors[3];
  EXPECT_EQ(errors[4].rfind("planted.json: bogus: unknown field", 0), 0u) << errors[4];
  EXPECT_NE(errors[4].find("(line 14)"), std::string::npos) << errors[4];
}

TEST(EveryError, FourErrorsInOneSectionGiveFourLines) {
  const std::vector<std::string> errors = errorsOf(scenarioWith({
      {7, "    \"start\": [10, 10], \"yaw\": true,"},
      {8, "    \"v_max\": -3,"},
      {9, "    \"quality\": \"good\", \"speeed\": 2,"},
  }));
  ASSERT_EQ(errors.size(), 4u) << ::testing::PrintToString(errors);
  EXPECT_NE(errors[0].find("uavs[0].yaw"), std::string::npos) << errors[0];
  EXPECT_NE(errors[0].find("(line 7)"), std::string::npos);
  EXPECT_NE(errors[1].find("uavs[0].v_max"), std::string::npos) << errors[1];
  EXPECT_NE(errors[2].find("uavs[0].quality"), std::string::npos) << errors[2];
  EXPECT_NE(errors[3].find("uavs[0].speeed: unknown field"), std::string::npos) << errors[3];
  EXPECT_NE(errors[3].find("(line 9)"), std::string::npos);
}

TEST(EveryError, EveryBadOverrideIsReportedWithTheFileErrors) {
  LoadOptions options;
  options.overrides = {"clock.dt=-2", "uavs.0.v_max=-1", "tracking.sigma_a=\"x\""};
  options.text_is_the_file = true;
  try {
    loadScenarioText(scenarioWith({}), "planted.json", options);
    FAIL() << "loaded";
  } catch (const ScenarioErrors& e) {
    EXPECT_EQ(e.errors().size(), 3u) << e.what();
  }
}

TEST(EveryError, LinesOfEveryFieldPathAreFoundInTheText) {
  const std::map<std::string, int> lines = jsonValueLines(
      "// a comment with { and [\n{\"a\": 1,\n \"b\": [\n  {\"c\": \"x]\\\"\"},\n  2],\n"
      " /* block\n */ \"d\": {\"e\": null}}");
  EXPECT_EQ(lines.at("a"), 2);
  EXPECT_EQ(lines.at("b"), 3);
  EXPECT_EQ(lines.at("b[0]"), 4);
  EXPECT_EQ(lines.at("b[0].c"), 4);
  EXPECT_EQ(lines.at("b[1]"), 5);
  EXPECT_EQ(lines.at("d"), 7);
  EXPECT_EQ(lines.at("d.e"), 7);
}

}  // namespace
}  // namespace canopy::spec
