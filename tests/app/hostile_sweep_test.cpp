// Hostile sweep files through the command line: ids that could collide, repeated values, axis
// products too large to build, and a corrected file in the folder of a refused one.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "tests/app/cli.h"

namespace {
namespace fs = std::filesystem;
using canopy::cli_test::fresh;
using canopy::cli_test::run;

// A two-second demo: one trial takes a fraction of a second.
void writeSweep(const fs::path& file, const std::string& axes, int trials = 1) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << R"({"name": "hostile", "scenario": "demo", "trials": )" << trials
                      << R"(, "set": {"clock.duration": 2}, "axes": )" << axes << "}";
}

std::set<std::string> configDirs(const fs::path& out) {
  std::set<std::string> dirs;
  for (const auto& entry : fs::directory_iterator(out / "trials"))
    dirs.insert(entry.path().filename());
  return dirs;
}

TEST(HostileSweep, ValuesWhoseNamesWouldCollideGetDistinctConfigurations) {
  const fs::path dir = fresh("sweep_collide");
  writeSweep(dir / "sweep.json", R"([{"path": "description", "values": ["a b", "a_b", "a/b"]}])");
  ASSERT_EQ(run("sweep " + (dir / "sweep.json").string() + " --out " + (dir / "out").string()), 0);
  const std::set<std::string> dirs = configDirs(dir / "out");
  EXPECT_EQ(dirs.size(), 3u);  // one folder per value, each with its trial
  for (const std::string& name : dirs) {
    EXPECT_EQ(name.rfind("description-a_b~", 0), 0u) << name;  // the readable part, then a hash
    EXPECT_TRUE(fs::exists(dir / "out" / "trials" / name / "trial_0000.json")) << name;
  }
}

TEST(HostileSweep, ARepeatedValueIsRefusedNamingIt) {
  const fs::path dir = fresh("sweep_repeat");
  writeSweep(dir / "sweep.json", R"([{"path": "planner.horizon", "values": [1, 5, 1.0]}])");
  EXPECT_EQ(run("sweep " + (dir / "sweep.json").string() + " --out " + (dir / "out").string()), 2);
  EXPECT_FALSE(fs::exists(dir / "out"));
  writeSweep(dir / "twice.json", R"([{"path": "planner.horizon", "values": [1]},
                                     {"path": "planner.horizon", "values": [5]}])");
  EXPECT_EQ(run("sweep " + (dir / "twice.json").string() + " --out " + (dir / "out").string()), 2);
}

TEST(HostileSweep, AnAxisProductTooLargeIsRefusedBeforeItIsBuilt) {
  const fs::path dir = fresh("sweep_product");
  std::string axes = "[";
  for (int a = 0; a < 10; ++a) {  // 10¹⁰ configurations
    axes += (a ? ", " : "") + std::string(R"({"path": "x)") + std::to_string(a) +
            R"(", "values": [0, 1, 2, 3, 4, 5, 6, 7, 8, 9]})";
  }
  writeSweep(dir / "sweep.json", axes + "]");
  EXPECT_EQ(run("sweep " + (dir / "sweep.json").string() + " --out " + (dir / "out").string()), 2);
  EXPECT_FALSE(fs::exists(dir / "out"));
  // --budget scales the limit (10⁵ configurations): two configurations fit, not under 10⁻⁵ of it.
  // (At 2·10⁻⁵ they would fit too, but one demo trial's tracking estimate, 4.4·10⁶ units, would
  // not, nor below 3·10⁻⁴ one demo step's, about 2·10⁵ units against 5·10⁸: every limit
  // scales.)
  writeSweep(dir / "small.json", R"([{"path": "planner.horizon", "values": [1, 2]}])");
  EXPECT_EQ(run("sweep " + (dir / "small.json").string() + " --budget 1e-5 --out " +
                (dir / "out").string()),
            2);
  EXPECT_EQ(run("sweep " + (dir / "small.json").string() + " --budget 1e-3 --out " +
                (dir / "out").string()),
            0);
}

TEST(HostileSweep, ACorrectedSweepRunsInTheFolderOfTheRefusedOne) {
  const fs::path dir = fresh("sweep_corrected");
  writeSweep(dir / "sweep.json", R"([{"path": "planner.horizon", "values": [1, 500]}])");
  EXPECT_EQ(run("sweep " + (dir / "sweep.json").string() + " --out " + (dir / "out").string()), 2);
  EXPECT_FALSE(fs::exists(dir / "out" / "sweep.json"));
  writeSweep(dir / "sweep.json", R"([{"path": "planner.horizon", "values": [1, 5]}])");
  EXPECT_EQ(run("sweep " + (dir / "sweep.json").string() + " --out " + (dir / "out").string()), 0);
  // A folder that holds a sweep but no finished trial is not protected either.
  fs::remove_all(dir / "out" / "trials");
  writeSweep(dir / "sweep.json", R"([{"path": "planner.horizon", "values": [2]}])");
  EXPECT_EQ(run("sweep " + (dir / "sweep.json").string() + " --out " + (dir / "out").string()), 0);
  // With finished trials, another sweep is still refused.
  writeSweep(dir / "sweep.json", R"([{"path": "planner.horizon", "values": [3]}])");
  EXPECT_EQ(run("sweep " + (dir / "sweep.json").string() + " --out " + (dir / "out").string()), 2);
}

// A link planted where a finished trial would be is no finished trial: the sweep runs that trial
// again and its file replaces the link, never what it points to. A FIFO there is not the sweep's
// to replace (issue 47): refused with exit 2 before any trial runs, never waited on, left as it
// was.
TEST(HostileSweep, PlantedTrialFilesAreRunAgainNotTrustedOrWaitedOn) {
  const fs::path dir = fresh("sweep_planted");
  writeSweep(dir / "sweep.json", R"([{"path": "planner.horizon", "values": [1]}])", 2);
  const std::string sweep =
      "sweep " + (dir / "sweep.json").string() + " --out " + (dir / "out").string();
  ASSERT_EQ(run(sweep), 0);
  const fs::path trials = dir / "out" / "trials" / "horizon-1";
  const std::string first = canopy::cli_test::slurp(trials / "trial_0000.json");
  const std::string second = canopy::cli_test::slurp(trials / "trial_0001.json");
  fs::remove(trials / "trial_0000.json");
  fs::remove(trials / "trial_0001.json");
  ASSERT_EQ(mkfifo((trials / "trial_0000.json").c_str(), 0600), 0);
  std::ofstream(dir / "outside.json") << "precious";
  fs::create_symlink(dir / "outside.json", trials / "trial_0001.json");
  const std::string command =
      "timeout 20 " + std::string(CANOPY_BINARY) + " " + sweep + " >/dev/null 2>&1";
  int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 2) << "killed after 20 s or not refused";
  EXPECT_EQ(fs::symlink_status(trials / "trial_0000.json").type(), fs::file_type::fifo);
  EXPECT_EQ(fs::symlink_status(trials / "trial_0001.json").type(), fs::file_type::symlink);
  fs::remove(trials / "trial_0000.json");
  status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "killed after 20 s or failed";
  EXPECT_EQ(fs::symlink_status(trials / "trial_0000.json").type(), fs::file_type::regular);
  EXPECT_EQ(fs::symlink_status(trials / "trial_0001.json").type(), fs::file_type::regular);
  EXPECT_EQ(canopy::cli_test::slurp(trials / "trial_0000.json"), first);  // same seed, same bits
  EXPECT_EQ(canopy::cli_test::slurp(trials / "trial_0001.json"), second);
  EXPECT_EQ(canopy::cli_test::slurp(dir / "outside.json"), "precious");
}

}  // namespace
