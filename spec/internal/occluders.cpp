// Reading occluder layouts: explicit discs and polygons, Poisson / grid / cluster generators,
// and includes of layout files.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>

#include "core/progress.h"
#include "spec/budget.h"
#include "spec/forest.h"
#include "spec/internal/referenced_file.h"
#include "spec/internal/sections.h"
#include "spec/loader.h"
#include "world/convex_pieces.h"

namespace canopy::spec::internal {
namespace fs = std::filesystem;
namespace {

constexpr int kMaxIncludeDepth = 16;

RadiusRange readRadius(const Field& field) {
  if (field.json().is_array()) {
    const std::vector<Field> lohi = field.elements(2, 2);
    const RadiusRange range{lohi[0].number(Bound::positive), lohi[1].number(Bound::positive)};
    if (range.hi < range.lo) field.fail("expected [min, max] with max >= min");
    for (std::size_t i = 0; i < 2; ++i) {
      const std::string problem =
          world::box2dProblem(world::TreeDef::disc(Vec2::Zero(), i ? range.hi : range.lo));
      if (!problem.empty()) lohi[i].fail(problem);
    }
    return range;
  }
  const double r = field.number(Bound::positive);
  if (const std::string problem = world::box2dProblem(world::TreeDef::disc(Vec2::Zero(), r));
      !problem.empty())
    field.fail(problem);
  return {r, r};
}

Aabb readRegion(ObjectReader& reader, const Aabb& aoi) {
  const auto field = reader.optional("region");
  if (!field) {
    (*reader.field().out())["region"] = Json{aoi.lo.x(), aoi.lo.y(), aoi.hi.x(), aoi.hi.y()};
    return aoi;
  }
  const std::vector<Field> v = field->elements(4, 4);
  const Aabb region{Vec2(v[0].number(), v[1].number()), Vec2(v[2].number(), v[3].number())};
  if (!(region.hi.x() > region.lo.x() && region.hi.y() > region.lo.y())) {
    field->fail("expected [x_min, y_min, x_max, y_max] with x_max > x_min and y_max > y_min");
  }
  if (!aoi.contains(region.lo) || !aoi.contains(region.hi)) {
    field->fail("expected a region inside the AOI");
  }
  return region;
}

std::optional<double> readMinGap(ObjectReader& reader) {
  if (auto gap = reader.optional("min_gap")) return gap->number(Bound::non_negative);
  return std::nullopt;
}

double treeLimit(const Field& field) {
  return workLimits(field.context() ? field.context()->budget_scale : 1.0).trees;
}

// The expected number of points a generator draws (before thinning or clipping), against the
// limit; and the limit handed to the generator, which bounds each draw as well.
std::size_t requireFeasibleCount(const Field& field, double expected_points, const char* what) {
  const double limit = treeLimit(field);
  if (!(expected_points <= limit)) field.fail(budgetMessage(expected_points, limit, what));
  return static_cast<std::size_t>(limit);
}

template <typename Generate>
auto drawBounded(const Field& field, Generate generate) {
  try {
    return generate();
  } catch (const ForestTooLarge& e) {
    field.fail("expected a layout of at most " + std::to_string(e.max_points) + " " +
               e.what_counted +
               ", this seed's draw needs more (the expected count is within the limit, this "
               "draw is not); change the seed or raise the limit with --budget K");
  }
}

void requireCentresInside(const Field& field, const std::vector<world::TreeDef>& trees,
                          const Aabb& aoi) {
  for (std::size_t k = 0; k < trees.size(); ++k) {
    if (!aoi.contains(trees[k].centre)) {
      std::ostringstream text;
      text << "expected every tree inside the AOI; tree " << k << " of this layout is at ("
           << trees[k].centre.x() << ", " << trees[k].centre.y() << ")";
      field.fail(text.str());
    }
  }
}

// A polygon: a convex one of at most b2_maxPolygonVertices vertices is one tree (a crown or a
// wall); any other simple polygon is a wall cut into convex pieces (world/convex_pieces.h), each
// a convex polygon wall of its own.
std::vector<world::TreeDef> readPolygon(ObjectReader& reader) {
  const Field list = reader.required("vertices");
  std::vector<Vec2> vertices;
  for (const Field& v : list.elements(3, world::kMaxWallVertices)) vertices.push_back(v.vec2());
  if (vertices.size() <= world::kMaxPolygonVertices &&
      world::isStrictlyConvex(vertices)) {
    // Box2D's own limits, checked here: a polygon it cannot build would abort the run.
    if (const std::string problem = world::box2dPolygonProblem(vertices); !problem.empty())
      list.fail(problem);
    return {world::TreeDef::polygon(std::move(vertices))};
  }
  if (const std::string problem = world::simplePolygonProblem(vertices); !problem.empty())
    list.fail(problem);
  if (reader.has("trunk_radius")) {
    reader.required("trunk_radius")
        .fail("expected no trunk on a concave polygon or one of more than " +
              std::to_string(world::kMaxPolygonVertices) +
              " vertices: it is a wall, cut into convex pieces");
  }
  std::vector<world::TreeDef> pieces;
  try {
    for (std::vector<Vec2>& piece : world::convexPieces(vertices))
      pieces.push_back(world::TreeDef::polygon(std::move(piece)));
  } catch (const std::invalid_argument& e) {
    list.fail(e.what());
  }
  return pieces;
}

// trunk_radius: every tree of the entry gets it, no wider than its crown. Absent, a disc keeps
// world::defaultTrunkRadius of its radius and a polygon stays a wall (world/tree.h).
void readTrunk(ObjectReader& reader, std::vector<world::TreeDef>& out, std::size_t first) {
  const auto field = reader.optional("trunk_radius");
  if (!field) return;
  const double trunk = field->number(Bound::positive);
  for (std::size_t k = first; k < out.size(); ++k) {
    if (trunk > out[k].radius) {
      std::ostringstream text;
      text << "expected a trunk no wider than its crown; tree " << k - first
           << " of this entry has a crown of radius " << out[k].radius << " m";
      field->fail(text.str());
    }
    out[k].trunk_radius = trunk;
  }
}

// Height (issue 53): crown_base and crown_top (m) give every crown of the entry its volume; a wall
// (a polygon without a trunk) stands from the ground to its `height`. Absent: from the ground to
// above any UAV, and nothing is written to the effective configuration.
void readHeights(ObjectReader& reader, std::vector<world::TreeDef>& out, std::size_t first) {
  const bool wall = first < out.size() && world::isWall(out[first]);
  if (wall) {
    if (auto height = reader.optional("height")) {
      const double top = height->number(Bound::positive);
      for (std::size_t k = first; k < out.size(); ++k) out[k].top = top;
    }
    return;
  }
  double base = 0.0, top = std::numeric_limits<double>::infinity();
  const auto base_field = reader.optional("crown_base");
  if (base_field) base = base_field->number(Bound::non_negative);
  if (auto top_field = reader.optional("crown_top")) {
    top = top_field->number(Bound::positive);
    if (!(top > base)) top_field->fail("expected crown_top above crown_base");
  }
  for (std::size_t k = first; k < out.size(); ++k) {
    out[k].base = base;
    out[k].top = top;
  }
}

void readGenerator(const std::string& type, ObjectReader& reader, const Aabb& aoi,
                   std::vector<world::TreeDef>& out) {
  const Field& field = reader.field();
  const std::size_t first = out.size();
  if (type == "disc") {
    const Field centre_field = reader.required("centre");
    const Vec2 centre = centre_field.vec2();
    const Field radius_field = reader.required("radius");
    const double radius = radius_field.number(Bound::positive);
    out.push_back(world::TreeDef::disc(centre, radius));
    if (const std::string problem = world::box2dProblem(out.back()); !problem.empty())
      radius_field.fail(problem);
    requireCentresInside(centre_field, {out.back()}, aoi);
  } else if (type == "polygon") {
    const std::vector<world::TreeDef> pieces = readPolygon(reader);
    requireCentresInside(field, pieces, aoi);
    out.insert(out.end(), pieces.begin(), pieces.end());
  } else if (type == "poisson") {
    PoissonForestDef def;
    def.region = readRegion(reader, aoi);
    def.lambda = reader.required("lambda").number(Bound::non_negative);
    def.radius = readRadius(reader.required("radius"));
    def.seed = static_cast<std::uint64_t>(reader.integer("seed", 1, 0, 2147483647));
    def.min_gap = readMinGap(reader);
    def.max_points = requireFeasibleCount(field, def.lambda * poissonDrawRegion(def).area(),
                                          "trees drawn (λ × the region dilated by 2 r_max + "
                                          "min_gap)");
    const auto trees = drawBounded(field, [&] { return poissonForest(def); });
    out.insert(out.end(), trees.begin(), trees.end());
  } else if (type == "grid") {
    GridForestDef def;
    def.origin = reader.required("origin").vec2();
    def.spacing = reader.required("spacing").vec2(Bound::non_negative);
    def.rows = reader.integer("rows", 1, 1, 100000);
    def.cols = reader.integer("cols", 1, 1, 100000);
    def.angle = reader.number("angle", 0.0);
    def.radius = readRadius(reader.required("radius"));
    def.jitter = reader.number("jitter", 0.0, Bound::non_negative);
    def.seed = static_cast<std::uint64_t>(reader.integer("seed", 1, 0, 2147483647));
    requireFeasibleCount(field, static_cast<double>(def.rows) * def.cols, "trees (rows × cols)");
    const auto trees = gridForest(def);
    requireCentresInside(field, trees, aoi);
    out.insert(out.end(), trees.begin(), trees.end());
  } else if (type == "cluster") {
    ClusterForestDef def;
    def.region = readRegion(reader, aoi);
    def.parent_lambda = reader.required("parent_lambda").number(Bound::non_negative);
    def.mean_trees = reader.required("mean_trees").number(Bound::non_negative);
    def.spread = reader.required("spread").number(Bound::positive);
    def.radius = readRadius(reader.required("radius"));
    def.seed = static_cast<std::uint64_t>(reader.integer("seed", 1, 0, 2147483647));
    def.min_gap = readMinGap(reader);
    const double parents = def.parent_lambda * clusterParentRegion(def).area();
    requireFeasibleCount(reader.required("parent_lambda"), parents,
                         "cluster parents (parent_lambda × the region dilated by 5 spread)");
    requireFeasibleCount(reader.required("mean_trees"), def.mean_trees, "trees per cluster");
    def.max_points = requireFeasibleCount(field, parents * (1.0 + def.mean_trees),
                                          "points drawn (parents × (1 + mean_trees))");
    const auto trees = drawBounded(field, [&] { return clusterForest(def); });
    out.insert(out.end(), trees.begin(), trees.end());
  }
  readTrunk(reader, out, first);
  readHeights(reader, out, first);
}

// What `canopy import` recorded of a layout's source (gis/import.cpp): one line.
std::string describeSource(const Field& source) {
  const Json& j = source.json();
  if (!j.is_object()) source.fail("expected an object (what canopy import recorded)");
  auto text = [&](const char* key) {
    return j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : std::string();
  };
  std::ostringstream line;
  line << "imported from " << (j.contains("files") ? j["files"].dump() : "?");
  if (!text("crs").empty()) line << " (" << text("crs") << ")";
  if (j.contains("imported") && j["imported"].is_object()) {
    const Json& n = j["imported"];
    const char* sep = ": ";
    for (const auto& [key, value] : n.items()) {
      if (!value.is_number()) continue;
      line << sep << value.dump() << " " << key;
      sep = ", ";
    }
  }
  if (!text("attribution").empty()) line << "; " << text("attribution");
  return line.str();
}

}  // namespace

std::vector<std::vector<Vec2>> readFootpathLines(const Field& list) {
  std::vector<std::vector<Vec2>> lines;
  for (const Field& line : list.elements(1)) {
    std::vector<Vec2> points;
    for (const Field& p : line.elements(2)) {
      points.push_back(p.vec2());
      if (points.back().cwiseAbs().maxCoeff() > world::kMaxTreeCoordinate)
        p.fail("expected coordinates within ±1e7 m");
    }
    lines.push_back(std::move(points));
  }
  return lines;
}

std::vector<std::vector<Vec2>> readLayoutFootpaths(const Field& name_field) {
  const ReferencedFile file = readReferencedFile(name_field, "layout file", libraryDir());
  try {
    const Json document = parseJson(file.text, file.shown);
    if (!document.is_object() || !document.contains("footpaths")) {
      throw ScenarioError(file.shown, "footpaths",
                          "expected a layout file with footpaths (as canopy import writes)");
    }
    return readFootpathLines(Field(document["footpaths"], file.shown, "footpaths", nullptr));
  } catch (const ScenarioError& e) {
    name_field.fail(std::string("in the layout file ") + e.what());
  }
}

ArrayLimit occluderListLimit(double tree_limit) {
  const auto most = static_cast<std::size_t>(std::floor(tree_limit));
  return {"occluders", most,
          "expected at most " + std::to_string(most) +
              " occluder entries (each is at least one tree of the tree budget), this file lists "
              "more (--budget K raises every work limit K-fold)"};
}

void readOccluders(const Field& list, const Aabb& aoi, std::vector<world::TreeDef>& trees,
                   Json& effective, std::vector<std::string>& include_stack,
                   std::vector<std::string>* sources) {
  const std::vector<Field> elements = list.elements();
  ProgressCounter progress("reading occluders", static_cast<double>(elements.size()));
  for (const Field& element : elements) {
    progress.add();
    Json element_out = Json::object();
    const Field item(element.json(), element.file(), element.path(), &element_out,
                     element.context());
    ObjectReader reader = item.object();
    if (reader.has("include")) {
      const Field name_field = reader.required("include");
      reader.finish();
      const ReferencedFile file = readReferencedFile(name_field, "layout file", libraryDir());
      const std::string canonical = file.path.string();
      if (std::find(include_stack.begin(), include_stack.end(), canonical) != include_stack.end()) {
        name_field.fail("include cycle: " + file.quoted + " is already being read");
      }
      if (static_cast<int>(include_stack.size()) > kMaxIncludeDepth) {
        name_field.fail("includes nested more than 16 deep");
      }
      // Errors inside the included file name it, behind the field that includes it.
      try {
        // Its list, like the scenario's, is refused as it is read when longer than the tree
        // budget (each entry is at least one tree).
        ArrayLimit as_list = occluderListLimit(treeLimit(name_field));
        ArrayLimit wrapped_list = as_list;
        as_list.key = "";
        const Json document = parseJson(file.text, file.shown, {as_list, wrapped_list});
        const bool wrapped = document.is_object();
        if (wrapped) {
          ObjectReader layout = Field(document, file.shown, "", nullptr).object();
          layout.optional("description");
          layout.required("occluders");
          if (auto lines = layout.optional("footpaths")) readFootpathLines(*lines);
          if (auto source = layout.optional("source")) {
            if (sources) sources->push_back(file.shown + ": " + describeSource(*source));
          }
          layout.finish();
        }
        const Json& inner = wrapped ? document.at("occluders") : document;
        include_stack.push_back(canonical);
        // The included file's fields are those of the including list: not logged twice.
        LoadContext quiet = name_field.context() ? *name_field.context() : LoadContext{};
        quiet.log = nullptr;
        readOccluders(Field(inner, file.path.string(), wrapped ? "occluders" : "", nullptr,
                            name_field.context() ? &quiet : nullptr),
                      aoi, trees, effective, include_stack, sources);
        include_stack.pop_back();
      } catch (const ScenarioError& e) {
        name_field.fail(std::string("in the layout file ") + e.what());
      }
      continue;
    }
    static const std::vector<std::string> kTypes{"disc", "polygon", "poisson", "grid", "cluster"};
    readGenerator(kTypes[reader.required("type").choice(kTypes)], reader, aoi, trees);
    reader.finish();
    effective.push_back(std::move(element_out));
  }
}

}  // namespace canopy::spec::internal
