// The people's grid (metrics/cell_grid.h) against a search of every point: the points it visits
// around p are exactly those whose cells are p's or a neighbour of it, each once, column by
// column, then by cell, then by index.
#include "metrics/cell_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>
#include <vector>

namespace canopy::metrics {
namespace {

// What forEachNear must visit around p, searched through every point: (column, cell, index).
std::vector<int> nearByEverything(const std::vector<Vec2>& points, const Vec2& p, double side) {
  auto cell = [&](double v) { return static_cast<long long>(std::floor(v / side)); };
  std::vector<std::tuple<long long, long long, int>> near;
  for (int j = 0; j < static_cast<int>(points.size()); ++j) {
    const Vec2& q = points[j];
    if (!(q.allFinite() && q.cwiseAbs().maxCoeff() < 1e15)) continue;
    if (std::llabs(cell(q.x()) - cell(p.x())) > 1 || std::llabs(cell(q.y()) - cell(p.y())) > 1)
      continue;
    near.emplace_back(cell(q.x()), cell(q.y()), j);
  }
  std::sort(near.begin(), near.end());
  std::vector<int> order;
  for (const auto& [x, y, j] : near) order.push_back(j);
  return order;
}

TEST(CellGrid, VisitsThePointsOfTheNineCellsAroundAPointInOrder) {
  std::mt19937_64 rng(20261208);
  const double side = 50.0;
  int visited = 0;
  for (int trial = 0; trial < 60; ++trial) {
    std::uniform_real_distribution<double> where(-400.0, 300.0);
    std::vector<Vec2> points(static_cast<std::size_t>(trial * 3));
    for (Vec2& q : points) q = Vec2(where(rng), where(rng));
    if (trial % 4 == 1) {  // points in no cell
      points.push_back(Vec2(std::nan(""), 3.0));
      points.push_back(Vec2(1.0, -2e15));
    }
    CellGrid grid;
    grid.build(points, side);
    ASSERT_TRUE(grid.usable());
    for (int probe = 0; probe < 40; ++probe) {
      // Probes inside the box, beside it and far from it; some on cell edges.
      const Vec2 p = probe % 10 == 0 ? Vec2(5000.0, -100.0)
                     : probe % 7 == 0 ? Vec2(50.0 * (probe - 20), -350.0)
                                      : Vec2(where(rng) * 1.3, where(rng) * 1.3);
      std::vector<int> order;
      grid.forEachNear(p, [&](int j) { order.push_back(j); });
      EXPECT_EQ(order, nearByEverything(points, p, side)) << "trial " << trial;
      visited += static_cast<int>(order.size());
    }
  }
  EXPECT_GT(visited, 2000);  // the probes found many points
}

TEST(CellGrid, ABoxOfMoreThanItsCellBoundHasNoGrid) {
  CellGrid grid;
  const double side = 50.0;
  // 2^20 cells: 1024 × 1024, the bound, is a grid; one column more is not.
  const double edge = 1024 * side - 1.0;
  grid.build(std::vector<Vec2>{Vec2(0, 0), Vec2(edge, edge)}, side);
  EXPECT_TRUE(grid.usable());
  grid.build(std::vector<Vec2>{Vec2(0, 0), Vec2(edge + side, edge)}, side);
  EXPECT_FALSE(grid.usable());
  grid.build(std::vector<Vec2>{Vec2(0, 0), Vec2(1e14, -1e14)}, side);
  EXPECT_FALSE(grid.usable());
  grid.build(std::vector<Vec2>{Vec2(0, 0)}, 1e-4);  // cells too small to number
  EXPECT_FALSE(grid.usable());
  grid.build(std::vector<Vec2>{}, side);  // nothing: an empty grid finds nothing
  ASSERT_TRUE(grid.usable());
  int found = 0;
  grid.forEachNear(Vec2(0, 0), [&](int) { ++found; });
  EXPECT_EQ(found, 0);
}

}  // namespace
}  // namespace canopy::metrics
