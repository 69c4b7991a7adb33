#include "world/footpaths.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <queue>
#include <stdexcept>

#include "core/random.h"

namespace canopy::world {
namespace {

// The point of segment a → b nearest p, as the fraction s ∈ [0, 1] from a.
double nearestFraction(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 e = b - a;
  const double length_sq = e.squaredNorm();
  return length_sq > 0.0 ? std::clamp((p - a).dot(e) / length_sq, 0.0, 1.0) : 0.0;
}

}  // namespace

FootpathNetwork::FootpathNetwork(const std::vector<std::vector<Vec2>>& lines) {
  // Weld vertices within kFootpathWeld through a grid of that cell size (a vertex looks in the
  // 3 × 3 cells about its own).
  std::map<std::pair<std::int64_t, std::int64_t>, std::vector<int>> grid;
  auto cell = [](double x) { return static_cast<std::int64_t>(std::floor(x / kFootpathWeld)); };
  auto nodeAt = [&](const Vec2& p) {
    const std::int64_t cx = cell(p.x()), cy = cell(p.y());
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto found = grid.find({cx + dx, cy + dy});
        if (found == grid.end()) continue;
        for (int n : found->second)
          if ((nodes_[static_cast<std::size_t>(n)] - p).norm() < kFootpathWeld) return n;
      }
    }
    const int n = static_cast<int>(nodes_.size());
    nodes_.push_back(p);
    adjacent_.emplace_back();
    grid[{cx, cy}].push_back(n);
    return n;
  };
  for (const std::vector<Vec2>& line : lines) {
    int previous = -1;
    for (const Vec2& p : line) {
      const int n = nodeAt(p);
      if (previous >= 0 && previous != n) {
        auto& a = adjacent_[static_cast<std::size_t>(previous)];
        auto& b = adjacent_[static_cast<std::size_t>(n)];
        if (std::find(a.begin(), a.end(), n) == a.end()) a.push_back(n);
        if (std::find(b.begin(), b.end(), previous) == b.end()) b.push_back(previous);
      }
      previous = n;
    }
  }
  for (auto& list : adjacent_) std::sort(list.begin(), list.end());
}

std::size_t FootpathNetwork::edgeCount() const {
  std::size_t twice = 0;
  for (const auto& list : adjacent_) twice += list.size();
  return twice / 2;
}

std::vector<std::pair<Vec2, Vec2>> FootpathNetwork::segments() const {
  std::vector<std::pair<Vec2, Vec2>> out;
  for (std::size_t a = 0; a < nodes_.size(); ++a) {
    for (int b : adjacent_[a])
      if (static_cast<std::size_t>(b) > a) out.emplace_back(nodes_[a], nodes_[static_cast<std::size_t>(b)]);
  }
  return out;
}

FootpathNetwork::Snap FootpathNetwork::nearest(const Vec2& p) const {
  Snap best;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < nodes_.size(); ++a) {
    for (int b : adjacent_[a]) {
      if (static_cast<std::size_t>(b) < a) continue;
      const Vec2 &pa = nodes_[a], &pb = nodes_[static_cast<std::size_t>(b)];
      const double s = nearestFraction(p, pa, pb);
      const Vec2 q = pa + s * (pb - pa);
      const double d = (q - p).norm();
      if (d < best_d) {
        best_d = d;
        best = {static_cast<int>(a), b, s, q};
      }
    }
  }
  if (best.a < 0) throw std::invalid_argument("the footpath network has no segment");
  return best;
}

double FootpathNetwork::distanceTo(const Vec2& p) const {
  return (nearest(p).p - p).norm();
}

std::vector<TimedPoint> FootpathNetwork::route(const Vec2& from, const Vec2& to,
                                               double speed) const {
  const Snap start = nearest(from), goal = nearest(to);
  // Dijkstra over the nodes plus two virtual ones: the start (index n) and the goal (n + 1),
  // each joined to its edge's two nodes (and to each other when on the same edge).
  const int n = static_cast<int>(nodes_.size());
  const int s_node = n, g_node = n + 1;
  auto position = [&](int i) {
    return i == s_node ? start.p : i == g_node ? goal.p : nodes_[static_cast<std::size_t>(i)];
  };
  auto neighbours = [&](int i) {
    std::vector<int> out;
    if (i == s_node) {
      out = {start.a, start.b};
      if (std::minmax(start.a, start.b) == std::minmax(goal.a, goal.b)) out.push_back(g_node);
      return out;
    }
    if (i == g_node) return std::vector<int>{goal.a, goal.b};
    out = adjacent_[static_cast<std::size_t>(i)];
    if (i == start.a || i == start.b) out.push_back(s_node);
    if (i == goal.a || i == goal.b) out.push_back(g_node);
    return out;
  };
  std::vector<double> dist(static_cast<std::size_t>(n + 2), std::numeric_limits<double>::infinity());
  std::vector<int> from_node(static_cast<std::size_t>(n + 2), -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  dist[static_cast<std::size_t>(s_node)] = 0.0;
  open.push({0.0, s_node});
  while (!open.empty()) {
    const auto [d, i] = open.top();
    open.pop();
    if (d > dist[static_cast<std::size_t>(i)]) continue;
    if (i == g_node) break;
    for (int j : neighbours(i)) {
      const double nd = d + (position(j) - position(i)).norm();
      if (nd < dist[static_cast<std::size_t>(j)]) {
        dist[static_cast<std::size_t>(j)] = nd;
        from_node[static_cast<std::size_t>(j)] = i;
        open.push({nd, j});
      }
    }
  }
  if (!std::isfinite(dist[static_cast<std::size_t>(g_node)]))
    throw std::invalid_argument("no footpath connects the start to the goal");
  std::vector<int> chain;
  for (int i = g_node; i >= 0; i = from_node[static_cast<std::size_t>(i)]) chain.push_back(i);
  std::reverse(chain.begin(), chain.end());
  std::vector<TimedPoint> points;
  double t = 0.0;
  for (std::size_t k = 0; k < chain.size(); ++k) {
    const Vec2 p = position(chain[k]);
    if (k > 0) {
      const double step = (p - points.back().p).norm();
      if (step <= 0.0) continue;  // the start or goal on a node: no zero-length leg
      t += step / speed;          // time = length / walking speed
    }
    points.push_back({t, p});
  }
  return points;
}

std::vector<TimedPoint> FootpathNetwork::randomWalk(const Vec2& from, double speed,
                                                    double duration, std::uint64_t seed,
                                                    std::uint64_t index) const {
  RandomStream rng(seed, "footpath_walk", index);
  const Snap start = nearest(from);
  std::vector<TimedPoint> points{{0.0, start.p}};
  // First leg: to either end of the start's edge (and from there on, never straight back).
  int at = rng.uniform() < 0.5 ? start.a : start.b;
  int previous = at == start.a ? start.b : start.a;
  double t = 0.0;
  auto walkTo = [&](int node) {
    const Vec2& p = nodes_[static_cast<std::size_t>(node)];
    const double step = (p - points.back().p).norm();
    if (step > 0.0) {
      t += step / speed;  // time = length / walking speed
      points.push_back({t, p});
    }
  };
  walkTo(at);
  while (t < duration) {
    const std::vector<int>& options = adjacent_[static_cast<std::size_t>(at)];
    std::vector<int> onward;
    for (int j : options)
      if (j != previous) onward.push_back(j);
    if (onward.empty()) onward = options;  // a dead end: back the way it came
    const auto pick = static_cast<std::size_t>(rng.uniform() * static_cast<double>(onward.size()));
    previous = at;
    at = onward[std::min(pick, onward.size() - 1)];
    walkTo(at);
  }
  return points;
}

}  // namespace canopy::world
