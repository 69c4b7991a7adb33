#include "render/scene_vector.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace canopy::render {
namespace {

// 100 × 80 px over the world box [0, 50] × [0, 40] m at 0.5 m per px: (x, y) m ↦ (2x, 80 − 2y) px.
Scene smallScene() {
  Scene scene;
  scene.viewport.size = {100, 80};
  scene.viewport.top_left = Vec2(0.0, 40.0);
  scene.viewport.pixel_size = 0.5;
  scene.background = Rgba{255, 255, 255, 255};
  add(scene.world, Polygon{{{10, 30}, {20, 30}, {20, 20}, {10, 20}}, Rgba{255, 0, 0, 255}});
  add(scene.world, Disc{Vec2(30, 10), 5.0, Rgba{0, 0, 255, 255}, Rgba{}, 0.0});
  add(scene.overlay, Polyline{{{0, 79}, {100, 79}}, 2.0, Rgba{0, 0, 0, 255}, false});
  return scene;
}

TEST(SceneVector, SvgPlacesWorldShapesThroughTheViewportAndOverlayInPixels) {
  const std::string svg = sceneToVector(smallScene(), VectorFormat::svg);
  EXPECT_NE(svg.find("width=\"100px\" height=\"80px\""), std::string::npos) << svg;
  // The square (10..20) × (20..30) m is (20..40) × (20..40) px.
  EXPECT_NE(svg.find("M 20 20 L 40 20 L 40 40 L 20 40 Z"), std::string::npos) << svg;
  EXPECT_NE(svg.find("rgb(100%,0%,0%)"), std::string::npos) << svg;
  // The disc of 5 m at (30, 10) m: 10 px at (60, 60) px; its arc starts at angle 0, (70, 60).
  EXPECT_NE(svg.find("M 70 60 C"), std::string::npos) << svg;
  EXPECT_NE(svg.find("rgb(0%,0%,100%)"), std::string::npos) << svg;
  // The overlay's line stays in pixels, 2 px wide.
  EXPECT_NE(svg.find("M 0 79 L 100 79"), std::string::npos) << svg;
  EXPECT_NE(svg.find("stroke-width:2"), std::string::npos) << svg;
}

TEST(SceneVector, PdfIsOnePageOfTheImagesSizeInPoints) {
  const std::string pdf = sceneToVector(smallScene(), VectorFormat::pdf);
  EXPECT_EQ(pdf.substr(0, 5), "%PDF-");
  EXPECT_NE(pdf.find("/MediaBox [ 0 0 100 80 ]"), std::string::npos);
  EXPECT_NE(pdf.find("/Count 1"), std::string::npos);
}

TEST(SceneVector, TheSameSceneGivesTheSameBytes) {
  for (const VectorFormat format : {VectorFormat::svg, VectorFormat::pdf}) {
    Scene scene = smallScene();
    add(scene.overlay, Text{Vec2(4, 4), Vec2::Zero(), "t = 1.0 s", 2.0, Rgba{0, 0, 0, 255}});
    add(scene.world, Marker{Vec2(25, 20), MarkerShape::arrow, 12.0, 0.5, Rgba{0, 128, 0, 255},
                            Rgba{0, 0, 0, 255}, 1.0});
    EXPECT_EQ(sceneToVector(scene, format), sceneToVector(scene, format));
  }
}

TEST(SceneVector, ArrowDartPointsAlongTheHeadingWithYDown) {
  // Heading 90° (up on the map) points to −y on the image: the tip is h px above the centre.
  const std::vector<Vec2> dart = arrowDart(Vec2(50, 50), 10.0, 0.5 * std::numbers::pi);
  ASSERT_EQ(dart.size(), 4u);
  EXPECT_NEAR(dart[0].x(), 50.0, 1e-12);
  EXPECT_NEAR(dart[0].y(), 40.0, 1e-12);
  EXPECT_NEAR(dart[2].y(), 54.5, 1e-12);                  // the notch 0.45 h behind the centre
  EXPECT_NEAR(std::abs(dart[1].x() - 50.0), 8.0, 1e-12);  // barbs 0.8 h to each side
  EXPECT_NEAR(dart[1].x() + dart[3].x(), 100.0, 1e-12);
}

}  // namespace
}  // namespace canopy::render
