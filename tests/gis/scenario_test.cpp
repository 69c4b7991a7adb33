// An imported place in a scenario (issue 52): the layout included as occluders, people walking
// its footpaths, `canopy validate` saying what was imported, and a run whose recorded people stay
// on the footpaths (the distance measured against the layout's polylines, not the network).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/app/cli.h"
#include "tests/gis/campus_data.h"

namespace canopy::cli_test {
namespace {

using Json = nlohmann::json;
using namespace canopy::gis_test;

double distanceToFootpaths(const Json& footpaths, double x, double y) {
  double best = 1e300;
  for (const Json& line : footpaths) {
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
      const double ax = line[i][0], ay = line[i][1], bx = line[i + 1][0], by = line[i + 1][1];
      const double ex = bx - ax, ey = by - ay;
      const double s = std::clamp(((x - ax) * ex + (y - ay) * ey) / (ex * ex + ey * ey), 0.0, 1.0);
      best = std::min(best, std::hypot(ax + s * ex - x, ay + s * ey - y));
    }
  }
  return best;
}

TEST(GisScenario, PeopleWalkTheImportedFootpathsAndStayOnThem) {
  const fs::path dir = fresh("gis_scenario");
  fs::create_directories(dir);
  std::ofstream(dir / "campus.geojson") << campusGeoJson();
  ASSERT_EQ(runIn(dir, "import campus.geojson --out campus.json --attribution synthetic").code, 0);
  const Json layout = Json::parse(slurp(dir / "campus.json"));
  const Json& extent = layout["source"]["extent"];
  const Json& paths = layout["footpaths"];
  // From the footway's west end to the pedestrian way's east end, and a random walker.
  const Json west = paths[0][0], east = paths[2].back();
  Json scenario = {
      {"name", "gis_walk"},
      {"aoi", {extent[0].get<double>() - 20, extent[1].get<double>() - 20,
               extent[2].get<double>() + 20, extent[3].get<double>() + 20}},
      {"clock", {{"dt", 0.2}, {"duration", 60.0}}},
      {"uavs", {{{"fov", {{"radius", 40}}},
                 {"path", {{"start", {west[0], west[1]}}, {"velocity", {1.5, 0.0}}}}}}},
      {"targets",
       {{{"name", "commuter"},
         {"path", {{"footpaths", "campus.json"}, {"from", west}, {"to", east}, {"speed", 1.4}}}},
        {{"name", "stroller"},
         {"path", {{"footpaths", "campus.json"}, {"from", {150, 60}}, {"seed", 4}, {"speed", 1.2}}}}}},
      {"occluders", {{{"include", "campus.json"}}}}};
  std::ofstream(dir / "walk.json") << scenario.dump(1);
  const Outcome validate = runIn(dir, "validate walk.json");
  ASSERT_EQ(validate.code, 0) << validate.err;
  EXPECT_NE(validate.out.find("layout campus.json: imported from [\"campus.geojson\"]"),
            std::string::npos)
      << validate.out;
  EXPECT_NE(validate.out.find("2 buildings"), std::string::npos) << validate.out;
  EXPECT_NE(validate.out.find("3 footpaths"), std::string::npos) << validate.out;
  EXPECT_NE(validate.out.find("; synthetic"), std::string::npos) << validate.out;

  const Outcome run = runIn(dir, "run walk.json --out r --frames --frame-every 100 --size 160x120");
  ASSERT_EQ(run.code, 0) << run.err;
  // The stated bound: every recorded position within 1 cm of a footpath (the target's body is
  // driven by velocity in Box2D, whose positions are floats: ~1e-4 m at a kilometre).
  std::istringstream record(slurp(dir / "r" / "record.jsonl"));
  std::string line;
  int steps = 0;
  double worst = 0.0, commuter_x_first = 0.0, commuter_x_last = 0.0;
  while (std::getline(record, line)) {
    const Json step = Json::parse(line);
    if (!step.contains("targets")) continue;
    for (const Json& target : step["targets"])
      worst = std::max(worst, distanceToFootpaths(paths, target["p"][0], target["p"][1]));
    (steps == 0 ? commuter_x_first : commuter_x_last) = step["targets"][0]["p"][0].get<double>();
    ++steps;
  }
  EXPECT_EQ(steps, 301);
  EXPECT_LT(worst, 0.01);
  // 60 s at 1.4 m/s east along the footway: 84 m.
  EXPECT_NEAR(commuter_x_last - commuter_x_first, 84.0, 0.1);
  EXPECT_TRUE(fs::exists(dir / "r" / "frames"));
  fs::remove_all(dir);
}

// A goal the start's footpaths do not reach, and a layout without footpaths: exit 2 naming the
// field (and the layout file).
TEST(GisScenario, UnreachableGoalsAndLayoutsWithoutFootpathsAreNamed) {
  const fs::path dir = fresh("gis_walk_errors");
  fs::create_directories(dir);
  std::ofstream(dir / "two.json")
      << R"({"occluders": [], "footpaths": [[[0, 0], [10, 0]], [[0, 5], [10, 5]]]})";
  std::ofstream(dir / "none.json") << R"({"occluders": []})";
  auto scenario = [](const std::string& path) {
    return R"({"aoi": [-20, -20, 20, 20], "uavs": [{"start": [0, 0]}], "targets": [{"path": )" +
           path + "}]}";
  };
  std::ofstream(dir / "a.json")
      << scenario(R"({"footpaths": "two.json", "from": [0, 0], "to": [10, 5]})");
  std::ofstream(dir / "b.json") << scenario(R"({"footpaths": "none.json", "from": [0, 0]})");
  const Outcome a = runIn(dir, "validate a.json");
  EXPECT_EQ(a.code, 2);
  EXPECT_NE(a.err.find("a.json: targets[0].path.to: expected a point the start's footpaths lead to"),
            std::string::npos)
      << a.err;
  const Outcome b = runIn(dir, "validate b.json");
  EXPECT_EQ(b.code, 2);
  EXPECT_NE(b.err.find("b.json: targets[0].path.footpaths: in the layout file none.json: footpaths: "
                       "expected a layout file with footpaths"),
            std::string::npos)
      << b.err;
  fs::remove_all(dir);
}

// The built-in example's layout is what `canopy import` makes of the synthetic GeoJSON today
// (the command in scenarios/library/campus_walk.json's header).
TEST(GisScenario, TheBuiltInCampusLayoutIsAFreshImport) {
  const fs::path dir = fresh("gis_builtin");
  const fs::path source = fs::path(CANOPY_SOURCE_DIR) / "examples" / "gis";
  const fs::path committed =
      fs::path(CANOPY_SOURCE_DIR) / "scenarios" / "library" / "layouts" / "synthetic_campus.json";
  const Json before = Json::parse(slurp(committed));
  const Outcome o =
      runIn(dir, "import '" + (source / "synthetic_campus.geojson").string() +
                     "' --out campus.json --attribution '" +
                     before["source"]["attribution"].get<std::string>() + "'");
  ASSERT_EQ(o.code, 0) << o.err;
  const Json now = Json::parse(slurp(dir / "campus.json"));
  EXPECT_EQ(now["occluders"], before["occluders"]);
  EXPECT_EQ(now["footpaths"], before["footpaths"]);
  for (const char* key : {"imported", "origin", "frame", "crs", "extent"})
    EXPECT_EQ(now["source"][key], before["source"][key]) << key;
  // The issue's bar on its shape: three concave buildings, one of 20 vertices, none skipped.
  EXPECT_EQ(before["source"]["imported"]["buildings"], 3);
  EXPECT_EQ(before["source"]["imported"]["buildings_skipped"], 0);
  bool twenty = false;
  for (const Json& o2 : before["occluders"])
    twenty = twenty || (o2["type"] == "polygon" && o2["vertices"].size() == 20u);
  EXPECT_TRUE(twenty);
  // The wood's trees (the discs after the walls) keep their trunks (0.25 m for a 2.5 m crown)
  // 1 m off every footpath, so nobody walks through a trunk: no warning from validate.
  bool after_walls = false;
  int wood_trees = 0;
  for (const Json& o2 : before["occluders"]) {
    after_walls = after_walls || o2["type"] == "polygon";
    if (!after_walls || o2["type"] != "disc") continue;
    ++wood_trees;
    EXPECT_GE(distanceToFootpaths(before["footpaths"], o2["centre"][0], o2["centre"][1]), 1.25);
  }
  EXPECT_EQ(wood_trees, before["source"]["imported"]["wood_trees"].get<int>());
  const Outcome validate = runIn(dir, "validate campus_walk");
  EXPECT_EQ(validate.code, 0) << validate.err;
  EXPECT_EQ(validate.err, "");
  EXPECT_NE(validate.out.find("synthetic_campus.json: imported from [\"examples/gis/synthetic_campus.geojson\"]"),
            std::string::npos)
      << validate.out;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace canopy::cli_test
