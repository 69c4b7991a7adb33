// Frames as a person sees them: a tree's centre has the tree's colour, a footprint tints the
// ground, a frame is not blank; FrameWriter writes every K-th step with one GL context.
#include <gtest/gtest.h>
#include <stb_image.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <set>

#include "render/frame_writer.h"
#include "render/scene_builder.h"

namespace canopy::render {
namespace {

namespace fs = std::filesystem;

struct World {
  SceneModel model;
  world::WorldSnapshot truth;

  World() {
    model.title = "frame";
    model.aoi = {Vec2(0, 0), Vec2(120, 80)};
    model.trees = {world::TreeDef::disc(Vec2(90, 60), 4.0),
                   world::TreeDef::disc(Vec2(15, 15), 2.0)};
    sensing::SensorDef sensor;
    sensor.footprint.size = Vec2(30, 20);
    model.sensors = {sensor};
    truth.uavs = {{Vec2(40, 40), Vec2::Zero(), 0.0}};
    truth.targets = {{Vec2(70, 20), Vec2::Zero()}};
  }

  world::WorldSnapshot at(int step) const {
    world::WorldSnapshot s = truth;
    s.step = step;
    s.time = 0.2 * step;
    s.targets[0].position += Vec2(0.3 * step, 0.0);
    return s;
  }
};

fs::path freshDir(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("canopy_render_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

TEST(Frame, TreeCentreHasTheTreeColourAndTheFootprintTintsTheGround) {
  const World w;
  const ImageSize size{800, 534};
  const Scene scene = buildScene(w.model, w.truth, {}, TargetTrails(), size);
  const Image image = Canvas(size).draw(scene);
  const Vec2 tree = scene.viewport.toPixel(Vec2(90, 60));
  EXPECT_EQ(image.pixel(static_cast<int>(tree.x()), static_cast<int>(tree.y())),
            palette::kTreeFill);
  // Inside the footprint, away from the UAV's arrow and label: ground under the UAV's colour
  // at alpha 60/255.
  const Vec2 p = scene.viewport.toPixel(Vec2(30, 45));
  const Rgba got = image.pixel(static_cast<int>(p.x()), static_cast<int>(p.y()));
  const Rgba c = uavColour(0), g = palette::kGround;
  const double a = 60.0 / 255.0;
  EXPECT_NEAR(got.r, a * c.r + (1 - a) * g.r, 1.0);
  EXPECT_NEAR(got.g, a * c.g + (1 - a) * g.g, 1.0);
  EXPECT_NEAR(got.b, a * c.b + (1 - a) * g.b, 1.0);
  // Outside the footprint: the bare ground; outside the AOI: the margin's colour.
  const Vec2 bare = scene.viewport.toPixel(Vec2(60, 70));
  EXPECT_EQ(image.pixel(static_cast<int>(bare.x()), static_cast<int>(bare.y())), palette::kGround);
  const Vec2 out = scene.viewport.toPixel(Vec2(-2, 40));
  EXPECT_EQ(image.pixel(static_cast<int>(out.x()), static_cast<int>(out.y())), palette::kOutside);
}

TEST(Frame, IsNotBlank) {
  const World w;
  const Image image =
      Canvas({400, 300}).draw(buildScene(w.model, w.truth, {}, TargetTrails(), {400, 300}));
  std::set<std::uint32_t> colours;
  int not_ground = 0;
  for (int y = 0; y < 300; ++y) {
    for (int x = 0; x < 400; ++x) {
      const Rgba c = image.pixel(x, y);
      colours.insert(std::uint32_t(c.r) << 16 | std::uint32_t(c.g) << 8 | c.b);
      not_ground += !(c == palette::kGround);
    }
  }
  EXPECT_GT(colours.size(), 20u);
  EXPECT_GT(not_ground, 400 * 300 / 10);
}

TEST(FrameWriter, WritesEveryKthStepWithOneGlContext) {
  const World w;
  const fs::path dir = freshDir("writer");
  fs::create_directories(dir);
  std::ofstream(dir / "frame_000001.png") << "stale";
  const int before = glContextsCreated();
  FrameOptions options;
  options.dir = dir;
  options.every = 3;
  options.size = {320, 240};
  FrameWriter writer(w.model, options);
  EXPECT_FALSE(fs::exists(dir / "frame_000001.png"));  // stale frames are removed
  EXPECT_EQ(glContextsCreated(), before);              // and no GL yet
  for (int k = 0; k <= 10; ++k) writer.onStep(w.at(k), {});
  EXPECT_EQ(writer.framesWritten(), 4);
  EXPECT_EQ(glContextsCreated(), before + 1);
  for (int k = 0; k <= 10; ++k) {
    EXPECT_EQ(fs::exists(FrameWriter::framePath(dir, k)), k % 3 == 0) << k;
  }
  EXPECT_EQ(FrameWriter::framePath(dir, 42).filename(), "frame_000042.png");
  int width = 0, height = 0, n = 0;
  ASSERT_TRUE(stbi_info(FrameWriter::framePath(dir, 9).c_str(), &width, &height, &n));
  EXPECT_EQ(width, 320);
  EXPECT_EQ(height, 240);
  fs::remove_all(dir);
}

TEST(FrameWriter, DefaultSizeFollowsTheAoi) {
  const World w;
  FrameOptions options;
  options.dir = freshDir("default");
  const FrameWriter writer(w.model, options);
  EXPECT_EQ(writer.size(), defaultFrameSize(w.model.aoi));
  EXPECT_EQ(writer.size().width, kDefaultFrameLongSide);
  fs::remove_all(options.dir);
}

}  // namespace
}  // namespace canopy::render
