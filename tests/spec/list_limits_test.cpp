// Lists whose length alone bounds the work (uavs, targets, occluders) are refused while the text
// is parsed, at the first element past the limit. That the parse stops there is shown without a
// clock: what follows that element is not JSON at all, and the error is the limit's, not a
// syntax error (the parser never reached the garbage).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "spec/error.h"
#include "spec/json_text.h"
#include "spec/loader.h"

namespace canopy::spec {
namespace {

std::string repeated(const std::string& element, std::size_t n) {
  std::string text;
  for (std::size_t i = 0; i < n; ++i) text += (i ? "," : "") + element;
  return text;
}

const std::vector<ArrayLimit> kThree = {{"list", 3, "too long"}};

TEST(ListLimits, TheLimitedArrayCountsItsOwnElementsOnly) {
  // Three elements pass, whatever they hold (nested arrays and objects are one element each).
  EXPECT_NO_THROW(parseBoundedJson(R"({"list": [[1, 2, 3, 4], {"a": [5, 6, 7, 8]}, 9]})", kThree));
  // Other keys, and the same key deeper down, are not limited.
  EXPECT_NO_THROW(parseBoundedJson(R"({"other": [1, 2, 3, 4], "x": {"list": [1, 2, 3, 4]}})",
                                   kThree));
  EXPECT_NO_THROW(parseBoundedJson(R"([1, 2, 3, 4, 5])", kThree));  // no limit on the root
  EXPECT_THROW(parseBoundedJson(R"({"list": [1, [2], {"3": 3}, null]})", kThree),
               JsonArrayTooLong);
  // A limit on the document itself (key ""): a bare list, not an object's key "".
  const std::vector<ArrayLimit> root = {{"", 2, "too long"}};
  EXPECT_THROW(parseBoundedJson("[[1, 2, 3], 4, 5]", root), JsonArrayTooLong);
  EXPECT_NO_THROW(parseBoundedJson("[[1, 2, 3], {\"a\": [4, 5, 6]}]", root));
  EXPECT_NO_THROW(parseBoundedJson(R"({"": [1, 2, 3], "b": 4, "c": 5})", root));
}

TEST(ListLimits, TheParseStopsAtTheFirstElementPastTheLimit) {
  // The fourth element is the last thing read: the unterminated garbage after it never is.
  const std::string text = R"({"list": [1, 2, 3, 4, )" + std::string(1000, '@');
  EXPECT_THROW(parseBoundedJson(text, kThree), JsonArrayTooLong);
  EXPECT_THROW(parseBoundedJson(text), nlohmann::json::parse_error);  // without the limit
}

// A scenario of `targets` targets, `uavs` UAVs and `discs` disc occluders, then `tail`.
std::string scenario(std::size_t uavs, std::size_t targets, std::size_t discs,
                     const std::string& tail = "]}") {
  return R"({"aoi": [0, 0, 100, 100], "uavs": [)" + repeated(R"({"start": [1, 1]})", uavs) +
         R"(], "occluders": [)" +
         repeated(R"({"type": "disc", "centre": [50, 50], "radius": 1})", discs) +
         R"(], "targets": [)" +
         repeated(R"({"path": {"start": [5, 5], "velocity": [0, 0]}})", targets) + tail;
}

ScenarioError loadError(const std::string& text, const LoadOptions& options = {}) {
  try {
    loadScenarioText(text, "big.json", options);
  } catch (const ScenarioError& e) {
    return e;
  }
  return ScenarioError("", "", "loaded");
}

TEST(ListLimits, AScenarioListPastItsLimitIsRefusedNamingTheFieldBeforeTheRestIsRead) {
  const std::string garbage = std::string(100, '@');
  // 100 001 targets: refused at the last, the garbage after it unread.
  ScenarioError e = loadError(scenario(1, 100001, 0, ", " + garbage));
  EXPECT_EQ(e.file(), "big.json");
  EXPECT_EQ(e.field(), "targets") << e.what();
  EXPECT_NE(e.message().find("0 to 100000 elements, got more than 100000"), std::string::npos)
      << e.message();
  e = loadError(scenario(257, 1, 0, garbage));
  EXPECT_EQ(e.field(), "uavs") << e.what();
  EXPECT_NE(e.message().find("1 to 256 elements, got more than 256"), std::string::npos);
  // 256 UAVs are allowed (refused here only for the garbage after them).
  EXPECT_NE(loadError(scenario(256, 1, 0, garbage)).message().find("invalid JSON"),
            std::string::npos);

  // Occluders: the tree budget, scaled by --budget (2·10⁶ × 1e-5 = 20 entries).
  LoadOptions small;
  small.budget_scale = 1e-5;
  e = loadError(scenario(1, 1, 21, garbage), small);
  EXPECT_EQ(e.field(), "occluders") << e.what();
  EXPECT_NE(e.message().find("at most 20 occluder entries"), std::string::npos) << e.message();
  EXPECT_NE(e.message().find("--budget K"), std::string::npos);
  // 20 are read on to the garbage (the other budgets, also scaled, are not the subject here).
  EXPECT_NE(loadError(scenario(1, 1, 20, garbage), small).message().find("invalid JSON"),
            std::string::npos);
}

TEST(ListLimits, AListThatAnOverrideReplacesIsNotRefusedForItsFileLength) {
  LoadOptions options;
  options.overrides = {"targets=[]"};
  EXPECT_EQ(loadScenarioText(scenario(1, 100001, 0), "big.json", options).targets.size(), 0u);
  options.overrides = {"targets.0.name=x"};  // an edit inside it does not replace it
  EXPECT_EQ(loadError(scenario(1, 100001, 0), options).field(), "targets");
}

TEST(ListLimits, AnIncludedLayoutPastTheTreeBudgetIsRefusedNamingTheInclude) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "canopy_list_limits";
  fs::create_directories(dir);
  std::ofstream(dir / "layout.json")
      << "[" << repeated(R"({"type": "disc", "centre": [50, 50], "radius": 1})", 21) << ", @@@";
  std::ofstream(dir / "scenario.json")
      << R"({"aoi": [0, 0, 100, 100], "uavs": [{"start": [1, 1]}],)"
      << R"( "occluders": [{"include": "layout.json"}]})";
  LoadOptions small;
  small.budget_scale = 1e-5;
  try {
    loadScenario((dir / "scenario.json").string(), small);
    ADD_FAILURE() << "loaded";
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.field(), "occluders[0].include") << e.what();
    EXPECT_NE(e.message().find("at most 20 occluder entries"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace canopy::spec
