#pragma once
// Occluder layout generators: Poisson forests, rows and grids, clustered forests. Each is a pure
// function of its definition (and its own seed), so a layout is the same in every trial.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

#include "core/types.h"
#include "world/tree.h"

namespace canopy::spec {

/// Thrown by a generator whose random draw exceeds its `max_points` (points drawn, counting
/// candidates later thinned or dropped and cluster parents), or whose min_gap thinning needs more
/// than 100 distance checks per allowed point: a bound on every draw, not only on the expected
/// count.
struct ForestTooLarge : std::length_error {
  ForestTooLarge(std::size_t limit, const char* counted)
      : std::length_error("forest draw exceeds its limit"),
        max_points(limit),
        what_counted(counted) {}
  std::size_t max_points;    // the limit
  const char* what_counted;  // "drawn points", or the thinning's distance checks (100 per point)
};

/// Crown radii drawn uniformly from [lo, hi] (lo == hi: a fixed radius).
struct RadiusRange {
  double lo = 1.0;  // m
  double hi = 1.0;  // m
};

/// A homogeneous Poisson process of intensity λ over `region`. With min_gap, Matérn type-II
/// hard-core thinning: every point gets a uniform mark and is removed when a point with a smaller
/// mark lies closer than r_a + r_b + min_gap, so that crowns are at least min_gap apart. For equal
/// radii r the retained intensity is (1 − exp(−λ π D²)) / (π D²) with D = 2 r + min_gap (Stoyan,
/// Kendall & Mecke, Stochastic Geometry, §5.4). Points are generated in the region dilated by the
/// largest interaction distance, so there is no edge effect.
struct PoissonForestDef {
  Aabb region;           // m
  double lambda = 0.01;  // trees per m²
  RadiusRange radius;
  std::uint64_t seed = 1;
  std::optional<double> min_gap;  // m, crown edge to crown edge
  std::size_t max_points = std::numeric_limits<std::size_t>::max();
};

/// rows × cols trees: centre(r, c) = origin + Rot(angle) · (c · spacing.x, r · spacing.y), plus
/// optional Gaussian jitter of σ = jitter on each coordinate. A row is a grid with one row.
struct GridForestDef {
  Vec2 origin = Vec2::Zero();       // m
  Vec2 spacing = Vec2(10.0, 10.0);  // m
  int rows = 1;
  int cols = 1;
  double angle = 0.0;  // rad
  RadiusRange radius;
  double jitter = 0.0;  // m
  std::uint64_t seed = 1;
};

/// A Thomas cluster process: parents Poisson(parent_lambda), each with Poisson(mean_trees)
/// trees displaced by N(0, spread² I); trees outside `region` are dropped. Optional min_gap
/// thinning as in PoissonForestDef.
struct ClusterForestDef {
  Aabb region;
  double parent_lambda = 1e-4;  // clusters per m²
  double mean_trees = 10.0;     // trees per cluster
  double spread = 10.0;         // m, σ of a tree around its cluster centre
  RadiusRange radius;
  std::uint64_t seed = 1;
  std::optional<double> min_gap;  // m
  std::size_t max_points = std::numeric_limits<std::size_t>::max();
};

std::vector<world::TreeDef> poissonForest(const PoissonForestDef& def);
std::vector<world::TreeDef> gridForest(const GridForestDef& def);
std::vector<world::TreeDef> clusterForest(const ClusterForestDef& def);

/// The region a generator draws its points from: `region` dilated by the interaction distance
/// (Poisson with min_gap: 2 r_max + min_gap) or by 5σ (cluster parents).
Aabb poissonDrawRegion(const PoissonForestDef& def);
Aabb clusterParentRegion(const ClusterForestDef& def);

/// Matérn II retained intensity for equal radii: (1 − exp(−λ π D²)) / (π D²), D = 2 r + gap.
double maternIIIntensity(double lambda, double radius, double min_gap);

}  // namespace canopy::spec
