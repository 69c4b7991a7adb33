#pragma once
// Reading GIS vector files with GDAL/OGR (any format it reads: GeoJSON, GeoPackage, Shapefile,
// OSM, …) into plain features: geometry in the layer's own CRS, and the attributes as tags.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/types.h"

namespace canopy::gis {

enum class GeometryKind { point, line, polygon };

struct Feature {
  long long fid = 0;
  GeometryKind kind = GeometryKind::point;
  /// point: one part of one point; line: one part per line; polygon: the exterior ring first,
  /// then its holes (rings without the repeated closing point). A multi-geometry is one Feature
  /// per member.
  std::vector<std::vector<Vec2>> parts;
  /// Every set attribute as text, and OpenStreetMap's other_tags ("k"=>"v", …) split out.
  std::map<std::string, std::string> tags;
};

struct SourceLayer {
  std::string file;    // as named on the command line
  std::string name;    // the layer's name
  std::string driver;  // GDAL's short name: "GeoJSON", "GPKG", "ESRI Shapefile", "OSM", …
  std::string crs_wkt;
  std::vector<std::string> fields;  // the layer's attribute names
  std::vector<Feature> features;
};

/// Every layer of `file`, or only `layer` when given. Throws spec::ScenarioError naming the file
/// (and --layer) when the file cannot be opened as vector data, has no such layer, or a layer
/// has no CRS.
std::vector<SourceLayer> readLayers(const std::string& file, const std::optional<std::string>& layer);

/// The value of tag `key` on `feature`, or nullopt. In a Shapefile, whose attribute names are
/// cut to 10 characters, a key longer than that is also found under its first 10.
std::optional<std::string> tag(const Feature& feature, const std::string& key,
                               bool shapefile = false);

/// The attribute name `key` has in the layer (itself, or cut to 10 characters in a Shapefile),
/// or nullopt when the layer has no such attribute.
std::optional<std::string> fieldName(const SourceLayer& layer, const std::string& key);

}  // namespace canopy::gis
