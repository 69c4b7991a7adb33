#include "gis/import.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "core/random.h"
#include "gis/local_frame.h"
#include "gis/ogr_features.h"
#include "gis/ring_cleanup.h"
#include "spec/error.h"
#include "world/convex_pieces.h"
#include "world/tree.h"

namespace canopy::gis {
namespace {

using Json = nlohmann::json;

constexpr const char* kWgs84 = "EPSG:4326";
constexpr double kMaxTreeSize = 1000.0;  // m: a crown radius or diameter beyond this is a typo
constexpr double kMaxWoodTrees = 2e6;    // expected trees in all wood fills together
constexpr double kPathHalfWidth = 1.0;   // m: a wood's trunks keep this far from a footpath

enum class Category { tree, building, wood, footpath, other };

struct Item {
  const SourceLayer* layer = nullptr;
  const Feature* feature = nullptr;
  Category category = Category::other;
  std::vector<std::vector<Vec2>> lonlat;  // the parts in WGS84 degrees (lon, lat)
};

std::string where(const SourceLayer& layer, const Feature& feature) {
  return "layer '" + layer.name + "', feature " + std::to_string(feature.fid);
}

bool isShapefile(const SourceLayer& layer) {
  return layer.driver == "ESRI Shapefile";
}

// A tree inventory: a layer of points without OpenStreetMap's tags, every point a tree.
bool isInventory(const SourceLayer& layer) {
  return !fieldName(layer, "natural") && !fieldName(layer, "other_tags");
}

Category categorise(const SourceLayer& layer, const Feature& feature) {
  const bool shp = isShapefile(layer);
  const auto value = [&](const char* key) { return tag(feature, key, shp); };
  switch (feature.kind) {
    case GeometryKind::point:
      if (value("natural") == "tree" || isInventory(layer)) return Category::tree;
      return Category::other;
    case GeometryKind::polygon:
      if (const auto b = value("building"); b && *b != "no" && !b->empty()) return Category::building;
      if (value("natural") == "wood" || value("landuse") == "forest") return Category::wood;
      return Category::other;
    case GeometryKind::line: {
      const auto h = value("highway");
      if (h == "footway" || h == "path" || h == "pedestrian") return Category::footpath;
      return Category::other;
    }
  }
  return Category::other;
}

// A length in metres: a number, optionally followed by "m" ("8", "8.5 m"); nullopt otherwise.
std::optional<double> parseMetres(const std::string& text) {
  const char* begin = text.c_str();
  char* end = nullptr;
  const double x = std::strtod(begin, &end);
  if (end == begin) return std::nullopt;
  std::string rest(end);
  rest.erase(std::remove(rest.begin(), rest.end(), ' '), rest.end());
  if (!rest.empty() && rest != "m") return std::nullopt;
  if (!std::isfinite(x)) return std::nullopt;
  return x;
}

double roundToMillimetre(double x) {
  return std::round(x * 1000.0) / 1000.0;
}

// Crossing-number test of p against a closed ring.
bool insideRing(const std::vector<Vec2>& ring, const Vec2& p) {
  bool inside = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Vec2 &a = ring[i], &b = ring[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      inside = !inside;
  }
  return inside;
}

bool insideBox(const Aabb& box, const Vec2& p) {
  return p.x() >= box.lo.x() && p.x() <= box.hi.x() && p.y() >= box.lo.y() && p.y() <= box.hi.y();
}

Vec2 mean(const std::vector<Vec2>& points) {
  Vec2 sum = Vec2::Zero();
  for (const Vec2& p : points) sum += p;
  return sum / static_cast<double>(points.size());
}

Json point(const Vec2& p) {
  return Json::array({p.x(), p.y()});
}

class Builder {
 public:
  explicit Builder(const ImportOptions& options) : options_(options) {}

  ImportResult run() {
    for (const std::string& file : options_.files) {
      for (SourceLayer& layer : readLayers(file, options_.layer)) layers_.push_back(std::move(layer));
    }
    collect();
    chooseFrame();
    ImportResult result;
    Json occluders = Json::array(), footpaths = Json::array();
    std::map<std::string, int> counts{{"trees", 0},        {"trees_default_radius", 0},
                                      {"buildings", 0},    {"buildings_skipped", 0},
                                      {"woods", 0},        {"wood_trees", 0},
                                      {"footpaths", 0},    {"other_features", 0}};
    Aabb extent{Vec2::Constant(std::numeric_limits<double>::infinity()),
                Vec2::Constant(-std::numeric_limits<double>::infinity())};
    auto grow = [&](const Vec2& p) {
      extent.lo = extent.lo.cwiseMin(p);
      extent.hi = extent.hi.cwiseMax(p);
    };
    // Trees, then walls, then wood fills, each in the order of the files and features (the same
    // data split into other layers or formats gives the same layout); the footpaths are read
    // before the woods, whose trees keep off them.
    for (const Item& item : items_) {
      if (item.category != Category::tree) continue;
      occluders.push_back(treeEntry(item, counts));
      ++counts["trees"];
      grow(Vec2(occluders.back()["centre"][0].get<double>(), occluders.back()["centre"][1].get<double>()));
    }
    for (const Item& item : items_) {
      if (item.category != Category::building) continue;
      std::vector<Vec2> ring = local(item, 0);
      std::string problem;
      ring = canonicalRing(cleanRing(canonicalRing(std::move(ring))));
      problem = world::simplePolygonProblem(ring);
      if (problem.empty()) {
        try {
          world::convexPieces(ring);
        } catch (const std::invalid_argument& e) {
          problem = e.what();
        }
      }
      if (!problem.empty()) {
        result.warnings.push_back(item.layer->file + ": " + where(*item.layer, *item.feature) +
                                  ": building skipped: " + problem);
        ++counts["buildings_skipped"];
        continue;
      }
      Json vertices = Json::array();
      for (const Vec2& v : ring) {
        vertices.push_back(point(v));
        grow(v);
      }
      occluders.push_back({{"type", "polygon"}, {"vertices", vertices}});
      ++counts["buildings"];
    }
    for (const Item& item : items_) {
      if (item.category != Category::footpath) continue;
      for (std::size_t part = 0; part < item.lonlat.size(); ++part) {
        std::vector<Vec2> line = local(item, part);
        std::vector<Vec2> kept;
        for (const Vec2& p : line) {
          if (kept.empty() || (p - kept.back()).norm() >= 0.01) kept.push_back(p);
        }
        if (kept.size() < 2) continue;
        Json json_line = Json::array();
        for (const Vec2& p : kept) {
          json_line.push_back(point(p));
          grow(p);
        }
        footpaths.push_back(std::move(json_line));
        footpath_lines_.push_back(kept);
        ++counts["footpaths"];
      }
    }
    std::uint64_t wood_index = 0;
    for (const Item& item : items_) {
      if (item.category != Category::wood) continue;
      const auto trees = woodFill(item, wood_index++);
      for (const Vec2& c : trees) {
        occluders.push_back({{"type", "disc"}, {"centre", point(c)}, {"radius", options_.default_radius}});
        grow(c);
      }
      counts["wood_trees"] += static_cast<int>(trees.size());
      ++counts["woods"];
    }
    for (const Item& item : items_) counts["other_features"] += item.category == Category::other;

    Json source;
    source["files"] = options_.files;
    Json layer_list = Json::array();
    for (const SourceLayer& layer : layers_) {
      layer_list.push_back(layer.file + ": " + layer.name + " (" + layer.driver + ", " +
                           std::to_string(layer.features.size()) + " features)");
    }
    source["layers"] = layer_list;
    source["crs"] = crs_name_;
    source["frame"] = frame_text_;
    source["origin"] = origin_json_;
    source["attribution"] = attribution();
    source["extent"] = occluders.empty() && footpaths.empty()
                           ? Json(nullptr)
                           : Json::array({extent.lo.x(), extent.lo.y(), extent.hi.x(), extent.hi.y()});
    Json imported;
    for (const auto& [key, n] : counts) imported[key] = n;
    source["imported"] = imported;
    std::ostringstream description;
    description << "Imported by canopy import: " << counts["trees"] << " trees, "
                << counts["buildings"] << " buildings, " << counts["woods"] << " woods ("
                << counts["wood_trees"] << " trees), " << counts["footpaths"] << " footpaths";
    result.layout = {{"description", description.str()},
                     {"source", source},
                     {"occluders", occluders},
                     {"footpaths", footpaths}};
    return result;
  }

 private:
  // Every feature kept: categorised, in WGS84, inside --bbox.
  void collect() {
    for (const SourceLayer& layer : layers_) {
      if (layer.features.empty()) continue;
      Projector to_wgs84 = makeProjector(layer, layer.crs_wkt, kWgs84);
      for (const Feature& feature : layer.features) {
        Item item{&layer, &feature, categorise(layer, feature), {}};
        if (item.category == Category::other) {
          items_.push_back(std::move(item));
          continue;
        }
        for (const std::vector<Vec2>& part : feature.parts) {
          std::vector<Vec2> degrees;
          for (const Vec2& p : part) degrees.push_back(project(to_wgs84, p, layer, feature));
          item.lonlat.push_back(std::move(degrees));
        }
        if (!clip(item)) continue;
        items_.push_back(std::move(item));
      }
    }
  }

  // --bbox: a tree by its point, a building or wood by the mean of its outline, a footpath cut
  // to its runs of vertices inside (each run a part). False when nothing is left.
  bool clip(Item& item) const {
    if (!options_.bbox) return true;
    const Aabb& box = *options_.bbox;
    if (item.category == Category::footpath) {
      std::vector<std::vector<Vec2>> runs;
      for (const std::vector<Vec2>& part : item.lonlat) {
        std::vector<Vec2> run;
        for (const Vec2& p : part) {
          if (insideBox(box, p)) {
            run.push_back(p);
          } else {
            if (run.size() >= 2) runs.push_back(run);
            run.clear();
          }
        }
        if (run.size() >= 2) runs.push_back(run);
      }
      item.lonlat = std::move(runs);
      return !item.lonlat.empty();
    }
    if (item.lonlat.empty() || item.lonlat.front().empty()) return false;
    return insideBox(box, mean(item.lonlat.front()));
  }

  Projector makeProjector(const SourceLayer& layer, const std::string& from,
                          const std::string& to) const {
    try {
      return Projector(from, to);
    } catch (const std::runtime_error& e) {
      throw spec::ScenarioError(layer.file, "layer '" + layer.name + "'", e.what());
    }
  }

  Vec2 project(const Projector& projector, const Vec2& p, const SourceLayer& layer,
               const Feature& feature) const {
    try {
      return projector(p);
    } catch (const std::runtime_error& e) {
      throw spec::ScenarioError(layer.file, where(layer, feature), e.what());
    }
  }

  // The local frame: the data's own metric CRS when every layer read has the same one, else a
  // transverse Mercator at --origin or the centre of the kept data.
  void chooseFrame() {
    std::string common;
    bool same_metric = true;
    for (const SourceLayer& layer : layers_) {
      if (layer.features.empty()) continue;
      if (common.empty()) common = layer.crs_wkt;
      same_metric = same_metric && layer.crs_wkt == common && isMetricProjected(layer.crs_wkt);
    }
    same_metric = same_metric && !common.empty();
    Aabb degrees{Vec2::Constant(std::numeric_limits<double>::infinity()),
                 Vec2::Constant(-std::numeric_limits<double>::infinity())};
    Aabb own = degrees;
    for (const Item& item : items_) {
      if (item.category == Category::other) continue;
      for (const auto& part : item.lonlat) {
        for (const Vec2& p : part) {
          degrees.lo = degrees.lo.cwiseMin(p);
          degrees.hi = degrees.hi.cwiseMax(p);
        }
      }
      for (const auto& part : item.feature->parts) {
        for (const Vec2& p : part) {
          own.lo = own.lo.cwiseMin(p);
          own.hi = own.hi.cwiseMax(p);
        }
      }
    }
    const bool any = std::isfinite(degrees.lo.x());
    if (same_metric) {
      metric_ = true;
      crs_name_ = crsName(common);
      if (options_.origin) {
        const Projector to_crs(kWgs84, common);
        offset_ = to_crs(Vec2(options_.origin->y(), options_.origin->x()));
      } else if (any) {
        offset_ = Vec2(std::round(0.5 * (own.lo.x() + own.hi.x())),
                       std::round(0.5 * (own.lo.y() + own.hi.y())));
      }
      frame_text_ = "the data's own CRS (" + crs_name_ + "), metres, shifted by the origin";
      origin_json_ = {{"offset", point(offset_)}};
      return;
    }
    crs_name_.clear();
    for (const SourceLayer& layer : layers_) {
      if (layer.features.empty()) continue;
      const std::string name = crsName(layer.crs_wkt);
      if (crs_name_.find(name) == std::string::npos) crs_name_ += (crs_name_.empty() ? "" : ", ") + name;
    }
    Vec2 lat_lon = options_.origin ? *options_.origin
                   : any ? Vec2(0.5 * (degrees.lo.y() + degrees.hi.y()),
                                0.5 * (degrees.lo.x() + degrees.hi.x()))
                         : Vec2::Zero();
    frame_text_ = localTransverseMercator(lat_lon.x(), lat_lon.y());
    origin_json_ = {{"lat", lat_lon.x()}, {"lon", lat_lon.y()}};
    to_local_.emplace(Projector(kWgs84, frame_text_));
  }

  // Part `part` of the item in the local frame, rounded to the millimetre.
  std::vector<Vec2> local(const Item& item, std::size_t part) const {
    std::vector<Vec2> out;
    if (metric_ && !options_.bbox) {
      for (const Vec2& p : item.feature->parts[part]) out.push_back(p - offset_);
    } else if (metric_) {
      // Clipped: back from degrees into the CRS (the runs kept are no longer the source parts).
      const Projector to_crs(kWgs84, item.layer->crs_wkt);
      for (const Vec2& p : item.lonlat[part]) out.push_back(to_crs(p) - offset_);
    } else {
      for (const Vec2& p : item.lonlat[part])
        out.push_back(project(*to_local_, p, *item.layer, *item.feature));
    }
    for (Vec2& p : out) p = Vec2(roundToMillimetre(p.x()), roundToMillimetre(p.y()));
    return out;
  }

  // A size attribute (m) of a tree; nullopt when the feature leaves it empty.
  std::optional<double> size(const Item& item, const std::string& key, const std::string& option,
                             bool required_field) const {
    const SourceLayer& layer = *item.layer;
    const auto name = fieldName(layer, key);
    if (!name && required_field && !item.feature->tags.count(key)) {
      std::string fields;
      for (const std::string& f : layer.fields) fields += (fields.empty() ? "" : ", ") + f;
      throw spec::ScenarioError(layer.file, option,
                                "layer '" + layer.name + "' has no field '" + key +
                                    "' (its fields: " + (fields.empty() ? "none" : fields) + ")");
    }
    const auto text = tag(*item.feature, key, isShapefile(layer));
    if (!text || text->empty()) return std::nullopt;
    const auto metres = parseMetres(*text);
    if (!metres || !(*metres > 0.0) || *metres > kMaxTreeSize) {
      throw spec::ScenarioError(layer.file, where(layer, *item.feature) + ", field '" + key + "'",
                                "expected a positive length in metres (at most 1000), got '" +
                                    *text + "'");
    }
    return *metres;
  }

  Json treeEntry(const Item& item, std::map<std::string, int>& counts) const {
    std::optional<double> radius;
    if (options_.radius_field) {
      radius = size(item, *options_.radius_field, "--radius-field", true);
    } else if (options_.diameter_field) {
      if (const auto d = size(item, *options_.diameter_field, "--diameter-field", true)) radius = 0.5 * *d;
    } else if (const auto d = size(item, "diameter_crown", "diameter_crown", false)) {
      radius = 0.5 * *d;  // OpenStreetMap: the crown's diameter in metres
    }
    if (!radius) {
      radius = options_.default_radius;
      ++counts["trees_default_radius"];
    }
    const Vec2 c = local(item, 0).front();
    Json entry = {{"type", "disc"}, {"centre", point(c)}, {"radius", *radius}};
    // OpenStreetMap's circumference: the trunk's girth (m), so its radius is c / (2π).
    if (const auto girth = tag(*item.feature, "circumference", isShapefile(*item.layer))) {
      if (const auto g = parseMetres(*girth); g && *g > 0.0)
        entry["trunk_radius"] = std::min(*radius, roundToMillimetre(*g / (2.0 * std::numbers::pi)));
    }
    return entry;
  }

  // A homogeneous Poisson process of density λ on the wood (its outline less its holes): a
  // Poisson count with mean λ × the box's area, uniform in the box, kept inside.
  std::vector<Vec2> woodFill(const Item& item, std::uint64_t index) const {
    std::vector<std::vector<Vec2>> rings;
    for (std::size_t part = 0; part < item.lonlat.size(); ++part) rings.push_back(local(item, part));
    Aabb box{rings.front().front(), rings.front().front()};
    for (const Vec2& p : rings.front()) {
      box.lo = box.lo.cwiseMin(p);
      box.hi = box.hi.cwiseMax(p);
    }
    const double expected = options_.wood_density * box.width() * box.height();
    if (!(expected <= kMaxWoodTrees)) {
      throw spec::ScenarioError(item.layer->file, "--wood-density",
                                where(*item.layer, *item.feature) + ": about " +
                                    std::to_string(static_cast<long long>(expected)) +
                                    " trees would be drawn in this wood's box; expected at most "
                                    "2e6 (a lower density or a --bbox)");
    }
    RandomStream rng(options_.seed, "wood", index);
    const int n = rng.poisson(expected);
    std::vector<Vec2> out;
    for (int k = 0; k < n; ++k) {
      const double x = rng.uniform(box.lo.x(), box.hi.x());
      const double y = rng.uniform(box.lo.y(), box.hi.y());
      const Vec2 p(roundToMillimetre(x), roundToMillimetre(y));
      bool inside = insideRing(rings.front(), p);
      for (std::size_t h = 1; h < rings.size() && inside; ++h) inside = !insideRing(rings[h], p);
      // Trees do not grow on footpaths: none whose trunk comes within kPathHalfWidth of one.
      if (inside && distanceToFootpaths(p) >= kPathHalfWidth + world::defaultTrunkRadius(options_.default_radius))
        out.push_back(p);
    }
    return out;
  }

  std::string attribution() const {
    if (options_.attribution) return *options_.attribution;
    for (const SourceLayer& layer : layers_) {
      if (layer.driver == "OSM" || fieldName(layer, "other_tags") || fieldName(layer, "osm_id") ||
          fieldName(layer, "@id"))
        return "© OpenStreetMap contributors, ODbL 1.0 (https://www.openstreetmap.org/copyright)";
    }
    return "";
  }

  // The least distance from p to an imported footpath (m); infinity without footpaths.
  double distanceToFootpaths(const Vec2& p) const {
    double best = std::numeric_limits<double>::infinity();
    for (const std::vector<Vec2>& line : footpath_lines_) {
      for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        const Vec2 e = line[i + 1] - line[i];
        const double s = std::clamp((p - line[i]).dot(e) / e.squaredNorm(), 0.0, 1.0);
        best = std::min(best, (line[i] + s * e - p).norm());
      }
    }
    return best;
  }

  const ImportOptions& options_;
  std::vector<SourceLayer> layers_;
  std::vector<std::vector<Vec2>> footpath_lines_;  // local frame, for the wood fills
  std::vector<Item> items_;
  bool metric_ = false;
  Vec2 offset_ = Vec2::Zero();
  std::optional<Projector> to_local_;
  std::string crs_name_, frame_text_;
  Json origin_json_;
};

}  // namespace

ImportResult importLayout(const ImportOptions& options) {
  return Builder(options).run();
}

std::string layoutText(const nlohmann::json& layout) {
  std::string text = "{\n";
  text += "  \"description\": " + layout.at("description").dump() + ",\n";
  text += "  \"source\": " + layout.at("source").dump() + ",\n";
  for (const char* key : {"occluders", "footpaths"}) {
    const Json& list = layout.at(key);
    text += std::string("  \"") + key + "\": [";
    for (std::size_t i = 0; i < list.size(); ++i) text += (i ? ",\n    " : "\n    ") + list[i].dump();
    text += list.empty() ? "]" : "\n  ]";
    text += std::string(key) == "occluders" ? ",\n" : "\n";
  }
  return text + "}\n";
}

}  // namespace canopy::gis
