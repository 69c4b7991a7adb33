#include "world/tree.h"

#include <box2d/b2_common.h>
#include <box2d/b2_math.h>
#include <box2d/b2_settings.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "world/plane_geometry.h"

namespace canopy::world {
static_assert(kMaxPolygonVertices == static_cast<std::size_t>(b2_maxPolygonVertices));
namespace {
using plane::cross;
using plane::metres;
using plane::pointSegmentDistance;
}  // namespace

TreeDef TreeDef::disc(const Vec2& centre, double radius) {
  TreeDef tree;
  tree.shape = TreeShape::disc;
  tree.centre = centre;
  tree.radius = radius;
  tree.trunk_radius = defaultTrunkRadius(radius);
  return tree;
}

double defaultTrunkRadius(double crown_radius) {
  return std::min(crown_radius, std::clamp(0.1 * crown_radius, 0.05, 0.5));
}

double solidDistance(const TreeDef& tree, const Vec2& p) {
  if (!isWall(tree)) return (p - tree.centre).norm() - tree.trunk_radius;
  // A convex polygon: 0 inside, else the distance to the nearest edge.
  const std::vector<Vec2>& v = tree.vertices;
  bool inside = true;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec2& a = v[i];
    const Vec2& b = v[(i + 1) % v.size()];
    const Vec2 e = b - a;
    if (cross(e, p - a) < 0.0) inside = false;  // right of a counter-clockwise edge: outside
    const double s = std::clamp((p - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (a + s * e - p).norm());
  }
  return inside ? 0.0 : best;
}

namespace {
// True when the segments a → b and c → d cross or touch; collinear ones are left to the
// distances of their ends.
bool segmentsCross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  if (d1 == 0.0 && d2 == 0.0) return false;
  return d1 * d2 <= 0.0 && d3 * d4 <= 0.0;
}
}  // namespace

double solidDistance(const TreeDef& tree, const Vec2& a, const Vec2& b) {
  if (!isWall(tree)) return pointSegmentDistance(tree.centre, a, b) - tree.trunk_radius;
  // A convex polygon: 0 when an end is inside or the segment crosses an edge; else the nearest
  // of the ends to the edges and of the vertices to the segment.
  if (solidDistance(tree, a) == 0.0 || solidDistance(tree, b) == 0.0) return 0.0;
  const std::vector<Vec2>& v = tree.vertices;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec2& c = v[i];
    const Vec2& d = v[(i + 1) % v.size()];
    if (segmentsCross(a, b, c, d)) return 0.0;
    best = std::min({best, pointSegmentDistance(a, c, d), pointSegmentDistance(b, c, d),
                     pointSegmentDistance(c, a, b)});
  }
  return best;
}

double signedArea(const std::vector<Vec2>& vertices) {
  double twice_area = 0.0;  // shoelace formula
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    twice_area += cross(vertices[i], vertices[(i + 1) % vertices.size()]);
  }
  return 0.5 * twice_area;
}

bool isStrictlyConvex(const std::vector<Vec2>& vertices) {
  const std::size_t n = vertices.size();
  if (n < 3) return false;
  int sign = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 e1 = vertices[(i + 1) % n] - vertices[i];
    const Vec2 e2 = vertices[(i + 2) % n] - vertices[(i + 1) % n];
    const double turn = cross(e1, e2);
    if (turn == 0.0) return false;
    const int s = turn > 0.0 ? 1 : -1;
    if (sign != 0 && s != sign) return false;
    sign = s;
  }
  // Turning the same way at every vertex could still wind twice; the angles must sum to 2π.
  double total_turn = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 e1 = vertices[(i + 1) % n] - vertices[i];
    const Vec2 e2 = vertices[(i + 2) % n] - vertices[(i + 1) % n];
    total_turn += std::atan2(cross(e1, e2), e1.dot(e2));
  }
  return std::abs(std::abs(total_turn) - 2.0 * std::numbers::pi) < 1e-6;
}

TreeDef TreeDef::polygon(std::vector<Vec2> vertices) {
  if (signedArea(vertices) < 0.0) std::reverse(vertices.begin(), vertices.end());
  const double area = signedArea(vertices);
  Vec2 centroid = Vec2::Zero();  // c = Σ (v_i + v_{i+1}) cross(v_i, v_{i+1}) / (6 A)
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const Vec2& a = vertices[i];
    const Vec2& b = vertices[(i + 1) % vertices.size()];
    centroid += (a + b) * cross(a, b);
  }
  TreeDef tree;
  tree.shape = TreeShape::polygon;
  tree.centre = centroid / (6.0 * area);
  tree.radius = std::sqrt(area / std::numbers::pi);  // disc of equal area
  tree.vertices = std::move(vertices);
  tree.trunk_radius = 0.0;  // a wall
  return tree;
}

bool strictlyInside(const TreeDef& tree, const Vec2& p) {
  if (tree.shape == TreeShape::disc)
    return (p - tree.centre).squaredNorm() < tree.radius * tree.radius;
  const std::size_t n = tree.vertices.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = tree.vertices[i];
    const Vec2& b = tree.vertices[(i + 1) % n];
    if (cross(b - a, p - a) <= 0.0) return false;  // on or right of a CCW edge: not inside
  }
  return true;
}

double segmentEntry(const TreeDef& tree, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  if (tree.shape == TreeShape::disc) {
    // |a + s d − c|² = r²  →  (d·d) s² + 2 (d·f) s + (f·f − r²) = 0 with f = a − c.
    const Vec2 f = a - tree.centre;
    const double r2 = tree.radius * tree.radius;
    const double c = f.squaredNorm() - r2;
    if (c < 0.0) return 0.0;  // a strictly inside
    const double dd = d.squaredNorm();
    if (dd == 0.0) return -1.0;
    const double bq = d.dot(f);
    const double disc = bq * bq - dd * c;
    if (disc <= 0.0) return -1.0;  // misses or only touches the rim
    const double s = (-bq - std::sqrt(disc)) / dd;
    return (s >= 0.0 && s < 1.0) ? s : -1.0;
  }
  // Cyrus–Beck clipping against the edges' half-planes cross(e, x − v) > 0.
  double s_in = 0.0, s_out = 1.0;
  const std::size_t n = tree.vertices.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& v = tree.vertices[i];
    const Vec2 e = tree.vertices[(i + 1) % n] - v;
    const double start = cross(e, a - v);  // > 0 inside this half-plane
    const double rate = cross(e, d);
    if (rate == 0.0) {
      if (start <= 0.0) return -1.0;  // parallel and outside (or on) this edge
      continue;
    }
    const double s = -start / rate;  // where the segment meets the edge's line
    if (rate > 0.0) {
      s_in = std::max(s_in, s);
    } else {
      s_out = std::min(s_out, s);
    }
    if (s_in >= s_out) return -1.0;
  }
  return s_in;
}

bool blocksSight(const TreeDef& tree, const Vec2& a, double ha, const Vec2& b, double hb) {
  double s_in = 0.0, s_out = 1.0;
  if ((b - a).squaredNorm() == 0.0) {
    if (!strictlyInside(tree, a)) return false;
  } else {
    s_in = segmentEntry(tree, a, b);
    if (s_in < 0.0) return false;
    const double back = segmentEntry(tree, b, a);  // entry of b → a: 1 − s_out
    s_out = back < 0.0 ? 1.0 : 1.0 - back;
  }
  const double h_in = ha + (hb - ha) * s_in;  // h(s) = ha + (hb − ha) s
  const double h_out = ha + (hb - ha) * s_out;
  return std::max(h_in, h_out) > tree.base && std::min(h_in, h_out) < tree.top;
}

Aabb bounds(const TreeDef& tree) {
  if (tree.shape == TreeShape::disc) {
    const Vec2 r(tree.radius, tree.radius);
    return {tree.centre - r, tree.centre + r};
  }
  Aabb box{tree.vertices.front(), tree.vertices.front()};
  for (const Vec2& v : tree.vertices) {
    box.lo = box.lo.cwiseMin(v);
    box.hi = box.hi.cwiseMax(v);
  }
  return box;
}

namespace {


// Box2D's b2PolygonShape::Set (2.4.1) on float vertices: the number of vertices its
// gift-wrapping hull keeps (it keeps the rightmost and every vertex with a strict left turn).
int box2dHullSize(const std::vector<b2Vec2>& ps) {
  const int n = static_cast<int>(ps.size());
  int i0 = 0;
  float x0 = ps[0].x;
  for (int i = 1; i < n; ++i) {
    const float x = ps[i].x;
    if (x > x0 || (x == x0 && ps[i].y < ps[i0].y)) {
      i0 = i;
      x0 = x;
    }
  }
  int m = 0;
  int ih = i0;
  for (;;) {
    if (m > n) return -1;  // cannot happen for finite input; never loop
    int ie = 0;
    for (int j = 1; j < n; ++j) {
      if (ie == ih) {
        ie = j;
        continue;
      }
      const b2Vec2 r = ps[ie] - ps[ih];
      const b2Vec2 v = ps[j] - ps[ih];
      const float c = b2Cross(r, v);
      if (c < 0.0f) ie = j;
      if (c == 0.0f && v.LengthSquared() > r.LengthSquared()) ie = j;
    }
    ++m;
    ih = ie;
    if (ie == i0) break;
  }
  return m;
}

// Box2D's ComputeCentroid area (float, from the first vertex), which it asserts > b2_epsilon.
float box2dArea(const std::vector<b2Vec2>& vs) {
  float area = 0.0f;
  const b2Vec2 s = vs[0];
  for (std::size_t i = 0; i < vs.size(); ++i) {
    const b2Vec2 p2 = vs[i] - s;
    const b2Vec2 p3 = (i + 1 < vs.size() ? vs[i + 1] : vs[0]) - s;
    area += 0.5f * b2Cross(p2, p3);
  }
  return area;
}

// The convex polygon's width: over its edges, the least of the farthest vertex's distance from
// the edge's line (counter-clockwise vertices).
std::pair<double, std::size_t> widthOf(const std::vector<Vec2>& ccw) {
  double width = std::numeric_limits<double>::infinity();
  std::size_t at = 0;
  for (std::size_t i = 0; i < ccw.size(); ++i) {
    const Vec2 e = ccw[(i + 1) % ccw.size()] - ccw[i];
    double farthest = 0.0;
    for (const Vec2& v : ccw) farthest = std::max(farthest, cross(e, v - ccw[i]) / e.norm());
    if (farthest < width) {
      width = farthest;
      at = i;
    }
  }
  return {width, at};
}

}  // namespace

std::string box2dPolygonProblem(const std::vector<Vec2>& vertices) {
  const std::size_t n = vertices.size();
  if (n < 3 || n > static_cast<std::size_t>(b2_maxPolygonVertices)) {
    return "expected 3 to " + std::to_string(b2_maxPolygonVertices) +
           " vertices (Box2D's b2_maxPolygonVertices), got " + std::to_string(n);
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!vertices[i].allFinite() || vertices[i].cwiseAbs().maxCoeff() > kMaxTreeCoordinate) {
      return "vertex " + std::to_string(i) +
             ": expected coordinates within ±1e7 m (Box2D keeps them as floats)";
    }
  }
  // What Box2D receives: the vertices rounded to floats.
  std::vector<b2Vec2> floats;
  std::vector<Vec2> rounded;
  for (const Vec2& v : vertices) {
    floats.emplace_back(static_cast<float>(v.x()), static_cast<float>(v.y()));
    rounded.emplace_back(floats.back().x, floats.back().y);
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      const double d = (rounded[j] - rounded[i]).norm();
      if (d < kMinPolygonEdge) {
        return "vertices " + std::to_string(i) + " and " + std::to_string(j) +
               ": expected at least 0.05 m apart (Box2D welds vertices closer than its linear "
               "slop), got " +
               metres(d) + " m";
      }
    }
  }
  if (!isStrictlyConvex(vertices)) {
    return "expected the vertices of a convex polygon in order, with no three in a line";
  }
  if (!isStrictlyConvex(rounded) || box2dHullSize(floats) != static_cast<int>(n)) {
    return "expected the vertices of a convex polygon in order, with no three in a line as "
           "Box2D's floats (rounded to float these vertices are not strictly convex)";
  }
  // Robust to rounding: "in a line" means within the slop of the chord of its neighbours, in
  // double and as floats; and the polygon is at least the slop wide in both.
  for (const std::vector<Vec2>* shape :
       {&vertices, static_cast<const std::vector<Vec2>*>(&rounded)}) {
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2& a = (*shape)[(i + n - 1) % n];
      const Vec2& b = (*shape)[(i + 1) % n];
      const double off = std::abs(cross(b - a, (*shape)[i] - a)) / (b - a).norm();
      if (!(off >= b2_linearSlop)) {
        return "vertex " + std::to_string(i) +
               ": expected the vertices of a convex polygon with no three in a line, this one "
               "lies " +
               metres(off) + " m from the line through its neighbours (Box2D's linear slop is " +
               metres(b2_linearSlop) + " m)";
      }
    }
  }
  std::vector<Vec2> ccw = vertices, ccw_rounded = rounded;
  if (signedArea(ccw) < 0.0) std::reverse(ccw.begin(), ccw.end());
  if (signedArea(ccw_rounded) < 0.0) std::reverse(ccw_rounded.begin(), ccw_rounded.end());
  auto [width, edge] = widthOf(ccw);
  if (const auto [w, e] = widthOf(ccw_rounded); w < width) {
    width = w;
    edge = e;
  }
  const float area = std::abs(box2dArea(floats));
  if (!(width >= b2_linearSlop) || !(area > 100.0f * b2_epsilon)) {
    return "expected a polygon at least " + metres(b2_linearSlop) +
           " m wide (Box2D's linear slop), got " + metres(width) + " m across from edge " +
           std::to_string(edge) + " (" + metres(area) + " m² in all)";
  }
  return "";
}

std::string box2dProblem(const TreeDef& tree) {
  if (tree.shape == TreeShape::polygon) return box2dPolygonProblem(tree.vertices);
  if (!tree.centre.allFinite() || tree.centre.cwiseAbs().maxCoeff() > kMaxTreeCoordinate)
    return "expected a centre within ±1e7 m (Box2D keeps coordinates as floats)";
  if (!(tree.radius > 0.0 && tree.radius <= kMaxTreeCoordinate) ||
      !(static_cast<float>(tree.radius) > 0.0f)) {
    return "expected a radius in (0, 1e7] m that stays positive as a float, got " +
           metres(tree.radius);
  }
  return "";
}

}  // namespace canopy::world
