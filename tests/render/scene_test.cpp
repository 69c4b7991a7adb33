// Scene building without GL: the projection, the 2-σ ellipse, footprint corners, trails, and
// what buildScene puts in a frame.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "render/scene_builder.h"
#include "render/trails.h"
#include "render/viewport.h"

namespace canopy::render {
namespace {

TEST(Viewport, FitKeepsTheAspectAndCentresTheView) {
  // 120 m × 80 m into 300 × 300 px: 0.4 m/px, the view 300 × 200 px, 50 px above and below.
  const Viewport v = Viewport::fit({Vec2(-60, -40), Vec2(60, 40)}, {300, 300});
  EXPECT_DOUBLE_EQ(v.pixel_size, 0.4);
  EXPECT_TRUE(v.toPixel(Vec2(-60, -40)).isApprox(Vec2(0, 250)));
  EXPECT_TRUE(v.toPixel(Vec2(60, 40)).isApprox(Vec2(300, 50)));
  EXPECT_TRUE(v.toWorld(v.toPixel(Vec2(12.5, -3.25))).isApprox(Vec2(12.5, -3.25)));
}

TEST(Viewport, ParsesSizesAndRejectsBadOnes) {
  EXPECT_EQ(parseImageSize("800x600"), (ImageSize{800, 600}));
  EXPECT_EQ(parseImageSize("16x4096"), (ImageSize{16, 4096}));
  for (const char* bad : {"0x5", "800", "x600", "800x", "-8x8", "15x100", "16x4097", "800x600x2",
                          "8.5x10", " 800x600", "800X600", ""}) {
    EXPECT_FALSE(parseImageSize(bad).has_value()) << bad;
  }
}

TEST(Viewport, FitSizeFollowsTheLongerSideAndRoundsToEven) {
  EXPECT_EQ(fitSize({Vec2(0, 0), Vec2(120, 80)}, 800), (ImageSize{800, 534}));  // 533.3 → 534
  EXPECT_EQ(fitSize({Vec2(0, 0), Vec2(50, 100)}, 800), (ImageSize{400, 800}));
}

TEST(CovarianceEllipse, PointsLieOnTheTwoSigmaContourCounterClockwise) {
  Mat2 P;
  P << 4.0, 1.5, 1.5, 2.0;
  const Vec2 c(3.0, -2.0);
  const std::vector<Vec2> points = covarianceEllipse(c, P, 64);
  ASSERT_EQ(points.size(), 64u);
  for (const Vec2& p : points) {
    const Vec2 d = p - c;
    EXPECT_NEAR(d.dot(P.ldlt().solve(d)), 4.0, 1e-9);  // Mahalanobis² = 2²
  }
  // The inscribed 64-gon's area is (64/2π)·sin(2π/64) = 99.8 % of the ellipse's π·2σ₁·2σ₂.
  double twice_area = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec2& a = points[i];
    const Vec2& b = points[(i + 1) % points.size()];
    twice_area += a.x() * b.y() - b.x() * a.y();
  }
  const double ellipse = std::numbers::pi * 4.0 * std::sqrt(P.determinant());
  EXPECT_NEAR(0.5 * twice_area / ellipse,
              64.0 / (2 * std::numbers::pi) * std::sin(2 * std::numbers::pi / 64), 1e-9);
  Mat2 bad = P;
  bad(0, 1) = std::nan("");
  EXPECT_TRUE(covarianceEllipse(c, bad).empty());
}

TEST(FootprintCorners, AreTheRotatedRectanglesCorners) {
  sensing::FootprintDef def;
  def.size = Vec2(20.0, 14.0);
  const sensing::Footprint f = sensing::Footprint::place(def, Vec2(5, 5), std::numbers::pi / 2);
  const std::vector<Vec2> corners = footprintCorners(f);
  ASSERT_EQ(corners.size(), 4u);
  // Heading +y: 20 m along y, 14 m across (along x).
  EXPECT_TRUE(corners[0].isApprox(Vec2(5 - 7, 5 + 10)));
  for (const Vec2& p : corners) EXPECT_TRUE(f.contains(p));
  def.shape = sensing::FootprintShape::disc;
  EXPECT_TRUE(footprintCorners(sensing::Footprint::place(def, Vec2(0, 0), 0.0)).empty());
}

TEST(FootprintCorners, ASectorIsItsApexThenItsArcAndCrownsCutWhatItSees) {
  sensing::FootprintDef def;
  def.shape = sensing::FootprintShape::sector;
  def.radius = 10.0;
  def.angle = std::numbers::pi / 2;
  const sensing::Footprint f = sensing::Footprint::place(def, Vec2(0, 0), 0.0);
  const std::vector<Vec2> outline = footprintCorners(f);
  // The apex, then 91 arc points 1° apart from −45° to +45°.
  ASSERT_EQ(outline.size(), 92u);
  EXPECT_EQ(outline.front(), Vec2(0, 0));
  EXPECT_TRUE(outline[1].isApprox(10.0 / std::sqrt(2.0) * Vec2(1, -1)));
  EXPECT_TRUE(outline[46].isApprox(Vec2(10, 0)));
  for (const Vec2& p : outline) EXPECT_TRUE(f.contains(p));
  // A crown of radius 1 at (5, 0): the ray along the heading stops where it enters it, at x = 4;
  // the ray at 20° passes 5 sin 20° = 1.71 m from its centre and is not cut.
  const std::vector<world::TreeDef> trees{world::TreeDef::disc({5, 0}, 1.0)};
  const std::vector<Vec2> seen = visibleSector(f, trees);
  ASSERT_EQ(seen.size(), outline.size());
  EXPECT_TRUE(seen[46].isApprox(Vec2(4, 0)));
  EXPECT_TRUE(seen[66].isApprox(outline[66]));
  EXPECT_EQ(seen.front(), outline.front());
}

TEST(TargetTrails, KeepTheLastSecondsOnly) {
  TargetTrails trails(1.0);
  for (int k = 0; k <= 10; ++k) {
    world::WorldSnapshot s;
    s.step = k;
    s.time = 0.25 * k;
    s.targets.push_back({Vec2(k, 0), Vec2::Zero()});
    trails.add(s);
  }
  // t = 2.5 s: the points at t ≥ 1.5 s are k = 6..10.
  const std::vector<Vec2>& trail = trails.trail(0);
  ASSERT_EQ(trail.size(), 5u);
  EXPECT_EQ(trail.front(), Vec2(6, 0));
  EXPECT_EQ(trail.back(), Vec2(10, 0));
  EXPECT_TRUE(trails.trail(1).empty());
}

// A small world with every kind of thing a frame shows.
struct Fixture {
  SceneModel model;
  world::WorldSnapshot truth;
  std::vector<agents::AgentBelief> beliefs;
  TargetTrails trails;

  Fixture() {
    model.title = "unit";
    model.aoi = {Vec2(-50, -30), Vec2(50, 30)};
    model.trees = {world::TreeDef::disc(Vec2(-20, 10), 3.0),
                   world::TreeDef::polygon({Vec2(20, -10), Vec2(25, -10), Vec2(25, -5)})};
    sensing::SensorDef rectangle, disc;
    rectangle.footprint.size = Vec2(20, 14);
    disc.footprint.shape = sensing::FootprintShape::disc;
    disc.footprint.radius = 12;
    model.sensors = {rectangle, disc};
    model.uav_names = {"alpha", "beta"};
    truth.step = 7;
    truth.time = 1.5;
    truth.uavs = {{Vec2(-30, 0), Vec2::Zero(), 0.3}, {Vec2(30, 5), Vec2::Zero(), 0.0}};
    truth.targets = {{Vec2(-28, 1), Vec2::Zero()}};
    trails.add(truth);
    agents::AgentBelief& b = beliefs.emplace_back();
    agents::TrackEstimate& track = b.tracks.emplace_back();
    track.belief.x << -27.5, 1.2, 0.0, 0.0;
    track.confirmed = true;
    agents::TreeEstimate& tree = b.trees.emplace_back();
    tree.belief.x << -19.0, 10.5, 2.5;
    b.planned_path = {Vec2(-28, 0), Vec2(-26, 0)};
    beliefs.emplace_back();
  }
};

template <class T>
std::vector<T> all(const std::vector<Primitive>& list) {
  std::vector<T> out;
  for (const Primitive& p : list) {
    if (const T* t = std::get_if<T>(&p)) out.push_back(*t);
  }
  return out;
}

TEST(BuildScene, DrawsTreesFootprintsBeliefsTargetsAndUavs) {
  const Fixture f;
  const Scene scene = buildScene(f.model, f.truth, f.beliefs, f.trails, {800, 534});
  const auto discs = all<Disc>(scene.world);
  const auto polygons = all<Polygon>(scene.world);
  const auto rings = all<Ring>(scene.world);
  const auto lines = all<Polyline>(scene.world);
  const auto markers = all<Marker>(scene.world);

  const auto has_disc = [&](const Vec2& c, double r, Rgba fill) {
    return std::any_of(discs.begin(), discs.end(), [&](const Disc& d) {
      return d.centre == c && d.radius == r && d.fill == fill;
    });
  };
  EXPECT_TRUE(has_disc(Vec2(-20, 10), 3.0, palette::kTreeFill));
  EXPECT_TRUE(has_disc(Vec2(30, 5), 12.0, withAlpha(uavColour(1), 60)));  // beta's footprint
  const auto footprint = std::find_if(polygons.begin(), polygons.end(), [](const Polygon& p) {
    return p.fill == withAlpha(uavColour(0), 60);
  });
  ASSERT_NE(footprint, polygons.end());
  const sensing::Footprint placed = sensing::footprintOf(f.truth, 0, f.model.sensors[0]);
  EXPECT_EQ(footprint->vertices, footprintCorners(placed));
  EXPECT_TRUE(std::any_of(polygons.begin(), polygons.end(), [](const Polygon& p) {
    return p.fill == palette::kTreeFill && p.vertices.size() == 3;
  }));
  // The occlusion-map estimate, the plan from the UAV, the 2-σ ellipse.
  EXPECT_TRUE(std::any_of(rings.begin(), rings.end(), [](const Ring& r) {
    return r.centre == Vec2(-19, 10.5) && r.radius == 2.5;
  }));
  EXPECT_TRUE(std::any_of(lines.begin(), lines.end(), [](const Polyline& l) {
    return !l.closed && l.points.size() == 3 && l.points[0] == Vec2(-30, 0);
  }));
  EXPECT_TRUE(std::any_of(lines.begin(), lines.end(),
                          [](const Polyline& l) { return l.closed && l.points.size() == 36; }));
  const auto marker = [&](MarkerShape shape, const Vec2& at) {
    return std::find_if(markers.begin(), markers.end(),
                        [&](const Marker& m) { return m.shape == shape && m.at.isApprox(at); });
  };
  EXPECT_NE(marker(MarkerShape::cross, Vec2(-27.5, 1.2)), markers.end());
  EXPECT_NE(marker(MarkerShape::dot, Vec2(-28, 1)), markers.end());
  const auto alpha = marker(MarkerShape::arrow, Vec2(-30, 0));
  ASSERT_NE(alpha, markers.end());
  EXPECT_DOUBLE_EQ(alpha->heading, 0.3);
  // Names and the time stamp.
  std::string text;
  for (const Text& t : all<Text>(scene.world)) text += t.text + "|";
  for (const Text& t : all<Text>(scene.overlay)) text += t.text + "|";
  for (const char* expected :
       {"alpha|", "beta|", "T1|", "t = 1.50 s", "k = 7", "tree|", "occlusion map|"}) {
    EXPECT_NE(text.find(expected), std::string::npos) << expected << " in " << text;
  }
}

TEST(BuildScene, AUavAtAnAltitudeIsLabelledWithItAndItsPitchedFootprintIsATrapezoid) {
  // Issue 53: "alpha" at 40 m with a camera pitched 45° (vfov = hfov = 60°): its label carries the
  // altitude and its footprint is the four corners of sensing::groundFootprint, the near edge
  // 40 tan 15° ahead of it and the far edge 40 tan 75°.
  Fixture f;
  f.model.sensors[0].camera =
      sensing::cameraWithAngles(std::numbers::pi / 3, std::numbers::pi / 3, std::numbers::pi / 4);
  f.truth.uavs[0].z = 40.0;
  f.truth.uavs[0].yaw = 0.0;
  const Scene scene = buildScene(f.model, f.truth, f.beliefs, f.trails, {800, 534});
  bool labelled = false, plain = false;
  for (const Text& t : all<Text>(scene.world)) {
    labelled = labelled || t.text == "alpha 40 m";
    plain = plain || t.text == "beta";  // no altitude: the plain name
  }
  EXPECT_TRUE(labelled);
  EXPECT_TRUE(plain);
  const double near = 40 * std::tan(std::numbers::pi / 12), far = 40 * std::tan(5 * std::numbers::pi / 12);
  bool trapezoid = false;
  for (const Polygon& p : all<Polygon>(scene.world)) {
    if (p.vertices.size() != 4) continue;
    double lo = 1e9, hi = -1e9;
    for (const Vec2& q : p.vertices) lo = std::min(lo, q.x()), hi = std::max(hi, q.x());
    trapezoid = trapezoid || (std::abs(lo - (-30 + near)) < 1e-9 && std::abs(hi - (-30 + far)) < 1e-9);
  }
  EXPECT_TRUE(trapezoid);
}

TEST(BuildScene, FitsTheAoiAboveTheLegendWithItsAspect) {
  const Fixture f;
  const ImageSize size{640, 640};
  const Scene scene = buildScene(f.model, f.truth, f.beliefs, f.trails, size);
  const Vec2 lo = scene.viewport.toPixel(f.model.aoi.lo),
             hi = scene.viewport.toPixel(f.model.aoi.hi);
  EXPECT_NEAR((hi.x() - lo.x()) / (lo.y() - hi.y()), 100.0 / 60.0, 1e-9);
  EXPECT_GT(lo.x(), 0.0);
  EXPECT_LT(hi.x(), size.width);
  // The legend band: an overlay polygon reaching the bottom edge; the AOI ends above it.
  double band_top = size.height;
  for (const Polygon& p : all<Polygon>(scene.overlay)) {
    if (p.vertices[2].y() == size.height) band_top = std::min(band_top, p.vertices[0].y());
  }
  EXPECT_LT(band_top, size.height);
  EXPECT_LT(lo.y(), band_top);
}

// The legend and the projection depend on the model only: a step before the agents hold any
// belief has the same band, the same viewport and the same entries as one after.
TEST(BuildScene, TheLegendAndTheViewDoNotChangeFromStepToStep) {
  Fixture f;
  f.model.plans = true;
  const Scene before = buildScene(f.model, f.truth, {}, f.trails, {800, 534});
  const Scene after = buildScene(f.model, f.truth, f.beliefs, f.trails, {800, 534});
  EXPECT_EQ(before.viewport.top_left, after.viewport.top_left);
  EXPECT_EQ(before.viewport.pixel_size, after.viewport.pixel_size);
  std::vector<std::string> a, b;
  for (const Text& t : all<Text>(before.overlay)) a.push_back(t.text);
  for (const Text& t : all<Text>(after.overlay)) b.push_back(t.text);
  EXPECT_EQ(a, b);
  EXPECT_NE(std::find(a.begin(), a.end(), "estimate, 2-sigma"), a.end());
  EXPECT_NE(std::find(a.begin(), a.end(), "plan"), a.end());
  EXPECT_TRUE(all<Ring>(before.world).empty());
}

// The red ring of an agent in contact has a legend entry exactly when some agent has a body.
TEST(BuildScene, TheLegendExplainsTheContactRingWhenAnAgentHasABody) {
  Fixture f;
  auto labels = [&f] {
    std::vector<std::string> out;
    const Scene scene = buildScene(f.model, f.truth, f.beliefs, f.trails, {800, 534});
    for (const Text& t : all<Text>(scene.overlay)) out.push_back(t.text);
    return out;
  };
  const std::vector<std::string> without = labels();
  EXPECT_EQ(std::find(without.begin(), without.end(), "contact"), without.end());
  f.model.contacts = true;
  const std::vector<std::string> with = labels();
  EXPECT_NE(std::find(with.begin(), with.end(), "contact"), with.end());
  EXPECT_EQ(with.size(), without.size() + 1);
}

// A view replaces the AOI as the fitted region: a 20 × 10 m box on 800 px with the default
// 4 % margin (0.8 m each side) is 21.6 m wide, so a pixel is 21.6/800 m.
TEST(BuildScene, TheViewIsWhatEveryFrameShows) {
  Fixture f;
  f.model.view = Aabb{Vec2(-40, -5), Vec2(-20, 5)};
  SceneOptions options;
  options.legend = false;
  const Scene scene = buildScene(f.model, f.truth, f.beliefs, f.trails, {800, 600}, options);
  EXPECT_NEAR(scene.viewport.pixel_size, 21.6 / 800.0, 1e-12);
  EXPECT_NEAR(scene.viewport.toPixel(Vec2(-30, 0)).x(), 400.0, 1e-9);
}

TEST(ScaleBar, TheLargestOneTwoOrFiveBelowAQuarterOfTheWidth) {
  EXPECT_DOUBLE_EQ(scaleBarLength(120.0), 20.0);  // a quarter is 30 → 20
  EXPECT_DOUBLE_EQ(scaleBarLength(38.0), 5.0);    // 9.5 → 5
  EXPECT_DOUBLE_EQ(scaleBarLength(40.0), 10.0);   // exactly 10
  EXPECT_DOUBLE_EQ(scaleBarLength(7.9), 1.0);     // 1.975 → 1
  EXPECT_DOUBLE_EQ(scaleBarLength(3000.0), 500.0);
  EXPECT_EQ(scaleBarLabel(20.0), "20 m");
  EXPECT_EQ(scaleBarLabel(2000.0), "2 km");
  EXPECT_EQ(scaleBarLabel(0.5), "0.5 m");
  const Fixture f;
  const Scene scene = buildScene(f.model, f.truth, f.beliefs, f.trails, {800, 534});
  bool found = false;
  for (const Text& t : all<Text>(scene.overlay)) found = found || t.text == "20 m";
  EXPECT_TRUE(found);  // the AOI with its margin is 108 m wide: a quarter is 27 → 20 m
}

// Two targets and two UAVs on one spot: four names, no two boxes overlapping.
TEST(BuildScene, NamesDoNotOverlap) {
  Fixture f;
  f.truth.targets = {{Vec2(0, 0), Vec2::Zero()}, {Vec2(0.1, 0), Vec2::Zero()}};
  f.truth.uavs = {{Vec2(0, 0.1), Vec2::Zero(), 0.0}, {Vec2(0.1, 0.1), Vec2::Zero(), 0.0}};
  f.model.target_names = {"I", "II"};
  const Scene scene = buildScene(f.model, f.truth, {}, f.trails, {800, 534});
  std::vector<Aabb> boxes;
  for (const Text& t : all<Text>(scene.world)) {
    const Vec2 lo = scene.viewport.toPixel(t.at) + t.offset_px;
    boxes.push_back({lo, lo + Vec2(textWidthPx(t.text, t.scale), 9.0 * t.scale)});
  }
  ASSERT_EQ(boxes.size(), 4u);
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    for (std::size_t j = i + 1; j < boxes.size(); ++j) {
      const bool overlap = boxes[i].lo.x() < boxes[j].hi.x() && boxes[j].lo.x() < boxes[i].hi.x() &&
                           boxes[i].lo.y() < boxes[j].hi.y() && boxes[j].lo.y() < boxes[i].hi.y();
      EXPECT_FALSE(overlap) << i << " and " << j;
    }
  }
}

// A crowded frame: three targets walking side by side with their trails, a UAV over each, and
// discs of crown all around, one right where a name goes by default and one under the title's
// usual corner. Every name and the title box must cover no marker, trail or crown, checked here by
// a second method: points sampled along each trail and each crown's rim, and the markers' boxes.
TEST(BuildScene, NamesAndTitleStayClearOfMarkersTrailsAndTrees) {
  Fixture f;
  f.model.trees.clear();
  for (double x = -45; x <= 45; x += 9) {
    for (double y = -25; y <= 25; y += 10)
      f.model.trees.push_back(world::TreeDef::disc({x, y}, 1.2));
  }
  f.model.trees.push_back(world::TreeDef::disc({-3.5, 4.5}, 1.5));  // above right of T1's dot
  f.model.trees.push_back(world::TreeDef::disc({-47, 28}, 2.0));    // the title's usual corner
  f.model.target_names = {"T1", "T2", "T3"};
  f.model.uav_names = {"alpha", "beta", "gamma"};
  f.model.sensors.push_back(f.model.sensors.front());
  TargetTrails trails;
  for (int k = 0; k <= 10; ++k) {  // 2 m/s east for 10 s
    f.truth.time = k;
    f.truth.targets = {{Vec2(-25 + 2 * k, 2), Vec2::Zero()},
                       {Vec2(-25 + 2 * k, -2), Vec2::Zero()},
                       {Vec2(-25 + 2 * k, -6), Vec2::Zero()}};
    trails.add(f.truth);
  }
  f.truth.uavs = {{Vec2(-5, 2.5), Vec2::Zero(), 0.0},
                  {Vec2(-5, -2.5), Vec2::Zero(), 0.0},
                  {Vec2(-5, -6.5), Vec2::Zero(), 0.0}};
  const Scene scene = buildScene(f.model, f.truth, {}, trails, {800, 534});
  const Viewport& v = scene.viewport;
  const double unit = 1.0;  // z.u at 800 px: text scale 2, u = 1

  std::vector<Aabb> labels;
  for (const Text& t : all<Text>(scene.world)) {
    const Vec2 lo = v.toPixel(t.at) + t.offset_px;
    labels.push_back({lo, lo + Vec2(textWidthPx(t.text, t.scale), 9.0 * t.scale)});
  }
  ASSERT_EQ(labels.size(), 6u);
  for (const Text& t : all<Text>(scene.overlay)) {  // the title panel: the panel round "unit …"
    if (t.text.rfind("unit", 0) != 0) continue;
    for (const Polygon& p : all<Polygon>(scene.overlay)) {
      const Aabb panel{p.vertices[0], p.vertices[2]};
      if (p.fill == palette::kPanel && panel.contains(t.at)) labels.push_back(panel);
    }
  }
  ASSERT_EQ(labels.size(), 7u);
  EXPECT_GT(labels.back().lo.x(), 50.0);  // the tree pushed the title off the top-left corner

  const auto inside = [](const Aabb& b, const Vec2& p) {
    return p.x() > b.lo.x() && p.x() < b.hi.x() && p.y() > b.lo.y() && p.y() < b.hi.y();
  };
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const Aabb& box = labels[i];
    for (const world::TreeDef& tree : f.model.trees) {  // the crown's disc: rim and centre
      const Vec2 c = v.toPixel(tree.centre);
      const double r = tree.radius / v.pixel_size;
      EXPECT_FALSE(inside(box, c)) << "label " << i << " on a crown's centre";
      for (int a = 0; a < 64; ++a) {
        const double angle = 2.0 * std::numbers::pi * a / 64;
        EXPECT_FALSE(inside(box, c + r * Vec2(std::cos(angle), std::sin(angle))))
            << "label " << i << " over the crown at " << tree.centre.transpose();
      }
    }
    for (int t = 0; t < 3; ++t) {  // the trails, sampled every 1/50 of a segment
      const std::vector<Vec2>& trail = trails.trail(t);
      for (std::size_t k = 0; k + 1 < trail.size(); ++k) {
        for (int s = 0; s <= 50; ++s) {
          const Vec2 p = v.toPixel(trail[k] + (trail[k + 1] - trail[k]) * (s / 50.0));
          EXPECT_FALSE(inside(box, p)) << "label " << i << " over trail " << t;
        }
      }
    }
    const auto clearOf = [&](const Vec2& at, double half) {
      const Vec2 c = v.toPixel(at);
      return box.hi.x() <= c.x() - half || box.lo.x() >= c.x() + half ||
             box.hi.y() <= c.y() - half || box.lo.y() >= c.y() + half;
    };
    for (const world::TargetState& target : f.truth.targets)
      EXPECT_TRUE(clearOf(target.position, 5.0 * unit)) << "label " << i << " over a target";
    for (const world::UavState& uav : f.truth.uavs)
      EXPECT_TRUE(clearOf(uav.position, 9.0 * unit)) << "label " << i << " over a UAV";
    for (std::size_t j = i + 1; j < labels.size(); ++j) {
      const Aabb& o = labels[j];
      EXPECT_FALSE(box.lo.x() < o.hi.x() && o.lo.x() < box.hi.x() && box.lo.y() < o.hi.y() &&
                   o.lo.y() < box.hi.y())
          << "labels " << i << " and " << j;
    }
  }
}

}  // namespace
}  // namespace canopy::render
