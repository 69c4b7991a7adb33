// Rendered coverage against closed-form areas of hand-built footprint layouts.
//
// A pixel is counted when its centre lies in a footprint (GL's rasterisation rule), so only
// pixels that the boundary crosses can be misclassified. Along an edge the signed errors of
// those pixels cancel except for at most half a pixel's width per unit of length (the worst
// case is an axis-aligned edge through a row of pixel centres), so for a boundary of length L
// the area error is below L·a/2 + a² per corner, with a the pixel size. The tests allow
// L·a + 4a² per shape: twice the edge term, and every shape's corners.
#include "render/coverage.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace canopy::render {
namespace {

using sensing::Footprint;
using sensing::FootprintDef;
using sensing::FootprintShape;

constexpr double kPi = std::numbers::pi;
const Aabb kAoi{Vec2(0, 0), Vec2(100, 80)};  // m
constexpr ImageSize kMask{500, 400};         // 0.2 m per pixel

Footprint rectangle(const Vec2& centre, double w, double h, double yaw) {
  FootprintDef def;
  def.size = Vec2(w, h);
  return Footprint::place(def, centre, yaw);
}

Footprint disc(const Vec2& centre, double r) {
  FootprintDef def;
  def.shape = FootprintShape::disc;
  def.radius = r;
  return Footprint::place(def, centre, 0.0);
}

// Area of the intersection of two discs at distance d (the lens).
double lens(double r1, double r2, double d) {
  return r1 * r1 * std::acos((d * d + r1 * r1 - r2 * r2) / (2 * d * r1)) +
         r2 * r2 * std::acos((d * d + r2 * r2 - r1 * r1) / (2 * d * r2)) -
         0.5 * std::sqrt((-d + r1 + r2) * (d + r1 - r2) * (d - r1 + r2) * (d + r1 + r2));
}

struct Expected {
  double covered;           // m², area of the union within the AOI
  double multi;             // m², area covered twice or more
  double covered_boundary;  // m, length bound of the union's boundary
  double multi_boundary;    // m
  int shapes;
};

void expectAreas(const CoverageCounts& counts, const CoverageCounter& counter, const Expected& e) {
  const double a = counter.viewport().pixel_size, a2 = counter.pixelArea();
  const double corner = 4.0 * a2 * e.shapes;
  EXPECT_NEAR(static_cast<double>(counts.covered_px) * a2, e.covered,
              e.covered_boundary * a + corner);
  EXPECT_NEAR(static_cast<double>(counts.multi_px) * a2, e.multi, e.multi_boundary * a + corner);
  EXPECT_EQ(counts.aoi_px, 500 * 400);
}

TEST(Coverage, RotatedRectangleMatchesItsArea) {
  CoverageCounter counter(kAoi, kMask);
  const Footprint f = rectangle(Vec2(50, 40), 20, 14, 0.3);
  const std::vector<Vec2> targets = {Vec2(50, 40), Vec2(80, 70), Vec2(-5, 10)};
  const CoverageCounts c = counter.count(std::span(&f, 1), targets);
  expectAreas(c, counter, {280.0, 0.0, 68.0, 0.0, 1});
  EXPECT_EQ(c.target_covered, (std::vector<std::uint8_t>{1, 0, 0}));
  EXPECT_NEAR(c.coveredFraction(), 280.0 / 8000.0, 68.0 * 0.2 / 8000.0);
}

TEST(Coverage, OverlappingRectanglesCountTheUnionAndTheOverlap) {
  CoverageCounter counter(kAoi, kMask);
  // x: [20, 40] and [30, 50]; y: [33, 47] and [37, 51] → overlap 10 × 10 m.
  const std::vector<Footprint> fs = {rectangle(Vec2(30, 40), 20, 14, 0.0),
                                     rectangle(Vec2(40, 44), 20, 14, 0.0)};
  const std::vector<Vec2> targets = {Vec2(35, 42), Vec2(22, 35), Vec2(48, 49.5)};
  const CoverageCounts c = counter.count(fs, targets);
  expectAreas(c, counter, {560.0 - 100.0, 100.0, 136.0, 40.0, 2});
  EXPECT_EQ(c.target_covered, (std::vector<std::uint8_t>{1, 1, 1}));
}

TEST(Coverage, OverlappingDiscsMatchTheLensFormula) {
  CoverageCounter counter(kAoi, kMask);
  const double r1 = 12.0, r2 = 9.0, d = 15.0;
  const std::vector<Footprint> fs = {disc(Vec2(40, 40), r1), disc(Vec2(40 + d, 40), r2)};
  const CoverageCounts c = counter.count(fs, std::vector<Vec2>{Vec2(40, 51.5), Vec2(40, 52.5)});
  const double boundary = 2 * kPi * (r1 + r2);  // bounds both the union's and the lens's
  expectAreas(
      c, counter,
      {kPi * (r1 * r1 + r2 * r2) - lens(r1, r2, d), lens(r1, r2, d), boundary, boundary, 2});
  EXPECT_EQ(c.target_covered, (std::vector<std::uint8_t>{1, 0}));  // 0.5 m inside, 0.5 m outside
}

TEST(Coverage, CountsOnlyTheAoi) {
  CoverageCounter counter(kAoi, kMask);
  // x ∈ [85, 105]: 15 m of its 20 m lie in the AOI.
  const Footprint f = rectangle(Vec2(95, 40), 20, 14, 0.0);
  const CoverageCounts c =
      counter.count(std::span(&f, 1), std::vector<Vec2>{Vec2(99, 40), Vec2(102, 40)});
  expectAreas(c, counter, {15.0 * 14.0, 0.0, 58.0, 0.0, 1});
  EXPECT_EQ(c.target_covered, (std::vector<std::uint8_t>{1, 0}));
}

TEST(Coverage, DisjointDiscAndRectangleAdd) {
  CoverageCounter counter(kAoi, kMask);
  const std::vector<Footprint> fs = {disc(Vec2(20, 20), 10.0),
                                     rectangle(Vec2(70, 50), 30, 16, -0.8)};
  const CoverageCounts c = counter.count(fs, {});
  expectAreas(c, counter, {kPi * 100.0 + 480.0, 0.0, 2 * kPi * 10.0 + 92.0, 0.0, 2});
  EXPECT_TRUE(c.target_covered.empty());
}

TEST(Coverage, AspectOfTheMaskDoesNotChangeTheAoiPixels) {
  // 100 × 80 m in 500 × 500 px: still 0.2 m per pixel, 500 × 400 pixels of AOI.
  CoverageCounter counter(kAoi, {500, 500});
  const Footprint f = rectangle(Vec2(50, 40), 20, 14, 0.3);
  const CoverageCounts c = counter.count(std::span(&f, 1), {});
  expectAreas(c, counter, {280.0, 0.0, 68.0, 0.0, 1});
}

TEST(Coverage, FinerMasksAreCloser) {
  const Footprint f = disc(Vec2(41.3, 37.9), 11.7);
  const double area = kPi * 11.7 * 11.7;
  double previous = 1e9;
  for (const ImageSize size : {ImageSize{100, 80}, ImageSize{400, 320}, ImageSize{1600, 1280}}) {
    CoverageCounter counter(kAoi, size);
    const double error = std::abs(
        static_cast<double>(counter.count(std::span(&f, 1), {}).covered_px) * counter.pixelArea() -
        area);
    EXPECT_LT(error, previous);
    previous = error;
  }
  EXPECT_LT(previous, 0.1);  // m², at 1/16 m per pixel (the bound L·a is 4.6 m²)
}

TEST(Coverage, CsvRowsFollowTheHeader) {
  const std::vector<std::string> names = {"T1", "T2"};
  EXPECT_EQ(coverageCsvHeader(names),
            "step,t,covered_px,visible_px,multi_px,aoi_px,covered_fraction,visible_fraction,"
            "covered_T1,covered_T2,visible_T1,visible_T2");
  CoverageCounts c;
  c.covered_px = 250;
  c.visible_px = 200;
  c.multi_px = 10;
  c.aoi_px = 1000;
  c.target_covered = {1, 1};
  c.target_visible = {0, 1};
  EXPECT_EQ(coverageCsvRow(12, 2.4, c), "12,2.4,250,200,10,1000,0.250000,0.200000,1,1,0,1");
}

// A 20 × 14 m footprint centred on its UAV's ground point (50, 40), a crown of radius 3 m at the
// centre: looking down, the visible area is the footprint minus the crown, 280 − 9π m².
TEST(Coverage, VisibleIsTheFootprintMinusTheCrowns) {
  CoverageCounter counter(kAoi, kMask, {world::TreeDef::disc(Vec2(50, 40), 3.0)});
  const Footprint f = rectangle(Vec2(50, 40), 20, 14, 0.0);
  const std::vector<Vec2> targets = {Vec2(50, 40), Vec2(44, 40), Vec2(59, 40)};
  const CoverageCounts c = counter.count(std::span(&f, 1), targets);
  const double a = counter.viewport().pixel_size, a2 = counter.pixelArea();
  EXPECT_NEAR(static_cast<double>(c.covered_px) * a2, 280.0, 68.0 * a + 4 * a2);
  EXPECT_NEAR(static_cast<double>(c.visible_px) * a2, 280.0 - 9.0 * kPi,
              (68.0 + 6.0 * kPi) * a + 8 * a2);
  EXPECT_EQ(c.target_covered, (std::vector<std::uint8_t>{1, 1, 1}));
  EXPECT_EQ(c.target_visible, (std::vector<std::uint8_t>{0, 1, 1}));
}

// Line of sight from the ground point A = (50, 40) past a crown of radius r = 2 at distance
// D = 5 (centre (55, 40)): the hidden region is the cone tangent to the crown, cut at the
// footprint's edge x = 60 (d = 10), less the part in front of the crown. With sin α = r/D,
// the cone's triangle is d² tan α; the kite A–T1–C–T2 (tangent points T) is L·r with
// L = √(D² − r²), and the crown's sector inside the kite r²·acos(r/D). Hidden:
// d² tan α − (L r − r² acos(r/D)) = 200/√21 − 2√21 + 4 acos 0.4 ≈ 39.12 m².
TEST(Coverage, LineOfSightShadowsAreNotVisible) {
  CoverageCounter counter(kAoi, kMask, {world::TreeDef::disc(Vec2(55, 40), 2.0)});
  const Footprint f = rectangle(Vec2(50, 40), 20, 14, 0.0);
  const std::vector<Vec2> targets = {Vec2(44, 40), Vec2(59, 40), Vec2(59, 46)};
  const CoverageCounts c =
      counter.count(std::span(&f, 1), targets, sensing::OcclusionModel::line_of_sight);
  const double hidden = 200.0 / std::sqrt(21.0) - 2.0 * std::sqrt(21.0) + 4.0 * std::acos(0.4);
  const double a = counter.viewport().pixel_size, a2 = counter.pixelArea();
  // Boundary of the hidden region: two rays of 10/cos α and the near arc (< 2πr).
  const double boundary = 68.0 + 2.0 * 10.0 / std::cos(std::asin(0.4)) + 4.0 * kPi;
  EXPECT_NEAR(static_cast<double>(c.visible_px) * a2, 280.0 - hidden, boundary * a + 8 * a2);
  EXPECT_EQ(c.target_visible, (std::vector<std::uint8_t>{1, 0, 1}));
  // Under the canopy model the same crown hides only itself.
  const CoverageCounts down = counter.count(std::span(&f, 1), targets);
  EXPECT_NEAR(static_cast<double>(down.visible_px) * a2, 280.0 - 4.0 * kPi,
              (68.0 + 4.0 * kPi) * a + 8 * a2);
  EXPECT_EQ(down.target_visible, (std::vector<std::uint8_t>{1, 1, 1}));
}

// Crown volumes (issue 53): a crown of radius r = 3 m from 3 m to T = 9 m at (50, 40), under a
// camera at H = 20 m straight above it. A head (1.7 m) at distance d > r from the centre is hidden
// while the sight line leaves the crown's outline (at s = r/d) below its top:
// H − (H − 1.7) r/d < T ⇔ d < R = r (H − 1.7)/(H − T) = 3 · 18.3/11 = 4.991 m, and every head
// under the crown is hidden. Visible: 280 − πR² ≈ 201.7 m². A camera at 2.5 m, below the base,
// sees under the crown: everything is visible.
TEST(Coverage, VolumesHideByTheSightLineFromTheCameraHeight) {
  world::TreeDef crown = world::TreeDef::disc(Vec2(50, 40), 3.0);
  crown.base = 3.0;
  crown.top = 9.0;
  CoverageCounter counter(kAoi, kMask, {crown});
  const Footprint f = rectangle(Vec2(50, 40), 20, 14, 0.0);
  const std::vector<Vec2> targets = {Vec2(50, 40), Vec2(54, 40), Vec2(56, 40)};
  const double high = 20.0, low = 2.5;
  const CoverageCounts c = counter.count(std::span(&f, 1), targets,
                                         sensing::OcclusionModel::volumes, std::span(&high, 1));
  const double R = 3.0 * (20.0 - 1.7) / (20.0 - 9.0);
  const double a = counter.viewport().pixel_size, a2 = counter.pixelArea();
  EXPECT_NEAR(static_cast<double>(c.visible_px) * a2, 280.0 - kPi * R * R,
              (68.0 + 2.0 * kPi * R) * a + 8 * a2);
  EXPECT_EQ(c.target_visible, (std::vector<std::uint8_t>{0, 0, 1}));  // d = 0, 4 < R, 6 > R
  const CoverageCounts under = counter.count(std::span(&f, 1), targets,
                                             sensing::OcclusionModel::volumes, std::span(&low, 1));
  EXPECT_EQ(under.visible_px, under.covered_px);
  EXPECT_EQ(under.target_visible, (std::vector<std::uint8_t>{1, 1, 1}));
}

}  // namespace
}  // namespace canopy::render
