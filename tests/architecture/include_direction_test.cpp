// The rooms and their one-way arrows (docs/architecture.md): every #include "room/…" in every
// source file points at the file's own room or at a room below it in the data flow, and a room's
// internal/ headers are included only from that room (and its tests). The table below is the
// picture in docs/architecture.md; a new include that runs against it fails here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace canopy {
namespace {
namespace fs = std::filesystem;

// Each room and the rooms it may include directly (its own room is always allowed). The agents'
// stack is split into its parts: the shared belief types, then tracking ← fusion, planning, then
// one UAV's tick (agent.h, team.h).
const std::map<std::string, std::set<std::string>> kMayInclude = {
    {"core", {}},
    {"world", {"core"}},
    {"sensing", {"core", "world"}},
    {"agents/common", {"core", "world", "sensing"}},
    {"agents/tracking", {"core", "world", "sensing", "agents/common"}},
    {"agents/fusion", {"core", "world", "sensing", "agents/common", "agents/tracking"}},
    {"agents/planning", {"core", "world", "sensing", "agents/common", "agents/tracking"}},
    {"agents/team",
     {"core", "world", "sensing", "agents/common", "agents/tracking", "agents/fusion",
      "agents/planning"}},
    {"metrics", {"core", "agents/fusion"}},
    // GIS data (GDAL, PROJ) → a layout file: the scenario format's errors, the world's walls.
    {"gis", {"core", "world", "spec"}},
    {"spec",
     {"core", "world", "sensing", "agents/common", "agents/tracking", "agents/fusion",
      "agents/planning", "agents/team"}},
    {"sim",
     {"core", "world", "sensing", "agents/common", "agents/tracking", "agents/fusion",
      "agents/planning", "agents/team", "metrics", "spec"}},
    {"experiments",
     {"core", "world", "sensing", "agents/common", "agents/tracking", "agents/fusion",
      "agents/planning", "agents/team", "metrics", "spec", "sim"}},
    {"render",
     {"core", "world", "sensing", "agents/common", "agents/tracking", "agents/fusion",
      "agents/planning", "agents/team", "spec", "sim"}},
    {"analysis",
     {"core", "world", "sensing", "agents/common", "agents/tracking", "agents/fusion",
      "agents/planning", "agents/team", "metrics", "spec", "sim", "experiments", "render"}},
    {"replay",
     {"core", "world", "sensing", "agents/common", "agents/tracking", "agents/fusion",
      "agents/planning", "agents/team", "metrics", "spec", "sim", "experiments", "render",
      "analysis"}},
};
// The front ends: they may include every library room, never one another.
const std::vector<std::string> kFrontEnds = {"app", "python", "fuzz", "bench"};

/// The room of a path relative to the source root ("agents/tracking/jpda.h" → "agents/tracking",
/// "agents/team.h" → "agents/team", "agents/belief.h" → "agents/common").
std::string roomOf(const std::string& path) {
  const std::string top = path.substr(0, path.find('/'));
  if (top != "agents") return top;
  const std::string rest = path.substr(top.size() + 1);
  if (rest.find('/') != std::string::npos) return "agents/" + rest.substr(0, rest.find('/'));
  const std::string name = rest.substr(0, rest.find('.'));
  return (name == "agent" || name == "team") ? "agents/team" : "agents/common";
}

bool isLibraryRoom(const std::string& room) {
  return kMayInclude.count(room) > 0;
}

/// What is wrong with `file` (relative to the source root) including `included`; empty if
/// nothing is.
std::string violation(const std::string& file, const std::string& included) {
  const std::string from = roomOf(file);
  const std::string to = roomOf(included);
  if (!isLibraryRoom(to)) {
    const bool own_front_end = from == to;
    return own_front_end ? "" : file + " includes " + included + ": not a library room";
  }
  if (included.find("/internal/") != std::string::npos && from != to) {
    return file + " includes " + included + ": internal to " + to;
  }
  if (!isLibraryRoom(from) || from == to) return "";  // a front end may include every library
  if (kMayInclude.at(from).count(to) == 0) {
    return file + " includes " + included + ": " + from + " may not include " + to +
           " (docs/architecture.md)";
  }
  return "";
}

std::vector<std::string> violationsIn(const fs::path& root, const std::string& folder) {
  static const std::regex kInclude(R"re(^\s*#\s*include\s+"([a-z_]+/[^"]+)")re");
  std::vector<std::string> found;
  for (const auto& entry : fs::recursive_directory_iterator(root / folder)) {
    const std::string ext = entry.path().extension().string();
    if (!entry.is_regular_file() || (ext != ".h" && ext != ".cpp")) continue;
    const std::string file = fs::relative(entry.path(), root).generic_string();
    std::ifstream in(entry.path());
    std::string line;
    std::smatch match;
    while (std::getline(in, line)) {
      if (!std::regex_search(line, match, kInclude)) continue;
      const std::string problem = violation(file, match[1]);
      if (!problem.empty()) found.push_back(problem);
    }
  }
  return found;
}

TEST(Architecture, EveryIncludePointsDownTheDataFlow) {
  const fs::path root = CANOPY_SOURCE_DIR;
  std::vector<std::string> folders = {"core",        "world",    "sensing", "agents",
                                      "metrics",     "spec",     "sim",     "render",
                                      "experiments", "analysis", "replay",  "gis"};
  folders.insert(folders.end(), kFrontEnds.begin(), kFrontEnds.end());
  std::size_t checked_folders = 0;
  for (const std::string& folder : folders) {
    ASSERT_TRUE(fs::is_directory(root / folder)) << folder;
    for (const std::string& problem : violationsIn(root, folder)) ADD_FAILURE() << problem;
    ++checked_folders;
  }
  EXPECT_EQ(checked_folders, 16u);
}

TEST(Architecture, EveryCodeFolderIsARoomOfThePicture) {
  // A new top-level folder of C++ code must be placed in the table (and in the picture).
  const fs::path root = CANOPY_SOURCE_DIR;
  const std::set<std::string> not_rooms = {"tests",     "examples", "build", "docs",
                                           "scenarios", "scripts",  "cmake", ".git"};
  for (const auto& entry : fs::directory_iterator(root)) {
    const std::string name = entry.path().filename().string();
    if (!entry.is_directory() || not_rooms.count(name) || name.starts_with(".")) continue;
    bool has_code = false;
    for (const auto& file : fs::recursive_directory_iterator(entry.path())) {
      const std::string ext = file.path().extension().string();
      has_code = has_code || ext == ".h" || ext == ".cpp";
    }
    if (!has_code) continue;
    const bool placed = name == "agents" || isLibraryRoom(name) ||
                        std::find(kFrontEnds.begin(), kFrontEnds.end(), name) != kFrontEnds.end();
    EXPECT_TRUE(placed) << name << "/ holds C++ but is not in docs/architecture.md's picture";
  }
}

// The checker itself: arrows against the flow, internals from outside and front ends including
// each other are caught; arrows with the flow are not.
TEST(Architecture, TheCheckerCatchesArrowsAgainstTheFlow) {
  EXPECT_NE(violation("spec/loader.cpp", "sim/simulation.h"), "");
  EXPECT_NE(violation("agents/tracking/jpda.cpp", "agents/planning/nominal_cost.h"), "");
  EXPECT_NE(violation("agents/belief.h", "agents/team.h"), "");
  EXPECT_NE(violation("render/canvas.cpp", "experiments/sweep.h"), "");
  EXPECT_NE(violation("sim/run.cpp", "spec/internal/sections.h"), "");
  EXPECT_NE(violation("app/main.cpp", "python/src/bindings.h"), "");
  EXPECT_NE(violation("core/random.h", "world/world.h"), "");

  EXPECT_EQ(violation("sim/run.cpp", "spec/loader.h"), "");
  EXPECT_EQ(violation("spec/loader.cpp", "spec/internal/sections.h"), "");
  EXPECT_EQ(violation("agents/team.cpp", "agents/planning/team_planner.h"), "");
  EXPECT_EQ(violation("app/cmd_run.cpp", "render/frame_observer.h"), "");
  EXPECT_EQ(violation("python/src/module.cpp", "python/src/bindings.h"), "");
  EXPECT_EQ(roomOf("agents/occlusion_map.h"), "agents/common");
  EXPECT_EQ(roomOf("agents/fusion/hungarian.h"), "agents/fusion");
}

// What README and docs/ cite lives in the repository: every path in backticks that names a source
// or a document (".md", ".h", ".cpp", ".py", ".js" with a folder) exists, and no page sends the
// reader to the team's design documents, which users never see. Placeholders (`DIR/…`, `out/…`)
// are not paths; the changelog names the old paths on purpose.
TEST(Architecture, DocsCiteOnlyFilesOfTheRepository) {
  const fs::path root = CANOPY_SOURCE_DIR;
  std::vector<fs::path> pages = {root / "README.md"};
  for (const auto& entry : fs::directory_iterator(root / "docs"))
    if (entry.path().extension() == ".md") pages.push_back(entry.path());
  static const std::regex kCited(R"re(`([\w./-]+/[\w./-]+\.(md|h|cpp|py|js))`)re");
  static const std::regex kDesignDocs(
      R"re((^|[^\w/`])(algorithms|scenarios|style)\.md|shared/design)re");
  std::size_t cited = 0;
  for (const fs::path& page : pages) {
    std::ifstream in(page);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (auto it = std::sregex_iterator(text.begin(), text.end(), kCited);
         it != std::sregex_iterator(); ++it) {
      const std::string path = (*it)[1];
      if (std::isupper(static_cast<unsigned char>(path[0])) || path.starts_with("out/")) continue;
      ++cited;
      EXPECT_TRUE(fs::exists(root / path)) << page.filename() << " cites " << path;
    }
    std::smatch design;
    EXPECT_FALSE(std::regex_search(text, design, kDesignDocs))
        << page.filename() << " sends the reader to the design documents: " << design[0];
  }
  EXPECT_GT(cited, 20u);  // the check reads real citations
}

}  // namespace
}  // namespace canopy
