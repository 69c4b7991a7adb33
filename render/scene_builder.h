#pragma once
// buildScene: truth, sensors and the agents' beliefs → a Scene (pure; no GL). What a frame shows,
// in drawing order: the AOI, tree crowns, every UAV's footprint (its own colour, translucent),
// the occlusion-map estimates (outlined discs), planned paths, targets' trails, the agents' fused
// estimates with 2-σ ellipses, the true targets, the UAV bodies with their headings and their
// names (each placed where it overlaps no name placed before it); then a time stamp, a scale bar
// and a legend band along the bottom. The view and the legend depend on the model only, so every
// frame of a run has the same projection.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "agents/belief.h"
#include "render/outlines.h"
#include "render/scene.h"
#include "render/trails.h"
#include "sensing/sensor.h"
#include "world/snapshot.h"
#include "world/tree.h"

namespace canopy::render {

/// What does not change during a run (the scenario, as the renderer needs it).
struct SceneModel {
  std::string title;  // e.g. the scenario's name
  Aabb aoi;           // m
  std::vector<world::TreeDef> trees;
  std::vector<sensing::SensorDef> sensors;  // one per UAV, in the snapshot's order
  std::vector<std::string> uav_names;       // optional; "uav1", "uav2", … when missing
  std::vector<std::string> target_names;    // optional; "T1", "T2", … when missing
  std::optional<Aabb> view;  // m, the region every frame shows (with the margin); AOI if unset
  bool plans = false;        // the UAVs plan: the legend has a "plan" entry
  bool contacts = false;     // some agent has a body: the legend has a "contact" entry

  /// The region the frames show: `view`, or the AOI.
  Aabb shown() const { return view.value_or(aoi); }
};

struct SceneOptions {
  double margin = 0.04;     // fraction of the AOI's larger side shown around it
  double text_scale = 0.0;  // font units → px; 0: chosen from the image width
  bool legend = true;       // the legend band along the bottom
  bool labels = true;       // names beside UAVs and targets
};

/// beliefs: one per UAV (may be empty before agents run); trails: the targets' recent
/// positions (may be empty). The map is fitted, aspect preserved, above the legend band.
Scene buildScene(const SceneModel& model, const world::WorldSnapshot& truth,
                 std::span<const agents::AgentBelief> beliefs, const TargetTrails& trails,
                 ImageSize size, const SceneOptions& options = {});

/// The length (m) of a scale bar for a map `width_m` wide: the largest 1, 2 or 5 × 10^k at most a
/// quarter of the width.
double scaleBarLength(double width_m);

/// "20 m", "500 m", "0.5 m", "2 km" for a scale bar.
std::string scaleBarLabel(double length_m);

}  // namespace canopy::render
