// `canopy record` and the readers of a compact record end to end: the same run written with
// --record compact and --record jsonl; `canopy record` prints the plain file's bytes from either,
// a step range is those lines, and coverage and the replay page read both forms alike.
#include <gtest/gtest.h>

#include <algorithm>
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

}  // namespace
}  // namespace canopy::cli_test::record_cli
