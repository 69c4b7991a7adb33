// Every input a fuzzer found (tests/data/fuzz_regressions/TARGET/) and every seed
// (fuzz/corpus/TARGET/) goes through the fuzz target's own entry point (fuzz/inputs.h): it must
// load or fail with a ScenarioError. Another exception fails the case; a crash fails the
// executable, and the sanitize preset adds leaks and undefined behaviour.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "core/text_file.h"
#include "fuzz/inputs.h"

namespace canopy::fuzz {
namespace {
namespace fs = std::filesystem;

struct Input {
  std::string target;
  fs::path file;
  bool seed = false;  // from fuzz/corpus/
};

const fs::path kSource = CANOPY_SOURCE_DIR;

// The regular files directly in `dir` (not those of pending/, found but not fixed yet), sorted.
std::vector<fs::path> filesIn(const fs::path& dir) {
  std::vector<fs::path> files;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(dir, error)) {
    if (entry.is_regular_file() && entry.path().filename() != "README.md")
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Findings (seed = false) and seeds (seed = true), target by target.
std::vector<Input> inputs(bool seeds) {
  std::vector<Input> all;
  for (const Target& target : targets()) {
    const fs::path dir = seeds ? kSource / "fuzz/corpus" / target.name
                               : kSource / "tests/data/fuzz_regressions" / target.name;
    for (const fs::path& file : filesIn(dir)) all.push_back({target.name, file, seeds});
  }
  return all;
}

// GoogleTest prints the parameter of a failing case with this.
void PrintTo(const Input& input, std::ostream* out) {
  *out << input.file.string();
}

std::string caseName(const testing::TestParamInfo<Input>& info) {
  std::string name = info.param.target + "_" + info.param.file.filename().string();
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

const Target& targetNamed(const std::string& name) {
  const auto& all = targets();
  return *std::find_if(all.begin(), all.end(), [&](const Target& t) { return t.name == name; });
}

std::string bytesOf(const fs::path& file) {
  const auto text = readTextFile(file);
  EXPECT_TRUE(text.has_value()) << file;
  return text.value_or("");
}

class FuzzInputs : public testing::TestWithParam<Input> {};

TEST_P(FuzzInputs, LoadOrFailWithScenarioError) {
  const Input& input = GetParam();
  const std::string data = bytesOf(input.file);
  EXPECT_NO_THROW(targetNamed(input.target).run(data)) << input.file;
}

INSTANTIATE_TEST_SUITE_P(Found, FuzzInputs, testing::ValuesIn(inputs(false)), caseName);
INSTANTIATE_TEST_SUITE_P(Seed, FuzzInputs, testing::ValuesIn(inputs(true)), caseName);

// A seed that the loader refuses would steer the fuzzer only into error paths, unless it is
// meant to (its name starts with "bad_").
class FuzzSeeds : public testing::TestWithParam<Input> {};

TEST_P(FuzzSeeds, LoadUnlessNamedBad) {
  const Input& input = GetParam();
  const bool bad = input.file.filename().string().rfind("bad_", 0) == 0;
  EXPECT_EQ(targetNamed(input.target).run(bytesOf(input.file)), !bad) << input.file;
}

INSTANTIATE_TEST_SUITE_P(Seed, FuzzSeeds, testing::ValuesIn(inputs(true)), caseName);

TEST(FuzzInputs, EveryTargetHasSeeds) {
  for (const Target& target : targets())
    EXPECT_FALSE(filesIn(kSource / "fuzz/corpus" / target.name).empty()) << target.name;
}

}  // namespace
}  // namespace canopy::fuzz
