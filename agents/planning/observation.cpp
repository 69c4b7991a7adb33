#include "agents/planning/observation.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sensing/footprint.h"

namespace canopy::agents::planning {
namespace {

// The ground point a plan leads to after `horizon` actions of `period` s: p + Σ a_m·Δ.
Vec2 intendedEnd(const Vec2& start, const Plan& plan, int horizon, double period) {
  Vec2 p = start;
  for (int m = 0; m < horizon; ++m) p += plan.action(m) * period;
  return p;
}

}  // namespace

Observation observe(int agent, std::span<const UavState> uavs,
                    std::span<const TargetGaussian> tracks, const OcclusionMap* map,
                    std::span<const Plan> intentions, int horizon, double period) {
  const UavState& me = uavs[static_cast<std::size_t>(agent)];
  const int n = static_cast<int>(uavs.size());
  Observation o;
  const Vec2 previous = intentions[static_cast<std::size_t>(agent)].command();
  o.self = {me.v_max / kSpeed,
            sensing::circumradius(me.footprint) / kLength,
            static_cast<double>(tracks.size()) / 10.0,
            static_cast<double>(n - 1) / 10.0,
            previous.x() / kSpeed,
            previous.y() / kSpeed};
  // The occlusion patch: cell (r, c) spans [c·s − W/2, (c+1)·s − W/2) east and the same north of
  // the agent, W = 5·s; sampled at its four quarter points.
  const double half = 0.5 * kOcclusionCells * kOcclusionCell;
  for (int r = 0; r < kOcclusionCells; ++r) {
    for (int c = 0; c < kOcclusionCells; ++c) {
      int hidden = 0;
      for (int s = 0; s < 4; ++s) {
        const Vec2 p = me.position + Vec2((c + 0.25 + 0.5 * (s % 2)) * kOcclusionCell - half,
                                          (r + 0.25 + 0.5 * (s / 2)) * kOcclusionCell - half);
        if (map && map->occludes(p)) ++hidden;
      }
      o.self.push_back(hidden / 4.0);
    }
  }

  std::vector<Vec2> mate_ends;  // teammates' intended ground points after H actions
  for (int k = 0; k < n; ++k) {
    if (k == agent) continue;
    const UavState& mate = uavs[static_cast<std::size_t>(k)];
    const Plan& plan = intentions[static_cast<std::size_t>(k)];
    const Vec2 end = intendedEnd(mate.position, plan, horizon, period);
    mate_ends.push_back(end);
    const Vec2 rel = (mate.position - me.position) / kLength;
    const Vec2 first = plan.action(0) / kSpeed;
    const Vec2 shift = (end - mate.position) / kLength;
    o.mates.insert(o.mates.end(), {rel.x(), rel.y(), first.x(), first.y(), shift.x(), shift.y(),
                                   sensing::circumradius(mate.footprint) / kLength});
  }

  const double lookahead = horizon * period;  // s, H·Δ
  for (const TargetGaussian& t : tracks) {
    const Vec2 p(t.x(0), t.x(1));
    const Vec2 v(t.x(2), t.x(3));
    const double sx = std::sqrt(std::max(t.P(0, 0), 0.0));
    const double sy = std::sqrt(std::max(t.P(1, 1), 0.0));
    const double rho = sx > 0.0 && sy > 0.0 ? std::clamp(t.P(0, 1) / (sx * sy), -1.0, 1.0) : 0.0;
    const Vec2 rel = (p - me.position) / kLength;
    o.tracks.insert(o.tracks.end(), {rel.x(), rel.y(), v.x() / kSpeed, v.y() / kSpeed,
                                     sx / kLength, sy / kLength, rho,
                                     std::log1p(std::max(t.P(0, 0) + t.P(1, 1), 0.0)) / 5.0});
    const Vec2 ahead = p + lookahead * v;
    if (mate_ends.empty()) {
      o.tracks.insert(o.tracks.end(), {0.0, 0.0, 0.0});
      continue;
    }
    Vec2 nearest = mate_ends.front();
    double best = std::numeric_limits<double>::infinity();
    for (const Vec2& q : mate_ends) {
      const double d = (ahead - q).squaredNorm();
      if (d < best) best = d, nearest = q;
    }
    const Vec2 off = (ahead - nearest) / kLength;
    o.tracks.insert(o.tracks.end(), {off.x(), off.y(), 1.0});
  }
  return o;
}

}  // namespace canopy::agents::planning
