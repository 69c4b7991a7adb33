// The OSMesa canvas: primitives land on the pixels their geometry says, blending follows the
// "over" formula, the same input gives the same bytes, and GL starts on the first draw only.
#include "render/canvas.h"

#include <gtest/gtest.h>
#include <stb_image.h>

#include <cmath>
#include <cstdlib>

#include "core/random.h"
#include "render/image.h"
#include "render/internal/font.h"
#include "render/internal/text.h"

namespace canopy::render {
namespace {

constexpr Rgba kBackground{10, 20, 30, 255};
constexpr Rgba kFill{200, 100, 50, 255};
constexpr Rgba kEdge{0, 0, 250, 255};

// A 100 × 100 px image of the world square [0, 100]²: 1 m per pixel, world (x, y) at pixel
// (x, 100 − y).
Scene square() {
  Scene scene;
  scene.viewport = Viewport::fit({Vec2(0, 0), Vec2(100, 100)}, {100, 100});
  scene.background = kBackground;
  return scene;
}

TEST(Canvas, RectangleCoversExactlyItsPixels) {
  Scene scene = square();
  // x ∈ [20, 60] m, y ∈ [30, 70] m → columns 20..59, rows 30..69 (rows counted from the top).
  add(scene.world, Polygon{{Vec2(20, 30), Vec2(60, 30), Vec2(60, 70), Vec2(20, 70)}, kFill});
  const Image image = Canvas({100, 100}).draw(scene);
  for (const auto& [x, y] : {std::pair{20, 30}, {59, 30}, {20, 69}, {59, 69}, {40, 50}}) {
    EXPECT_EQ(image.pixel(x, y), kFill) << x << "," << y;
  }
  for (const auto& [x, y] : {std::pair{19, 30}, {20, 29}, {60, 69}, {59, 70}, {19, 29}, {60, 70}}) {
    EXPECT_EQ(image.pixel(x, y), kBackground) << x << "," << y;
  }
}

TEST(Canvas, DiscHasItsFillInsideAndItsEdgeInTheOuterBand) {
  Scene scene = square();
  // Radius 10 px with a 3 px outline: fill within 7 px of the centre, edge from 7 to 10 px.
  add(scene.world, Disc{Vec2(50, 50), 10.0, kFill, kEdge, 3.0});
  const Image image = Canvas({100, 100}).draw(scene);
  EXPECT_EQ(image.pixel(50, 50), kFill);  // centre (50.5, 50.5) px: 0.7 px from the disc's centre
  EXPECT_EQ(image.pixel(58, 49), kEdge);  // every sample 8.2–8.8 px out
  EXPECT_EQ(image.pixel(61, 50), kBackground);  // 11 px out
  EXPECT_EQ(image.pixel(50, 38), kBackground);
}

TEST(Canvas, DiscEdgeIsAntiAliasedByCoverage) {
  Scene scene = square();
  // Centred on pixel (50, 50): pixel (60, 50)'s centre lies on the rim, half covered; pixel
  // (55, 50)'s is 5 px inside, pixel (62, 50)'s 2 px outside.
  add(scene.world, Disc{Vec2(50.5, 49.5), 10.0, kFill, kFill, 0.0});
  const Image image = Canvas({100, 100}).draw(scene);
  const Rgba half = image.pixel(60, 50);
  EXPECT_NEAR(half.r, 0.5 * (kFill.r + kBackground.r), 1.5);
  EXPECT_NEAR(half.g, 0.5 * (kFill.g + kBackground.g), 1.5);
  EXPECT_NEAR(half.b, 0.5 * (kFill.b + kBackground.b), 1.5);
  EXPECT_EQ(image.pixel(55, 50), kFill);
  EXPECT_EQ(image.pixel(62, 50), kBackground);
  // The same disc as a mask is not anti-aliased: covered or not, by the pixel's centre.
  Scene mask = square();
  add(mask.world, Disc{Vec2(50.5, 49.5), 9.9, Rgba{1, 0, 0, 0}, Rgba{1, 0, 0, 0}, 0.0});
  Canvas canvas({100, 100});
  const std::vector<std::uint8_t>& layers = canvas.accumulate(mask);
  EXPECT_EQ(layers[50 * 100 + 59], 1);  // 9 px out
  EXPECT_EQ(layers[50 * 100 + 60], 0);  // 10 px out
}

TEST(Canvas, TranslucentFillBlendsOverTheBackground) {
  Scene scene = square();
  const Rgba half{250, 250, 250, 128};
  add(scene.world, Polygon{{Vec2(0, 0), Vec2(100, 0), Vec2(100, 100), Vec2(0, 100)}, half});
  const Image image = Canvas({100, 100}).draw(scene);
  // out = a·src + (1 − a)·dst with a = 128/255.
  const double a = 128.0 / 255.0;
  const Rgba got = image.pixel(50, 50);
  EXPECT_NEAR(got.r, a * 250 + (1 - a) * 10, 1.0);
  EXPECT_NEAR(got.g, a * 250 + (1 - a) * 20, 1.0);
  EXPECT_NEAR(got.b, a * 250 + (1 - a) * 30, 1.0);
}

TEST(Canvas, TextDrawsInsideItsBoxOnly) {
  Scene scene = square();
  // "H" at scale 2: within its advance width and a line's height, from its top-left corner.
  add(scene.overlay, Text{Vec2(10, 10), Vec2::Zero(), "H", 2.0, kFill});
  const Image image = Canvas({100, 100}).draw(scene);
  const double right = 10 + 2 * internal::textWidth("H"),
               bottom = 10 + 2 * internal::kTextLineHeight;
  int inside = 0, outside = 0;
  for (int y = 0; y < 100; ++y) {
    for (int x = 0; x < 100; ++x) {
      if (!(image.pixel(x, y) == kFill)) continue;
      (x >= 10 && x < right && y >= 10 && y < bottom ? inside : outside)++;
    }
  }
  EXPECT_GT(inside, 20);
  EXPECT_EQ(outside, 0);
}

// With fonts-dejavu-core installed (./canopy installs it) text is DejaVu Sans through FreeType:
// anti-aliased (some pixels between ink and paper), and "1" is not drawn like "I" (the stroke
// font drew "UAV1" as "UAVI").
TEST(Canvas, TextIsDejaVuThroughFreeType) {
  ASSERT_NE(internal::Font::instance(), nullptr) << internal::kFontPath;
  const auto render = [](const std::string& text) {
    Scene scene = square();
    add(scene.overlay, Text{Vec2(10, 10), Vec2::Zero(), text, 4.0, Rgba{0, 0, 0, 255}});
    return Canvas({100, 100}).draw(scene);
  };
  const Image one = render("1"), eye = render("I");
  EXPECT_NE(one.rgb, eye.rgb);
  const Rgba paper = one.pixel(95, 95);
  int ink = 0, between = 0;
  for (int y = 0; y < 100; ++y) {
    for (int x = 0; x < 100; ++x) {
      const Rgba p = one.pixel(x, y);
      if (p == Rgba{0, 0, 0, 255}) ++ink;
      if (!(p == paper) && !(p == Rgba{0, 0, 0, 255})) ++between;
    }
  }
  EXPECT_GT(ink, 10);
  EXPECT_GT(between, 4);
  // Widths are the font's advances: additive without kerning.
  EXPECT_NEAR(internal::textWidth("UAV1"), internal::textWidth("UAV") + internal::textWidth("1"),
              1e-9);
  EXPECT_NE(internal::textWidth("W"), internal::textWidth("i"));  // proportional
}

TEST(Canvas, SameSceneGivesTheSameBytes) {
  Scene scene = square();
  add(scene.world, Disc{Vec2(40, 40), 17.3, Rgba{90, 160, 70, 200}, kEdge, 1.5});
  add(scene.world,
      Polyline{{Vec2(5, 5), Vec2(95, 60), Vec2(30, 90)}, 2.5, Rgba{0, 0, 0, 180}, false});
  add(scene.world, Marker{Vec2(70, 30), MarkerShape::arrow, 14.0, 0.7, kFill, kEdge, 1.0});
  Canvas a({100, 100}), b({100, 100});
  const std::vector<std::uint8_t> first = encodePng(a.draw(scene));
  EXPECT_EQ(encodePng(a.draw(scene)), first);
  EXPECT_EQ(encodePng(b.draw(scene)), first);
}

TEST(Canvas, CreatesItsGlContextOnTheFirstDrawOnly) {
  const int before = glContextsCreated();
  Canvas canvas({64, 48});
  Scene scene;
  scene.viewport = Viewport::fit({Vec2(0, 0), Vec2(4, 3)}, {64, 48});
  EXPECT_EQ(glContextsCreated(), before);
  canvas.draw(scene);
  EXPECT_EQ(glContextsCreated(), before + 1);
  canvas.draw(scene);
  EXPECT_EQ(glContextsCreated(), before + 1);
}

TEST(Canvas, AccumulateCountsOverlappingLayers) {
  Scene scene = square();
  const Rgba one{1, 0, 0, 0};
  add(scene.world, Polygon{{Vec2(10, 10), Vec2(50, 10), Vec2(50, 50), Vec2(10, 50)}, one});
  add(scene.world, Polygon{{Vec2(30, 30), Vec2(70, 30), Vec2(70, 70), Vec2(30, 70)}, one});
  Canvas canvas({100, 100});
  const std::vector<std::uint8_t>& layers = canvas.accumulate(scene);
  const auto at = [&](int x, int y) { return layers[static_cast<std::size_t>(y) * 100 + x]; };
  EXPECT_EQ(at(15, 85), 1);  // world (15.5, 14.5): first square only
  EXPECT_EQ(at(40, 60), 2);  // world (40.5, 39.5): both
  EXPECT_EQ(at(65, 35), 1);  // world (65.5, 64.5): second only
  EXPECT_EQ(at(80, 10), 0);
}

TEST(Canvas, RejectsSizesOutOfRange) {
  EXPECT_THROW(Canvas({0, 10}), std::invalid_argument);
  EXPECT_THROW(Canvas({9000, 100}), std::invalid_argument);
}

TEST(Png, DecodesToTheSamePixels) {
  Scene scene = square();
  add(scene.world, Disc{Vec2(30, 60), 20.0, kFill, kEdge, 2.0});
  const Image image = Canvas({100, 100}).draw(scene);
  const std::vector<std::uint8_t> png = encodePng(image);
  int w = 0, h = 0, n = 0;
  unsigned char* decoded =
      stbi_load_from_memory(png.data(), static_cast<int>(png.size()), &w, &h, &n, 3);
  ASSERT_NE(decoded, nullptr);
  EXPECT_EQ(w, 100);
  EXPECT_EQ(h, 100);
  EXPECT_EQ(std::vector<std::uint8_t>(decoded, decoded + 100 * 100 * 3), image.rgb);
  std::free(decoded);
}

// The encoder's corner cases: literals of every byte value (8- and 9-bit codes), runs longer
// than one match, row matches at distances that need many extra bits (rows of 9000 bytes).
TEST(Png, RoundTripsNoiseFlatAndRepeatedRows) {
  Image image;
  image.size = {3000, 24};
  image.rgb.resize(3000 * 24 * 3);
  RandomStream rng(5, "png");
  for (int y = 0; y < 24; ++y) {
    std::uint8_t* row = image.rgb.data() + static_cast<std::size_t>(y) * 9000;
    for (int i = 0; i < 9000; ++i) {
      switch (y % 4) {
        case 0:
          row[i] = static_cast<std::uint8_t>(rng.nextU64());
          break;  // noise
        case 1:
          row[i] = static_cast<std::uint8_t>(i % 3 == 0 ? 200 : 17);
          break;  // flat
        case 2:
          row[i] = row[i - 9000];
          break;  // repeated
        default:
          row[i] = static_cast<std::uint8_t>(i < 4500 ? 255 : rng.nextU64() % 4);
          break;
      }
    }
  }
  const std::vector<std::uint8_t> png = encodePng(image);
  int w = 0, h = 0, n = 0;
  unsigned char* decoded =
      stbi_load_from_memory(png.data(), static_cast<int>(png.size()), &w, &h, &n, 3);
  ASSERT_NE(decoded, nullptr) << stbi_failure_reason();
  EXPECT_EQ(w, 3000);
  EXPECT_EQ(h, 24);
  EXPECT_EQ(std::vector<std::uint8_t>(decoded, decoded + image.rgb.size()), image.rgb);
  std::free(decoded);
}

}  // namespace
}  // namespace canopy::render
