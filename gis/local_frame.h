#pragma once
// Coordinates of GIS data in canopy's plane (issue 52), through PROJ: from any source CRS to
// WGS84 longitude/latitude, and from there to the local metric frame — a transverse Mercator
// centred on an origin (scale 1 on its central meridian, so distances near the origin are true
// to ~x²/(2R²): 1.2 × 10⁻⁸ at 1 km, 1.2 × 10⁻⁶ at 10 km). Data already in a projected CRS in
// metres keeps its coordinates, shifted by an origin offset.
#include <memory>
#include <string>

#include "core/types.h"

namespace canopy::gis {

/// One PROJ transformation, its axes in the "visualisation" order (x = easting or longitude,
/// y = northing or latitude), as GDAL hands vector coordinates over.
class Projector {
 public:
  /// source, target: anything proj_create takes (WKT, "EPSG:4326", a PROJ string). Throws
  /// std::runtime_error with PROJ's reason when no transformation can be made.
  Projector(const std::string& source, const std::string& target);
  ~Projector();
  Projector(Projector&&) noexcept;
  Projector& operator=(Projector&&) noexcept;
  Projector(const Projector&) = delete;
  Projector& operator=(const Projector&) = delete;

  /// Throws std::runtime_error when the point cannot be transformed (outside the CRS's domain).
  Vec2 operator()(const Vec2& xy) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The PROJ definition of the default local frame: a transverse Mercator on the WGS84 ellipsoid
/// with its origin (x = y = 0) at (lat, lon) degrees.
std::string localTransverseMercator(double lat, double lon);

/// True when the CRS (WKT) is projected with metre units (then its coordinates are kept).
bool isMetricProjected(const std::string& wkt);

/// A short name for a CRS (WKT): "EPSG:4326 (WGS 84)", or its name alone.
std::string crsName(const std::string& wkt);

}  // namespace canopy::gis
