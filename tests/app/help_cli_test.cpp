// The command line helps: --help for every command with each option's default, --version and the
// commit in manifest.json, "did you mean", the short table of `run` and its --json, every error
// of a scenario in one pass, and analyze's explanation of its terms.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/app/cli.h"

namespace canopy::cli_test {
namespace {

using Json = nlohmann::json;

TEST(HelpCli, EveryCommandHasHelpListingItsOptionsWithDefaults) {
  const fs::path dir = fresh("help");
  const std::vector<std::pair<std::string, std::vector<std::string>>> commands = {
      {"run", {"--out DIR", "--seed N", "--json", "--frames", "--fps F", "--budget K"}},
      {"validate", {"--set PATH=VALUE", "--allow-path DIR"}},
      {"coverage", {"--size WxH", "--check GOLDEN.csv", "--tolerance F"}},
      {"sweep", {"--jobs N", "--shard I/N", "--mpi", "--status DIR"}},
      {"analyze", {"--out DIR", "--state NAME", "--before-hiding S"}},
      {"reproduce", {"--trials N", "--seed S"}},
      {"forest", {"--aoi", "--lambda L", "--min-gap G"}},
      {"list", {}}};
  for (const auto& [command, options] : commands) {
    for (const char* flag : {"--help", "-h"}) {
      const Outcome o = runIn(dir, command + " " + flag);
      EXPECT_EQ(o.code, 0) << command << o.err;
      EXPECT_NE(o.out.find("usage: canopy " + command), std::string::npos) << o.out;
      for (const std::string& option : options)
        EXPECT_NE(o.out.find("  " + option), std::string::npos) << command << ": " << option;
    }
  }
  // Defaults are shown in brackets beside each option.
  const Outcome reproduce = runIn(dir, "reproduce --help");
  EXPECT_NE(reproduce.out.find("[40]"), std::string::npos) << reproduce.out;
  const Outcome tolerance = runIn(dir, "coverage --help");
  EXPECT_NE(tolerance.out.find("[0.001]"), std::string::npos) << tolerance.out;
  EXPECT_EQ(runIn(dir, "help sweep").out, runIn(dir, "sweep --help").out);
  fs::remove_all(dir);
}

TEST(HelpCli, VersionAndTheCommitInTheManifest) {
  const fs::path dir = fresh("version");
  const Outcome version = runIn(dir, "--version");
  ASSERT_EQ(version.code, 0);
  ASSERT_EQ(version.out.rfind("canopy 0.1.0 (git ", 0), 0u) << version.out;
  const std::string commit =
      version.out.substr(18, version.out.find(')') - 18);  // after "canopy 0.1.0 (git "
  EXPECT_FALSE(commit.empty());
  ASSERT_EQ(runIn(dir, "run demo --set clock.duration=1 --out r").code, 0);
  const Json manifest = Json::parse(slurp(dir / "r" / "manifest.json"));
  EXPECT_EQ(manifest.at("git_commit"), commit);
  EXPECT_EQ(manifest.at("canopy_version"), "0.1.0");
  fs::remove_all(dir);
}

TEST(HelpCli, MistypedCommandsAndOptionsGetASuggestion) {
  const fs::path dir = fresh("typo");
  const Outcome command = runIn(dir, "rnu demo");
  EXPECT_EQ(command.code, 2);
  EXPECT_NE(command.err.find("unknown command 'rnu'; did you mean `canopy run`?"),
            std::string::npos)
      << command.err;
  const Outcome option = runIn(dir, "run demo --seeed 3");
  EXPECT_EQ(option.code, 2);
  EXPECT_NE(option.err.find("--seeed: unknown option for `canopy run`; did you mean --seed?"),
            std::string::npos)
      << option.err;
  const Outcome far = runIn(dir, "sweep x.json --zzzzzz");
  EXPECT_EQ(far.code, 2);
  EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far.err;
  fs::remove_all(dir);
}

// The table's numbers are the summary's, read back from --json (a second route to them).
TEST(HelpCli, RunPrintsAShortTableAndJsonOnRequest) {
  const fs::path dir = fresh("table");
  const Outcome table = runIn(dir, "run demo --set clock.duration=4 --out t");
  ASSERT_EQ(table.code, 0) << table.err;
  const Outcome json = runIn(dir, "run demo --set clock.duration=4 --out j --json");
  ASSERT_EQ(json.code, 0) << json.err;
  const Json summary = Json::parse(json.out);  // stdout is JSON and nothing else
  EXPECT_EQ(summary, Json::parse(slurp(dir / "j" / "summary.json")));
  EXPECT_LT(std::count(table.out.begin(), table.out.end(), '\n'), 12) << table.out;
  EXPECT_NE(table.out.find("target  visible  covered\n"), std::string::npos) << table.out;
  for (const Json& t : summary.at("targets")) {
    char line[120];
    std::snprintf(line, sizeof line, "%s  %6.1f %%  %5.1f %%\n",
                  t.at("name").get<std::string>().c_str(),
                  100.0 * t.at("visible_fraction").get<double>(),
                  100.0 * t.at("in_footprint_fraction").get<double>());
    std::string expected = line;
    expected.insert(t.at("name").get<std::string>().size(),
                    6 - t.at("name").get<std::string>().size(), ' ');
    EXPECT_NE(table.out.find(expected), std::string::npos) << expected << table.out;
  }
  char ospa[64];
  std::snprintf(ospa, sizeof ospa, "OSPA %.3g m",
                summary.at("team").at("ospa_mean_m").get<double>());
  EXPECT_NE(table.out.find(ospa), std::string::npos) << table.out;
  char gospa[64];
  std::snprintf(gospa, sizeof gospa, ", GOSPA %.3g m",
                summary.at("team").at("gospa_mean_m").get<double>());
  EXPECT_NE(table.out.find(gospa), std::string::npos) << table.out;
  EXPECT_NE(table.out.find("planning: none (scripted paths)"), std::string::npos) << table.out;
  fs::remove_all(dir);
}

TEST(HelpCli, ValidateReportsEveryErrorInOnePass) {
  const fs::path dir = fresh("validate_all");
  fs::create_directories(dir);
  std::ofstream(dir / "bad.json")
      << R"({"aoi": [0, 0, 100, 100], "clock": {"dt": 0.2, "duration": 10},
    "uavs": [{"name": "u", "start": [1, 1], "v_max": -3}], "targets": [],
    "tracking": {"p_survival": 7}, "fusion": {"rounds": "x"}, "bogus": 1})";
  const Outcome o = runIn(dir, "validate bad.json");
  EXPECT_EQ(o.code, 2);
  for (const char* error :
       {"bad.json: uavs[0].v_max: expected a positive number",
        "bad.json: tracking.p_survival: unknown field",
        "bad.json: fusion.rounds: expected an integer", "bad.json: bogus: unknown field"}) {
    EXPECT_NE(o.err.find(std::string("canopy: ") + error), std::string::npos) << error << "\n"
                                                                              << o.err;
  }
  EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 4) << o.err;
  fs::remove_all(dir);
}

TEST(HelpCli, AnalyzeExplainsItsTermsAndSaysWhenNoStatesAreNamed) {
  const fs::path dir = fresh("analyze_terms");
  fs::create_directories(dir);
  std::ofstream(dir / "s.json")
      << R"({"scenario": "demo", "trials": 1, "seed": 1, "set": {"clock.duration": 2},
            "axes": [{"path": "uavs.0.v_max", "values": [3]}]})";
  ASSERT_EQ(runIn(dir, "sweep s.json --out o --jobs 1").code, 0);
  const Outcome o = runIn(dir, "analyze o");
  ASSERT_EQ(o.code, 0) << o.err;
  EXPECT_NE(o.out.find("95 % Wilson interval"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("\"Other\": every target owned, in no named state"), std::string::npos);
  EXPECT_NE(o.out.find("note: the scenario names no analysis.states"), std::string::npos) << o.out;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace canopy::cli_test
