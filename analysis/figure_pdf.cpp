#include "analysis/figure_pdf.h"

#include <cairo-pdf.h>
#include <cairo.h>

#include <memory>
#include <stdexcept>
#include <vector>

#include "render/cairo_string.h"

namespace canopy::analysis {
namespace {

void setColour(cairo_t* cr, const Colour& c) {
  cairo_set_source_rgba(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0, c.alpha);
}

void path(cairo_t* cr, const std::vector<Vec2>& points) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i == 0)
      cairo_move_to(cr, points[i].x(), points[i].y());
    else
      cairo_line_to(cr, points[i].x(), points[i].y());
  }
}

void draw(cairo_t* cr, const Figure& figure) {
  setColour(cr, figure.background);
  cairo_paint(cr);
  // The SVG's font: sans-serif, a capital letter about 0.7 em high.
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  for (const Shape& shape : figure.shapes) {
    if (const auto* p = std::get_if<FilledPolygon>(&shape)) {
      if (p->points.size() < 3) continue;
      path(cr, p->points);
      cairo_close_path(cr);
      setColour(cr, p->fill);
      cairo_fill(cr);
    } else if (const auto* l = std::get_if<Line>(&shape)) {
      if (l->points.size() < 2) continue;
      path(cr, l->points);
      const std::vector<double> pattern = dashPattern(l->dash);
      cairo_set_dash(cr, pattern.data(), static_cast<int>(pattern.size()), 0.0);
      cairo_set_line_width(cr, l->width);
      cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
      setColour(cr, l->colour);
      cairo_stroke(cr);
    } else if (const auto* t = std::get_if<Label>(&shape)) {
      cairo_set_font_size(cr, t->size / 0.7);
      cairo_text_extents_t extents;
      cairo_text_extents(cr, t->text.c_str(), &extents);
      const double shift = t->anchor == Anchor::start    ? 0.0
                           : t->anchor == Anchor::middle ? extents.x_advance / 2.0
                                                         : extents.x_advance;
      cairo_move_to(cr, t->at.x() - shift, t->at.y());
      setColour(cr, t->colour);
      cairo_show_text(cr, t->text.c_str());
    }
  }
}

}  // namespace

std::string toPdf(const Figure& figure) {
  std::string pdf;
  const std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
      cairo_pdf_surface_create_for_stream(render::appendToString, &pdf, figure.width,
                                          figure.height),
      cairo_surface_destroy);
  // No creation date: the same figure gives the same bytes.
  cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATE_DATE, "");
  {
    const std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr(cairo_create(surface.get()),
                                                                cairo_destroy);
    draw(cr.get(), figure);
    if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS)
      throw std::runtime_error(std::string("PDF figure: ") +
                               cairo_status_to_string(cairo_status(cr.get())));
  }
  cairo_surface_finish(surface.get());
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(std::string("PDF figure: ") +
                             cairo_status_to_string(cairo_surface_status(surface.get())));
  return pdf;
}

}  // namespace canopy::analysis
