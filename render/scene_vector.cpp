#include "render/scene_vector.h"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>

#include "render/cairo_string.h"

namespace canopy::render {
namespace {

void setColour(cairo_t* cr, const Rgba& c) {
  cairo_set_source_rgba(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0, c.a / 255.0);
}

void path(cairo_t* cr, const std::vector<Vec2>& points, bool closed) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i == 0)
      cairo_move_to(cr, points[i].x(), points[i].y());
    else
      cairo_line_to(cr, points[i].x(), points[i].y());
  }
  if (closed) cairo_close_path(cr);
}

void stroke(cairo_t* cr, double width, const Rgba& colour) {
  cairo_set_line_width(cr, width);
  setColour(cr, colour);
  cairo_stroke(cr);
}

void fill(cairo_t* cr, const Rgba& colour) {
  setColour(cr, colour);
  cairo_fill(cr);
}

void circle(cairo_t* cr, const Vec2& c, double r) {
  cairo_new_sub_path(cr);
  cairo_arc(cr, c.x(), c.y(), r, 0.0, 2.0 * std::numbers::pi);
}

// A disc of radius r px with an outline of edge px inside its rim.
void disc(cairo_t* cr, const Vec2& c, double r, const Rgba& colour, double edge, const Rgba& rim) {
  circle(cr, c, r);
  fill(cr, colour);
  if (edge <= 0.0) return;
  circle(cr, c, std::max(0.0, r - 0.5 * edge));
  stroke(cr, std::min(edge, r), rim);
}

void marker(cairo_t* cr, const Marker& m, const Vec2& c) {
  const double h = 0.5 * m.size_px, edge = m.edge_px;
  switch (m.shape) {
    case MarkerShape::dot:
      disc(cr, c, h, m.fill, edge, m.edge);
      break;
    case MarkerShape::square:
    case MarkerShape::arrow: {
      const std::vector<Vec2> outline = m.shape == MarkerShape::arrow
                                            ? arrowDart(c, h, m.heading)
                                            : std::vector<Vec2>{c + Vec2(-h, -h), c + Vec2(h, -h),
                                                                c + Vec2(h, h), c + Vec2(-h, h)};
      path(cr, outline, true);
      fill(cr, m.fill);
      if (edge > 0.0) {
        path(cr, outline, true);
        stroke(cr, edge, m.edge);
      }
      break;
    }
    case MarkerShape::cross: {  // an ×, its edge the same cross wider underneath
      const double w = std::max(2.0, 0.25 * m.size_px), d = h / std::sqrt(2.0);
      const Vec2 a(d, d), e(d, -d);
      auto cross = [&](double width, const Rgba& colour) {
        path(cr, {c - a, c + a}, false);
        path(cr, {c - e, c + e}, false);
        stroke(cr, width, colour);
      };
      cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
      if (edge > 0.0) cross(w + 2.0 * edge, m.edge);
      cross(w, m.fill);
      break;
    }
  }
}

// Draws every primitive of `list` but text; `point` maps a position to px, `length` a length.
template <class Point, class Length>
void shapes(cairo_t* cr, const std::vector<Primitive>& list, Point point, Length length) {
  std::vector<Vec2> px;
  for (const Primitive& primitive : list) {
    if (const auto* p = std::get_if<Polygon>(&primitive)) {
      px.clear();
      for (const Vec2& v : p->vertices) px.push_back(point(v));
      path(cr, px, true);
      fill(cr, p->fill);
    } else if (const auto* d = std::get_if<Disc>(&primitive)) {
      disc(cr, point(d->centre), length(d->radius), d->fill, d->edge_px, d->edge);
    } else if (const auto* r = std::get_if<Ring>(&primitive)) {
      circle(cr, point(r->centre), length(r->radius));
      stroke(cr, r->width_px, r->colour);
    } else if (const auto* l = std::get_if<Polyline>(&primitive)) {
      px.clear();
      for (const Vec2& v : l->points) px.push_back(point(v));
      cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
      path(cr, px, l->closed);
      stroke(cr, l->width_px, l->colour);
    } else if (const auto* m = std::get_if<Marker>(&primitive)) {
      marker(cr, *m, point(m->at));
    }
  }
}

template <class Point>
void texts(cairo_t* cr, const std::vector<Primitive>& list, Point point) {
  for (const Primitive& primitive : list) {
    const auto* t = std::get_if<Text>(&primitive);
    if (t == nullptr) continue;
    cairo_set_font_size(cr, 8.0 * t->scale);  // an em of 8 font units (internal/font.h)
    cairo_font_extents_t font;
    cairo_font_extents(cr, &font);
    const Vec2 top_left = point(t->at) + t->offset_px;
    cairo_move_to(cr, top_left.x(), top_left.y() + font.ascent);  // the baseline
    setColour(cr, t->colour);
    cairo_show_text(cr, t->text.c_str());
  }
}

void draw(cairo_t* cr, const Scene& scene) {
  setColour(cr, scene.background);
  cairo_paint(cr);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  const Viewport& view = scene.viewport;
  auto world = [&](const Vec2& p) { return view.toPixel(p); };
  auto metres = [&](double m) { return m / view.pixel_size; };
  auto px = [](const Vec2& p) { return p; };
  auto same = [](double l) { return l; };
  shapes(cr, scene.world, world, metres);
  shapes(cr, scene.overlay, px, same);
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  texts(cr, scene.world, world);
  texts(cr, scene.overlay, px);
}

void check(cairo_status_t status) {
  if (status != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(std::string("vector frame: ") + cairo_status_to_string(status));
}

}  // namespace

std::vector<Vec2> arrowDart(const Vec2& c, double h, double heading) {
  // On the image y points down, so the heading's direction is (cos ψ, −sin ψ).
  const Vec2 f(std::cos(heading), -std::sin(heading));
  const Vec2 s(-f.y(), f.x());
  return {c + h * f, c - h * f + 0.8 * h * s, c - 0.45 * h * f, c - h * f - 0.8 * h * s};
}

std::string sceneToVector(const Scene& scene, VectorFormat format) {
  std::string out;
  const double w = scene.viewport.size.width, h = scene.viewport.size.height;
  const std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
      format == VectorFormat::pdf ? cairo_pdf_surface_create_for_stream(appendToString, &out, w, h)
                                  : cairo_svg_surface_create_for_stream(appendToString, &out, w, h),
      cairo_surface_destroy);
  check(cairo_surface_status(surface.get()));
  if (format == VectorFormat::pdf)  // no creation date: the same scene gives the same bytes
    cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATE_DATE, "");
  else
    cairo_svg_surface_set_document_unit(surface.get(), CAIRO_SVG_UNIT_PX);
  {
    const std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr(cairo_create(surface.get()),
                                                                cairo_destroy);
    draw(cr.get(), scene);
    check(cairo_status(cr.get()));
  }
  cairo_surface_finish(surface.get());
  check(cairo_surface_status(surface.get()));
  if (format == VectorFormat::svg) {
    // cairo names the page's group after a process-wide surface counter ("surface16"): one name,
    // so that the same scene gives the same bytes in any process and at any call.
    const std::string group = "<g id=\"surface";
    const std::size_t at = out.find(group);
    const std::size_t end = at == std::string::npos ? at : out.find('"', at + group.size());
    if (end != std::string::npos) out.replace(at + group.size(), end - at - group.size(), "1");
  }
  return out;
}

}  // namespace canopy::render
