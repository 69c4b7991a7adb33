// Outline sharing (agents/fusion/outline_sharing.h): each member of a tree's cluster takes the
// outline of the linked member with the most observations (the first such, lowest member first),
// keeping its own when none has more. Worked by hand on a complete graph (its fast path) and on a
// path graph (the pairwise loop).
#include "agents/fusion/outline_sharing.h"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

namespace canopy::agents::fusion {
namespace {

// One cluster of five agents holding tree 0; member a's outline has `observations[a]`
// observations and is told apart by its vertex count a + 3.
std::vector<int> shared(const std::vector<int>& observations, double range) {
  const int n = static_cast<int>(observations.size());
  std::vector<std::vector<tracking::TreeTrack>> trees(n, std::vector<tracking::TreeTrack>(1));
  Clusters clusters;
  clusters.start = {0, n};
  clusters.keys.resize(1);
  std::vector<Vec2> positions;
  for (int a = 0; a < n; ++a) {
    clusters.members.push_back({a, 0, false});
    trees[a][0].outline.observations = observations[a];
    trees[a][0].outline.mean.vertices = a + 3;
    positions.emplace_back(10.0 * a, 0.0);
  }
  CommGraph graph;
  graph.build(positions, range);
  std::vector<tracking::TreeOutline> scratch;
  shareOutlines(trees, clusters, graph, scratch);
  std::vector<int> picked;  // whose outline each member holds now
  for (int a = 0; a < n; ++a) picked.push_back(trees[a][0].outline.mean.vertices - 3);
  return picked;
}

TEST(OutlineSharing, CompleteGraphTakesTheFirstWithTheMostUnlessOneHasAsMany) {
  const double everyone = std::numeric_limits<double>::infinity();
  // Most: 7, first held by member 1; member 3 has as many and keeps its own.
  EXPECT_EQ(shared({3, 7, 2, 7, 1}, everyone), (std::vector<int>{1, 1, 1, 3, 1}));
  // Member 0 has the most: everyone takes its outline.
  EXPECT_EQ(shared({9, 7, 2, 7, 1}, everyone), (std::vector<int>{0, 0, 0, 0, 0}));
  // All equal: everyone keeps its own.
  EXPECT_EQ(shared({4, 4, 4, 4, 4}, everyone), (std::vector<int>{0, 1, 2, 3, 4}));
}

TEST(OutlineSharing, PathGraphTakesFromNeighboursOnly) {
  // Range 10 m: a path 0 – 1 – 2 – 3 – 4. Member 0 sees 1 (7); 1 sees 0 and 2 (3, 2): keeps its
  // own; 2 sees 1 and 3 (7, 7): the first, 1; 3 sees 2 and 4: keeps; 4 sees 3 (7).
  EXPECT_EQ(shared({3, 7, 2, 7, 1}, 10.0), (std::vector<int>{1, 1, 1, 3, 3}));
}

}  // namespace
}  // namespace canopy::agents::fusion
