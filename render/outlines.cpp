#include "render/outlines.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace canopy::render {

std::vector<Vec2> covarianceEllipse(const Vec2& centre, const Mat2& P, int points) {
  if (!P.allFinite() || !centre.allFinite() || points < 3) return {};
  const Eigen::SelfAdjointEigenSolver<Mat2> eigen(0.5 * (P + P.transpose()));
  Mat2 V = eigen.eigenvectors();
  if (V.determinant() < 0.0)
    V.col(1) = -V.col(1);  // a rotation, so the points run counter-clockwise
  // P = V Λ Vᵀ: the points c + V (2√λ₁ cos θ, 2√λ₂ sin θ) satisfy (p − c)ᵀ P⁻¹ (p − c) = 4.
  const Vec2 axes = 2.0 * eigen.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  std::vector<Vec2> out;
  out.reserve(static_cast<std::size_t>(points));
  for (int k = 0; k < points; ++k) {
    const double theta = 2.0 * std::numbers::pi * k / points;
    out.push_back(centre + V * Vec2(axes.x() * std::cos(theta), axes.y() * std::sin(theta)));
  }
  return out;
}

std::vector<Vec2> footprintCorners(const sensing::Footprint& f) {
  if (f.shape == sensing::FootprintShape::disc) return {};
  if (f.shape == sensing::FootprintShape::sector) {
    constexpr double kArcStep = std::numbers::pi / 180.0;  // rad, 1°
    const int arcs = std::max(2, static_cast<int>(std::ceil(2.0 * f.half_angle / kArcStep)));
    std::vector<Vec2> out{f.centre};
    for (int k = 0; k <= arcs; ++k)
      out.push_back(f.sectorPoint(f.half_angle * (2.0 * k / arcs - 1.0)));
    return out;
  }
  if (f.shape == sensing::FootprintShape::quad)  // a pitched camera's trapezoid (issue 53)
    return {f.quadCorner(0), f.quadCorner(1), f.quadCorner(2), f.quadCorner(3)};
  const Vec2 along = f.half.x() * Vec2(f.cos_yaw, f.sin_yaw);
  const Vec2 across = f.half.y() * Vec2(-f.sin_yaw, f.cos_yaw);
  return {f.centre + along + across, f.centre - along + across, f.centre - along - across,
          f.centre + along - across};
}

std::vector<Vec2> visibleSector(const sensing::Footprint& sector,
                                const std::vector<world::TreeDef>& trees) {
  std::vector<Vec2> out = footprintCorners(sector);
  if (out.empty()) return out;
  const Aabb box = sector.bounds();
  std::vector<const world::TreeDef*> near;
  for (const world::TreeDef& tree : trees) {
    const Aabb b = world::bounds(tree);
    if (b.lo.x() <= box.hi.x() && box.lo.x() <= b.hi.x() && b.lo.y() <= box.hi.y() &&
        box.lo.y() <= b.hi.y())
      near.push_back(&tree);
  }
  const Vec2 apex = out.front();
  for (std::size_t k = 1; k < out.size(); ++k) {
    double first = 1.0;  // the fraction of the ray apex → arc point before any crown
    for (const world::TreeDef* tree : near) {
      const double s = world::segmentEntry(*tree, apex, out[k]);
      if (s >= 0.0 && s < first) first = s;
    }
    out[k] = apex + first * (out[k] - apex);
  }
  return out;
}

}  // namespace canopy::render
