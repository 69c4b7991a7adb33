// Hostile outputs end to end: names that would leave out/, links planted in --out, a disk that
// fills mid-run, and messages that quote the user's bytes.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/app/cli.h"

namespace canopy::cli_test {
namespace {

// A small valid scenario: 4 s at 0.2 s, 21 records; `name` is spliced in as JSON text.
std::string tinyScenario(const std::string& name_json, double duration = 4.0) {
  return R"({"name": )" + name_json +
         R"(, "aoi": [0, 0, 100, 50], "clock": {"dt": 0.2, "duration": )" +
         std::to_string(duration) +
         R"(}, "uavs": [{"start": [10, 10]}], "targets": [{"path": {"start": [20, 20], "velocity": [1, 0]}}]})";
}

void writeText(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

// Every path under `dir` (recursively, links not followed), relative to it.
std::set<std::string> tree(const fs::path& dir) {
  std::set<std::string> paths;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    paths.insert(fs::relative(entry.path(), dir).string());
  return paths;
}

// `raw` as one shell word whatever its bytes, for /bin/sh (dash has no $'...'): every byte as an
// octal escape of printf.
std::string word(const std::string& raw) {
  std::string escaped;
  for (const char c : raw) {
    char octal[8];
    std::snprintf(octal, sizeof octal, "\\%03o", static_cast<unsigned char>(c));
    escaped += octal;
  }
  return "\"$(printf '" + escaped + "')\"";
}

bool hasControlBytes(const std::string& text) {
  return std::any_of(text.begin(), text.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return (u < 0x20 && u != '\n') || u == 0x7F;
  });
}

// No library's own wording reaches the user.
void expectNoLibraryText(const std::string& text) {
  for (const char* library : {"json.exception", "stoull", "filesystem error", "basic_string"})
    EXPECT_EQ(text.find(library), std::string::npos) << library << " in: " << text;
}

class Outputs : public testing::Test {
 protected:
  void SetUp() override {
    base_ = fresh(std::string("outputs_") +
                  testing::UnitTest::GetInstance()->current_test_info()->name() + "_" +
                  std::to_string(::getpid()));
  }
  void TearDown() override { fs::remove_all(base_); }
  fs::path base_;
};

// The scenario's name builds the default output directory out/NAME: whatever the name, the run
// writes exactly one directory inside out/ of the working directory and nothing anywhere else.
TEST_F(Outputs, ScenarioNamesStayUnderTheOutputRoot) {
  const std::vector<std::string> names = {
      R"("../../x")", R"("..")", R"(".")", R"("a/b")", R"("/tmp/abs")", R"("\u001b[31mred\u0007")",
      R"("")"};
  for (std::size_t i = 0; i < names.size(); ++i) {
    SCOPED_TRACE(names[i]);
    const fs::path top = base_ / std::to_string(i);
    const fs::path work = top / "a" / "b" / "work";  // out/../../x would be top/a/b/x
    writeText(top / "scenario.json", tinyScenario(names[i]));
    fs::create_directories(work);
    const Outcome o = runIn(work, "run ../../../scenario.json");
    ASSERT_EQ(o.code, 0) << o.err;
    for (const std::string& path : tree(top)) {
      EXPECT_TRUE(path == "scenario.json" || path == "a" || path == "a/b" || path == "a/b/work" ||
                  path.starts_with("a/b/work/out/") || path == "a/b/work/out")
          << "written outside out/: " << path;
    }
    std::vector<fs::path> runs;
    for (const auto& entry : fs::directory_iterator(work / "out")) runs.push_back(entry.path());
    ASSERT_EQ(runs.size(), 1u);
    EXPECT_TRUE(fs::is_directory(fs::symlink_status(runs[0])));
    EXPECT_TRUE(fs::is_regular_file(runs[0] / "summary.json"));
    EXPECT_EQ(runs[0].filename().string().find('/'), std::string::npos);
    EXPECT_NE(runs[0].filename().string().front(), '.');
    EXPECT_FALSE(fs::exists("/tmp/abs/summary.json"));
    EXPECT_FALSE(hasControlBytes(o.out)) << o.out;
  }
}

// Links planted in --out under every name a run writes, old temporary names included, point at
// files outside: the run replaces the links with its own files and the targets stay unchanged.
TEST_F(Outputs, LinksPlantedInOutAreReplacedNotFollowed) {
  const fs::path out = base_ / "out", outside = base_ / "outside";
  writeText(base_ / "scenario.json", tinyScenario(R"("tiny")"));
  fs::create_directories(out);
  const std::vector<std::string> names = {
      "record.jsonl",      "timings.jsonl",    "manifest.json",    "summary.json",
      "manifest.json.tmp", "summary.json.tmp", "record.jsonl.tmp", "timings.jsonl.tmp"};
  for (const std::string& name : names) {
    writeText(outside / name, "precious " + name);
    fs::create_symlink(outside / name, out / name);
  }
  const Outcome o = runIn(base_, "run scenario.json --out out");
  ASSERT_EQ(o.code, 0) << o.err;
  for (const std::string& name : names) EXPECT_EQ(slurp(outside / name), "precious " + name);
  for (const char* name : {"record.jsonl", "timings.jsonl", "manifest.json", "summary.json"}) {
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(out / name))) << name;
  }
  // 21 steps (0 to 4 s at 0.2 s): one line each.
  const std::string record = slurp(out / "record.jsonl");
  EXPECT_EQ(std::count(record.begin(), record.end(), '\n'), 21);
}

// A frames directory planted as a link would have its frame_*.png deleted and replaced: refused.
TEST_F(Outputs, AFramesDirectoryThatIsALinkIsRefused) {
  const fs::path out = base_ / "out", outside = base_ / "outside";
  writeText(base_ / "scenario.json", tinyScenario(R"("tiny")"));
  writeText(outside / "frame_000000.png", "precious");
  fs::create_directories(out);
  fs::create_directory_symlink(outside, out / "frames");
  const Outcome o = runIn(base_, "run scenario.json --out out --frames --size 64x32");
  EXPECT_EQ(o.code, 1) << o.err;
  EXPECT_NE(o.err.find("frames"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("symbolic link"), std::string::npos) << o.err;
  EXPECT_EQ(slurp(outside / "frame_000000.png"), "precious");
  EXPECT_EQ(tree(outside), std::set<std::string>{"frame_000000.png"});
}

// Files limited in size as on a full disk: the run fails with code 1 naming the file it could not
// write, and leaves none of its files (nor those of the complete run before it) behind.
TEST_F(Outputs, AFullDiskFailsTheRunAndLeavesNoPartialRecord) {
  writeText(base_ / "scenario.json", tinyScenario(R"("tiny")", 20.0));
  const Outcome complete = runIn(base_, "run scenario.json --out out");
  ASSERT_EQ(complete.code, 0) << complete.err;
  const auto manifest_bytes = fs::file_size(base_ / "out" / "manifest.json");
  const auto record_bytes = fs::file_size(base_ / "out" / "record.jsonl");
  ASSERT_GT(record_bytes, manifest_bytes + 4096);

  struct Limit {
    rlim_t bytes;
    const char* fails;
  };
  // Below the manifest: its write fails. Above it but below the record: the record's fails.
  for (const Limit limit :
       {Limit{manifest_bytes / 2, "manifest.json"}, Limit{manifest_bytes + 2048, "record.jsonl"}}) {
    SCOPED_TRACE(limit.fails);
    const Outcome o = runIn(base_, "run scenario.json --out out", limit.bytes);
    EXPECT_EQ(o.code, 1) << o.err;
    EXPECT_NE(o.err.find(std::string("cannot write '") + "out/" + limit.fails + "'"),
              std::string::npos)
        << o.err;
    EXPECT_NE(o.err.find("File too large"), std::string::npos) << o.err;
    EXPECT_EQ(tree(base_ / "out"), std::set<std::string>{}) << "left behind";
    ASSERT_EQ(runIn(base_, "run scenario.json --out out").code, 0);  // complete again
  }
}

// A sweep's trial files, the analysis tables and the standard output: every write is checked.
TEST_F(Outputs, EveryOtherWriteIsCheckedToo) {
  writeText(base_ / "scenario.json", tinyScenario(R"("tiny")"));
  writeText(base_ / "sweep.json", R"({"scenario": "scenario.json", "trials": 1, "seed": 1})");
  const Outcome sweep = runIn(base_, "sweep sweep.json --out s", 256);
  EXPECT_EQ(sweep.code, 1) << sweep.err;
  EXPECT_NE(sweep.err.find("cannot write 's/"), std::string::npos) << sweep.err;

  ASSERT_EQ(runIn(base_, "sweep sweep.json --out s").code, 0);
  const Outcome analyze = runIn(base_, "analyze s", 64);
  EXPECT_EQ(analyze.code, 1) << analyze.err;
  EXPECT_NE(analyze.err.find("cannot write 's/analysis/"), std::string::npos) << analyze.err;

  const Outcome full = runIn(base_, "validate scenario.json", std::nullopt, "/dev/full");
  EXPECT_EQ(full.code, 1) << full.err;
  EXPECT_NE(full.err.find("cannot write the standard output"), std::string::npos) << full.err;
}

// Bad input exits 2 naming its source, in the program's own words, with every byte printable.
TEST_F(Outputs, BadInputExitsWith2InItsOwnWords) {
  writeText(base_ / "scenario.json", tinyScenario(R"("tiny")"));
  writeText(base_ / "a_file", "not a directory");
  struct Case {
    std::string args;
    std::vector<std::string> expected;
  };
  const std::vector<Case> cases = {
      {"run scenario.json --set uavs.99999999999999999999999.v_max=3",
       {"--set: uavs.99999999999999999999999.v_max: 'uavs' is an array of 1 elements",
        "got '99999999999999999999999'"}},
      {"run scenario.json --set " + word("name=bad\xff"), {"--set: name=bad\\xFF", "UTF-8"}},
      {"run scenario.json --set " + word("uavs.0.na\xc3me=x"),
       {"--set: uavs.0.na\\xC3me=x", "UTF-8"}},
      {"run scenario.json --set uavs.0.v_max=1e999",
       {"--set: uavs.0.v_max: expected a finite value, got '1e999'"}},
      {"run scenario.json --set " + word("uavs.\x1b[2J=1"),
       {"--set: uavs.\\x1B[2J: 'uavs' is an array"}},
      {"run scenario.json --out a_file",
       {"command line: --out: expected a directory", "'a_file', which exists and is not"}},
      {"run scenario.json --out a_file/sub", {"--out: expected a directory", "through a file"}},
      {"sweep scenario.json --out a_file", {"--out: expected a directory"}},
      {"analyze . --out a_file", {"--out: expected a directory"}},
      {"run scenario.json --seed " + word("\x1b]0;x\x07"), {"--seed: expected", "\\x1B]0;x\\x07"}},
      {word("\x1b[2Jrun"), {"unknown command '\\x1B[2Jrun'"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.args);
    const Outcome o = runIn(base_, c.args);
    EXPECT_EQ(o.code, 2) << o.err;
    for (const std::string& fragment : c.expected)
      EXPECT_NE(o.err.find(fragment), std::string::npos)
          << "missing " << fragment << " in " << o.err;
    EXPECT_FALSE(hasControlBytes(o.err)) << o.err;
    expectNoLibraryText(o.err);
    EXPECT_FALSE(fs::exists(base_ / "out")) << "bad input wrote outputs";
  }
}

// Names with control characters are shown escaped wherever they are printed.
TEST_F(Outputs, ControlCharactersInNamesNeverReachTheTerminal) {
  writeText(base_ / "scenario.json", tinyScenario(R"("\u001b[2Jname\u0085")"));
  const Outcome run = runIn(base_, "run scenario.json --out out");
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.out.find("\\x1B[2Jname\\xC2\\x85: 21 steps"), std::string::npos) << run.out;
  EXPECT_FALSE(hasControlBytes(run.out));
  EXPECT_EQ(run.out.find("\xC2\x85"), std::string::npos);

  const Outcome validate =
      runIn(base_, "validate scenario.json --set " + word("planner.algorithm=\x1b[31m"));
  EXPECT_EQ(validate.code, 2);
  EXPECT_NE(validate.err.find("got the string \"\\u001b[31m\""), std::string::npos) << validate.err;
  EXPECT_FALSE(hasControlBytes(validate.err)) << validate.err;
}

}  // namespace
}  // namespace canopy::cli_test

namespace canopy::cli_test {
namespace {

// `validate` counts the steps a run records: k = 0 … duration/dt, so 30 s of 0.2 s is 151 steps,
// as many lines as record.jsonl then holds (counted from a real run).
TEST_F(Outputs, ValidateCountsTheStepsARunRecords) {
  const Outcome checked = runIn(base_, "validate demo --set clock.duration=2");
  EXPECT_EQ(checked.code, 0) << checked.err;
  EXPECT_NE(checked.out.find("11 steps (k = 0 … 10, dt = 0.2 s)"), std::string::npos)
      << checked.out;
  ASSERT_EQ(runIn(base_, "run demo --set clock.duration=2 --out r").code, 0);
  std::ifstream record(base_ / "r" / "record.jsonl");
  int lines = 0;
  for (std::string line; std::getline(record, line);) ++lines;
  EXPECT_EQ(lines, 11);
}

// `forest` writes one tree a line, and the whole is one JSON layout document.
TEST_F(Outputs, ForestPrintsOneTreeALine) {
  const Outcome forest =
      runIn(base_, "forest --aoi 0,0,100,100 --lambda 0.003 --radius 1,2 --seed 3");
  ASSERT_EQ(forest.code, 0) << forest.err;
  int tree_lines = 0, lines = 0;
  std::stringstream text(forest.out);
  for (std::string line; std::getline(text, line); ++lines)
    tree_lines += line.find("\"type\":\"disc\"") != std::string::npos;
  const std::size_t trees = forest.out.find(" trees\"");
  ASSERT_NE(trees, std::string::npos);
  const std::size_t start = forest.out.rfind(' ', trees - 1) + 1;
  const int stated = std::stoi(forest.out.substr(start, trees - start));
  EXPECT_GT(stated, 0);
  EXPECT_EQ(tree_lines, stated);
  EXPECT_EQ(lines, stated + 5);  // {, description, "occluders": [, one line a tree, ], }
}

// A target scripted through a wall: validate warns, naming the target, its waypoints and the
// wall, and passes; with --strict the warning is an error and the exit code 2 (issue 27).
TEST_F(Outputs, ValidateWarnsOfATargetWalkingThroughAWallAndStrictRefusesIt) {
  writeText(base_ / "through.json", R"({"name": "through", "aoi": [-20, -20, 20, 20],
    "uavs": [{"start": [0, 0]}],
    "targets": [{"name": "W", "path": {"waypoints": [{"t": 0, "p": [-10, 0]},
                                                     {"t": 10, "p": [10, 0]}]}}],
    "occluders": [{"type": "polygon", "vertices": [[-1, -5], [1, -5], [1, 5], [-1, 5]]}]})");
  const Outcome warned = runIn(base_, "validate through.json");
  EXPECT_EQ(warned.code, 0) << warned.err;
  EXPECT_NE(warned.err.find("warning: target \"W\": its path from waypoint 0 (t = 0 s) to "
                            "waypoint 1 (t = 10 s) runs into wall 0"),
            std::string::npos)
      << warned.err;
  const Outcome strict = runIn(base_, "validate through.json --strict");
  EXPECT_EQ(strict.code, 2);
  EXPECT_NE(strict.err.find("error: target \"W\""), std::string::npos) << strict.err;
  // A clear path: no warning, --strict passes.
  writeText(base_ / "clear.json", tinyScenario("\"clear\""));
  const Outcome clear = runIn(base_, "validate clear.json --strict");
  EXPECT_EQ(clear.code, 0);
  EXPECT_EQ(clear.err, "");
}

}  // namespace
}  // namespace canopy::cli_test
