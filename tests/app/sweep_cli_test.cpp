#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <thread>

#include "tests/app/cli.h"

namespace {
namespace fs = std::filesystem;
using canopy::cli_test::fresh;
using canopy::cli_test::run;
using canopy::cli_test::slurp;

std::map<std::string, std::string> trialFiles(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir / "trials")) {
    if (entry.is_regular_file())
      files[fs::relative(entry.path(), dir).string()] = slurp(entry.path());
  }
  return files;
}

int countTrials(const fs::path& dir) {
  int n = 0;
  std::error_code error;
  for (auto it = fs::recursive_directory_iterator(dir / "trials", error);
       !error && it != fs::end(it); it.increment(error)) {
    n += it->path().extension() == ".json";
  }
  return n;
}

// One file per test: tests run in parallel, and a file rewritten while another test's sweep reads
// it could be seen empty.
fs::path sweepFile(const std::string& test) {
  const fs::path file = fs::temp_directory_path() / ("canopy_cli_sweep_" + test + ".json");
  std::ofstream(file)
      << R"({"name": "cli", "scenario": "trajectory_handover", "trials": 5, "seed": 3,
    "axes": [{"path": "planner.algorithm", "values": ["sma", "dec_pomdp"]},
             {"path": "planner.horizon", "values": [1, 5]}]})";
  return file;
}

TEST(SweepCommand, KilledMidwayAndResumedGivesTheSameSummaryAsUninterrupted) {
  const fs::path whole = fresh("whole"), killed = fresh("killed");
  ASSERT_EQ(run("sweep " + sweepFile("killed").string() + " --out " + whole.string() + " --jobs 2"),
            0);

  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::freopen("/dev/null", "w", stderr);  // no progress bar in the test log
    std::freopen("/dev/null", "w", stdout);
    const std::string out = killed.string(), file = sweepFile("killed").string();
    execl(CANOPY_BINARY, CANOPY_BINARY, "sweep", file.c_str(), "--out", out.c_str(), "--jobs", "2",
          static_cast<char*>(nullptr));
    _exit(127);
  }
  // Kill it without warning once some, but not all, trials are written.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (countTrials(killed) < 4 && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  kill(child, SIGKILL);
  int status = 0;
  waitpid(child, &status, 0);
  const int finished_before_kill = countTrials(killed);
  EXPECT_GE(finished_before_kill, 4);
  EXPECT_LT(finished_before_kill, 20) << "the sweep finished before it could be killed";

  ASSERT_EQ(
      run("sweep " + sweepFile("killed").string() + " --out " + killed.string() + " --jobs 2"), 0);
  EXPECT_EQ(slurp(killed / "summary.json"), slurp(whole / "summary.json"));
  EXPECT_EQ(trialFiles(killed), trialFiles(whole));
  for (const auto& entry : fs::recursive_directory_iterator(killed)) {
    EXPECT_NE(entry.path().extension(), ".tmp") << "leftover " << entry.path();
  }
}

TEST(SweepCommand, OneAndTwoJobsGiveIdenticalResults) {
  const fs::path one = fresh("jobs1"), two = fresh("jobs2");
  ASSERT_EQ(run("sweep " + sweepFile("jobs").string() + " --out " + one.string() + " --jobs 1"), 0);
  ASSERT_EQ(run("sweep " + sweepFile("jobs").string() + " --out " + two.string() + " --jobs 2"), 0);
  EXPECT_EQ(trialFiles(one), trialFiles(two));
  EXPECT_EQ(slurp(one / "summary.json"), slurp(two / "summary.json"));
  ASSERT_EQ(run("analyze " + one.string()), 0);
  ASSERT_EQ(run("analyze " + two.string()), 0);
  EXPECT_EQ(slurp(one / "analysis" / "ownership_states.csv"),
            slurp(two / "analysis" / "ownership_states.csv"));
}

TEST(AnalyzeCommand, ADirectoryThatIsNotASweepExitsWith2) {
  const fs::path dir = fresh("not_a_sweep");
  fs::create_directories(dir);
  EXPECT_EQ(run("analyze " + dir.string()), 2);
  EXPECT_EQ(run("sweep /nonexistent.json --out " + dir.string()), 2);
}

TEST(AnalyzeCommand, TwoNumericAxesGiveADeterministicSensitivityMap) {
  const fs::path file = fs::temp_directory_path() / "canopy_cli_map.json";
  std::ofstream(file)
      << R"({"name": "map", "scenario": "trajectory_handover", "trials": 2, "seed": 3,
    "axes": [{"path": "planner.horizon", "values": [1, 2]},
             {"path": "uavs.0.v_max", "values": [6, 4]}]})";
  const fs::path dir = fresh("map");
  ASSERT_EQ(run("sweep " + file.string() + " --out " + dir.string() + " --jobs 2"), 0);
  ASSERT_EQ(run("analyze " + dir.string()), 0);
  const fs::path map = dir / "analysis" / "heatmap_horizon_vs_v_max";
  for (const char* extension : {".csv", ".svg", ".pdf", ".png"})
    EXPECT_TRUE(fs::exists(map.string() + extension)) << extension;
  // Every figure also as PDF for a paper (issue 51), and no CSV field is ever inf: two trials per
  // configuration leave some intervals unbounded, whose ends are empty fields.
  int pdfs = 0, csvs = 0;
  for (const auto& entry : fs::directory_iterator(dir / "analysis")) {
    if (entry.path().extension() == ".svg") {
      fs::path pdf = entry.path();
      pdf.replace_extension(".pdf");
      ASSERT_TRUE(fs::exists(pdf)) << pdf;
      EXPECT_EQ(slurp(pdf).rfind("%PDF-", 0), 0u) << pdf;
      ++pdfs;
    } else if (entry.path().extension() == ".csv") {
      EXPECT_EQ(slurp(entry.path()).find("inf"), std::string::npos) << entry.path();
      ++csvs;
    }
  }
  EXPECT_GE(pdfs, 3);  // the map, the coverage curves and a Sankey diagram per configuration
  EXPECT_GE(csvs, 6);
  const std::string csv = slurp(map.string() + ".csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5);  // the header and 2 × 2 cells
  ASSERT_EQ(run("analyze " + dir.string() + " --out " + (dir / "again").string()), 0);
  EXPECT_EQ(slurp(dir / "again" / "heatmap_horizon_vs_v_max.svg"), slurp(map.string() + ".svg"));
  EXPECT_EQ(slurp(dir / "again" / "heatmap_horizon_vs_v_max.pdf"), slurp(map.string() + ".pdf"));
  EXPECT_EQ(run("analyze " + dir.string() + " --state nonsense"), 2);
  // One style file for every figure (issue 51): the shipped defaults change nothing; another
  // style recolours the first series; a bad file is refused before anything is written.
  ASSERT_EQ(run("analyze " + dir.string() + " --out " + (dir / "styled").string() + " --style " +
                CANOPY_SOURCE_DIR "/docs/figure-style.json"),
            0);
  EXPECT_EQ(slurp(dir / "styled" / "coverage.svg"), slurp(dir / "analysis" / "coverage.svg"));
  const fs::path style = dir / "style.json";
  std::ofstream(style) << R"({"series": ["#000000"], "font_scale": 1.5})";
  ASSERT_EQ(run("analyze " + dir.string() + " --out " + (dir / "black").string() + " --style " +
                style.string()),
            0);
  const std::string black = slurp(dir / "black" / "coverage.svg");
  EXPECT_NE(black.find("rgb(0,0,0)"), std::string::npos);
  EXPECT_EQ(black.find("rgb(31,119,180)"), std::string::npos);  // the first default colour
  EXPECT_NE(slurp(dir / "analysis" / "coverage.svg").find("rgb(31,119,180)"), std::string::npos);
  std::ofstream(style, std::ios::trunc) << R"({"ink": "red"})";
  EXPECT_EQ(run("analyze " + dir.string() + " --out " + (dir / "bad").string() + " --style " +
                style.string()),
            2);
  EXPECT_FALSE(fs::exists(dir / "bad" / "coverage.svg"));
}

}  // namespace

namespace {

// A built-in sweep runs by its name, as scenarios do (issue 51: "no such file"); one shard of
// one trial keeps it short. An unknown name exits with 2 and lists the built-in sweeps.
TEST(SweepCommand, ABuiltInSweepRunsByName) {
  const fs::path dir = fresh("sweep_by_name");
  const canopy::cli_test::Outcome ran = canopy::cli_test::runIn(
      fs::temp_directory_path(),
      "sweep handover_horizons --out " + dir.string() + " --shard 0/40 --jobs 1");
  EXPECT_EQ(ran.code, 0) << ran.err;
  EXPECT_NE(ran.out.find("handover_horizons: shard 0/40 ran 1 trials"), std::string::npos)
      << ran.out;
  EXPECT_EQ(countTrials(dir), 1);
  const canopy::cli_test::Outcome unknown = canopy::cli_test::runIn(
      fs::temp_directory_path(), "sweep handover_horizon --out " + dir.string() + "_x");
  EXPECT_EQ(unknown.code, 2);
  EXPECT_NE(unknown.err.find("no built-in sweep of that name"), std::string::npos) << unknown.err;
  EXPECT_NE(unknown.err.find("did you mean handover_horizons?"), std::string::npos) << unknown.err;
  fs::remove_all(dir);
}

}  // namespace
