#pragma once
// A footpath network (issue 52): polylines (imported from GIS data, or written by hand) as a graph
// whose nodes are their vertices — vertices closer than kFootpathWeld are one node, so that paths
// meeting at a shared point are joined — and whose edges are their segments. People walk it: the
// shortest route between two points, or a seeded random walk, as timed points a Path follows.
#include <cstdint>
#include <vector>

#include "core/types.h"
#include "world/path.h"

namespace canopy::world {

/// Vertices of different footpaths closer than this (m) are one junction.
constexpr double kFootpathWeld = 0.01;

class FootpathNetwork {
 public:
  /// lines: each a polyline of at least 2 points (m).
  explicit FootpathNetwork(const std::vector<std::vector<Vec2>>& lines);

  std::size_t nodeCount() const { return nodes_.size(); }
  std::size_t edgeCount() const;
  const std::vector<Vec2>& nodes() const { return nodes_; }
  /// Every segment of the network, as pairs of node positions.
  std::vector<std::pair<Vec2, Vec2>> segments() const;

  /// The distance from p to the nearest point of the network (m).
  double distanceTo(const Vec2& p) const;

  /// Walks at `speed` (m/s) from the network point nearest `from` to the one nearest `to` along
  /// the shortest route (Dijkstra), starting at time 0; then stays. Throws std::invalid_argument
  /// when the two are on parts of the network that do not connect.
  std::vector<TimedPoint> route(const Vec2& from, const Vec2& to, double speed) const;

  /// Walks at `speed` from the network point nearest `from` for at least `duration` s: at every
  /// junction a branch drawn uniformly among those other than the one it came along (turning back
  /// only at a dead end), from the stream (seed, "footpath_walk", index).
  std::vector<TimedPoint> randomWalk(const Vec2& from, double speed, double duration,
                                     std::uint64_t seed, std::uint64_t index) const;

 private:
  struct Snap {
    int a = -1, b = -1;  // the edge's nodes
    double s = 0.0;      // fraction from a to b
    Vec2 p = Vec2::Zero();
  };
  Snap nearest(const Vec2& p) const;
  std::vector<Vec2> nodes_;
  std::vector<std::vector<int>> adjacent_;  // per node, its neighbours (sorted, each once)
};

}  // namespace canopy::world
