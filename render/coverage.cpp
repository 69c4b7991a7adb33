#include "render/coverage.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/outlines.h"
#include "render/scene.h"

namespace canopy::render {
namespace {

// Each footprint adds 1 to the red channel of the pixels it covers (additive blending).
constexpr Rgba kOneLayer{1, 0, 0, 0};

bool boxesMeet(const Aabb& a, const Aabb& b) {
  return a.lo.x() <= b.hi.x() && b.lo.x() <= a.hi.x() && a.lo.y() <= b.hi.y() &&
         b.lo.y() <= a.hi.y();
}

}  // namespace

CoverageCounter::CoverageCounter(const Aabb& aoi, ImageSize size, std::vector<world::TreeDef> trees)
    : viewport_(Viewport::fit(aoi, size)), canvas_(size), trees_(std::move(trees)) {
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

void CoverageCounter::markVisible(std::span<const sensing::Footprint> footprints,
                                  sensing::OcclusionModel model,
                                  std::span<const double> camera_heights,
                                  const std::vector<std::uint8_t>& layers) {
  const int width = viewport_.size.width;
  visible_.assign(layers.size(), 0);
  for (std::size_t i = 0; i < footprints.size(); ++i) {
    const sensing::Footprint& f = footprints[i];
    // A sector is a ground robot's camera, which sees by line of sight whatever the team's
    // model (sensing::occlusionModel).
    const bool line_of_sight = model == sensing::OcclusionModel::line_of_sight ||
                               f.shape == sensing::FootprintShape::sector;
    // Under `volumes` every camera, a robot's too, sees by the 3-D line of sight from its height.
    const bool volumes = model == sensing::OcclusionModel::volumes;
    const double height = i < camera_heights.size() ? camera_heights[i] : sensing::kDefaultAltitude;
    // A crown outside the footprint's box can neither hold a point of the footprint nor cross a
    // segment from the footprint's centre (the UAV's ground point) to such a point.
    const Aabb box = f.bounds();
    near_.clear();
    for (std::size_t t = 0; t < trees_.size(); ++t) {
      if (boxesMeet(world::bounds(trees_[t]), box)) near_.push_back(static_cast<int>(t));
    }
    const Vec2 lo = viewport_.toPixel(Vec2(box.lo.x(), box.hi.y()));
    const Vec2 hi = viewport_.toPixel(Vec2(box.hi.x(), box.lo.y()));
    const int px0 = std::max(x0_, static_cast<int>(std::floor(lo.x())));
    const int px1 = std::min(x1_, static_cast<int>(std::ceil(hi.x())));
    const int py0 = std::max(y0_, static_cast<int>(std::floor(lo.y())));
    const int py1 = std::min(y1_, static_cast<int>(std::ceil(hi.y())));
    for (int y = py0; y <= py1; ++y) {
      for (int x = px0; x <= px1; ++x) {
        const std::size_t at = static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x);
        if (visible_[at] || layers[at] == 0) continue;
        const Vec2 p = viewport_.toWorld(Vec2(x + 0.5, y + 0.5));
        if (!f.contains(p)) continue;
        bool hidden = false;
        for (const int t : near_) {
          if (volumes) {  // (centre, h) → (p, head): world::blocksSight, as sensing tests it
            hidden = world::blocksSight(trees_[t], f.centre, height, p, sensing::kTargetHeight);
          } else {
            hidden = line_of_sight ? world::segmentEntry(trees_[t], f.centre, p) >= 0.0
                                   : world::strictlyInside(trees_[t], p);
          }
          if (hidden) break;
        }
        visible_[at] = hidden ? 0 : 1;
      }
    }
  }
}

CoverageCounts CoverageCounter::count(std::span<const sensing::Footprint> footprints,
                                      std::span<const Vec2> targets, sensing::OcclusionModel model,
                                      std::span<const double> camera_heights) {
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
  markVisible(footprints, model, camera_heights, layers);

  CoverageCounts counts;
  const int width = viewport_.size.width;
  for (int y = y0_; y <= y1_; ++y) {
    const std::uint8_t* row = layers.data() + static_cast<std::size_t>(y) * width;
    for (int x = x0_; x <= x1_; ++x) {
      counts.covered_px += row[x] >= 1;
      counts.multi_px += row[x] >= 2;
      counts.visible_px += visible_[static_cast<std::size_t>(y) * width + x];
    }
  }
  counts.aoi_px = std::max(0L, long(x1_ - x0_ + 1) * long(y1_ - y0_ + 1));
  counts.target_covered.reserve(targets.size());
  counts.target_visible.reserve(targets.size());
  for (const Vec2& p : targets) {
    const Vec2 px = viewport_.toPixel(p);
    const double fx = std::floor(px.x()), fy = std::floor(px.y());
    const bool in =
        std::isfinite(fx) && std::isfinite(fy) && fx >= x0_ && fx <= x1_ && fy >= y0_ && fy <= y1_;
    const std::size_t at =
        in ? static_cast<std::size_t>(fy) * width + static_cast<std::size_t>(fx) : 0;
    counts.target_covered.push_back(in && layers[at] >= 1 ? 1 : 0);
    counts.target_visible.push_back(in && visible_[at] ? 1 : 0);
  }
  return counts;
}

CoverageCounts CoverageCounter::count(const world::WorldSnapshot& truth,
                                      std::span<const sensing::SensorDef> sensors,
                                      sensing::OcclusionModel model) {
  footprints_.clear();
  camera_heights_.clear();
  const std::size_t n = std::min(sensors.size(), truth.uavs.size());
  for (std::size_t i = 0; i < n; ++i) {
    footprints_.push_back(sensing::footprintOf(truth, static_cast<int>(i), sensors[i]));
    camera_heights_.push_back(sensing::cameraHeight(sensors[i], truth.uavs[i].z));
  }
  targets_.clear();
  for (const world::TargetState& target : truth.targets) targets_.push_back(target.position);
  return count(footprints_, targets_, model, camera_heights_);
}

std::string coverageCsvHeader(std::span<const std::string> target_names) {
  std::string header =
      "step,t,covered_px,visible_px,multi_px,aoi_px,covered_fraction,visible_fraction";
  for (const std::string& name : target_names) header += ",covered_" + name;
  for (const std::string& name : target_names) header += ",visible_" + name;
  return header;
}

std::string coverageCsvRow(int step, double time, const CoverageCounts& counts) {
  char buffer[200];
  std::snprintf(buffer, sizeof buffer, "%d,%.6g,%ld,%ld,%ld,%ld,%.6f,%.6f", step, time,
                counts.covered_px, counts.visible_px, counts.multi_px, counts.aoi_px,
                counts.coveredFraction(), counts.visibleFraction());
  std::string row = buffer;
  for (const std::uint8_t covered : counts.target_covered) row += covered ? ",1" : ",0";
  for (const std::uint8_t visible : counts.target_visible) row += visible ? ",1" : ",0";
  return row;
}

}  // namespace canopy::render
