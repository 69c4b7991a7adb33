#pragma once
// The synthetic campus the GIS tests import: OpenStreetMap-tagged GeoJSON in real coordinates
// (near 52.2° N, 0.12° E; made up, not surveyed).
#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

namespace canopy::gis_test {

using Json = nlohmann::json;

constexpr double kLat0 = 52.2053, kLon0 = 0.1218;  // the campus's south-west corner
// Metres east/north of the corner as degrees (a local approximation good to ~0.3 %: only to
// place the data; every check uses the degrees written).
inline Json lonLat(double east, double north) {
  const double m_per_deg_lat = 111254.0;
  const double m_per_deg_lon = 111412.0 * std::cos(kLat0 * std::numbers::pi / 180.0);
  return Json::array({kLon0 + east / m_per_deg_lon, kLat0 + north / m_per_deg_lat});
}

inline Json feature(const Json& properties, const std::string& type, const Json& coordinates) {
  return {{"type", "Feature"},
          {"properties", properties},
          {"geometry", {{"type", type}, {"coordinates", coordinates}}}};
}

inline Json ring(const std::vector<std::pair<double, double>>& metres, double east, double north) {
  Json r = Json::array();
  for (const auto& [x, y] : metres) r.push_back(lonLat(east + x, north + y));
  r.push_back(r.front());
  return r;
}

// Tree positions (m east, north of the corner) and crown diameters ("" : none).
inline const std::vector<std::tuple<double, double, std::string>> kTrees = {
    {0, 0, "8"}, {30, 10, "6.5"}, {-500, 400, "10 m"}, {800, -600, ""}, {1200, 900, "4"},
    {-50, -20, "12"}};

inline std::string campusGeoJson() {
  Json features = Json::array();
  for (const auto& [e, n, d] : kTrees) {
    Json p = {{"natural", "tree"}};
    if (!d.empty()) p["diameter_crown"] = d;
    features.push_back(feature(p, "Point", lonLat(e, n)));
  }
  features.push_back(feature({{"amenity", "bench"}}, "Point", lonLat(5, 5)));  // not a tree
  // An L-shaped building (20 × 20 m less its north-east quarter) and a 20-vertex star.
  features.push_back(feature({{"building", "university"}}, "Polygon",
                             Json::array({ring({{0, 0}, {20, 0}, {20, 10}, {10, 10}, {10, 20}, {0, 20}},
                                               100, 50)})));
  std::vector<std::pair<double, double>> star;
  for (int k = 0; k < 20; ++k) {
    const double a = std::numbers::pi * k / 10.0, r = k % 2 ? 5.0 : 12.0;
    star.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  features.push_back(feature({{"building", "yes"}}, "Polygon", Json::array({ring(star, 200, 150)})));
  // A wood, 100 m square.
  features.push_back(feature({{"natural", "wood"}}, "Polygon",
                             Json::array({ring({{0, 0}, {100, 0}, {100, 100}, {0, 100}}, 300, 300)})));
  // Three footpaths meeting at (150, 0), and a road that is not one.
  features.push_back(feature({{"highway", "footway"}}, "LineString",
                             Json::array({lonLat(-60, 0), lonLat(60, 0), lonLat(150, 0)})));
  features.push_back(feature({{"highway", "path"}}, "LineString",
                             Json::array({lonLat(150, 0), lonLat(150, 120), lonLat(250, 200)})));
  features.push_back(feature({{"highway", "pedestrian"}}, "LineString",
                             Json::array({lonLat(150, 0), lonLat(300, -40)})));
  features.push_back(feature({{"highway", "residential"}}, "LineString",
                             Json::array({lonLat(0, -100), lonLat(300, -100)})));
  return Json{{"type", "FeatureCollection"}, {"features", features}}.dump(1);
}

}  // namespace canopy::gis_test
