// `canopy record` and the readers of a compact record end to end: the same run written with
// --record compact and --record jsonl; `canopy record` prints the plain file's bytes from either,
// a step range is those lines, and coverage and the replay page read both forms alike.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "tests/app/cli.h"

namespace canopy::cli_test::record_cli {  // named: the sanitizer's unity build merges files
namespace {

// Lines from..to−1 of `text`.
std::string lines(const std::string& text, std::size_t from, std::size_t to) {
  std::size_t begin = 0;
  for (std::size_t i = 0; i < from; ++i) begin = text.find('\n', begin) + 1;
  std::size_t end = begin;
  for (std::size_t i = from; i < to; ++i) end = text.find('\n', end) + 1;
  return text.substr(begin, end - begin);
}

TEST(RecordCli, PrintsThePlainLinesFromEitherFormAndEveryReaderReadsBoth) {
  const fs::path dir = fresh("record");
  const std::string run = "run demo --set clock.duration=4 --out ";
  ASSERT_EQ(runIn(dir, run + "c --record compact").code, 0);
  ASSERT_EQ(runIn(dir, run + "j --record jsonl").code, 0);
  EXPECT_TRUE(fs::exists(dir / "c" / "record.jsonl.zst"));
  EXPECT_FALSE(fs::exists(dir / "c" / "record.jsonl"));
  const std::string plain = slurp(dir / "j" / "record.jsonl");
  ASSERT_EQ(std::count(plain.begin(), plain.end(), '\n'), 21);

  const Outcome compact = runIn(dir, "record c");
  EXPECT_EQ(compact.code, 0) << compact.err;
  EXPECT_EQ(compact.out, plain);
  EXPECT_EQ(runIn(dir, "record j").out, plain);
  EXPECT_EQ(runIn(dir, "record c --steps 3:7").out, lines(plain, 3, 7));
  EXPECT_EQ(runIn(dir, "record c --steps 19:").out, lines(plain, 19, 21));
  EXPECT_EQ(runIn(dir, "record c --steps :2").out, lines(plain, 0, 2));
  // demo's two UAVs: each slice is one line per step, shorter than the whole line, starting as
  // it does (its "agents" list comes first); sim/compact_record_test.cpp checks the slice's keys.
  const std::string first = lines(plain, 0, 1);
  for (const char* agent : {"0", "1"}) {
    const Outcome slice = runIn(dir, std::string("record c --steps 0:1 --agent ") + agent);
    EXPECT_EQ(slice.code, 0) << slice.err;
    EXPECT_LT(slice.out.size(), first.size());
    EXPECT_EQ(slice.out.rfind("{\"agents\":[{", 0), 0u);
    EXPECT_EQ(slice.out.back(), '\n');
  }

  // A run again in the same folder with the other form leaves only that form.
  ASSERT_EQ(runIn(dir, run + "c --record jsonl").code, 0);
  EXPECT_FALSE(fs::exists(dir / "c" / "record.jsonl.zst"));
  ASSERT_EQ(runIn(dir, run + "c --record compact").code, 0);
  EXPECT_FALSE(fs::exists(dir / "c" / "record.jsonl"));

  const Outcome coverage = runIn(dir, "coverage c");
  EXPECT_EQ(coverage.code, 0) << coverage.err;
  EXPECT_EQ(coverage.out, runIn(dir, "coverage j").out);
  // coverage --steps: the header and the rows of those steps.
  const std::string all = coverage.out, header = all.substr(0, all.find('\n') + 1);
  const std::string rows = all.substr(header.size());
  EXPECT_EQ(runIn(dir, "coverage c --steps 3:7").out, header + lines(rows, 3, 7));
  EXPECT_EQ(runIn(dir, "coverage j --steps 3:7").out, header + lines(rows, 3, 7));
  const Outcome page = runIn(dir, "view c --out -");
  EXPECT_EQ(page.code, 0) << page.err;
  EXPECT_EQ(page.out, runIn(dir, "view j --out -").out);

  for (const auto& [args, says] : std::vector<std::pair<std::string, std::string>>{
           {"record c --steps 5:2", "--steps: expected A:B"},
           {"record c --agent 3", "--agent"},
           {"coverage c --steps 1:2 --check g.csv", "--steps: does not apply with --check"},
           {"record missing", "missing: no such directory"},
           {"run demo --record zip", "--record: expected auto, jsonl or compact"}}) {
    const Outcome o = runIn(dir, args);
    EXPECT_EQ(o.code, 2) << args;
    EXPECT_NE(o.err.find(says), std::string::npos) << args << ": " << o.err;
  }
  fs::remove_all(dir);
}

// The budget sizes the record `--record auto` writes: past 6.4e7 bytes of record.jsonl the compact
// form, a 20th of it. One UAV over ten people for 10⁶ steps: record.jsonl estimated at
// 10⁶ × (1000 + 600 × 10) = 7.0e9 bytes, over the 4e9 limit; written compact, 3.5e8. Admitted;
// the same run asked for as plain lines is refused before anything is written.
TEST(RecordCli, PlainLinesPastTheLimitAreRefusedWhereTheCompactRecordIsAdmitted) {
  const fs::path dir = fresh("record-limit");
  fs::create_directories(dir);
  std::string people;
  for (int i = 0; i < 10; ++i) {
    people += std::string(i ? ", " : "") + R"({"path": {"start": [)" + std::to_string(20 + i) +
              R"(, 20], "velocity": [0, 0]}})";
  }
  std::ofstream(dir / "long.json") << (R"({"aoi": [0, 0, 100, 50], "uavs": [{"start": [10, 10]}],
    "targets": [)" + people + R"(], "clock": {"dt": 0.01, "duration": 10000}})");
  EXPECT_EQ(runIn(dir, "validate long.json").code, 0);
  const Outcome plain = runIn(dir, "run long.json --record jsonl --out p");
  EXPECT_EQ(plain.code, 2);
  EXPECT_NE(plain.err.find("--record: jsonl: expected at most 4.0e+09 bytes of record.jsonl"),
            std::string::npos)
      << plain.err;
  EXPECT_NE(plain.err.find("about 7.0e+09"), std::string::npos) << plain.err;
  EXPECT_FALSE(fs::exists(dir / "p"));
}

}  // namespace
}  // namespace canopy::cli_test::record_cli
