// The dynamic occlusion map's shape error for a wall (issue "Walls, faulty links and ground
// robots"): a 40 × 2 m wall seen by a hovering UAV is mapped as a polygon whose error falls as
// σ_r/√n with the number n of scans, where the equal-area disc it used to become is wrong by
// nearly the wall's whole area.
//
// Independent of the code under test: the areas are computed here by convex polygon clipping
// (Sutherland–Hodgman), and the expected errors come from the measurement model in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "sim/simulation.h"
#include "spec/loader.h"

namespace canopy::sim {
namespace {

using Polygon = std::vector<Vec2>;

double area(const Polygon& p) {  // shoelace, counter-clockwise positive
  double a = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2& u = p[i];
    const Vec2& v = p[(i + 1) % p.size()];
    a += u.x() * v.y() - v.x() * u.y();
  }
  return 0.5 * a;
}

// The part of `subject` inside the convex counter-clockwise `clip` (Sutherland–Hodgman).
Polygon clipConvex(Polygon subject, const Polygon& clip) {
  for (std::size_t e = 0; e < clip.size() && !subject.empty(); ++e) {
    const Vec2 a = clip[e];
    const Vec2 b = clip[(e + 1) % clip.size()];
    const auto side = [&](const Vec2& p) {  // > 0: left of a → b, inside
      return (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x());
    };
    Polygon out;
    for (std::size_t i = 0; i < subject.size(); ++i) {
      const Vec2 p = subject[i];
      const Vec2 q = subject[(i + 1) % subject.size()];
      const double sp = side(p), sq = side(q);
      if (sp >= 0.0) out.push_back(p);
      if ((sp >= 0.0) != (sq >= 0.0)) out.push_back(p + (q - p) * (sp / (sp - sq)));
    }
    subject = std::move(out);
  }
  return subject;
}

// |A △ B| = |A| + |B| − 2 |A ∩ B| for convex counter-clockwise polygons.
double symmetricDifference(const Polygon& a, const Polygon& b) {
  return area(a) + area(b) - 2.0 * area(clipConvex(a, b));
}

// The wall: 40 m along x, 2 m across, centred on (10, 5); a UAV hovers over its centre with a
// footprint that holds all of it. σ_r = 0.5 m per vertex axis; the UAV's measurement noise is
// small next to it (α = 0.01 at about 1 m).
constexpr const char* kWall = R"({
  "aoi": [-40, -40, 60, 60], "clock": {"dt": 0.2, "duration": 40},
  "sensing": {"tree_radius_sigma": 0.5},
  "uavs": [{"name": "above", "start": [10, 5], "fov": {"size": [50, 50]},
            "quality": 0.01, "r0": 1.0}],
  "targets": [],
  "occluders": [{"type": "polygon", "vertices": [[-10, 4], [30, 4], [30, 6], [-10, 6]]}]
})";

const Polygon kTrueWall{{-10, 4}, {30, 4}, {30, 6}, {-10, 6}};

struct MappedWall {
  Polygon polygon;          // vertices of the map's crown (centre + mean offsets), in outline order
  double vertex_rms = 0.0;  // m, √(mean over vertices of |v̂ − v|²)
};

MappedWall mappedWall(const Simulation& sim) {
  const auto& trees = sim.lastStep().beliefs[0].trees;
  EXPECT_EQ(trees.size(), 1u);
  MappedWall out;
  if (trees.empty()) return out;
  const agents::TreeEstimate& wall = trees.front();
  EXPECT_EQ(wall.outline.vertices, 4);
  double sum = 0.0;
  for (int v = 0; v < wall.outline.vertices; ++v) {
    out.polygon.push_back(wall.belief.x.head<2>() + wall.outline.offsets[v]);
    sum += (out.polygon.back() - kTrueWall[v]).squaredNorm();
  }
  out.vertex_rms = std::sqrt(sum / wall.outline.vertices);
  return out;
}

TEST(WallMap, AWallIsMappedAsAPolygonWhoseErrorFallsAsSigmaOverRootN) {
  const spec::ScenarioSpec spec = spec::loadScenarioText(kWall, "wall_map_test.json");
  ASSERT_EQ(spec.trees.size(), 1u);
  ASSERT_EQ(spec.trees[0].shape, world::TreeShape::polygon);
  EXPECT_NEAR(area(kTrueWall), 80.0, 1e-12);

  Simulation sim(spec);
  std::vector<MappedWall> at;  // the map after n = 10, 40, 200 scans
  for (int n = 1; !sim.done(); ++n) {
    sim.tick();
    if (n == 10 || n == 40 || n == 200) at.push_back(mappedWall(sim));
  }
  ASSERT_EQ(at.size(), 3u);

  // Each vertex offset is the mean of n offsets with independent N(0, σ_r² I) noise: its error
  // has E|e|² = 2 σ_r²/n. The centre's error (the tree track's Kalman estimate, R ≈ 0.01 · 0.1 ·
  // [1, π] m² per scan) adds about 0.002/n m². The RMS over 4 vertices of a χ²₈-distributed sum:
  // within [0.3, 1.9] × √(2 σ_r²/n) with probability above 0.999 on each side.
  const double sigma_r = 0.5;
  const int scans[] = {10, 40, 200};
  for (int i = 0; i < 3; ++i) {
    const double expected = std::sqrt(2.0 * sigma_r * sigma_r / scans[i]);
    EXPECT_GT(at[i].vertex_rms, 0.3 * expected) << "n = " << scans[i];
    EXPECT_LT(at[i].vertex_rms, 1.9 * expected) << "n = " << scans[i];
  }

  // Shape error as area: |mapped △ true| ≈ perimeter × mean edge displacement, so it falls with n
  // too; after 200 scans (σ_r/√n = 0.035 m) it is a few percent of the 80 m² wall.
  const double error_10 = symmetricDifference(at[0].polygon, kTrueWall);
  const double error_200 = symmetricDifference(at[2].polygon, kTrueWall);
  EXPECT_LT(error_200, error_10);
  EXPECT_LT(error_200, 0.05 * 80.0);

  // The equal-area disc (r = √(80/π)) at the wall's centre, in closed form: it crosses the 2 m
  // strip whole (r < 20), so |disc ∩ wall| = ∫_{−1}^{1} 2√(r² − y²) dy
  //   = 2 [y√(r² − y²) + r² asin(y/r)]_{0}^{1} · 2, and |disc △ wall| = 160 − 2 |disc ∩ wall|.
  const double r = std::sqrt(80.0 / std::numbers::pi);
  const double overlap = 2.0 * (2.0 * std::sqrt(r * r - 1.0) + 2.0 * r * r * std::asin(1.0 / r));
  const double disc_error = 160.0 - 2.0 * overlap;
  EXPECT_NEAR(disc_error, 79.8, 0.1);
  EXPECT_LT(error_200, 0.05 * disc_error);
}

}  // namespace
}  // namespace canopy::sim
