#pragma once
// A figure as plain shapes in pixel coordinates (x right, y down), written as SVG here and as
// PNG through the renderer's canvas (figure_png.h), so that canopy draws its own figures.
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "core/types.h"

namespace canopy::analysis {

struct Colour {
  std::uint8_t r = 0, g = 0, b = 0;
  double alpha = 1.0;  // 0 transparent … 1 opaque
};

/// A filled convex polygon (bands are built from convex quads so the PNG path can fill them).
struct FilledPolygon {
  std::vector<Vec2> points;  // px
  Colour fill;
};

/// A line's pattern: solid, dashed (10 px on, 5 off), dotted (2 on, 4 off), dash-dot
/// (10 on, 4 off, 2 on, 4 off).
enum class Dash { solid, dashed, dotted, dash_dot };
/// The pattern in px drawn, px skipped, …; empty for solid.
std::vector<double> dashPattern(Dash dash);

struct Line {
  std::vector<Vec2> points;  // px
  double width = 1.0;        // px
  Colour colour;
  Dash dash = Dash::solid;
};

/// The pieces of `line` that are drawn under its dash pattern (the whole line when solid).
std::vector<std::vector<Vec2>> dashPieces(const Line& line);

enum class Anchor { start, middle, end };

struct Label {
  Vec2 at = Vec2::Zero();  // px, the baseline's anchor point
  std::string text;        // ASCII
  double size = 12.0;      // px, the height of a capital letter
  Anchor anchor = Anchor::start;
  Colour colour;
};

using Shape = std::variant<FilledPolygon, Line, Label>;

struct Figure {
  int width = 800;   // px
  int height = 600;  // px
  Colour background{255, 255, 255};
  std::vector<Shape> shapes;  // drawn in order
};

/// The figure as an SVG document.
std::string toSvg(const Figure& figure);

/// The ink of axes, ticks and text.
inline constexpr Colour kInk{30, 30, 30};

/// Adds the axis-aligned rectangle [x0, x1] × [y0, y1] filled with `fill`.
void addRect(Figure& f, double x0, double y0, double x1, double y1, Colour fill);

/// A qualitative colour for series or states (repeats after 8).
Colour seriesColour(int index);

}  // namespace canopy::analysis
