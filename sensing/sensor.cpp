#include "sensing/sensor.h"

#include <algorithm>
#include <cmath>

namespace canopy::sensing {

FootprintDef footprintAt(const SensorDef& sensor, double altitude) {
  return sensor.camera ? groundFootprint(*sensor.camera, altitude) : sensor.footprint;
}

Mat2 measurementCovariance(const Vec2& z, const Vec2& p, double altitude, const SensorDef& sensor) {
  const Mat2 R = rangeBearingCovariance(z, p, sensor.quality);
  if (!sensor.camera) return R;
  return slantNoiseFactor(z, p, altitude) * R;  // (ℓ(h) / ℓ(h_ref)) · R(z, p)
}

Footprint footprintOf(const world::WorldSnapshot& truth, int uav, const SensorDef& sensor) {
  const world::UavState& state = truth.uavs[uav];
  if (sensor.camera) {
    return Footprint::place(groundFootprint(*sensor.camera, state.z), state.position, state.yaw);
  }
  return Footprint::place(sensor.footprint, state.position, state.yaw);
}

void sense(const world::World& world, const world::WorldSnapshot& truth, int uav,
           const SensorDef& sensor, const SensingConfig& config,
           std::span<const LabelId> target_labels, RandomStream& rng, SenseScratch& scratch,
           Scan& out) {
  out.clear();
  out.uav = uav;
  const Vec2 p_i = truth.uavs[uav].position;
  const double h = truth.uavs[uav].z;
  out.sensor_position = p_i;
  out.sensor_height = cameraHeight(sensor, h);
  const Footprint footprint = footprintOf(truth, uav, sensor);
  const OcclusionModel model = occlusionModel(sensor, config);

  scratch.candidates.clear();
  world.queryAabb(footprint.bounds(), scratch.candidates);  // sorted: UAVs, targets, trees

  // Targets: V_{i,k} = {t : χ_t ∈ φ_i ∧ χ_t ∉ W} (eq. 3), then detection and noise (eq. 2).
  for (const world::BodyRef& ref : scratch.candidates) {
    if (ref.kind != world::BodyKind::target) continue;
    const Vec2& chi = truth.targets[ref.index].position;
    if (!footprint.contains(chi)) continue;
    out.in_footprint.push_back(ref.index);
    if (isOccluded(world, p_i, chi, model, cameraHeight(sensor, h))) continue;
    out.visible.push_back(ref.index);
    if (!rng.bernoulli(config.p_detect)) continue;
    const Mat2 R_truth = measurementCovariance(chi, p_i, h, sensor);
    const Vec2 z = chi + rng.gaussian(config.truth_noise_scale * R_truth);
    out.observations.push_back({target_labels[ref.index], z,
                                measurementCovariance(z, p_i, h, sensor), 0.0, 0.0, ref.index, {}});
  }

  // Clutter: Poisson count, uniform over the footprint.
  const int clutter = rng.poisson(config.clutter_rate);
  for (int c = 0; c < clutter; ++c) {
    const double u = rng.uniform();
    const Vec2 z = footprint.pointFromUnitSquare(u, rng.uniform());
    out.observations.push_back(
        {config.clutter_label, z, measurementCovariance(z, p_i, h, sensor), 0.0, 0.0, -1, {}});
  }

  // Trees (SOO): observed when the crown's centre is in φ_i; from above exempt from occlusion, at
  // ground level hidden by any other crown nearer on the line of sight to the centre.
  const double radius_variance = config.tree_radius_sigma * config.tree_radius_sigma;
  for (const world::BodyRef& ref : scratch.candidates) {
    if (ref.kind != world::BodyKind::tree) continue;
    const world::TreeDef& tree = world.trees()[ref.index];
    if (!footprint.contains(tree.centre)) continue;
    if (sensor.ground_level && world.firstOccluderOnSegment(p_i, tree.centre) != ref.index)
      continue;
    const Mat2 R_truth = measurementCovariance(tree.centre, p_i, h, sensor);
    const Vec2 z = tree.centre + rng.gaussian(config.truth_noise_scale * R_truth);
    const double radius =
        std::max(0.0, tree.radius + config.tree_radius_sigma * std::sqrt(config.truth_noise_scale) *
                                        rng.normal());
    out.observations.push_back({kTreeLabel, z, measurementCovariance(z, p_i, h, sensor), radius,
                                radius_variance, ref.index, {}});
    // A polygonal crown (or wall) is seen whole: each vertex's offset from the centroid with the
    // radius's noise σ_r per axis, in the crown's vertex order.
    if (tree.shape == world::TreeShape::polygon) {
      Outline& outline = out.observations.back().outline;
      const Mat2 vertex_noise = config.truth_noise_scale * radius_variance * Mat2::Identity();
      outline.vertices = static_cast<int>(tree.vertices.size());
      for (int v = 0; v < outline.vertices; ++v) {
        outline.offsets[v] = tree.vertices[v] - tree.centre + rng.gaussian(vertex_noise);
      }
    }
  }
}

}  // namespace canopy::sensing
