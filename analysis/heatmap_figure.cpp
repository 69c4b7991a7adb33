#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "analysis/heatmap.h"
#include "render/scene.h"

namespace canopy::analysis {
namespace {

constexpr Colour kWhite{255, 255, 255};
constexpr Colour kMissing{225, 225, 225};

std::string fixed2(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", x);
  return text;
}

// Ink that reads on `fill`: white on dark cells (ITU-R BT.601 luma below 140), dark otherwise.
Colour inkOn(const Colour& fill) {
  const double luma = 0.299 * fill.r + 0.587 * fill.g + 0.114 * fill.b;
  return luma < 140.0 ? kWhite : kInk;
}

}  // namespace

Colour heatColour(double u) {
  // Four anchors at u = 0, 1/3, 2/3, 1, linear in each channel between them.
  static const Colour kAnchors[] = {
      {255, 250, 205}, {160, 215, 150}, {50, 150, 170}, {30, 50, 130}};
  const double v = 3.0 * std::clamp(u, 0.0, 1.0);
  const int i = std::min(2, static_cast<int>(v));
  const double s = v - i;
  auto mix = [&](std::uint8_t a, std::uint8_t b) {
    return static_cast<std::uint8_t>(std::lround(a + s * (b - a)));
  };
  const Colour& a = kAnchors[i];
  const Colour& b = kAnchors[i + 1];
  return {mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b)};
}

Figure heatmapFigure(const Heatmap& map, const std::string& title) {
  const int nx = static_cast<int>(map.x_values.size());
  const int ny = static_cast<int>(map.y_values.size());
  const double left = 120, top = 90, cell_w = 110, cell_h = 64, scale_w = 18;
  const double grid_h = ny * cell_h;
  const double scale_h = std::max(grid_h, 160.0);
  std::string subtitle = map.metric.label;
  for (const std::string& o : map.others) subtitle += ", " + displayOverride(o);
  // Wide enough for the grid and the scale, and for the title lines as the PNG font draws them
  // (a label of size s is drawn at scale s/7).
  const double text_w =
      std::max(render::textWidthPx(title, 14 / 7.0), render::textWidthPx(subtitle, 10 / 7.0)) + 40;
  Figure f;
  f.width = static_cast<int>(std::max(left + nx * cell_w + 150, text_w));
  f.height = static_cast<int>(top + scale_h + 80);
  const double max = map.metric.max > 0 ? map.metric.max : 1.0;

  // The cells first, row by row from the smallest y (drawn at the bottom), x increasing.
  auto cellTop = [&](int y) { return top + (ny - 1 - y) * cell_h; };
  for (int y = 0; y < ny; ++y) {
    for (int x = 0; x < nx; ++x) {
      const auto& cell = map.cells[y][x];
      const double x0 = left + x * cell_w, y0 = cellTop(y);
      addRect(f, x0, y0, x0 + cell_w - 2, y0 + cell_h - 2,
              cell ? heatColour(cell->value.value / max) : kMissing);
    }
  }
  for (int y = 0; y < ny; ++y) {
    for (int x = 0; x < nx; ++x) {
      const auto& cell = map.cells[y][x];
      const double cx = left + x * cell_w + (cell_w - 2) / 2, y0 = cellTop(y);
      if (!cell) {
        f.shapes.push_back(
            Label{Vec2(cx, y0 + cell_h / 2 + 4), "no trials", 9, Anchor::middle, kInk});
        continue;
      }
      const Colour ink = inkOn(heatColour(cell->value.value / max));
      f.shapes.push_back(
          Label{Vec2(cx, y0 + 26), fixed2(cell->value.value), 12, Anchor::middle, ink});
      const ConfidenceInterval& ci = cell->value.ci;
      const std::string interval =
          ci.bounded() ? "[" + fixed2(ci.low) + ", " + fixed2(ci.high) + "]"
                       : "too few trials (n = " + std::to_string(cell->value.trials) + ")";
      f.shapes.push_back(Label{Vec2(cx, y0 + 44), interval, 8, Anchor::middle, ink});
    }
  }

  // Axes: values under the columns and left of the rows, the paths as titles.
  f.shapes.push_back(Label{Vec2(f.width / 2.0, 30), title, 14, Anchor::middle, kInk});
  f.shapes.push_back(Label{Vec2(f.width / 2.0, 52), subtitle, 10, Anchor::middle, kInk});
  for (int x = 0; x < nx; ++x) {
    f.shapes.push_back(Label{Vec2(left + x * cell_w + (cell_w - 2) / 2, top + grid_h + 18),
                             displayValue(map.x_values[x]), 10, Anchor::middle, kInk});
  }
  f.shapes.push_back(
      Label{Vec2(left + nx * cell_w / 2, top + grid_h + 44), map.x_path, 11, Anchor::middle, kInk});
  for (int y = 0; y < ny; ++y) {
    f.shapes.push_back(Label{Vec2(left - 10, cellTop(y) + cell_h / 2 + 4),
                             displayValue(map.y_values[y]), 10, Anchor::end, kInk});
  }
  f.shapes.push_back(Label{Vec2(12, top - 14), map.y_path, 11, Anchor::start, kInk});

  // The colour scale: 40 slices from 0 (bottom) to max (top), ticks every quarter of it.
  const double sx = left + nx * cell_w + 30;
  constexpr int kSlices = 40;
  for (int i = 0; i < kSlices; ++i) {
    const double y1 = top + scale_h * (1.0 - static_cast<double>(i) / kSlices);
    const double y0 = top + scale_h * (1.0 - static_cast<double>(i + 1) / kSlices);
    addRect(f, sx, y0, sx + scale_w, y1, heatColour((i + 0.5) / kSlices));
  }
  for (int q = 0; q <= 4; ++q) {
    const double y = top + scale_h * (1.0 - q / 4.0);
    f.shapes.push_back(Line{{Vec2(sx + scale_w, y), Vec2(sx + scale_w + 5, y)}, 1, kInk});
    f.shapes.push_back(
        Label{Vec2(sx + scale_w + 8, y + 4), fixed2(max * q / 4.0), 9, Anchor::start, kInk});
  }
  f.shapes.push_back(Label{Vec2(12, f.height - 12.0),
                           std::string("in brackets: the 95 % interval (") +
                               (map.metric.state.empty() ? "Student t" : "Wilson") + ")",
                           9, Anchor::start, kInk});
  return f;
}

}  // namespace canopy::analysis
