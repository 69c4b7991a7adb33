// Hostile input, run through the real command line under the limits the issue sets: every case
// must exit within 20 s, under a 3 GB address-space cap, with code 2 and a message that names
// the scenario file and field — or, where the input is legitimate but extreme, finish normally.
// Cases that need files, links or FIFOs around the scenario live here; plain broken files are
// in malformed_test.cpp's table.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace {
namespace fs = std::filesystem;

struct Outcome {
  int exit_code = -1;
  std::string output;
};

// `canopy ARGUMENTS` in a shell with a 3 GB address-space cap, killed after 20 s. AddressSanitizer
// reserves terabytes of address space for its shadow memory, so its builds run without the cap
// (and with a longer clock).
#ifdef __SANITIZE_ADDRESS__
constexpr const char* kLimits = "exec timeout -s KILL 120 ";
#else
constexpr const char* kLimits = "ulimit -v 3145728; exec timeout -s KILL 20 ";
#endif
Outcome runCapped(const std::string& arguments) {
  const std::string command =
      "bash -c '" + std::string(kLimits) + std::string(CANOPY_BINARY) + " " + arguments + "' 2>&1";
  Outcome outcome;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return outcome;
  std::array<char, 4096> buffer;
  while (std::fgets(buffer.data(), buffer.size(), pipe)) outcome.output += buffer.data();
  const int status = pclose(pipe);
  outcome.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return outcome;
}

fs::path freshDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("canopy_hostile_" + name) / "scenarios";
  fs::remove_all(dir.parent_path());
  fs::create_directories(dir);
  return dir;
}

void write(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

std::string scenarioWithTrack(const std::string& track) {
  return R"({"aoi": [0, 0, 100, 50], "uavs": [{"start": [10, 10]}],
             "targets": [{"path": {"track": ")" +
         track + R"("}}]})";
}

std::string scenarioWithInclude(const std::string& include) {
  return R"({"aoi": [0, 0, 100, 50], "uavs": [{"start": [10, 10]}],
             "occluders": [{"include": ")" +
         include + R"("}]})";
}

void expectRefused(const Outcome& outcome, const std::vector<std::string>& fragments) {
  EXPECT_EQ(outcome.exit_code, 2) << outcome.output;
  for (const std::string& fragment : fragments) {
    EXPECT_NE(outcome.output.find(fragment), std::string::npos)
        << "missing \"" << fragment << "\" in: " << outcome.output;
  }
}

TEST(HostileFiles, ATrackOutsideTheScenarioFolderIsRefusedUnlessAllowed) {
  const fs::path dir = freshDir("track_outside");
  write(dir.parent_path() / "outside.csv", "0,20,20\n10,30,20\n");
  write(dir / "up.json", scenarioWithTrack("../outside.csv"));
  expectRefused(runCapped("validate " + (dir / "up.json").string()),
                {"up.json: targets[0].path.track: the track file", "outside.csv' lies outside",
                 "--allow-path"});
  EXPECT_EQ(runCapped("validate " + (dir / "up.json").string() + " --allow-path " +
                      dir.parent_path().string())
                .exit_code,
            0);
  write(dir / "absolute.json", scenarioWithTrack("/etc/passwd"));
  const Outcome absolute = runCapped("validate " + (dir / "absolute.json").string());
  expectRefused(absolute, {"absolute.json: targets[0].path.track", "lies outside"});
  EXPECT_EQ(absolute.output.find("root:"), std::string::npos) << "file content echoed";
}

TEST(HostileFiles, DevicesAndFifosAreRefusedWithoutWaiting) {
  const fs::path dir = freshDir("devices");
  ASSERT_EQ(mkfifo((dir / "pipe.csv").c_str(), 0600), 0);
  write(dir / "fifo.json", scenarioWithTrack("pipe.csv"));
  expectRefused(runCapped("validate " + (dir / "fifo.json").string()),
                {"fifo.json: targets[0].path.track", "not a regular file"});
  write(dir / "zero.json", scenarioWithInclude("/dev/zero"));
  expectRefused(runCapped("validate " + (dir / "zero.json").string() + " --allow-path /dev"),
                {"zero.json: occluders[0].include", "not a regular file"});
  ASSERT_EQ(mkfifo((dir / "layout.json").c_str(), 0600), 0);
  write(dir / "fifo_include.json", scenarioWithInclude("layout.json"));
  expectRefused(runCapped("validate " + (dir / "fifo_include.json").string()),
                {"fifo_include.json: occluders[0].include", "not a regular file"});
}

TEST(HostileFiles, ALinkInsideTheFolderPointingOutIsJudgedByItsTarget) {
  const fs::path dir = freshDir("link");
  write(dir.parent_path() / "secret.json", R"([{"type": "disc", "centre": [5, 5], "radius": 1}])");
  fs::create_symlink(dir.parent_path() / "secret.json", dir / "layout.json");
  write(dir / "scenario.json", scenarioWithInclude("layout.json"));
  expectRefused(runCapped("validate " + (dir / "scenario.json").string()),
                {"scenario.json: occluders[0].include", "layout.json' (a link to '",
                 "secret.json') lies outside"});
  // A link to a file inside the folder is fine.
  write(dir / "real.json", R"([{"type": "disc", "centre": [5, 5], "radius": 1}])");
  fs::create_symlink(dir / "real.json", dir / "alias.json");
  write(dir / "inside.json", scenarioWithInclude("alias.json"));
  EXPECT_EQ(runCapped("validate " + (dir / "inside.json").string()).exit_code, 0);
}

TEST(HostileFiles, ErrorsInsideAnIncludedFileNameTheScenarioFieldAndTheIncludedFile) {
  const fs::path dir = freshDir("included_error");
  fs::create_directories(dir / "layouts");
  write(dir / "layouts" / "bad.json", R"([{"type": "disc", "centre": [5, 5], "radius": -1}])");
  write(dir / "layouts" / "middle.json", R"([{"include": "bad.json"}])");
  write(dir / "scenario.json", scenarioWithInclude("layouts/middle.json"));
  expectRefused(runCapped("validate " + (dir / "scenario.json").string()),
                {"scenario.json: occluders[0].include: in the layout file",
                 "middle.json: [0].include: in the layout file",
                 "bad.json: [0].radius: expected a "
                 "positive number"});
}

TEST(HostileFiles, BinaryContentIsQuotedEscapedAndShort) {
  const fs::path dir = freshDir("binary");
  write(dir / "noise.csv",
        std::string("t,x,y\n0,1,1\n\x1b[2J\x07garbage") + std::string(500, 'A') + "\n");
  write(dir / "scenario.json", scenarioWithTrack("noise.csv"));
  const Outcome outcome = runCapped("validate " + (dir / "scenario.json").string());
  expectRefused(outcome, {"scenario.json: targets[0].path.track: in the track file",
                          "noise.csv: line 3", "\\x1B[2J\\x07garbage"});
  EXPECT_EQ(outcome.output.find('\x1b'), std::string::npos) << "a raw escape reached the terminal";
  EXPECT_LT(outcome.output.size(), 600u) << outcome.output;
}

TEST(HostileDepth, NestingTenThousandDeepIsRefusedNotACrash) {
  const fs::path dir = freshDir("deep");
  const int depth = 70000;
  write(dir / "deep.json", R"({"aoi": [0, 0, 100, 50], "uavs": [{"start": [10, 10]}], "x": )" +
                               std::string(depth, '[') + std::string(depth, ']') + "}");
  expectRefused(runCapped("validate " + (dir / "deep.json").string()),
                {"deep.json", "nested at most 64 levels deep"});
  write(dir / "ok.json", R"({"aoi": [0, 0, 100, 50], "uavs": [{"start": [10, 10]}]})");
  expectRefused(runCapped("validate " + (dir / "ok.json").string() +
                          " --set description=" + std::string(5000, '[') + std::string(5000, ']')),
                {"--set", "nested at most 64 levels deep"});
}

// Legitimate but extreme: two tiny trees a thousand kilometres apart, planned around with the
// a-priori map. The occlusion map's grid index must stay small (it once allocated gigabytes).
TEST(HostileExtremes, TinyTreesFarApartRunWithinTheMemoryCap) {
  const fs::path dir = freshDir("far_trees");
  write(dir / "far.json",
        R"({"aoi": [-600000, -10, 600000, 10], "clock": {"dt": 0.2, "duration": 2},
    "uavs": [{"start": [0, 0]}], "targets": [{"path": {"start": [1, 0], "velocity": [1, 0]}}],
    "occluders": [{"type": "disc", "centre": [-500000, 0], "radius": 1e-6},
                  {"type": "disc", "centre": [500000, 0], "radius": 1e-6}],
    "planner": {"algorithm": "sma", "horizon": 1, "occlusion_map": "a_priori"}})");
  const Outcome outcome = runCapped("run " + (dir / "far.json").string() + " --out " +
                                    (dir.parent_path() / "out").string());
  EXPECT_EQ(outcome.exit_code, 0) << outcome.output;
}

}  // namespace
