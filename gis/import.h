#pragma once
// `canopy import` (issue 52): GIS vector files → a canopy layout file. Trees become discs with
// trunks, buildings walls of any shape (world/convex_pieces.h), wooded areas Poisson fills, and
// footpaths a network people can walk (world/footpaths.h). docs/gis-import.md says every rule.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/types.h"

namespace canopy::gis {

struct ImportOptions {
  std::vector<std::string> files;
  std::optional<std::string> layer;           // read only this layer of each file
  std::optional<std::string> radius_field;    // a tree's crown radius (m), an attribute
  std::optional<std::string> diameter_field;  // or its crown diameter (m)
  double default_radius = 2.5;                // m, a tree without a size
  /// Clip to this box of WGS84 longitude (x) and latitude (y), degrees.
  std::optional<Aabb> bbox;
  /// The local frame's origin: (lat, lon) degrees. Default: the centre of the kept data's
  /// longitude/latitude bounding box.
  std::optional<Vec2> origin;
  double wood_density = 0.01;  // trees per m² drawn in natural=wood / landuse=forest areas
  std::uint64_t seed = 1;      // the wood fills' seed
  std::optional<std::string> attribution;  // default: OpenStreetMap's when the data is OSM's
};

struct ImportResult {
  nlohmann::json layout;              // {"description", "source", "occluders", "footpaths"}
  std::vector<std::string> warnings;  // features skipped, and why
};

/// Reads every file and builds the layout. Bad input — a file GDAL cannot read, an unknown layer,
/// a missing or malformed field, no CRS — throws spec::ScenarioError naming the file and field.
ImportResult importLayout(const ImportOptions& options);

/// The layout as text: one occluder and one footpath a line.
std::string layoutText(const nlohmann::json& layout);

}  // namespace canopy::gis
