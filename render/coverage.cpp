#include "render/coverage.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/scene.h"
#include "render/scene_builder.h"

namespace canopy::render {
namespace {

// Each footprint adds 1 to the red channel of the pixels it covers (additive blending).
constexpr Rgba kOneLayer{1, 0, 0, 0};

}  // namespace

CoverageCounter::CoverageCounter(const Aabb& aoi, ImageSize size)
    : viewport_(Viewport::fit(aoi, size)), canvas_(size) {
  // Pixel (i, j) is in the AOI when its centre is: lo ≤ top_left + (i + ½)·a ≤ hi in x, and
  // likewise (downwards) in y; a small slack absorbs the rounding of an exact fit.
  const double a = viewport_.pixel_size, eps = 1e-9;
  const Vec2& tl = viewport_.top_left;
  x0_ = std::max(0, static_cast<int>(std::ceil((aoi.lo.x() - tl.x()) / a - 0.5 - eps)));
  x1_ =
      std::min(size.width - 1, static_cast<int>(std::floor((aoi.hi.x() - tl.x()) / a - 0.5 + eps)));
  y0_ = std::max(0, static_cast<int>(std::ceil((tl.y() - aoi.hi.y()) / a - 0.5 - eps)));
  y1_ = std::min(size.height - 1,
                 static_cast<int>(std::floor((tl.y() - aoi.lo.y()) / a - 0.5 + eps)));
}

CoverageCounts CoverageCounter::count(std::span<const sensing::Footprint> footprints,
                                      std::span<const Vec2> targets) {
  Scene mask;
  mask.viewport = viewport_;
  mask.background = Rgba{0, 0, 0, 0};
  for (const sensing::Footprint& f : footprints) {
    if (f.shape == sensing::FootprintShape::disc) {
      add(mask.world, Disc{f.centre, f.radius, kOneLayer, kOneLayer, 0.0});
    } else {
      add(mask.world, Polygon{footprintCorners(f), kOneLayer});
    }
  }
  const std::vector<std::uint8_t>& layers = canvas_.accumulate(mask);

  CoverageCounts counts;
  const int width = viewport_.size.width;
  for (int y = y0_; y <= y1_; ++y) {
    const std::uint8_t* row = layers.data() + static_cast<std::size_t>(y) * width;
    for (int x = x0_; x <= x1_; ++x) {
      counts.covered_px += row[x] >= 1;
      counts.multi_px += row[x] >= 2;
    }
  }
  counts.aoi_px = std::max(0L, long(x1_ - x0_ + 1) * long(y1_ - y0_ + 1));
  counts.target_covered.reserve(targets.size());
  for (const Vec2& p : targets) {
    const Vec2 px = viewport_.toPixel(p);
    const double fx = std::floor(px.x()), fy = std::floor(px.y());
    const bool in =
        std::isfinite(fx) && std::isfinite(fy) && fx >= x0_ && fx <= x1_ && fy >= y0_ && fy <= y1_;
    counts.target_covered.push_back(
        in && layers[static_cast<std::size_t>(fy) * width + static_cast<std::size_t>(fx)] >= 1 ? 1
                                                                                               : 0);
  }
  return counts;
}

CoverageCounts CoverageCounter::count(const world::WorldSnapshot& truth,
                                      std::span<const sensing::SensorDef> sensors) {
  footprints_.clear();
  const std::size_t n = std::min(sensors.size(), truth.uavs.size());
  for (std::size_t i = 0; i < n; ++i) {
    footprints_.push_back(sensing::footprintOf(truth, static_cast<int>(i), sensors[i]));
  }
  targets_.clear();
  for (const world::TargetState& target : truth.targets) targets_.push_back(target.position);
  return count(footprints_, targets_);
}

std::string coverageCsvHeader(std::span<const std::string> target_names) {
  std::string header = "step,t,covered_px,multi_px,aoi_px,covered_fraction";
  for (const std::string& name : target_names) header += ",covered_" + name;
  return header;
}

std::string coverageCsvRow(int step, double time, const CoverageCounts& counts) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "%d,%.6g,%ld,%ld,%ld,%.6f", step, time, counts.covered_px,
                counts.multi_px, counts.aoi_px, counts.coveredFraction());
  std::string row = buffer;
  for (const std::uint8_t covered : counts.target_covered) row += covered ? ",1" : ",0";
  return row;
}

}  // namespace canopy::render
