// canopy import: GIS vector files → a layout file (gis/import.h, docs/gis-import.md).
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "app/commands.h"
#include "core/output_file.h"
#include "core/printable.h"
#include "gis/import_loader.h"
#include "world/tree.h"

namespace canopy::app {
namespace {

// "A,B" as two finite numbers.
std::optional<Vec2> readPair(const std::string& text) {
  std::istringstream in(text);
  double a = 0.0, b = 0.0;
  char comma = 0;
  if (!(in >> a >> comma >> b) || comma != ',' || !(in >> std::ws).eof()) return std::nullopt;
  if (!std::isfinite(a) || !std::isfinite(b)) return std::nullopt;
  return Vec2(a, b);
}

std::optional<Vec2> readLatLon(const std::string& text) {
  const auto p = readPair(text);
  if (!p || std::abs(p->x()) > 90.0 || std::abs(p->y()) > 180.0) return std::nullopt;
  return p;
}

std::optional<Aabb> readLonLatBox(const std::string& text) {
  std::istringstream in(text);
  double v[4];
  char comma = 0;
  for (int i = 0; i < 4; ++i) {
    if (!(in >> v[i])) return std::nullopt;
    if (i < 3 && (!(in >> comma) || comma != ',')) return std::nullopt;
  }
  if (!(in >> std::ws).eof()) return std::nullopt;
  const Aabb box{Vec2(v[0], v[1]), Vec2(v[2], v[3])};
  if (!(box.hi.x() > box.lo.x() && box.hi.y() > box.lo.y())) return std::nullopt;
  if (std::abs(box.lo.x()) > 180 || std::abs(box.hi.x()) > 180 || std::abs(box.lo.y()) > 90 ||
      std::abs(box.hi.y()) > 90)
    return std::nullopt;
  return box;
}

class Import : public Command {
 public:
  explicit Import(CLI::App& canopy)
      : Command(canopy, "import", "canopy import GIS_FILE [GIS_FILE …] --out LAYOUT.json [options]",
                "Makes a layout file from GIS vector data (GeoJSON, GeoPackage, Shapefile, OSM, "
                "any format GDAL/OGR reads): trees (natural=tree, or every point of a tree "
                "inventory) as discs with trunks, buildings (building=*) as walls, woods "
                "(natural=wood, landuse=forest) as Poisson fills, footpaths "
                "(highway=footway|path|pedestrian) as a network people walk. Coordinates go to a "
                "local frame in metres: a transverse Mercator centred on --origin (default the "
                "data's centre); data in a projected CRS in metres keeps its units, shifted by "
                "the origin. docs/gis-import.md has every rule.") {
    CLI::App& o = options();
    o.add_option("GIS_FILE", options_.files, "GIS vector files, read in order")->required();
    o.add_option("--out", out_, "the layout file to write")->required()->type_name("LAYOUT.json");
    o.add_option("--layer", layer_, "read only this layer of each file")->type_name("NAME");
    o.add_option("--radius-field", radius_field_, "tree inventory: the attribute holding a crown's radius (m)")
        ->type_name("NAME");
    o.add_option("--diameter-field", diameter_field_,
                 "tree inventory: the attribute holding a crown's diameter (m)")
        ->type_name("NAME");
    addValue(o, "--default-radius", "R", options_.default_radius,
             finiteNumber("a radius in (0, 1000] (m)", [](double r) { return r > 0.0 && r <= 1000.0; }),
             "crown radius of a tree without one (m)")
        ->default_str("2.5");
    addValue(o, "--bbox", "W,S,E,N", options_.bbox,
             Reader<Aabb>{readLonLatBox,
                          "W,S,E,N: WGS84 longitudes and latitudes (degrees), E > W and N > S"},
             "clip to this box: trees by their point, buildings and woods by their outline's "
             "mean, footpaths to their runs of vertices inside")
        ->default_str("none");
    addValue(o, "--origin", "LAT,LON", options_.origin,
             Reader<Vec2>{readLatLon, "LAT,LON in degrees (|LAT| <= 90, |LON| <= 180)"},
             "the local frame's origin (default: the centre of the data's bounding box)")
        ->default_str("the data's centre");
    addValue(o, "--wood-density", "L", options_.wood_density,
             finiteNumber("a density in [0, 10] (trees per m²)", [](double l) { return l >= 0.0 && l <= 10.0; }),
             "trees per m² drawn in woods (a Poisson process)")
        ->default_str("0.01");
    addValue(o, "--seed", "S", options_.seed, nonNegativeInteger(), "the wood fills' seed")
        ->default_str("1");
    o.add_option("--attribution", attribution_,
                 "the data's attribution, recorded in the layout (default: OpenStreetMap's when "
                 "the data is OSM's, else none)")
        ->type_name("TEXT");
  }
  int run() override;

 private:
  gis::ImportOptions options_;
  std::string out_, layer_, radius_field_, diameter_field_, attribution_;
};

int Import::run() {
  if (!layer_.empty()) options_.layer = layer_;
  if (!radius_field_.empty() && !diameter_field_.empty())
    usageError("--diameter-field", "give only one of --radius-field and --diameter-field");
  if (!radius_field_.empty()) options_.radius_field = radius_field_;
  if (!diameter_field_.empty()) options_.diameter_field = diameter_field_;
  if (options().count("--attribution")) options_.attribution = attribution_;
  checkOutputFile(out_);
  const gis::ImportedLayout imported = gis::importThroughModule(options_);
  const gis::ImportResult& result = imported.result;
  constexpr std::size_t kShown = 10;
  for (std::size_t i = 0; i < std::min(kShown, result.warnings.size()); ++i)
    std::fprintf(stderr, "warning: %s\n", printable(result.warnings[i], 400).c_str());
  if (result.warnings.size() > kShown)
    std::fprintf(stderr, "warning: … and %zu more\n", result.warnings.size() - kShown);
  AtomicFile file(out_);
  file.write(imported.text);
  file.commit();
  const auto& source = result.layout["source"];
  std::printf("%s: %s\n  frame: %s\n  extent (m): %s\n", printable(out_, 200).c_str(),
              printable(result.layout["description"].get<std::string>(), 400).c_str(),
              printable(source["frame"].get<std::string>(), 400).c_str(),
              source["extent"].dump().c_str());
  return kExitOk;
}

}  // namespace

std::unique_ptr<Command> makeImport(CLI::App& canopy) {
  return std::make_unique<Import>(canopy);
}

}  // namespace canopy::app
