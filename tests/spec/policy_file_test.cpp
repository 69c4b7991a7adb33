// Policy files (issue 54): a good file reads; every hostile one is a ScenarioError naming the file
// and the field, never a crash.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "spec/error.h"
#include "spec/policy_file.h"

namespace canopy::spec {
namespace {

std::string row(int n, double x) {
  std::string s = "[";
  for (int i = 0; i < n; ++i) s += (i ? "," : "") + std::to_string(x);
  return s + "]";
}

std::string layer(int out, int in, double x) {
  std::string w = "[";
  for (int i = 0; i < out; ++i) w += (i ? "," : "") + row(in, x);
  return "{\"weight\": " + w + "], \"bias\": " + row(out, 0.0) + "}";
}

// A valid file: track 11 → 3, mate 7 → 2, head 31 + 6 + 4 = 41 → 2.
std::string goodFile() {
  return "{\"format\": \"canopy-policy\", \"version\": 1,\n"
         " \"features\": {\"self\": 31, \"track\": 11, \"mate\": 7},\n"
         " \"layers\": {\"track\": [" + layer(3, 11, 0.1) + "],\n"
         "            \"mate\": [" + layer(2, 7, 0.2) + "],\n"
         "            \"head\": [" + layer(2, 41, 0.01) + "]},\n"
         " \"training\": {\"anything\": [1, 2]}}";
}

std::string fieldOf(const std::string& text) {
  try {
    parsePolicy(text, "p.json");
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.file(), "p.json");
    return e.field();
  }
  return "(accepted)";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(PolicyFile, AGoodFileReads) {
  const auto net = parsePolicy(goodFile(), "p.json");
  EXPECT_EQ(net->track.size(), 1u);
  EXPECT_EQ(net->head[0].weight.cols(), 41);
  EXPECT_DOUBLE_EQ(net->mate[0].weight(1, 6), 0.2);
  EXPECT_EQ(net->file, "p.json");
}

TEST(PolicyFile, EachMistakeNamesItsField) {
  const std::string good = goodFile();
  EXPECT_EQ(fieldOf(replaced(good, "canopy-policy", "other")), "format");
  EXPECT_EQ(fieldOf(replaced(good, "\"version\": 1", "\"version\": 2")), "version");
  EXPECT_EQ(fieldOf(replaced(good, "\"track\": 11", "\"track\": 12")), "features.track");
  EXPECT_EQ(fieldOf(replaced(good, "\"self\": 31, ", "")), "features.self");
  EXPECT_EQ(fieldOf(replaced(good, "\"training\"", "\"trainin\"")), "trainin");
  EXPECT_EQ(fieldOf(replaced(good, "[0.200000,", "[\"x\",")), "layers.mate[0].weight[0][0]");
  EXPECT_EQ(fieldOf(replaced(good, "\"mate\": [", "\"mate\": [[], ")), "layers.mate[0]");
  // The head's input must be 31 + 2·3 + 2·2 = 41.
  EXPECT_EQ(fieldOf(replaced(good, layer(2, 41, 0.01), layer(2, 40, 0.01))),
            "layers.head[0].weight");
  EXPECT_EQ(fieldOf(replaced(good, layer(2, 41, 0.01), layer(3, 41, 0.01))),
            "layers.head[0].weight");
  EXPECT_EQ(fieldOf("[1, 2]"), "");
  EXPECT_EQ(fieldOf(std::string(200, '[')), "");  // too deep: the JSON reader's error
  EXPECT_EQ(fieldOf(good.substr(0, good.size() / 2)).rfind("line 5, column", 0), 0u);  // cut short
}

// Random byte edits of a good file: each is read or refused with a ScenarioError, nothing else.
TEST(PolicyFile, SurvivesRandomEdits) {
  const std::string good = goodFile();
  std::mt19937 rng(54);
  const std::string alphabet = "[]{},:\"0123456789.-e ntruefalsx";
  int refused = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::string text = good;
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = rng() % text.size();
      switch (rng() % 3) {
        case 0: text[at] = alphabet[rng() % alphabet.size()]; break;
        case 1: text.erase(at, 1 + rng() % 8); break;
        default: text.insert(at, 1, alphabet[rng() % alphabet.size()]); break;
      }
    }
    try {
      const auto net = parsePolicy(text, "p.json");
      EXPECT_EQ(net->shapeError(), "");
    } catch (const ScenarioError&) {
      ++refused;
    }
  }
  EXPECT_GT(refused, 1000);
}

}  // namespace
}  // namespace canopy::spec
