// Golden determinism: the bytes of record.jsonl for fixed runs, against hashes stored in
// tests/data/record_golden/cases.json. Regenerate deliberately with
//   CANOPY_UPDATE_GOLDENS=1 build/release/tests/sim/sim_test --gtest_filter='Golden.*'
// (see the README.md there).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "core/random.h"
#include "core/text_file.h"
#include "sim/run.h"
#include "spec/loader.h"

namespace canopy::sim {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

const fs::path kCases =
    fs::path(CANOPY_SOURCE_DIR) / "tests" / "data" / "record_golden" / "cases.json";

std::string hex(std::uint64_t value) {
  std::ostringstream text;
  text << std::hex << std::setw(16) << std::setfill('0') << value;
  return text.str();
}

// record.jsonl of one case, run into a fresh directory.
std::string recordOf(const Json& c) {
  spec::LoadOptions load;
  load.overrides = c.at("set").get<std::vector<std::string>>();
  const spec::ScenarioSpec spec = spec::loadScenario(c.at("scenario").get<std::string>(), load);
  const fs::path dir =
      fs::temp_directory_path() /
      ("canopy_golden_" + c.at("name").get<std::string>() + "_" + std::to_string(::getpid()));
  RunOptions options;
  options.out_dir = dir;
  runScenario(spec, options);
  const std::optional<std::string> record = readTextFile(dir / "record.jsonl");
  fs::remove_all(dir);
  return record.value_or("");
}

TEST(Golden, RecordsMatchTheirStoredHashes) {
  const bool update = std::getenv("CANOPY_UPDATE_GOLDENS") != nullptr;
  const std::optional<std::string> text = readTextFile(kCases);
  ASSERT_TRUE(text) << kCases;
  Json cases = Json::parse(*text);
  ASSERT_FALSE(cases.at("cases").empty());
  for (Json& c : cases.at("cases")) {
    const std::string record = recordOf(c);
    ASSERT_FALSE(record.empty());
    const std::string hash = hex(fnv1a64(record));
    if (update) {
      c["fnv1a64"] = hash;
      c["bytes"] = record.size();
      continue;
    }
    EXPECT_EQ(hash, c.at("fnv1a64").get<std::string>())
        << c.at("name") << ": record.jsonl changed (" << record.size() << " bytes, stored "
        << c.at("bytes") << "); if the change is meant, regenerate as "
        << "tests/data/record_golden/README.md says";
  }
  if (update) {
    std::ofstream(kCases, std::ios::binary | std::ios::trunc) << cases.dump(2) << "\n";
    std::printf("updated %s\n", kCases.c_str());
  }
}

}  // namespace
}  // namespace canopy::sim
