#include "sensing/sensor.h"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <cmath>

namespace canopy::sensing {
namespace {

using world::Path;
using world::TreeDef;

struct Bench {
  world::WorldDef def;
  std::vector<LabelId> labels;
  SensorDef sensor{{FootprintShape::rectangle, Vec2(40, 40), 0.0}, {0.3, 2.0}};
  SensingConfig config;

  void target(const Vec2& p) {
    def.targets.push_back({Path::constantVelocity(p, Vec2::Zero())});
    labels.push_back(1);
  }
  Scan scan(RandomStream& rng) {
    world::World w(def);
    SenseScratch scratch;
    Scan out;
    sense(w, w.snapshot(), 0, sensor, config, labels, rng, scratch, out);
    return out;
  }
};

Bench oneUavAtOrigin() {
  Bench b;
  b.def.aoi = {Vec2(-100, -100), Vec2(100, 100)};
  b.def.uavs.push_back({Vec2(0, 0), 0.0, world::YawMode::fixed, 5.0});
  return b;
}

TEST(Sense, CanopyAndLineOfSightDifferOnAHandBuiltLayout) {
  Bench b = oneUavAtOrigin();
  b.def.trees.push_back(TreeDef::disc(Vec2(5, 0), 1.0));
  b.target(Vec2(10, 0));   // 0: behind the tree, not under it
  b.target(Vec2(5, 0.5));  // 1: under the crown
  b.target(Vec2(0, 8));    // 2: in the open
  b.target(Vec2(30, 0));   // 3: outside the 40 x 40 footprint
  b.target(Vec2(5, 1.0));  // 4: on the rim: not strictly inside, but the ray cuts the crown
  RandomStream rng(1, "sensing");
  const Scan canopy = b.scan(rng);
  EXPECT_EQ(canopy.in_footprint, (std::vector<int>{0, 1, 2, 4}));
  EXPECT_EQ(canopy.visible, (std::vector<int>{0, 2, 4}));
  b.config.occlusion_model = OcclusionModel::line_of_sight;
  const Scan los = b.scan(rng);
  EXPECT_EQ(los.in_footprint, (std::vector<int>{0, 1, 2, 4}));
  EXPECT_EQ(los.visible, (std::vector<int>{2}));
}

TEST(Sense, ObservationNoiseHasCovarianceScaledR) {
  Bench b = oneUavAtOrigin();
  const Vec2 chi(6, -9);
  b.target(chi);
  b.config.truth_noise_scale = 0.5;
  world::World w(b.def);
  const world::WorldSnapshot snap = w.snapshot();
  const Mat2 R = 0.5 * rangeBearingCovariance(chi, Vec2(0, 0), b.sensor.quality);
  const Eigen::LLT<Mat2> llt(R);
  RandomStream rng(3, "sensing");
  SenseScratch scratch;
  Scan out;
  const int n = 20000;
  double chi2 = 0.0;
  for (int i = 0; i < n; ++i) {
    sense(w, snap, 0, b.sensor, b.config, b.labels, rng, scratch, out);
    ASSERT_EQ(out.observations.size(), 1u);
    const Observation& o = out.observations[0];
    EXPECT_EQ(o.truth, 0);
    chi2 += llt.matrixL().solve(o.z - chi).squaredNorm();
    // The filter's R is evaluated at the measurement, unscaled.
    ASSERT_TRUE(o.R.isApprox(rangeBearingCovariance(o.z, Vec2(0, 0), b.sensor.quality)));
  }
  EXPECT_NEAR(chi2, 2.0 * n, 5.0 * std::sqrt(4.0 * n));  // χ²(2n): mean 2n, variance 4n
}

TEST(Sense, DetectionProbabilityThinsVisibleTargets) {
  Bench b = oneUavAtOrigin();
  b.target(Vec2(3, 3));
  b.config.p_detect = 0.3;
  world::World w(b.def);
  RandomStream rng(4, "sensing");
  SenseScratch scratch;
  Scan out;
  const int n = 20000;
  int detections = 0;
  for (int i = 0; i < n; ++i) {
    sense(w, w.snapshot(), 0, b.sensor, b.config, b.labels, rng, scratch, out);
    EXPECT_EQ(out.visible.size(), 1u);
    detections += static_cast<int>(out.observations.size());
  }
  EXPECT_NEAR(detections / double(n), 0.3, 5 * std::sqrt(0.3 * 0.7 / n));
}

TEST(Sense, ClutterIsPoissonAndUniformOverTheFootprint) {
  Bench b = oneUavAtOrigin();
  b.def.uavs[0].yaw = 0.4;
  b.config.clutter_rate = 3.0;
  b.config.clutter_label = 2;
  world::World w(b.def);
  RandomStream rng(5, "sensing");
  SenseScratch scratch;
  Scan out;
  const Footprint f = footprintOf(w.snapshot(), 0, b.sensor);
  const int n = 5000;
  double count = 0.0;
  double mean_x = 0.0;
  for (int i = 0; i < n; ++i) {
    sense(w, w.snapshot(), 0, b.sensor, b.config, b.labels, rng, scratch, out);
    for (const Observation& o : out.observations) {
      EXPECT_EQ(o.truth, -1);
      EXPECT_EQ(o.label, 2);
      EXPECT_TRUE(f.contains(o.z));
      mean_x += o.z.x();
    }
    count += static_cast<double>(out.observations.size());
  }
  EXPECT_NEAR(count / n, 3.0, 5 * std::sqrt(3.0 / n));
  EXPECT_NEAR(mean_x / count, 0.0, 0.5);  // centred on the UAV
}

TEST(Sense, TreesAreSeenWhenTheirCentreIsInTheFootprintAndNeverHideThemselves) {
  Bench b = oneUavAtOrigin();
  b.def.trees.push_back(TreeDef::disc(Vec2(19, 0), 3.0));  // centre inside
  b.def.trees.push_back(TreeDef::disc(Vec2(21, 0), 3.0));  // centre outside, crown overlaps
  b.config.tree_radius_sigma = 0.2;
  world::World w(b.def);
  RandomStream rng(6, "sensing");
  SenseScratch scratch;
  Scan out;
  const int n = 20000;
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < n; ++i) {
    sense(w, w.snapshot(), 0, b.sensor, b.config, b.labels, rng, scratch, out);
    ASSERT_EQ(out.observations.size(), 1u);
    const Observation& o = out.observations[0];
    EXPECT_EQ(o.label, kTreeLabel);
    EXPECT_EQ(o.truth, 0);
    EXPECT_DOUBLE_EQ(o.radius_variance, 0.04);
    sum += o.radius;
    sum2 += o.radius * o.radius;
  }
  const double mean = sum / n;
  EXPECT_NEAR(mean, 3.0, 5 * 0.2 / std::sqrt(n));
  EXPECT_NEAR(std::sqrt(sum2 / n - mean * mean), 0.2, 0.01);
}

}  // namespace
}  // namespace canopy::sensing
