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

}  // namespace
}  // namespace canopy::cli_test
