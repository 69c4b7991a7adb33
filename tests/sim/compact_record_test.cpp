// The compact record (record.jsonl.zst) against the plain one: one run writes both (a second
// Recorder in --record jsonl beside the run's own compact one, of steps: index version 2), and
// the compact form decoded by canopy's reader is the plain file byte for byte; the same lines as
// a version-1 file (lines in zstd frames) decode alike, also by zstd's own streaming decoder that
// knows nothing of the index; a step range decodes only its blocks; broken files are errors that
// name the file.
#include "sim/compact_record.h"

#include <gtest/gtest.h>
#include <unistd.h>
#include <zstd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/text_file.h"
#include "sim/record_lines.h"
#include "sim/record_reader.h"
#include "sim/record_slice.h"
#include "sim/recorder.h"
#include "sim/run.h"
#include "spec/error.h"
#include "spec/loader.h"

namespace canopy::sim::compact_record_test {  // named: the sanitizer's unity build merges files
namespace {
namespace fs = std::filesystem;

fs::path freshDir(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("canopy_compact_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// zstd's streaming decoder over the whole file: every frame in turn, skippable frames (the
// index) skipped, as `zstd -dc` does.
std::string zstdDecodeAll(const std::string& bytes) {
  ZSTD_DStream* stream = ZSTD_createDStream();
  ZSTD_inBuffer in{bytes.data(), bytes.size(), 0};
  std::string text;
  std::vector<char> chunk(ZSTD_DStreamOutSize());
  while (in.pos < in.size) {
    ZSTD_outBuffer out{chunk.data(), chunk.size(), 0};
    const std::size_t result = ZSTD_decompressStream(stream, &out, &in);
    EXPECT_FALSE(ZSTD_isError(result)) << ZSTD_getErrorName(result);
    if (ZSTD_isError(result)) break;
    text.append(chunk.data(), out.pos);
  }
  ZSTD_freeDStream(stream);
  return text;
}

std::string linesOf(const fs::path& record, const LineRange& range = {}) {
  std::string text;
  forEachRecordLine(record, range, [&](const std::string& line, int) { text += line + '\n'; });
  return text;
}

struct BothForms {
  std::string plain;  // record.jsonl of the --record jsonl recorder
  fs::path compact;   // the run's record.jsonl.zst
  fs::path dir;
};

// One run of `name` (overrides `set`) writing the compact form in blocks of `lines` lines, and
// beside it the plain form from the same steps.
BothForms runBoth(const std::string& name, std::vector<std::string> set, std::uint32_t lines) {
  spec::LoadOptions load;
  load.overrides = std::move(set);
  const spec::ScenarioSpec spec = spec::loadScenario(name, load);
  BothForms both;
  both.dir = freshDir(name);
  const fs::path plain_dir = both.dir / "plain";
  fs::create_directories(plain_dir);
  Recorder plain(plain_dir, spec, RecordFormat::jsonl);
  RunOptions options;
  options.out_dir = both.dir / "compact";
  options.command_line = "test";
  options.observers = {&plain};
  options.record = RecordFormat::compact;
  options.record_blocks = {std::size_t{1} << 30, lines};
  runScenario(spec, options);
  plain.commit();
  both.plain = slurp(plain_dir / "record.jsonl");
  both.compact = recordFileOf(options.out_dir);
  return both;
}

// Each paper scenario and mixed_team, whole: decoded, the compact record is the plain one.
TEST(CompactRecord, DecodesToThePlainLinesOfThePaperScenariosAndMixedTeam) {
  for (const std::string name : {"joint_effect", "occlusion_sharing", "resource_allocation",
                                 "trajectory_handover", "mixed_team"}) {
    SCOPED_TRACE(name);
    const BothForms both = runBoth(name, {}, 16);
    EXPECT_EQ(both.compact.filename(), "record.jsonl.zst");
    EXPECT_FALSE(fs::exists(both.compact.parent_path() / "record.jsonl"));
    const std::string bytes = slurp(both.compact);
    ASSERT_FALSE(both.plain.empty());
    EXPECT_EQ(linesOf(both.compact), both.plain);
    EXPECT_LT(bytes.size(), both.plain.size() / 4);  // compressed, not copied
    const CompactRecordReader reader(both.compact);
    EXPECT_EQ(reader.version(), 2u);
    // The same lines as a version-1 file: zstd alone gives them back.
    const std::string lines = compactRecordOf(both.plain, {std::size_t{1} << 20, 16});
    EXPECT_EQ(zstdDecodeAll(lines), both.plain);
    {
      const fs::path v1 = both.dir / "v1.zst";
      std::ofstream(v1, std::ios::binary) << lines;
      EXPECT_EQ(CompactRecordReader(v1).version(), 1u);
      EXPECT_EQ(linesOf(v1), both.plain);
    }
    const auto steps =
        static_cast<std::uint64_t>(std::count(both.plain.begin(), both.plain.end(), '\n'));
    EXPECT_EQ(reader.lines(), steps);
    EXPECT_EQ(reader.blocks().size(), (steps + 15) / 16);
    fs::remove_all(both.dir);
  }
}

// The plain lines from..to−1 of `text`.
std::string plainLines(const std::string& text, std::size_t from, std::size_t to) {
  std::size_t begin = 0;
  for (std::size_t i = 0; i < from; ++i) begin = text.find('\n', begin) + 1;
  std::size_t end = begin;
  for (std::size_t i = from; i < to; ++i) end = text.find('\n', end) + 1;
  return text.substr(begin, end - begin);
}

TEST(CompactRecord, AStepRangeDecodesOnlyTheBlocksThatHoldIt) {
  const BothForms both = runBoth("demo", {"clock.duration=6"}, 5);  // 31 steps, 7 blocks
  EXPECT_EQ(linesOf(both.compact, {7, 13}), plainLines(both.plain, 7, 13));
  EXPECT_EQ(linesOf(both.compact, {30, 99}), plainLines(both.plain, 30, 31));
  EXPECT_EQ(linesOf(both.compact, {40, 50}), "");
  // The truth reader's range, against its whole read.
  const std::vector<world::WorldSnapshot> all = readRun(both.compact.parent_path()).truth;
  const std::vector<world::WorldSnapshot> some = readRun(both.compact.parent_path(), {9, 12}).truth;
  ASSERT_EQ(all.size(), 31u);
  ASSERT_EQ(some.size(), 3u);
  EXPECT_EQ(some[0].step, 9);
  EXPECT_EQ(some[2].uavs[0].position, all[11].uavs[0].position);

  // Block 0's frame (lines 0–4) broken: a range after it still reads, one with it does not.
  std::string bytes = slurp(both.compact);
  const CompactRecordReader before(both.compact);
  bytes[before.blocks()[0].offset + before.blocks()[0].compressed / 2] ^= 0x5A;
  std::ofstream(both.compact, std::ios::binary | std::ios::trunc) << bytes;
  EXPECT_EQ(linesOf(both.compact, {5, 10}), plainLines(both.plain, 5, 10));
  EXPECT_THROW(linesOf(both.compact, {3, 6}), spec::ScenarioError);
  fs::remove_all(both.dir);
}

// What reading `bytes` as a compact record says.
std::string errorOf(const std::string& bytes) {
  const fs::path dir = freshDir("broken");
  fs::create_directories(dir);
  std::ofstream(dir / "record.jsonl.zst", std::ios::binary) << bytes;
  std::string what;
  try {
    linesOf(dir / "record.jsonl.zst");
  } catch (const spec::ScenarioError& e) {
    what = e.what();
  }
  fs::remove_all(dir);
  return what;
}

TEST(CompactRecord, BrokenFilesAreErrorsNamingTheFileAndThePart) {
  const std::string jsonl = "{\"k\":0}\n{\"k\":1}\n{\"k\":2}\n";
  const std::string good = compactRecordOf(jsonl, {1 << 20, 2});
  EXPECT_EQ(errorOf(good), "");
  EXPECT_EQ(zstdDecodeAll(good), jsonl);
  EXPECT_NE(errorOf("").find("record.jsonl.zst: expected a step index"), std::string::npos);
  EXPECT_NE(errorOf(good.substr(0, good.size() - 1)).find("index"), std::string::npos);
  EXPECT_NE(errorOf(good.substr(1)).find("expected a frame that ends before the index"),
            std::string::npos);
  std::string lines = good;
  const std::size_t count = lines.size() - 12 - 24 + 20;  // entry 1's line count
  lines[count] = 5;
  EXPECT_NE(errorOf(lines).find("frame 1: expected 5 lines"), std::string::npos) << errorOf(lines);
  // A refused file is closed: no descriptor is left open by a reader that threw.
  const auto open_files = [] {
    return std::distance(fs::directory_iterator("/proc/self/fd"), fs::directory_iterator{});
  };
  const auto before = open_files();
  for (int i = 0; i < 20; ++i) errorOf(good.substr(0, good.size() - 1));
  EXPECT_EQ(open_files(), before);
    // A link where the record goes is refused, not followed.
  const fs::path dir = freshDir("link");
  fs::create_directories(dir);
  std::ofstream(dir / "real.zst", std::ios::binary) << good;
  fs::create_symlink(dir / "real.zst", dir / "record.jsonl.zst");
  EXPECT_THROW(linesOf(dir / "record.jsonl.zst"), spec::ScenarioError);
  fs::remove_all(dir);
}

TEST(CompactRecord, CityScaleIsCompactByDefaultThePaperScenariosArePlain) {
  EXPECT_EQ(resolveRecordFormat(RecordFormat::automatic, spec::loadScenario("city_swarm")),
            RecordFormat::compact);
  for (const std::string name : {"demo", "joint_effect", "occlusion_sharing", "resource_allocation",
                                 "trajectory_handover", "mixed_team"}) {
    EXPECT_EQ(resolveRecordFormat(RecordFormat::automatic, spec::loadScenario(name)),
              RecordFormat::jsonl)
        << name;
  }
  EXPECT_EQ(resolveRecordFormat(RecordFormat::jsonl, spec::loadScenario("city_swarm")),
            RecordFormat::jsonl);
}

// --agent: each line's "agents" and "scans" are agent I's entry of the whole line; every other
// key is the whole line's.
TEST(CompactRecord, AnAgentsSliceIsItsEntryOfTheWholeLine) {
  const BothForms both = runBoth("mixed_team", {"clock.duration=2"}, 4);
  const std::string line = both.plain.substr(0, both.plain.find('\n'));
  const nlohmann::json whole = nlohmann::json::parse(line);
  ASSERT_GE(whole["agents"].size(), 2u);
  for (std::size_t i = 0; i < whole["agents"].size(); ++i) {
    const std::optional<std::string> slice = agentSlice(line, i);
    ASSERT_TRUE(slice) << i;
    const nlohmann::json part = nlohmann::json::parse(*slice);
    EXPECT_EQ(part["agents"], nlohmann::json::array({whole["agents"][i]}));
    EXPECT_EQ(part["scans"], nlohmann::json::array({whole["scans"][i]}));
    nlohmann::json rest = whole, rest_part = part;
    for (const char* key : {"agents", "scans"}) {
      rest.erase(key);
      rest_part.erase(key);
    }
    EXPECT_EQ(rest_part, rest);
  }
  EXPECT_FALSE(agentSlice(line, whole["agents"].size()));
  EXPECT_FALSE(agentSlice("{\"k\":1}", 0));
  fs::remove_all(both.dir);
}

}  // namespace
}  // namespace canopy::sim::compact_record_test
