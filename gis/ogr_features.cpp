#include "gis/ogr_features.h"

#include <cpl_error.h>
#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <mutex>

#include "spec/error.h"

namespace canopy::gis {
namespace {

void registerOnce() {
  static std::once_flag once;
  std::call_once(once, [] {
    GDALAllRegister();
    CPLSetErrorHandler(CPLQuietErrorHandler);  // errors are read back and reported by us
  });
}

std::vector<Vec2> points(const OGRSimpleCurve& curve) {
  std::vector<Vec2> out;
  for (int i = 0; i < curve.getNumPoints(); ++i) out.emplace_back(curve.getX(i), curve.getY(i));
  return out;
}

std::vector<Vec2> ring(const OGRLinearRing& r) {
  std::vector<Vec2> out = points(r);
  if (out.size() > 1 && out.front() == out.back()) out.pop_back();
  return out;
}

// Appends one Feature per simple member of `geometry` (which OGR may nest in collections).
void addGeometry(const OGRGeometry& geometry, const Feature& base, std::vector<Feature>& out) {
  const OGRwkbGeometryType type = wkbFlatten(geometry.getGeometryType());
  Feature f = base;
  switch (type) {
    case wkbPoint: {
      const auto& p = *geometry.toPoint();
      if (p.IsEmpty()) return;
      f.kind = GeometryKind::point;
      f.parts = {{Vec2(p.getX(), p.getY())}};
      out.push_back(std::move(f));
      return;
    }
    case wkbLineString: {
      f.kind = GeometryKind::line;
      f.parts = {points(*geometry.toLineString())};
      out.push_back(std::move(f));
      return;
    }
    case wkbPolygon: {
      const OGRPolygon& polygon = *geometry.toPolygon();
      if (polygon.IsEmpty()) return;
      f.kind = GeometryKind::polygon;
      f.parts.push_back(ring(*polygon.getExteriorRing()));
      for (int i = 0; i < polygon.getNumInteriorRings(); ++i)
        f.parts.push_back(ring(*polygon.getInteriorRing(i)));
      out.push_back(std::move(f));
      return;
    }
    case wkbMultiPoint:
    case wkbMultiLineString:
    case wkbMultiPolygon:
    case wkbGeometryCollection: {
      const OGRGeometryCollection& all = *geometry.toGeometryCollection();
      for (int i = 0; i < all.getNumGeometries(); ++i) addGeometry(*all.getGeometryRef(i), base, out);
      return;
    }
    default:
      return;  // curves, surfaces, …: not read
  }
}

// OpenStreetMap's other_tags as GDAL's OSM driver writes it: "k1"=>"v1","k2"=>"v2" (backslash
// escapes inside the quotes).
void splitOtherTags(const std::string& text, std::map<std::string, std::string>& tags) {
  std::size_t i = 0;
  auto quoted = [&](std::string& out) {
    while (i < text.size() && text[i] != '"') ++i;
    if (i >= text.size()) return false;
    ++i;
    out.clear();
    while (i < text.size() && text[i] != '"') {
      if (text[i] == '\\' && i + 1 < text.size()) ++i;
      out += text[i++];
    }
    if (i >= text.size()) return false;
    ++i;
    return true;
  };
  std::string key, value;
  while (quoted(key) && quoted(value)) tags.emplace(key, value);
}

}  // namespace

std::vector<SourceLayer> readLayers(const std::string& file,
                                    const std::optional<std::string>& layer_name) {
  registerOnce();
  CPLErrorReset();
  GDALDatasetUniquePtr dataset(
      GDALDataset::Open(file.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
  if (!dataset) {
    const std::string why = CPLGetLastErrorMsg();
    throw spec::ScenarioError(file, "",
                              "cannot be read as GIS vector data (GDAL/OGR: " +
                                  (why.empty() ? std::string("not a format it recognises") : why) +
                                  ")");
  }
  const std::string driver = dataset->GetDriver() ? dataset->GetDriver()->GetDescription() : "";
  std::vector<OGRLayer*> chosen;
  if (layer_name) {
    OGRLayer* found = dataset->GetLayerByName(layer_name->c_str());
    if (!found) {
      std::string names;
      for (OGRLayer* l : dataset->GetLayers()) names += (names.empty() ? "" : ", ") + std::string(l->GetName());
      throw spec::ScenarioError(file, "--layer",
                                "no layer named '" + *layer_name + "' (its layers: " + names + ")");
    }
    chosen.push_back(found);
  } else {
    for (OGRLayer* l : dataset->GetLayers()) chosen.push_back(l);
  }
  std::vector<SourceLayer> out;
  for (OGRLayer* layer : chosen) {
    SourceLayer source;
    source.file = file;
    source.name = layer->GetName();
    source.driver = driver;
    OGRFeatureDefn* defn = layer->GetLayerDefn();
    for (int i = 0; i < defn->GetFieldCount(); ++i)
      source.fields.emplace_back(defn->GetFieldDefn(i)->GetNameRef());
    const OGRSpatialReference* srs = layer->GetSpatialRef();
    if (srs) {
      char* wkt = nullptr;
      const char* options[] = {"FORMAT=WKT2_2019", nullptr};
      if (srs->exportToWkt(&wkt, options) == OGRERR_NONE && wkt) source.crs_wkt = wkt;
      CPLFree(wkt);
    }
    layer->ResetReading();
    for (const auto& feature : *layer) {
      Feature base;
      base.fid = static_cast<long long>(feature->GetFID());
      for (int i = 0; i < feature->GetFieldCount(); ++i) {
        if (!feature->IsFieldSetAndNotNull(i)) continue;
        const std::string name = defn->GetFieldDefn(i)->GetNameRef();
        const std::string value = feature->GetFieldAsString(i);
        if (name == "other_tags") {
          splitOtherTags(value, base.tags);
        } else {
          base.tags[name] = value;
        }
      }
      if (const OGRGeometry* geometry = feature->GetGeometryRef())
        addGeometry(*geometry, base, source.features);
    }
    if (source.crs_wkt.empty() && !source.features.empty()) {
      throw spec::ScenarioError(file, "layer '" + source.name + "'",
                                "has no coordinate reference system (a Shapefile needs its .prj "
                                "file beside it)");
    }
    out.push_back(std::move(source));
  }
  return out;
}

std::optional<std::string> tag(const Feature& feature, const std::string& key, bool shapefile) {
  if (const auto it = feature.tags.find(key); it != feature.tags.end()) return it->second;
  if (shapefile && key.size() > 10) {
    if (const auto it = feature.tags.find(key.substr(0, 10)); it != feature.tags.end())
      return it->second;
  }
  return std::nullopt;
}

std::optional<std::string> fieldName(const SourceLayer& layer, const std::string& key) {
  if (std::find(layer.fields.begin(), layer.fields.end(), key) != layer.fields.end()) return key;
  if (layer.driver == "ESRI Shapefile" && key.size() > 10 &&
      std::find(layer.fields.begin(), layer.fields.end(), key.substr(0, 10)) != layer.fields.end())
    return key.substr(0, 10);
  return std::nullopt;
}

}  // namespace canopy::gis
