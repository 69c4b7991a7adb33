#pragma once
// One UAV's scan: footprint ∩ bodies (Box2D AABB query), visibility, noisy labelled observations.
#include <span>
#include <vector>

#include <optional>

#include "core/random.h"
#include "sensing/camera.h"
#include "sensing/footprint.h"
#include "sensing/noise.h"
#include "sensing/observation.h"
#include "sensing/visibility.h"
#include "world/snapshot.h"
#include "world/world.h"

namespace canopy::sensing {

/// Team-wide sensing settings (algorithms.md §3).
struct SensingConfig {
  OcclusionModel occlusion_model = OcclusionModel::canopy;
  double p_detect = 1.0;           // probability that a visible target is detected
  double clutter_rate = 0.0;       // expected false detections per scan (Poisson)
  LabelId clutter_label = 1;       // label given to clutter
  double truth_noise_scale = 1.0;  // noise is drawn from N(0, scale · R)
  double tree_radius_sigma = 0.1;  // m, σ of the measured crown radius
};

/// One agent's camera.
struct SensorDef {
  FootprintDef footprint;
  SensorQuality quality;
  bool ground_level = false;  // a ground robot's forward camera: see occlusionModel()
  // A UAV that flies at an altitude (issue 53): its pinhole camera, whose footprint follows from
  // the altitude and replaces `footprint`, and whose noise grows with the slant distance
  // (sensing/camera.h). Empty: the paper's fixed footprint and eq. 2, whatever the altitude.
  std::optional<CameraDef> camera = std::nullopt;
};

/// The footprint definition of `sensor` at `altitude` (m): the camera's ground footprint, or the
/// fixed footprint of a sensor without a camera.
FootprintDef footprintAt(const SensorDef& sensor, double altitude);

/// R of a measurement at z by `sensor` from the ground point p at `altitude`: eq. 2, times the
/// slant factor of sensing/camera.h for a sensor with a camera.
Mat2 measurementCovariance(const Vec2& z, const Vec2& p, double altitude, const SensorDef& sensor);

/// What hides a target from this camera: the team's model for a UAV's downward camera; always
/// line of sight for a camera at ground level, where every crown and wall blocks the view; under
/// `volumes` the 3-D line of sight for every camera (a robot sees under a high crown).
inline OcclusionModel occlusionModel(const SensorDef& sensor, const SensingConfig& config) {
  if (config.occlusion_model == OcclusionModel::volumes) return OcclusionModel::volumes;
  return sensor.ground_level ? OcclusionModel::line_of_sight : config.occlusion_model;
}

/// The camera's height above the ground (m): a ground robot's kGroundCameraHeight, a UAV's
/// altitude.
inline double cameraHeight(const SensorDef& sensor, double altitude) {
  return sensor.ground_level ? kGroundCameraHeight : altitude;
}

/// Buffers reused from scan to scan so that sensing does not allocate in steady state.
struct SenseScratch {
  std::vector<world::BodyRef> candidates;
};

/// Scans for UAV `uav` at the snapshot's step and writes the result into `out` (cleared first).
/// Targets are hidden under occlusionModel(sensor, config). Trees are observed when their centre
/// is in the footprint; a camera at ground level sees a tree only when no other crown stands
/// first on the segment from the robot to its centre.
/// target_labels[t] is target t's label. All draws come from `rng` (the UAV's sensing stream),
/// in a fixed order: per visible target (ascending) detection then noise; clutter; per tree.
void sense(const world::World& world, const world::WorldSnapshot& truth, int uav,
           const SensorDef& sensor, const SensingConfig& config,
           std::span<const LabelId> target_labels, RandomStream& rng, SenseScratch& scratch,
           Scan& out);

/// The footprint of UAV `uav` at the snapshot.
Footprint footprintOf(const world::WorldSnapshot& truth, int uav, const SensorDef& sensor);

}  // namespace canopy::sensing
