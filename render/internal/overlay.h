#pragma once
// What a frame draws in pixels over the map (Scene::overlay): the legend band along the bottom,
// the time stamp at the top left and the scale bar above the band.
#include <string>
#include <vector>

#include "render/internal/scene_sizes.h"
#include "render/scene.h"
#include "render/scene_builder.h"
#include "render/viewport.h"
#include "world/snapshot.h"

namespace canopy::render::internal {

/// One entry of the legend band: a symbol, placed by addLegend, then its label.
struct LegendEntry {
  std::string label;
  std::vector<Primitive> symbol;  // around (0, 0), px
};

/// The legend's entries: one per UAV, then the targets, trees, estimates, occlusion map, contacts
/// when an agent has a body, and plans when the UAVs plan; every entry a run can need, so that the
/// band keeps its height.
std::vector<LegendEntry> legendEntries(const SceneModel& model, std::size_t uavs, double u);

/// Lays the entries out left to right in rows along the bottom; returns the band's height (px).
double addLegend(const std::vector<LegendEntry>& entries, ImageSize size, const Sizes& z,
                 std::vector<Primitive>& out);

/// The title panel's text: the scenario's title, t and k.
std::string timeStampText(const SceneModel& model, const world::WorldSnapshot& truth);
/// The title panel's size (px) for that text.
Vec2 timeStampSize(const std::string& text, const Sizes& z);
/// The title panel with its top-left corner at `lo` (px; scene_builder.cpp picks a corner of the
/// map clear of what the frame shows).
void addTimeStamp(const std::string& text, const Vec2& lo, const Sizes& z,
                  std::vector<Primitive>& out);

/// A bar of scaleBarLength(map width) metres at the bottom left of the map, above the legend
/// band of height `band` (px).
void addScaleBar(const Viewport& v, ImageSize size, double band, const Sizes& z,
                 std::vector<Primitive>& out);

}  // namespace canopy::render::internal
