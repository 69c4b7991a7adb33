// The command line helps: --help for every command with each option's default, --version and the
// commit in manifest.json, "did you mean", the short table of `run` and its --json, every error
// of a scenario in one pass, and analyze's explanation of its terms.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>

#include "tests/app/cli.h"

namespace canopy::cli_test {
namespace {

using Json = nlohmann::json;

TEST(HelpCli, EveryCommandHasHelpListingItsOptionsWithDefaults) {
  const fs::path dir = fresh("help");
  const std::vector<std::pair<std::string, std::vector<std::string>>> commands = {
      {"run", {"--out DIR", "--seed N", "--json", "--frames", "--fps F", "--budget K"}},
      {"validate", {"--set PATH=VALUE", "--allow-path DIR"}},
      {"coverage", {"--size WxH", "--steps A:B", "--check GOLDEN.csv", "--tolerance F"}},
      {"record", {"--steps A:B", "--agent I"}},
      {"sweep", {"--jobs N", "--shard I/N", "--mpi", "--status DIR"}},
      {"analyze", {"--out DIR", "--state NAME", "--before-hiding S"}},
      {"reproduce", {"--trials N", "--seed S", "--timing-trials N"}},
      {"forest", {"--aoi", "--lambda L", "--min-gap G"}},
      {"import", {"--out LAYOUT.json", "--origin LAT,LON", "--bbox W,S,E,N", "--radius-field NAME"}},
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
  // Every command's options, whatever comes before the typo; nothing ran.
  for (const auto& [args, expected] : std::vector<std::pair<std::string, std::string>>{
           {"sweeep x.json", "unknown command 'sweeep'; did you mean `canopy sweep`?"},
           {"valdiate demo", "unknown command 'valdiate'; did you mean `canopy validate`?"},
           {"coverage r --check g.csv --tolerence 0.1",
            "--tolerence: unknown option for `canopy coverage`; did you mean --tolerance?"},
           {"forest --aoi 0,0,10,10 --lamda 1 --radius 1",
            "--lamda: unknown option for `canopy forest`; did you mean --lambda?"},
           {"run demo --frames --frame-evry 2",
            "--frame-evry: unknown option for `canopy run`; did you mean --frame-every?"},
           {"analyze d --hepl",
            "--hepl: unknown option for `canopy analyze`; did you mean --help?"}}) {
    const Outcome o = runIn(dir, args);
    EXPECT_EQ(o.code, 2) << args;
    EXPECT_NE(o.err.find(expected), std::string::npos) << args << ": " << o.err;
  }
  EXPECT_FALSE(fs::exists(dir / "out"));
  fs::remove_all(dir);
}

// The options of a command as its --help lists them: "--jobs" → "N" ("" for a flag).
std::map<std::string, std::string> helpOptions(const std::string& help) {
  std::map<std::string, std::string> options;
  const std::regex row(R"(\n  (--[a-z-]+)( [^ ]+)? +.*\[)");
  for (std::sregex_iterator m(help.begin(), help.end(), row), end; m != end; ++m)
    options[(*m)[1]] = (*m)[2].matched ? (*m)[2].str().substr(1) : "";
  return options;
}

// README's tour table and each command's --help say the same options, and the parser takes every
// one of them: `canopy COMMAND OPTION VALUE --zz-canary` is refused for the canary, so OPTION and
// its VALUE were taken (and nothing runs).
TEST(HelpCli, EveryOptionInTheReadmeAndInHelpIsAcceptedByTheParser) {
  const fs::path dir = fresh("readme_options");
  fs::create_directories(dir);
  const std::string readme = slurp(CANOPY_README);
  const std::size_t tour = readme.find("## A short tour");
  ASSERT_NE(tour, std::string::npos);
  const std::string table =
      readme.substr(tour, readme.find("\n\n", readme.find("| command", tour)) - tour);
  // Rows: | `./canopy NAME …` | or | `… NAME …` | (the second row of run).
  std::map<std::string, std::set<std::string>> readme_options;
  const std::regex row(R"(\| `(?:\./canopy|…) (\w+)([^`]*)`)");
  const std::regex option_name(R"(--[a-z][a-z-]*)");
  for (std::sregex_iterator m(table.begin(), table.end(), row), end; m != end; ++m) {
    const std::string rest = (*m)[2];
    readme_options[(*m)[1]];
    for (std::sregex_iterator o(rest.begin(), rest.end(), option_name); o != end; ++o)
      readme_options[(*m)[1]].insert(o->str());
  }
  const std::set<std::string> commands = {"run",   "validate", "coverage",  "view",
                                          "record", "sweep",   "analyze",   "reproduce",
                                          "forest", "import",  "schema",  "list",
                                          "imitate"};
  std::set<std::string> in_readme;
  for (const auto& [command, options] : readme_options) in_readme.insert(command);
  EXPECT_EQ(in_readme, commands) << "README's tour lists other commands than canopy has";
  // A value each option takes, by the name --help gives it.
  const std::map<std::string, std::string> samples = {{"DIR", "."},
                                                      {"N", "2"},
                                                      {"K", "2"},
                                                      {"S", "1"},
                                                      {"F", "0.5"},
                                                      {"G", "1"},
                                                      {"L", "0.01"},
                                                      {"WxH", "64x48"},
                                                      {"I/N", "0/2"},
                                                      {"I", "0"},
                                                      {"A:B", "0:2"},
                                                      {"auto|jsonl|compact", "jsonl"},
                                                      {"png|svg|pdf", "svg"},
                                                      {"NAME", "x"},
                                                      {"GOLDEN.csv", "g.csv"},
                                                      {"FILE", "page.html"},
                                                      {"PATH=VALUE", "seed=1"},
                                                      {"R[,R_MAX]", "1,2"},
                                                      {"x0,y0,x1,y1", "0,0,10,10"},
                                                      {"aoi|action|x0,y0,x1,y1", "aoi"},
                                                      {"LAYOUT.json", "l.json"},
                                                      {"W,S,E,N", "0,0,1,1"},
                                                      {"LAT,LON", "0,0"},
                                                      {"R", "1"},
                                                      {"TEXT", "t"}};
  for (const std::string& command : commands) {
    SCOPED_TRACE(command);
    const Outcome help = runIn(dir, command + " --help");
    ASSERT_EQ(help.code, 0) << help.err;
    const std::map<std::string, std::string> options = helpOptions(help.out);
    for (const std::string& option : readme_options[command])
      EXPECT_TRUE(options.count(option)) << "README lists " << option << ", --help does not";
    // forest refuses to parse without its three required options.
    // forest and import refuse to parse without their required options.
    const std::string base = command == "forest"   ? "forest --aoi 0,0,10,10 --lambda 1 --radius 1"
                             : command == "import" ? "import x.geojson --out l.json"
                             : command == "imitate" ? "imitate collect"
                                                    : command;
    for (const auto& [option, value] : options) {
      ASSERT_TRUE(value.empty() || samples.count(value)) << option << " " << value;
      const std::string args =
          base + " " + option + (value.empty() ? "" : " " + samples.at(value)) + " --zz-canary";
      const Outcome o = runIn(dir, args);
      EXPECT_EQ(o.code, 2) << args;
      EXPECT_NE(o.err.find("command line: --zz-canary: unknown option for `canopy " + command),
                std::string::npos)
          << args << ": " << o.err;
    }
  }
  EXPECT_FALSE(fs::exists(dir / "out"));
  fs::remove_all(dir);
}

// CLI11's own refusals come out in the program's words: the option and what it expected.
TEST(HelpCli, MissingValuesAndRequiredOptionsNameTheOption) {
  const fs::path dir = fresh("missing_values");
  for (const auto& [args, expected] : std::vector<std::pair<std::string, std::string>>{
           {"run demo --seed",
            "canopy: command line: --seed: expected a value after --seed (--seed N)"},
           {"sweep s.json --out", "canopy: command line: --out: expected a value after --out"},
           {"forest --lambda 1 --radius 1",
            "canopy: command line: --aoi: required, expected --aoi x0,y0,x1,y1"},
           {"run demo --frames --frame-every 0",
            "canopy: command line: --frame-every: expected an integer in [1, 1000000], got '0'"},
           {"sweep s.json --out o --jobs=abc",
            "canopy: command line: --jobs: expected an integer in [1, 1024], got 'abc'"},
           {"run a b", "canopy: command line: b: expected one SCENARIO, got a second one"},
           {"list extra", "canopy: command line: extra: `canopy list` takes no arguments"}}) {
    const Outcome o = runIn(dir, args);
    EXPECT_EQ(o.code, 2) << args;
    EXPECT_NE(o.err.find(expected), std::string::npos) << args << ": " << o.err;
  }
  EXPECT_FALSE(fs::exists(dir / "out"));
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

// `canopy validate --help` promises the work estimate: the total in instructions and CPU time,
// and one figure per stage that add up to it.
TEST(HelpCli, ValidatePrintsTheWorkEstimateByStage) {
  const fs::path dir = fresh("validate_work");
  const Outcome help = runIn(dir, "validate --help");
  EXPECT_NE(help.out.find("estimated in instructions and CPU time"), std::string::npos)
      << help.out;
  const Outcome o = runIn(dir, "validate trajectory_handover");
  ASSERT_EQ(o.code, 0) << o.err;
  double total = 0.0, seconds = 0.0, limit = 0.0;
  const std::size_t at = o.out.find("  work: about ");
  ASSERT_NE(at, std::string::npos) << o.out;
  ASSERT_EQ(std::sscanf(o.out.c_str() + at,
                        "  work: about %lf instructions, about %lf CPU-s on the machine the "
                        "estimate was measured on (limit %lf CPU-s)",
                        &total, &seconds, &limit),
            3)
      << o.out;
  EXPECT_NEAR(seconds, total / 1e10, 0.01 * seconds);
  EXPECT_DOUBLE_EQ(limit, 1800.0);
  const std::size_t stages = o.out.find("  work by stage (instructions): ");
  ASSERT_NE(stages, std::string::npos) << o.out;
  std::istringstream words(o.out.substr(stages + 32, o.out.find('\n', stages) - stages - 32));
  std::string name;
  double value = 0.0, sum = 0.0;
  int count = 0;
  while (words >> name >> value) {
    sum += value;
    ++count;
  }
  EXPECT_EQ(count, 10) << o.out;
  EXPECT_NEAR(sum, total, 0.01 * total) << o.out;  // each printed to three digits
  // The paper scenario runs in well under a CPU-second.
  EXPECT_LT(seconds, 1.0);
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
