// Hostile input, second pass, through the real command line: every file canopy reads back (a
// run's manifest, record and summary, a golden CSV, a sweep's sweep.json, scenarios.json and
// trial files, the folders of $CANOPY_PATH) × every hostile form of it (nested too deep, larger
// than its limit as a sparse file, a FIFO, a symbolic link loop, a directory): exit 2 within
// 20 s under a 3 GB address-space cap, with a message naming the file. Also: shapes Box2D could
// not build refused at `validate` with their index, and numbers that must not pass.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
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
  int code = -1;
  std::string output;  // stdout and stderr together
};

#ifdef __SANITIZE_ADDRESS__
constexpr const char* kLimits = "exec timeout -s KILL 120 ";
#else
constexpr const char* kLimits = "ulimit -v 3145728; exec timeout -s KILL 20 ";
#endif

// `canopy ARGUMENTS` (quoted by the caller) in bash, capped in memory and time.
Outcome canopy(const std::string& arguments, const std::string& environment = "") {
  const std::string command = "bash -c '" +
                              (environment.empty() ? "" : "export " + environment + "; ") +
                              std::string(kLimits) + CANOPY_BINARY + " " + arguments + "' 2>&1";
  Outcome outcome;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return outcome;
  std::array<char, 4096> buffer;
  while (std::fgets(buffer.data(), buffer.size(), pipe)) outcome.output += buffer.data();
  const int status = pclose(pipe);
  outcome.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return outcome;
}

void write(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("canopy_hostile2_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// One finished run and one finished sweep, made once; each case works on a copy.
struct Templates {
  fs::path run, sweep_file, sweep;
};

const Templates& templates() {
  static const Templates t = [] {
    Templates made;
    // Per process: ctest runs this file's tests side by side, each making its own.
    const fs::path dir = scratch("templates_" + std::to_string(::getpid()));
    made.run = dir / "run";
    made.sweep_file = dir / "sweep.json";
    made.sweep = dir / "sweep";
    const Outcome run = canopy("run demo --set clock.duration=2 --out " + made.run.string());
    EXPECT_EQ(run.code, 0) << run.output;
    write(made.sweep_file, R"({"name": "s", "scenario": "demo", "trials": 1,
        "set": {"clock.duration": 2}, "axes": [{"path": "planner.horizon", "values": [1]}]})");
    const Outcome sweep =
        canopy("sweep " + made.sweep_file.string() + " --out " + made.sweep.string());
    EXPECT_EQ(sweep.code, 0) << sweep.output;
    return made;
  }();
  return t;
}

// How a file is made hostile.
struct Hostility {
  std::string name;
  std::function<void(const fs::path&)> plant;
  std::string expected;  // a fragment of the message besides the file's name
};

const std::vector<Hostility>& hostilities() {
  static const std::vector<Hostility> all = {
      {"deep",
       [](const fs::path& p) {
         // Nested 100 000 deep: JSON files as one document, the record as one line, the CSV as
         // a line of brackets (refused as a header).
         const int depth = 100000;
         write(p, std::string(depth, '[') + std::string(depth, ']') + "\n");
       },
       ""},
      {"sparse_2GiB",
       [](const fs::path& p) {
         write(p, "{");
         fs::resize_file(p, (std::uintmax_t{2} << 30) + 1);  // sparse: nothing is written
       },
       "larger than"},
      {"fifo", [](const fs::path& p) { ASSERT_EQ(::mkfifo(p.c_str(), 0600), 0); }, "FIFO"},
      {"link_loop",
       [](const fs::path& p) {
         fs::create_symlink(p.filename().string() + ".other", p);
         fs::create_symlink(p.filename(), p.string() + ".other");
       },
       "link"},
      {"directory", [](const fs::path& p) { fs::create_directories(p / "inside"); }, "director"},
  };
  return all;
}

// A file kind: where it lives in a copy of a template, and the command that reads it.
struct FileKind {
  std::string name;
  bool in_sweep;  // else in the run folder
  std::string relative;
  std::function<std::string(const fs::path& folder)> command;
};

const std::vector<FileKind>& fileKinds() {
  static const std::vector<FileKind> all = {
      {"manifest", false, "manifest.json",
       [](const fs::path& run) { return "coverage " + run.string(); }},
      {"record", false, "record.jsonl",
       [](const fs::path& run) { return "coverage " + run.string(); }},
      {"summary", false, "summary.json",
       [](const fs::path& run) {
         return "view " + run.string() + " --out " + (run / "r.html").string();
       }},
      {"golden_csv", false, "golden.csv",
       [](const fs::path& run) {
         return "coverage " + run.string() + " --check " + (run / "golden.csv").string();
       }},
      {"sweep_manifest", true, "sweep.json",
       [](const fs::path& sweep) { return "analyze " + sweep.string(); }},
      {"trial", true, "trials/horizon-1/trial_0000.json",
       [](const fs::path& sweep) { return "analyze " + sweep.string(); }},
      {"sweep_status", true, "sweep.json",
       [](const fs::path& sweep) { return "sweep --status " + sweep.string(); }},
      {"scenarios", true, "scenarios.json",
       [](const fs::path& sweep) {
         return "sweep " + templates().sweep_file.string() + " --out " + sweep.string();
       }},
  };
  return all;
}

TEST(HostileResultFiles, EveryFileKindTimesEveryHostilityExitsTwoNamingTheFile) {
  const Templates& t = templates();
  for (const FileKind& kind : fileKinds()) {
    for (const Hostility& hostility : hostilities()) {
      const std::string label = kind.name + " × " + hostility.name;
      const fs::path dir = scratch(kind.name + "_" + hostility.name);
      const fs::path folder = dir / "folder";
      fs::copy(kind.in_sweep ? t.sweep : t.run, folder, fs::copy_options::recursive);
      const fs::path file = folder / kind.relative;
      fs::remove(file);
      hostility.plant(file);
      const Outcome outcome = canopy(kind.command(folder));
      EXPECT_EQ(outcome.code, 2) << label << ": " << outcome.output;
      EXPECT_NE(outcome.output.find(file.filename().string()), std::string::npos)
          << label << ": the message does not name the file: " << outcome.output;
      if (!hostility.expected.empty() && hostility.name != "deep") {
        EXPECT_NE(outcome.output.find(hostility.expected), std::string::npos)
            << label << ": " << outcome.output;
      }
      EXPECT_LT(outcome.output.size(), 2000u) << label << ": an unbounded echo";
      fs::remove_all(dir);
    }
  }
}

// --- Box2D's limits, through validate and run ---------------------------------------------------

std::string scenarioWithPolygon(const std::string& vertices) {
  return R"({"aoi": [0, 0, 100, 50], "clock": {"duration": 1}, "uavs": [{"start": [10, 10]}],
    "occluders": [{"type": "disc", "centre": [5, 5], "radius": 1},
                  {"type": "disc", "centre": [15, 5], "radius": 1},
                  {"type": "polygon", "vertices": [[20, 20], [24, 20], [22, 24]]},
                  {"type": "polygon", "vertices": )" +
         vertices + "}]}";
}

TEST(HostileShapes, PolygonsBox2dCannotBuildAreRefusedAtValidateWithTheirIndex) {
  const fs::path dir = scratch("shapes");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"sliver", "[[30, 30], [40, 30], [35, 30.000000001]]"},
      {"thin_quad", "[[30, 30], [40, 30], [40, 30.001], [30, 30.001]]"},
      {"collinear", "[[30, 30], [31, 30], [32, 30], [31, 31]]"},
      {"nearly_collinear", "[[30, 30], [31, 30.0001], [32, 30], [31, 31]]"},
      {"duplicate", "[[30, 30], [34, 30], [34, 30], [32, 34]]"},
      {"near_duplicate", "[[30, 30], [34, 30], [34.001, 30.001], [32, 34]]"},
      {"tiny", "[[30, 30], [30.01, 30], [30.005, 30.01]]"},
      {"huge", "[[-1e30, -1e30], [1e30, -1e30], [0, 2e30]]"},
      // Nine convex vertices are a wall cut into convex pieces now (issue 52); a self-crossing
      // outline and one that doubles back on itself are not polygons at all.
      {"self_crossing", "[[30, 30], [34, 34], [34, 30], [30, 34]]"},
      {"doubling_back", "[[30, 30], [36, 30], [36, 34], [33, 34], [36, 34.00001], [30, 34]]"},
      {"two_vertices", "[[30, 30], [34, 30]]"},
  };
  for (const auto& [name, vertices] : cases) {
    const fs::path file = dir / (name + ".json");
    write(file, scenarioWithPolygon(vertices));
    for (const std::string command : {"validate ", "run "}) {
      const Outcome outcome = canopy(command + file.string() +
                                     (command == "run " ? " --out " + (dir / name).string() : ""));
      EXPECT_EQ(outcome.code, 2) << name << " " << command << outcome.output;
      EXPECT_NE(outcome.output.find(name + ".json: occluders[3].vertices"), std::string::npos)
          << name << ": " << outcome.output;
    }
  }
  // A disc Box2D could not hold: a radius beyond 1e7 m, or one that is zero as a float.
  write(dir / "disc.json", R"({"aoi": [0, 0, 100, 50], "uavs": [{"start": [10, 10]}],
    "occluders": [{"type": "disc", "centre": [5, 5], "radius": 1e-50}]})");
  const Outcome disc = canopy("validate " + (dir / "disc.json").string());
  EXPECT_EQ(disc.code, 2) << disc.output;
  EXPECT_NE(disc.output.find("occluders[0].radius"), std::string::npos) << disc.output;
}

// --- Numbers on the command line -----------------------------------------------------------------

TEST(HostileNumbers, CommandLineNumbersAreFiniteInRangeAndPlainlyWritten) {
  const fs::path dir = scratch("numbers");
  const std::string forest = "forest --aoi 0,0,100,100 --lambda 0.001 ";
  const std::vector<std::string> refused = {
      forest + "--radius 1,inf",
      forest + "--radius inf",
      forest + "--radius 1,1e400",
      forest + "--radius nan",
      forest + "--radius +1",
      forest + "--radius 1x,2",
      forest + "--radius 0x10",
      forest + "--radius 1,2,3",
      forest + "--radius 1e300",
      forest + "--radius 2,1",
      forest + "--radius 1,",
      "forest --aoi 0,0,1e300,100 --lambda 0 --radius 1",
      "forest --aoi 0,0,100,100, --lambda 0 --radius 1",
      "forest --aoi 0,0,100,100 --lambda +0.1 --radius 1",
      "forest --aoi 0,0,100,100 --lambda 0x1p-3 --radius 1",
      "forest --aoi 0,0,100,100 --lambda infinity --radius 1",
  };
  for (const std::string& arguments : refused) {
    const Outcome outcome = canopy(arguments);
    EXPECT_EQ(outcome.code, 2) << arguments << ": " << outcome.output;
  }
  EXPECT_EQ(canopy(forest + "--radius 1,2.5e0").code, 0);
  EXPECT_EQ(canopy(forest + "--radius 0.5").code, 0);

  // --shard: plain digits only. (Values with blanks cannot be quoted inside canopy()'s bash -c
  // '…': option_grammar_test.cpp passes every option's blanks through execv.)
  for (const std::string shard : {"+1/2", "1/+2", "01/2", "1/02", "-0/2",
                                  "1/2x", "0x1/2", "2/2", "1/0", "1/1000001", "1//2"}) {
    const Outcome outcome = canopy("sweep " + templates().sweep_file.string() + " --out " +
                                   (dir / "out").string() + " --shard " + shard);
    EXPECT_EQ(outcome.code, 2) << shard << ": " << outcome.output;
    EXPECT_NE(outcome.output.find("--shard"), std::string::npos) << outcome.output;
  }
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// --- Golden CSVs
// -----------------------------------------------------------------------------------

TEST(HostileGolden, AMalformedGoldenIsBadInputNamingTheFileWithABoundedEcho) {
  const fs::path dir = scratch("golden");
  fs::copy(templates().run, dir / "run", fs::copy_options::recursive);
  const Outcome printed =
      canopy("coverage " + (dir / "run").string() + " > " + (dir / "good.csv").string());
  ASSERT_EQ(printed.code, 0) << printed.output;
  std::ifstream in(dir / "good.csv");
  std::string header, rest, line;
  std::getline(in, header);
  while (std::getline(in, line)) rest += line + "\n";
  const std::string big(20 << 20, 'x');
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"renamed", "step,t,covered_px_renamed" +
                      header.substr(std::string("step,t,covered_px").size()) + "\n" + rest},
      {"extra", header + ",extra\n" + rest},
      {"long_column_name", header + "," + big + "\n" + rest},
      {"long_cell", header + "\n" + big + "\n"},
      {"wrong_width", header + "\n1,2\n"},
      {"not_numbers",
       header + "\n" + std::string(std::count(header.begin(), header.end(), ','), ',') + "\n"},
      {"hex_number", header + "\n" + "0x1" + rest.substr(rest.find(','))},
      {"header_only_junk", "hello\n"},
      {"empty", ""},
  };
  for (const auto& [name, text] : cases) {
    const fs::path golden = dir / (name + ".csv");
    write(golden, text);
    const Outcome outcome =
        canopy("coverage " + (dir / "run").string() + " --check " + golden.string());
    EXPECT_EQ(outcome.code, 2) << name << ": " << outcome.output.substr(0, 500);
    EXPECT_NE(outcome.output.find(name + ".csv"), std::string::npos)
        << name << ": " << outcome.output.substr(0, 500);
    EXPECT_LT(outcome.output.size(), 1500u) << name << ": the echo is not bounded";
  }
  // The good golden still matches, through a link the user names too.
  fs::create_symlink(dir / "good.csv", dir / "link.csv");
  EXPECT_EQ(
      canopy("coverage " + (dir / "run").string() + " --check " + (dir / "link.csv").string()).code,
      0);
}

// --- CANOPY_PATH
// -------------------------------------------------------------------------------------

TEST(HostileSearchPath, ALinkLoopIsSkippedWithAWarningAndRefusedWhenNamed) {
  const fs::path dir = scratch("canopy_path");
  write(dir / "mine.json", R"({"description": "my own", "aoi": [0, 0, 100, 50],
                               "uavs": [{"start": [10, 10]}]})");
  fs::create_symlink("loop_b.json", dir / "loop_a.json");
  fs::create_symlink("loop_a.json", dir / "loop_b.json");
  fs::create_symlink("nowhere.json", dir / "dangling.json");
  const std::string env = "CANOPY_PATH=" + dir.string();
  const Outcome list = canopy("list", env);
  EXPECT_EQ(list.code, 0) << list.output;
  EXPECT_NE(list.output.find("mine"), std::string::npos) << list.output;
  EXPECT_NE(list.output.find("my own"), std::string::npos) << list.output;
  EXPECT_NE(list.output.find("demo"), std::string::npos) << list.output;  // the library still
  EXPECT_NE(list.output.find("loop_a.json: a symbolic link loop"), std::string::npos)
      << list.output;
  EXPECT_NE(list.output.find("dangling.json"), std::string::npos) << list.output;
  for (const std::string name : {"loop_a", "loop_a.json"}) {
    const Outcome run = canopy("validate " + name, env);
    EXPECT_EQ(run.code, 2) << run.output;
    EXPECT_NE(run.output.find("loop_a.json"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("loop"), std::string::npos) << run.output;
  }
  const Outcome direct = canopy("validate " + (dir / "loop_b.json").string());
  EXPECT_EQ(direct.code, 2) << direct.output;
  EXPECT_NE(direct.output.find("loop_b.json"), std::string::npos) << direct.output;
}

// --- Sweep folders -------------------------------------------------------------------------------

TEST(HostileSweepFolders, ATrialOfAnotherSweepIsNamedAsSuch) {
  const fs::path dir = scratch("other_sweep");
  fs::copy(templates().sweep, dir / "sweep", fs::copy_options::recursive);
  // Another sweep's trial planted in this sweep's configuration folder.
  const fs::path trial = dir / "sweep" / "trials" / "horizon-1" / "trial_0000.json";
  std::ifstream in(trial);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  const std::string from = "\"config_id\":\"horizon-1\"";
  ASSERT_NE(text.find(from), std::string::npos) << text.substr(0, 300);
  text.replace(text.find(from), from.size(), "\"config_id\":\"horizon-7\"");
  write(trial, text);
  const Outcome analyze = canopy("analyze " + (dir / "sweep").string());
  EXPECT_EQ(analyze.code, 2) << analyze.output;
  EXPECT_NE(analyze.output.find("belongs to another sweep"), std::string::npos) << analyze.output;
  EXPECT_NE(analyze.output.find("trial_0000.json"), std::string::npos) << analyze.output;
}

TEST(HostileSweepFolders, TwoSpellingsOfOneFieldAreOneAxis) {
  const fs::path dir = scratch("spellings");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"index_zeros", R"([{"path": "uavs.0.v_max", "values": [5]},
                          {"path": "uavs.00.v_max", "values": [6]}])"},
      {"named_and_path", R"([{"path": "planner.horizon", "values": [1]},
                             {"name": "H", "values": ["a"], "set": [{"planner.horizon": 2}]}])"},
      {"parent_and_field", R"([{"path": "planner.horizon", "values": [1]},
                               {"path": "planner", "values": [{"horizon": 2}]}])"},
      {"two_named", R"([{"name": "A", "values": ["a"], "set": [{"clock.dt": 0.1}]},
                        {"name": "B", "values": ["b"], "set": [{"clock.dt": 0.2}]}])"},
  };
  for (const auto& [name, axes] : cases) {
    const fs::path file = dir / (name + ".json");
    write(file, R"({"name": "s", "scenario": "demo", "trials": 1, "set": {"clock.duration": 2},
                    "axes": )" +
                    axes + "}");
    const Outcome outcome = canopy("sweep " + file.string() + " --out " + (dir / name).string());
    EXPECT_EQ(outcome.code, 2) << name << ": " << outcome.output;
    EXPECT_NE(outcome.output.find("axes[1]"), std::string::npos) << name << ": " << outcome.output;
    EXPECT_NE(outcome.output.find("one axis only"), std::string::npos)
        << name << ": " << outcome.output;
    EXPECT_FALSE(fs::exists(dir / name)) << name;
  }
}

}  // namespace
