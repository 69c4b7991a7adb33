#pragma once
// Rendered coverage: a mask pass counts the AOI's pixels under at least one footprint and under
// two or more, and tells whether each target's pixel is covered. A pixel belongs to a shape when
// its centre does (GL's rasterisation rule), so the counts approach the areas as pixels shrink.
// A covered pixel is also *visible* when some UAV whose footprint holds its centre sees that
// centre under the UAV's occlusion model (sensing/visibility.h): not inside a crown (`canopy`),
// nor behind one as seen from the UAV's ground point (`line_of_sight`), nor (`volumes`, issue 53)
// behind a crown volume on the 3-D segment from the camera to a walker's head standing there
// (world::blocksSight, as sensing tests it: a walker under a high crown is seen). The visible
// count is therefore the footprints minus the crowns and the shadows.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "render/canvas.h"
#include "render/viewport.h"
#include "sensing/footprint.h"
#include "sensing/sensor.h"
#include "sensing/visibility.h"
#include "world/snapshot.h"
#include "world/tree.h"

namespace canopy::render {

struct CoverageCounts {
  long covered_px = 0;                       // AOI pixels under ≥ 1 footprint
  long visible_px = 0;                       // covered AOI pixels some UAV sees (not occluded)
  long multi_px = 0;                         // AOI pixels under ≥ 2 footprints
  long aoi_px = 0;                           // pixels whose centre lies in the AOI
  std::vector<std::uint8_t> target_covered;  // per target: 1 when its pixel is an AOI pixel
                                             // under ≥ 1 footprint, else 0
  std::vector<std::uint8_t> target_visible;  // per target: 1 when its pixel is a visible pixel

  double coveredFraction() const { return aoi_px > 0 ? double(covered_px) / double(aoi_px) : 0.0; }
  double visibleFraction() const { return aoi_px > 0 ? double(visible_px) / double(aoi_px) : 0.0; }
};

class CoverageCounter {
 public:
  /// The mask is `size` px with the AOI fitted, aspect preserved, without margin. `trees` are the
  /// occluders of the visible count (none: every covered pixel is visible). Creates no GL context
  /// until the first count().
  CoverageCounter(const Aabb& aoi, ImageSize size, std::vector<world::TreeDef> trees = {});

  const Viewport& viewport() const { return viewport_; }
  /// Area of one pixel (m²).
  double pixelArea() const { return viewport_.pixel_size * viewport_.pixel_size; }

  /// Each footprint's centre is its UAV's ground point; `model` is the team's occlusion model.
  /// camera_heights: each footprint's camera above the ground (m, sensing::cameraHeight), the
  /// start of `volumes`' sight lines; empty: every camera at sensing::kDefaultAltitude.
  CoverageCounts count(std::span<const sensing::Footprint> footprints,
                       std::span<const Vec2> targets,
                       sensing::OcclusionModel model = sensing::OcclusionModel::canopy,
                       std::span<const double> camera_heights = {});
  /// The footprints of every UAV of the snapshot (sensors[i] for UAV i) and its targets.
  CoverageCounts count(const world::WorldSnapshot& truth,
                       std::span<const sensing::SensorDef> sensors,
                       sensing::OcclusionModel model = sensing::OcclusionModel::canopy);

 private:
  bool inAoi(int x, int y) const { return x >= x0_ && x <= x1_ && y >= y0_ && y <= y1_; }
  /// Marks visible_ for the covered AOI pixels that some footprint sees.
  void markVisible(std::span<const sensing::Footprint> footprints, sensing::OcclusionModel model,
                   std::span<const double> camera_heights, const std::vector<std::uint8_t>& layers);

  Viewport viewport_;
  int x0_ = 0, x1_ = -1, y0_ = 0, y1_ = -1;  // the AOI's pixels: columns x0..x1, rows y0..y1
  Canvas canvas_;
  std::vector<world::TreeDef> trees_;
  std::vector<sensing::Footprint> footprints_;
  std::vector<double> camera_heights_;  // m, per footprint of the snapshot overload
  std::vector<Vec2> targets_;
  std::vector<std::uint8_t> visible_;  // per pixel, row-major: 1 when visible
  std::vector<int> near_;              // scratch: trees whose box meets one footprint's box
};

/// "step,t,covered_px,visible_px,multi_px,aoi_px,covered_fraction,visible_fraction,
/// covered_<name>...,visible_<name>..." (no newline).
std::string coverageCsvHeader(std::span<const std::string> target_names);
/// One CSV row matching coverageCsvHeader (no newline).
std::string coverageCsvRow(int step, double time, const CoverageCounts& counts);

}  // namespace canopy::render
