#include "spec/forest.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <unordered_map>

#include "core/random.h"

namespace canopy::spec {
namespace {

// Distance checks of Matérn thinning allowed per point of the draw limit (ForestTooLarge beyond).
constexpr std::size_t kChecksPerPoint = 100;

struct Candidate {
  Vec2 centre;
  double radius;
  double mark;  // Matérn II priority: smaller marks win
};

Aabb dilate(const Aabb& box, double margin) {
  return {box.lo - Vec2(margin, margin), box.hi + Vec2(margin, margin)};
}

double drawRadius(const RadiusRange& range, RandomStream& rng) {
  return range.lo == range.hi ? range.lo : rng.uniform(range.lo, range.hi);
}

// Counts the points of one draw and throws ForestTooLarge past the limit.
class DrawCounter {
 public:
  explicit DrawCounter(std::size_t limit, const char* what = "drawn points")
      : limit_(limit), what_(what) {}
  void add(std::size_t n = 1) {
    if (n > limit_ - count_) throw ForestTooLarge(limit_, what_);
    count_ += n;
  }

 private:
  std::size_t limit_, count_ = 0;
  const char* what_;
};

std::size_t checkLimit(std::size_t max_points) {
  const std::size_t most = std::numeric_limits<std::size_t>::max();
  return max_points > most / kChecksPerPoint ? most : kChecksPerPoint * max_points;
}

// Homogeneous Poisson points on `box`: x-coordinates are the arrivals of a 1-D Poisson process
// of rate λ · height (exponential gaps), y-coordinates uniform. Exact, and O(number of points).
template <typename Emit>
void poissonPoints(const Aabb& box, double lambda, RandomStream& rng, DrawCounter& drawn,
                   Emit emit) {
  const double rate = lambda * box.height();  // points per metre along x
  if (!(rate > 0.0)) return;
  for (double x = box.lo.x() + rng.exponential(rate); x < box.hi.x(); x += rng.exponential(rate)) {
    drawn.add();
    emit(Vec2(x, rng.uniform(box.lo.y(), box.hi.y())));
  }
}

// Matérn II thinning on a uniform hash grid; keeps the input order of the survivors. Each cell
// lists its points by ascending mark, so a point looks only at the points that could dominate it
// and stops at the first that does: in a crowded cell that is one of the first few. The distance
// checks are counted against `max_checks` (a bound on the work of every draw).
std::vector<Candidate> thin(const std::vector<Candidate>& points, double max_radius, double gap,
                            std::size_t max_checks) {
  const double reach = 2.0 * max_radius + gap;  // largest centre distance that can conflict
  if (points.empty() || reach <= 0.0) return points;
  auto cellOf = [reach](const Vec2& p) {
    return std::pair<long long, long long>(static_cast<long long>(std::floor(p.x() / reach)),
                                           static_cast<long long>(std::floor(p.y() / reach)));
  };
  auto key = [](long long cx, long long cy) { return (cx * 73856093LL) ^ (cy * 19349663LL); };
  std::unordered_map<long long, std::vector<int>> grid;  // lookups only: order never matters
  for (int i = 0; i < static_cast<int>(points.size()); ++i) {
    const auto [cx, cy] = cellOf(points[i].centre);
    grid[key(cx, cy)].push_back(i);
  }
  const auto by_mark = [&points](int a, int b) {
    return points[a].mark < points[b].mark || (points[a].mark == points[b].mark && a < b);
  };
  for (auto& [cell, members] : grid) std::sort(members.begin(), members.end(), by_mark);
  DrawCounter checks(max_checks, "distance checks of the min_gap thinning");
  std::vector<Candidate> kept;
  for (int i = 0; i < static_cast<int>(points.size()); ++i) {
    const Candidate& p = points[i];
    const auto [cx, cy] = cellOf(p.centre);
    // The 3 × 3 neighbouring cells merged in ascending mark: the first smaller-mark point within
    // reach ends the search, wherever it lies.
    std::array<std::pair<const int*, const int*>, 9> cursors{};
    int n_cursors = 0;
    for (long long dx = -1; dx <= 1; ++dx) {
      for (long long dy = -1; dy <= 1; ++dy) {
        const auto cell = grid.find(key(cx + dx, cy + dy));
        if (cell != grid.end() && !cell->second.empty()) {
          cursors[n_cursors++] = {cell->second.data(), cell->second.data() + cell->second.size()};
        }
      }
    }
    bool dominated = false;
    while (!dominated) {
      int best = -1;
      for (int c = 0; c < n_cursors; ++c) {
        if (cursors[c].first == cursors[c].second) continue;
        if (best < 0 || by_mark(*cursors[c].first, *cursors[best].first)) best = c;
      }
      if (best < 0) break;
      const Candidate& q = points[*cursors[best].first++];
      if (!(q.mark < p.mark)) break;  // every remaining point has a larger mark
      checks.add();
      const double d = p.radius + q.radius + gap;
      dominated = (q.centre - p.centre).squaredNorm() < d * d;
    }
    if (!dominated) kept.push_back(p);
  }
  return kept;
}

std::vector<world::TreeDef> keepInside(const std::vector<Candidate>& points, const Aabb& region) {
  std::vector<world::TreeDef> trees;
  for (const Candidate& p : points) {
    if (region.contains(p.centre)) trees.push_back(world::TreeDef::disc(p.centre, p.radius));
  }
  return trees;
}

}  // namespace

double maternIIIntensity(double lambda, double radius, double min_gap) {
  const double d = 2.0 * radius + min_gap;
  const double area = std::numbers::pi * d * d;
  return (1.0 - std::exp(-lambda * area)) / area;
}

Aabb poissonDrawRegion(const PoissonForestDef& def) {
  return dilate(def.region, def.min_gap ? 2.0 * def.radius.hi + *def.min_gap : 0.0);
}

Aabb clusterParentRegion(const ClusterForestDef& def) {
  // Parents beyond 5σ of the region contribute a negligible share of trees inside it.
  return dilate(def.region, 5.0 * def.spread);
}

std::vector<world::TreeDef> poissonForest(const PoissonForestDef& def) {
  RandomStream rng(def.seed, "forest.poisson");
  DrawCounter drawn(def.max_points);
  std::vector<Candidate> points;
  poissonPoints(poissonDrawRegion(def), def.lambda, rng, drawn, [&](const Vec2& p) {
    const double radius = drawRadius(def.radius, rng);
    points.push_back({p, radius, rng.uniform()});
  });
  if (def.min_gap) points = thin(points, def.radius.hi, *def.min_gap, checkLimit(def.max_points));
  return keepInside(points, def.region);
}

std::vector<world::TreeDef> gridForest(const GridForestDef& def) {
  RandomStream rng(def.seed, "forest.grid");
  const double c = std::cos(def.angle), s = std::sin(def.angle);
  std::vector<world::TreeDef> trees;
  for (int r = 0; r < def.rows; ++r) {
    for (int col = 0; col < def.cols; ++col) {
      const Vec2 local(col * def.spacing.x(), r * def.spacing.y());
      Vec2 centre = def.origin + Vec2(c * local.x() - s * local.y(), s * local.x() + c * local.y());
      if (def.jitter > 0.0) centre += def.jitter * Vec2(rng.normal(), rng.normal());
      trees.push_back(world::TreeDef::disc(centre, drawRadius(def.radius, rng)));
    }
  }
  return trees;
}

std::vector<world::TreeDef> clusterForest(const ClusterForestDef& def) {
  RandomStream rng(def.seed, "forest.cluster");
  DrawCounter drawn(def.max_points);
  std::vector<Vec2> parents;
  poissonPoints(clusterParentRegion(def), def.parent_lambda, rng, drawn,
                [&](const Vec2& p) { parents.push_back(p); });
  std::vector<Candidate> points;
  for (const Vec2& parent : parents) {
    const int n = rng.poisson(def.mean_trees);
    drawn.add(static_cast<std::size_t>(std::max(n, 0)));
    for (int k = 0; k < n; ++k) {
      const Vec2 centre = parent + def.spread * Vec2(rng.normal(), rng.normal());
      const double radius = drawRadius(def.radius, rng);
      points.push_back({centre, radius, rng.uniform()});
    }
  }
  if (def.min_gap) points = thin(points, def.radius.hi, *def.min_gap, checkLimit(def.max_points));
  return keepInside(points, def.region);
}

}  // namespace canopy::spec
