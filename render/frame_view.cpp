#include "render/frame_view.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <vector>

#include "core/number_text.h"
#include "core/printable.h"
#include "sensing/footprint.h"
#include "spec/error.h"

namespace canopy::render {

Aabb actionBox(const spec::ScenarioSpec& spec) {
  Vec2 lo = Vec2::Constant(INFINITY), hi = Vec2::Constant(-INFINITY);
  const auto grow = [&](const Vec2& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  };
  const int steps = spec.steps();
  double reach = 0.0;  // m, how far a footprint reaches from its UAV
  for (const spec::UavSpec& uav : spec.uavs) {
    // A UAV at an altitude (issue 53) reaches farthest at its highest.
    reach = std::max(reach,
                     sensing::circumradius(sensing::footprintAt(uav.sensor, uav.body.z_max)));
    grow(uav.body.start);
    if (!uav.path || spec.planner.algorithm != agents::PlannerAlgorithm::none) continue;
    for (int k = 0; k < steps; ++k) grow(uav.path->positionAt(k * spec.dt));
  }
  for (const spec::TargetSpec& target : spec.targets) {
    for (int k = 0; k < steps; ++k) grow(target.path.positionAt(k * spec.dt));
  }
  if (!lo.allFinite() || !hi.allFinite()) return spec.aoi;
  lo -= Vec2::Constant(reach);
  hi += Vec2::Constant(reach);
  const double pad = std::max(2.0, 0.1 * std::max(hi.x() - lo.x(), hi.y() - lo.y()));
  // Never beyond the AOI: everything scripted starts and stays inside it.
  const Vec2 view_lo = (lo - Vec2::Constant(pad)).cwiseMax(spec.aoi.lo);
  const Vec2 view_hi = (hi + Vec2::Constant(pad)).cwiseMin(spec.aoi.hi);
  if (!(view_hi.x() > view_lo.x() && view_hi.y() > view_lo.y())) return spec.aoi;
  return {view_lo, view_hi};
}

namespace {

std::optional<Aabb> viewBox(const std::string& text) {
  std::vector<double> v;
  std::stringstream stream(text);
  for (std::string item; std::getline(stream, item, ',');) {
    const std::optional<double> x = strictNumber(item);
    if (!x) return std::nullopt;
    v.push_back(*x);
  }
  if (text.empty() || text.back() == ',') return std::nullopt;
  if (v.size() != 4 || !(v[2] > v[0] && v[3] > v[1])) return std::nullopt;
  return Aabb{Vec2(v[0], v[1]), Vec2(v[2], v[3])};
}

}  // namespace

bool isViewText(const std::string& text) {
  return text == "aoi" || text == "action" || viewBox(text).has_value();
}

Aabb viewFor(const std::string& text, const spec::ScenarioSpec& spec) {
  if (text == "aoi") return spec.aoi;
  if (text == "action") return actionBox(spec);
  const std::optional<Aabb> box = viewBox(text);
  if (!box) {
    throw spec::ScenarioError(
        "command line", "--view",
        "expected aoi, action or x0,y0,x1,y1 (m) with x1 > x0 and y1 > y0, got '" +
            printable(text, 100) + "'");
  }
  return *box;
}

}  // namespace canopy::render
