#include "analysis/figure_style.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "spec/error.h"

namespace canopy::analysis {
namespace {

namespace fs = std::filesystem;

fs::path writeStyleFile(const std::string& name, const std::string& text) {
  const fs::path path = fs::temp_directory_path() / ("canopy_style_" + name + ".json");
  std::ofstream(path) << text;
  return path;
}

Figure styleSample() {
  Figure f;
  f.shapes.push_back(Line{{Vec2(0, 0), Vec2(10, 10)}, 2.0, seriesColour(1), Dash::solid});
  f.shapes.push_back(FilledPolygon{{Vec2(0, 0), Vec2(1, 0), Vec2(1, 1)},
                                   Colour{seriesColour(9).r, seriesColour(9).g, seriesColour(9).b,
                                          0.3}});  // index 9 is colour 1 again, 30 % opaque
  f.shapes.push_back(Label{Vec2(5, 5), "axis", 10.0, Anchor::start, kInk});
  f.shapes.push_back(Line{{Vec2(0, 5), Vec2(10, 5)}, 1.0, Colour{200, 200, 200}, Dash::dashed});
  return f;
}

TEST(FigureStyle, TheShippedFileIsTheDefaultStyle) {
  const FigureStyle shipped = readFigureStyle(CANOPY_SOURCE_DIR "/docs/figure-style.json");
  const FigureStyle defaults;
  for (int i = 0; i < 8; ++i) {
    EXPECT_EQ(shipped.series[i].r, defaults.series[i].r) << i;
    EXPECT_EQ(shipped.series[i].g, defaults.series[i].g) << i;
    EXPECT_EQ(shipped.series[i].b, defaults.series[i].b) << i;
  }
  EXPECT_EQ(shipped.ink.r, 30);  // kInk, #1e1e1e
  EXPECT_EQ(shipped.font_scale, 1.0);
  EXPECT_EQ(shipped.line_scale, 1.0);
}

TEST(FigureStyle, TheDefaultStyleLeavesAFigureAsItIs) {
  Figure figure = styleSample();
  restyle(figure, FigureStyle{});
  EXPECT_EQ(toSvg(figure), toSvg(styleSample()));
}

TEST(FigureStyle, ColoursByIndexInkAndScales) {
  const FigureStyle style = readFigureStyle(writeStyleFile(
      "custom",
      R"({"series": ["#000001", "#0a0b0c"], "ink": "#ff0000", "background": "#fafafa",
          "font_scale": 2, "line_scale": 0.5})"));
  Figure f = styleSample();
  restyle(f, style);
  const Line& line = std::get<Line>(f.shapes[0]);
  EXPECT_EQ(line.colour.r, 10);  // series 1 → "#0a0b0c"
  EXPECT_EQ(line.colour.g, 11);
  EXPECT_EQ(line.colour.b, 12);
  EXPECT_EQ(line.width, 1.0);
  const FilledPolygon& band = std::get<FilledPolygon>(f.shapes[1]);
  EXPECT_EQ(band.fill.b, 12);
  EXPECT_EQ(band.fill.alpha, 0.3);  // opacity kept
  const Label& label = std::get<Label>(f.shapes[2]);
  EXPECT_EQ(label.colour.r, 255);
  EXPECT_EQ(label.colour.g, 0);
  EXPECT_EQ(label.size, 20.0);
  const Line& grid = std::get<Line>(f.shapes[3]);
  EXPECT_EQ(grid.colour.r, 200);  // neither a series colour nor the ink: kept
  EXPECT_EQ(f.background.r, 0xfa);
}

TEST(FigureStyle, BadFilesNameTheFileAndTheField) {
  const struct {
    const char* text;
    const char* field;
  } cases[] = {
      {R"({"ink": "red"})", "ink: expected a colour"},
      {R"({"ink": "#12345g"})", "ink: expected a colour"},
      {R"({"ink": "#1234 5"})", "ink: expected a colour"},
      {R"({"series": ["#000000", 3]})", "series[1]: expected a colour"},
      {R"({"series": []})", "series: expected a list of 1 to 8"},
      {R"({"series": ["#000000","#000000","#000000","#000000","#000000","#000000","#000000","#000000","#000000"]})",
       "series: expected a list of 1 to 8"},
      {R"({"font_scale": 10})", "font_scale: expected a number in [0.25, 4]"},
      {R"({"line_scale": "1"})", "line_scale: expected a number"},
      {R"({"colour": "#000000"})", "colour: unknown field"},
      {R"([1, 2])", "expected a JSON object"},
      {R"({"ink": )", "not JSON"},
  };
  for (const auto& c : cases) {
    const fs::path path = writeStyleFile("bad", c.text);
    try {
      readFigureStyle(path);
      ADD_FAILURE() << c.text;
    } catch (const spec::ScenarioError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(path.string() + ": ", 0), 0u) << what;
      EXPECT_NE(what.find(c.field), std::string::npos) << what;
    }
  }
  EXPECT_THROW(readFigureStyle("/nonexistent/style.json"), spec::ScenarioError);
}

}  // namespace
}  // namespace canopy::analysis
