// NearbyUavs (agents/planning/nearby_uavs.h): every UAV within reach of a point is listed, by
// increasing index, against a brute-force distance test.
#include "agents/planning/nearby_uavs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/random.h"

namespace canopy::agents::planning {
namespace {

TEST(NearbyUavs, ListsEveryUavWithinReachInIndexOrder) {
  RandomStream rng(61, "nearby-uavs-test");
  for (int scene = 0; scene < 20; ++scene) {
    const double side = 50.0 + 400.0 * scene, reach = 14.2;
    std::vector<Vec2> position(120);
    std::vector<int> uavs;
    for (int i = 0; i < 120; ++i) {
      position[i] = Vec2(rng.uniform(-side, side), rng.uniform(0, side));
      if (i % 3 != 1) uavs.push_back(i);  // only some UAVs are indexed
    }
    NearbyUavs index;
    ASSERT_TRUE(index.build(uavs, position, reach));
    std::vector<int> listed;
    for (int q = 0; q < 200; ++q) {
      // Half the queries next to an indexed UAV, some exactly `reach` away.
      const Vec2 at = position[uavs[q % uavs.size()]];
      const Vec2 z = q % 2 == 0 ? Vec2(rng.uniform(-side, side), rng.uniform(-side, 2 * side))
                                : at + Vec2(q % 4 == 1 ? reach : rng.uniform(-reach, reach), 0.0);
      index.near(z, listed);
      EXPECT_TRUE(std::is_sorted(listed.begin(), listed.end()));
      for (const int i : uavs) {
        if ((position[i] - z).norm() > reach) continue;
        EXPECT_TRUE(std::binary_search(listed.begin(), listed.end(), i))
            << "scene " << scene << ", query " << q << ", UAV " << i;
      }
      for (const int i : listed) {  // only indexed UAVs, each at most two cells' diagonal away
        EXPECT_TRUE(std::binary_search(uavs.begin(), uavs.end(), i));
        EXPECT_LE((position[i] - z).norm(), 2.0 * std::sqrt(2.0) * reach + 1e-9);
      }
      // Exactly the indexed UAVs of the nine cells around z's: cells of side `reach` from the
      // corner of the indexed UAVs' box.
      Vec2 corner = position[uavs.front()];
      for (const int i : uavs) corner = corner.cwiseMin(position[i]);
      auto cell = [&](const Vec2& p) {
        const Vec2 d = (p - corner) / reach;
        return std::pair{std::floor(d.x()), std::floor(d.y())};
      };
      std::vector<int> nine;
      for (const int i : uavs) {
        const auto [x, y] = cell(position[i]);
        const auto [zx, zy] = cell(z);
        if (std::abs(x - zx) <= 1 && std::abs(y - zy) <= 1) nine.push_back(i);
      }
      EXPECT_EQ(listed, nine) << "scene " << scene << ", query " << q;
    }
  }
}

TEST(NearbyUavs, RefusesCellsTooSmallForTheSpread) {
  const std::vector<Vec2> position = {Vec2(0, 0), Vec2(1e6, 0)};
  const std::vector<int> uavs = {0, 1};
  NearbyUavs index;
  EXPECT_FALSE(index.build(uavs, position, 1e-6));  // 10¹² cells across
  EXPECT_TRUE(index.build(uavs, position, 1.0));
}

}  // namespace
}  // namespace canopy::agents::planning
