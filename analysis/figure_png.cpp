#include "analysis/figure_png.h"

#include <algorithm>
#include <cmath>

#include "analysis/figure_pdf.h"
#include "core/text_file.h"
#include "render/canvas.h"
#include "render/image.h"
#include "render/scene.h"

namespace canopy::analysis {
namespace {

render::Rgba rgba(const Colour& c) {
  return {c.r, c.g, c.b,
          static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(c.alpha, 0.0, 1.0)))};
}
// Figure pixels (y down) as renderer world coordinates under a 1 px = 1 unit viewport whose
// top-left corner is the origin: world y = −pixel y.
Vec2 world(const Vec2& p) {
  return {p.x(), -p.y()};
}

}  // namespace

void writeFigurePng(const Figure& figure, const std::filesystem::path& path) {
  render::Scene scene;
  scene.viewport.size = {figure.width, figure.height};
  scene.viewport.top_left = Vec2::Zero();
  scene.viewport.pixel_size = 1.0;
  scene.background = rgba(figure.background);
  for (const Shape& shape : figure.shapes) {
    if (const auto* p = std::get_if<FilledPolygon>(&shape)) {
      render::Polygon polygon;
      for (const Vec2& v : p->points) polygon.vertices.push_back(world(v));
      polygon.fill = rgba(p->fill);
      render::add(scene.world, std::move(polygon));
    } else if (const auto* l = std::get_if<Line>(&shape)) {
      for (const std::vector<Vec2>& piece : dashPieces(*l)) {
        render::Polyline line;
        for (const Vec2& v : piece) line.points.push_back(world(v));
        line.width_px = l->width;
        line.colour = rgba(l->colour);
        render::add(scene.world, std::move(line));
      }
    } else if (const auto* t = std::get_if<Label>(&shape)) {
      render::Text text;
      text.scale = t->size / 7.0;  // a capital letter is 7 font units high
      const double width = render::textWidthPx(t->text, text.scale);
      const double shift = t->anchor == Anchor::start    ? 0.0
                           : t->anchor == Anchor::middle ? width / 2
                                                         : width;
      text.at = t->at - Vec2(shift, t->size);  // the label's top-left corner
      text.text = t->text;
      text.colour = rgba(t->colour);
      render::add(scene.overlay, std::move(text));
    }
  }
  render::Canvas canvas({figure.width, figure.height});
  render::writePng(path, canvas.draw(scene));
}

void writeFigure(const Figure& figure, const std::filesystem::path& stem,
                 const FigureStyle& style) {
  Figure styled = figure;
  restyle(styled, style);
  writeFileAtomically(stem.string() + ".svg", toSvg(styled));
  writeFileAtomically(stem.string() + ".pdf", toPdf(styled));
  writeFigurePng(styled, stem.string() + ".png");
}

}  // namespace canopy::analysis
