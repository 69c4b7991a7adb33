#include "render/internal/tessellate.h"

#include <cmath>
#include <numbers>

#include "render/internal/font.h"
#include "render/internal/text.h"
#include "render/scene_vector.h"

namespace canopy::render::internal {
namespace {

// A polyline gets a round join only where it turns by more than this: below it the gap
// between two butt-ended segments is under a tenth of the line's width.
constexpr double kJoinAngle = 20.0 * std::numbers::pi / 180.0;  // rad

// Round quads reach this far (px) beyond their shape, for the anti-aliased edge's outer half.
constexpr double kFeather = 1.0;

// Where the primitives of one layer land in the image.
struct Transform {
  const Viewport* viewport = nullptr;  // world layer; null for the overlay (already in px)

  Vec2 point(const Vec2& p) const { return viewport ? viewport->toPixel(p) : p; }
  double length(double d) const { return viewport ? d / viewport->pixel_size : d; }  // → px
};

class Builder {
 public:
  explicit Builder(Mesh& out) : out_(out) {}

  void triangle(const Vec2& a, const Vec2& b, const Vec2& c, Rgba colour) {
    batch(false, colour.a < 255, 3);
    for (const Vec2* p : {&a, &b, &c}) vertex(*p, 0.0, 0.0, -1.0, 2.0, 0.0, colour, colour);
  }

  void convex(const std::vector<Vec2>& points, Rgba colour) {
    for (std::size_t i = 2; i < points.size(); ++i) {
      triangle(points[0], points[i - 1], points[i], colour);
    }
  }

  // A circle of radius r (px) centred at c; with edge > 0, its outer band of that width (px)
  // is drawn in `edge_colour`.
  void disc(const Vec2& c, double r, Rgba fill, double edge, Rgba edge_colour) {
    if (!(r > 0.0)) return;
    const bool edged = edge > 0.0;
    quad(c, r, -1.0, edged ? std::max(0.0, r - edge) / r : 2.0, fill, edged ? edge_colour : fill);
  }

  // A circle's outline of `width` px centred on the rim.
  void ring(const Vec2& c, double r, double width, Rgba colour) {
    const double outer = r + 0.5 * width, inner = r - 0.5 * width;
    if (!(outer > 0.0)) return;
    quad(c, outer, inner > 0.0 ? inner / outer : -1.0, 2.0, colour, colour);
  }

  // A butt-ended segment: a round quad whose v runs across the line, ±1 at its sides.
  void segment(const Vec2& a, const Vec2& b, double width, Rgba colour) {
    const Vec2 d = b - a;
    const double length = d.norm(), half = 0.5 * width;
    if (!(length > 0.0) || !(half > 0.0)) return;
    const double reach = (half + kFeather) / half;  // v at the quad's sides
    const Vec2 n = Vec2(-d.y(), d.x()) * ((half + kFeather) / length);
    const Vec2 corners[4] = {a + n, b + n, b - n, a - n};
    const double v[4] = {reach, reach, -reach, -reach};
    batch(true, true, 6);
    for (const int i : {0, 1, 2, 0, 2, 3})
      vertex(corners[i], 0.0, v[i], -1.0, 2.0, half, colour, colour);
  }

  // Segments with round caps, and round joins where the line turns sharply.
  void polyline(const std::vector<Vec2>& points, double width, bool closed, Rgba colour) {
    const std::size_t n = points.size();
    if (n < 2) return;
    const std::size_t segments = closed && n > 2 ? n : n - 1;
    for (std::size_t i = 0; i < segments; ++i)
      segment(points[i], points[(i + 1) % n], width, colour);
    for (std::size_t i = 0; i < n; ++i) {
      const bool end = !closed && (i == 0 || i + 1 == n);
      if (end || sharpTurn(points[(i + n - 1) % n], points[i], points[(i + 1) % n])) {
        disc(points[i], 0.5 * width, colour, 0.0, colour);
      }
    }
  }

  // stb_easy_font draws on a pixel grid: whole-pixel origins keep integer-scaled glyphs crisp.
  void text(const Vec2& top_left, const std::string& text, double scale, Rgba colour) {
    boxes_.clear();
    textBoxes(text, boxes_);
    const Vec2 origin(std::round(top_left.x()), std::round(top_left.y()));
    for (const Aabb& box : boxes_) {
      const Vec2 lo = origin + scale * box.lo, hi = origin + scale * box.hi;
      triangle(lo, Vec2(hi.x(), lo.y()), hi, colour);
      triangle(lo, hi, Vec2(lo.x(), hi.y()), colour);
    }
  }

 private:
  static bool sharpTurn(const Vec2& a, const Vec2& b, const Vec2& c) {
    const Vec2 u = b - a, v = c - b;
    const double nu = u.norm(), nv = v.norm();
    if (!(nu > 0.0 && nv > 0.0)) return true;
    return u.dot(v) < std::cos(kJoinAngle) * nu * nv;
  }

  // A square around c reaching kFeather px beyond the circle of radius r (px); (u, v) = ±1
  // on that circle.
  void quad(const Vec2& c, double r, double inner, double edge, Rgba fill, Rgba edge_colour) {
    const double h = r + kFeather, k = h / r;
    const Vec2 corners[4] = {c + Vec2(-h, -h), c + Vec2(h, -h), c + Vec2(h, h), c + Vec2(-h, h)};
    const double uv[4][2] = {{-k, -k}, {k, -k}, {k, k}, {-k, k}};
    batch(true, true, 6);
    for (const int i : {0, 1, 2, 0, 2, 3}) {
      vertex(corners[i], uv[i][0], uv[i][1], inner, edge, r, fill, edge_colour);
    }
  }

  // Extends the last batch by `vertices`, or starts a new one when the GL state changes.
  void batch(bool round, bool blend, int vertices) {
    if (out_.batches.empty() || out_.batches.back().round != round ||
        out_.batches.back().blend != blend) {
      out_.batches.push_back({static_cast<int>(out_.vertices.size()), 0, round, blend});
    }
    out_.batches.back().count += vertices;
  }

  void vertex(const Vec2& p, double u, double v, double inner, double edge, double scale, Rgba fill,
              Rgba edge_colour) {
    Vertex& x = out_.vertices.emplace_back();
    x.x = static_cast<float>(p.x());
    x.y = static_cast<float>(p.y());
    x.u = static_cast<float>(u);
    x.v = static_cast<float>(v);
    x.inner = static_cast<float>(inner);
    x.edge = static_cast<float>(edge);
    x.scale = static_cast<float>(scale);
    const Rgba* colours[2] = {&fill, &edge_colour};
    std::uint8_t* targets[2] = {x.rgba, x.edge_rgba};
    for (int k = 0; k < 2; ++k) {
      targets[k][0] = colours[k]->r;
      targets[k][1] = colours[k]->g;
      targets[k][2] = colours[k]->b;
      targets[k][3] = colours[k]->a;
    }
  }

  Mesh& out_;
  std::vector<Aabb> boxes_;
};

void marker(Builder& b, const Marker& m, const Vec2& c) {
  const double h = 0.5 * m.size_px, edge = m.edge_px;
  switch (m.shape) {
    case MarkerShape::dot:
      b.disc(c, h, m.fill, edge, m.edge);
      break;
    case MarkerShape::square: {
      const std::vector<Vec2> square = {c + Vec2(-h, -h), c + Vec2(h, -h), c + Vec2(h, h),
                                        c + Vec2(-h, h)};
      b.convex(square, m.fill);
      if (edge > 0.0) b.polyline(square, edge, true, m.edge);
      break;
    }
    case MarkerShape::arrow: {
      // A dart pointing along the heading.
      const std::vector<Vec2> dart = arrowDart(c, h, m.heading);
      b.triangle(dart[0], dart[1], dart[2], m.fill);
      b.triangle(dart[0], dart[2], dart[3], m.fill);
      if (edge > 0.0) b.polyline(dart, edge, true, m.edge);
      break;
    }
    case MarkerShape::cross: {
      // An ×: the edge is the same cross, wider, underneath.
      const double w = std::max(2.0, 0.25 * m.size_px);
      const double d = h / std::sqrt(2.0);
      const Vec2 a(d, d), e(d, -d);
      if (edge > 0.0) {
        b.polyline({c - a, c + a}, w + 2.0 * edge, false, m.edge);
        b.polyline({c - e, c + e}, w + 2.0 * edge, false, m.edge);
      }
      b.polyline({c - a, c + a}, w, false, m.fill);
      b.polyline({c - e, c + e}, w, false, m.fill);
      break;
    }
  }
}

void primitives(const std::vector<Primitive>& list, const Transform& t, Builder& b) {
  std::vector<Vec2> points;
  for (const Primitive& primitive : list) {
    if (const auto* p = std::get_if<Polygon>(&primitive)) {
      points.clear();
      for (const Vec2& v : p->vertices) points.push_back(t.point(v));
      b.convex(points, p->fill);
    } else if (const auto* d = std::get_if<Disc>(&primitive)) {
      b.disc(t.point(d->centre), t.length(d->radius), d->fill, d->edge_px, d->edge);
    } else if (const auto* r = std::get_if<Ring>(&primitive)) {
      b.ring(t.point(r->centre), t.length(r->radius), r->width_px, r->colour);
    } else if (const auto* l = std::get_if<Polyline>(&primitive)) {
      points.clear();
      for (const Vec2& v : l->points) points.push_back(t.point(v));
      b.polyline(points, l->width_px, l->closed, l->colour);
    } else if (const auto* m = std::get_if<Marker>(&primitive)) {
      marker(b, *m, t.point(m->at));
    } else if (const auto* x = std::get_if<Text>(&primitive); x && !Font::instance()) {
      b.text(t.point(x->at) + x->offset_px, x->text, x->scale, x->colour);
    }
  }
}

}  // namespace

void tessellate(const Scene& scene, Mesh& out) {
  Builder builder(out);
  primitives(scene.world, {&scene.viewport}, builder);
  primitives(scene.overlay, {nullptr}, builder);
}

}  // namespace canopy::render::internal
