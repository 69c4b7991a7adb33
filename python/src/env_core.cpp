#include "python/src/env_core.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace canopy::python {

EnvLayout makeLayout(const spec::ScenarioSpec& spec, int max_tracks, int max_trees,
                     double map_radius, bool full_trace) {
  if (max_tracks < 0 || max_trees < 0)
    throw std::invalid_argument("expected max_tracks ≥ 0 and max_trees ≥ 0");
  if (!(map_radius > 0.0) || !std::isfinite(map_radius))
    throw std::invalid_argument("map_radius: expected a finite length > 0 (m)");
  EnvLayout layout;
  layout.max_tracks = max_tracks;
  layout.max_trees = max_trees;
  layout.map_radius = map_radius;
  layout.full_trace = full_trace;

  double reach = std::max({std::abs(spec.aoi.lo.x()), std::abs(spec.aoi.lo.y()),
                           std::abs(spec.aoi.hi.x()), std::abs(spec.aoi.hi.y())});
  double v_max = 0.0;
  for (const spec::UavSpec& u : spec.uavs) {
    reach = std::max({reach, std::abs(u.body.start.x()), std::abs(u.body.start.y())});
    v_max = std::max(v_max, u.body.v_max);
  }
  const auto position = static_cast<float>(std::ceil(reach + v_max * spec.duration));
  const auto speed = static_cast<float>(std::max(50.0, 5.0 * v_max));
  layout.position = position;
  layout.speed = speed;
  const float variance = 1.0e4F;  // m²
  const auto pi = static_cast<float>(std::numbers::pi);
  const auto radius = static_cast<float>(map_radius);

  auto add = [&](float lo, float hi) {
    layout.low.push_back(lo);
    layout.high.push_back(hi);
  };
  add(-position, position);
  add(-position, position);
  add(-pi, pi);
  for (int j = 0; j < max_tracks; ++j) {
    add(-position, position);
    add(-position, position);
    add(-speed, speed);
    add(-speed, speed);
    add(0.0F, variance);
    add(0.0F, variance);
    add(0.0F, 1.0F);
  }
  for (int j = 0; j < max_trees; ++j) {
    add(-radius, radius);
    add(-radius, radius);
    add(0.0F, radius);
    add(0.0F, 1.0F);
  }
  return layout;
}

void observe(const sim::StepRecord& record, int agent, const EnvLayout& layout, float* out) {
  const auto size = static_cast<std::size_t>(layout.size());
  std::fill(out, out + size, 0.0F);
  const auto i = static_cast<std::size_t>(agent);
  const sim::UavRecord& uav = record.uavs[i];
  out[0] = static_cast<float>(uav.position.x());
  out[1] = static_cast<float>(uav.position.y());
  out[2] = static_cast<float>(uav.yaw);

  const auto& tracks = record.beliefs[i].tracks;
  float* row = out + 3;
  const std::size_t m = std::min(tracks.size(), static_cast<std::size_t>(layout.max_tracks));
  for (std::size_t j = 0; j < m; ++j, row += EnvLayout::kTrack) {
    const auto& b = tracks[j].belief;
    for (int a = 0; a < 4; ++a) row[a] = static_cast<float>(b.x(a));
    row[4] = static_cast<float>(b.P(0, 0));
    row[5] = static_cast<float>(b.P(1, 1));
    row[6] = 1.0F;
  }

  // The discs nearest to the agent within map_radius, nearest first (ties in map order).
  const auto& trees = record.beliefs[i].trees;
  struct Near {
    double distance;
    std::size_t index;
  };
  std::vector<Near> near;
  near.reserve(trees.size());
  for (std::size_t t = 0; t < trees.size(); ++t) {
    const double dx = trees[t].belief.x(0) - uav.position.x();
    const double dy = trees[t].belief.x(1) - uav.position.y();
    const double d = std::hypot(dx, dy);
    if (d <= layout.map_radius) near.push_back({d, t});
  }
  std::stable_sort(near.begin(), near.end(),
                   [](const Near& a, const Near& b) { return a.distance < b.distance; });
  row = out + 3 + EnvLayout::kTrack * layout.max_tracks;
  const std::size_t k = std::min(near.size(), static_cast<std::size_t>(layout.max_trees));
  for (std::size_t j = 0; j < k; ++j, row += EnvLayout::kTree) {
    const auto& x = trees[near[j].index].belief.x;
    row[0] = static_cast<float>(x(0) - uav.position.x());
    row[1] = static_cast<float>(x(1) - uav.position.y());
    row[2] = static_cast<float>(x(2));
    row[3] = 1.0F;
  }
  for (std::size_t e = 0; e < size; ++e) out[e] = std::clamp(out[e], layout.low[e], layout.high[e]);
}

double stageReward(const sim::StepRecord& record, int agent, bool full_trace) {
  double cost = 0.0;
  const int n = full_trace ? 4 : 2;
  for (const auto& track : record.beliefs[static_cast<std::size_t>(agent)].tracks) {
    double trace = 0.0;
    for (int a = 0; a < n; ++a) trace += track.belief.P(a, a);
    cost += trace;
  }
  return -cost;
}

}  // namespace canopy::python
