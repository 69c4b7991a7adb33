#pragma once
// A frame as a list of drawing primitives: plain values, no GL (MuJoCo's mjvScene). Built by
// buildScene (scene_builder.h), drawn by Canvas (canvas.h), which is the only GL code.
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "core/types.h"
#include "render/colour.h"
#include "render/viewport.h"

namespace canopy::render {

/// A filled convex polygon, vertices in either orientation.
struct Polygon {
  std::vector<Vec2> vertices;
  Rgba fill;
};

/// A filled circle, drawn exactly (per pixel, not as a polygon), with an optional outline of
/// `edge_px` inside its rim.
struct Disc {
  Vec2 centre = Vec2::Zero();
  double radius = 1.0;
  Rgba fill;
  Rgba edge;
  double edge_px = 0.0;  // px of the output image; 0: no outline
};

/// A circle's outline of constant width, centred on the rim.
struct Ring {
  Vec2 centre = Vec2::Zero();
  double radius = 1.0;
  double width_px = 1.0;  // px of the output image
  Rgba colour;
};

/// Connected segments of constant width with round joins.
struct Polyline {
  std::vector<Vec2> points;
  double width_px = 1.0;  // px of the output image
  Rgba colour;
  bool closed = false;
};

enum class MarkerShape { dot, arrow, cross, square };

/// A symbol of fixed pixel size at a point: dot (a target), arrow (a UAV and its heading),
/// cross (an estimate), square (a legend swatch).
struct Marker {
  Vec2 at = Vec2::Zero();
  MarkerShape shape = MarkerShape::dot;
  double size_px = 8.0;  // px, the symbol's overall extent
  double heading = 0.0;  // rad, counter-clockwise from +x as seen on the image (arrow only)
  Rgba fill;
  Rgba edge;
  double edge_px = 1.0;  // px; 0 for no edge
};

/// A line of ASCII text (stb_easy_font); its top-left corner is at `at` moved by `offset_px`.
struct Text {
  Vec2 at = Vec2::Zero();
  Vec2 offset_px = Vec2::Zero();  // px, x right, y down
  std::string text;
  double scale = 2.0;  // glyph pixels per font unit; a capital letter is 7 units high
  Rgba colour;
};

using Primitive = std::variant<Polygon, Disc, Ring, Polyline, Marker, Text>;

/// The width (px) a Text with this string and scale takes on the image, for aligning labels.
double textWidthPx(const std::string& text, double scale);

/// Appends a primitive, constructed in place. Prefer it to push_back(T{…}): GCC 12 misreports
/// the move of a temporary variant as a read of uninitialised memory (-Wmaybe-uninitialized).
template <class T>
void add(std::vector<Primitive>& list, T primitive) {
  list.emplace_back(std::in_place_type<T>, std::move(primitive));
}

/// Primitives are drawn in order, world first, with alpha blending over `background`.
struct Scene {
  Viewport viewport;  // world → output image
  Rgba background = palette::kOutside;
  std::vector<Primitive> world;    // positions and radii in m; *_px sizes in output px
  std::vector<Primitive> overlay;  // everything in output px (x right, y down), e.g. the legend
};

}  // namespace canopy::render
