#include "world/convex_pieces.h"

#include <box2d/b2_common.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

#include "world/plane_geometry.h"
#include "world/tree.h"

namespace canopy::world {
namespace {

using plane::cross;
using plane::metres;
using plane::pointSegmentDistance;

// Orientation of c against the directed line a → b: > 0 left, < 0 right, 0 on it.
double orient(const Vec2& a, const Vec2& b, const Vec2& c) {
  return cross(b - a, c - a);
}
// c on the segment a → b, given that the three are collinear.
bool withinBox(const Vec2& a, const Vec2& b, const Vec2& c) {
  return std::min(a.x(), b.x()) <= c.x() && c.x() <= std::max(a.x(), b.x()) &&
         std::min(a.y(), b.y()) <= c.y() && c.y() <= std::max(a.y(), b.y());
}
// True when the closed segments a–b and c–d share a point.
bool segmentsMeet(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double o1 = orient(a, b, c), o2 = orient(a, b, d);
  const double o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
    return true;
  return (o1 == 0 && withinBox(a, b, c)) || (o2 == 0 && withinBox(a, b, d)) ||
         (o3 == 0 && withinBox(c, d, a)) || (o4 == 0 && withinBox(c, d, b));
}

// How far a new diagonal must pass from every other vertex, m: twice Box2D's linear slop.
constexpr double kEarClearance = 2.0 * b2_linearSlop;


// The smallest angle of the triangle a, b, c (rad).
double smallestAngle(const Vec2& a, const Vec2& b, const Vec2& c) {
  auto angle = [](const Vec2& at, const Vec2& u, const Vec2& w) {
    const Vec2 e1 = u - at, e2 = w - at;
    return std::atan2(std::abs(cross(e1, e2)), e1.dot(e2));
  };
  return std::min({angle(a, b, c), angle(b, c, a), angle(c, a, b)});
}

// Ear clipping of a counter-clockwise simple polygon into triangles of vertex indices.
std::vector<std::vector<int>> earClip(const std::vector<Vec2>& v) {
  const int n = static_cast<int>(v.size());
  std::vector<int> prev(v.size()), next(v.size());
  for (int i = 0; i < n; ++i) {
    prev[i] = (i + n - 1) % n;
    next[i] = (i + 1) % n;
  }
  // An ear at i: a strictly convex corner whose triangle (prev, i, next) holds no other remaining
  // vertex, not even on its boundary, and whose new edge (the diagonal prev–next) passes no other
  // vertex closer than `clearance` (a diagonal through a vertex, as the L's from corner to corner
  // through its reflex corner, would leave a flat sliver behind); its score is the triangle's
  // smallest angle (−1: no ear).
  double clearance = kEarClearance;
  auto earScore = [&](int i) {
    const Vec2 &p = v[prev[i]], &c = v[i], &q = v[next[i]];
    if (!(orient(p, c, q) > 0.0)) return -1.0;
    for (int j = next[next[i]]; j != prev[i]; j = next[j]) {
      const Vec2& x = v[j];
      if (orient(p, c, x) >= 0.0 && orient(c, q, x) >= 0.0 && orient(q, p, x) >= 0.0) return -1.0;
      if (clearance > 0.0 && pointSegmentDistance(x, p, q) < clearance) return -1.0;
    }
    return smallestAngle(p, c, q);
  };
  std::vector<double> score(v.size());
  for (int i = 0; i < n; ++i) score[i] = earScore(i);
  std::vector<std::vector<int>> triangles;
  int start = 0;
  for (int remaining = n; remaining > 3; --remaining) {
    int best = -1;
    int i = start;
    do {
      if (score[i] >= 0.0 && (best < 0 || score[i] > score[best])) best = i;
      i = next[i];
    } while (i != start);
    if (best < 0 && clearance > 0.0) {
      // No ear keeps its diagonal clear of every vertex: take the exact test (the pieces are
      // then checked for Box2D as every piece is).
      clearance = 0.0;
      for (int k = next[start]; ; k = next[k]) {
        score[k] = earScore(k);
        if (k == start) break;
      }
      ++remaining;
      continue;
    }
    if (best < 0) throw std::invalid_argument("no ear found (the polygon is not simple)");
    triangles.push_back({prev[best], best, next[best]});
    next[prev[best]] = next[best];
    prev[next[best]] = prev[best];
    start = next[best];
    score[prev[best]] = earScore(prev[best]);
    score[next[best]] = earScore(next[best]);
  }
  triangles.push_back({prev[start], start, next[start]});
  return triangles;
}

std::string indexList(const std::vector<int>& piece) {
  std::string text;
  for (std::size_t k = 0; k < piece.size(); ++k)
    text += (k ? (k + 1 == piece.size() ? " and " : ", ") : "") + std::to_string(piece[k]);
  return text;
}

}  // namespace

std::string simplePolygonProblem(const std::vector<Vec2>& vertices) {
  const std::size_t n = vertices.size();
  if (n < 3 || n > kMaxWallVertices) {
    return "expected 3 to " + std::to_string(kMaxWallVertices) + " vertices, got " +
           std::to_string(n);
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!vertices[i].allFinite() || vertices[i].cwiseAbs().maxCoeff() > kMaxTreeCoordinate) {
      return "vertex " + std::to_string(i) +
             ": expected coordinates within ±1e7 m (Box2D keeps them as floats)";
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      const double d = (vertices[j] - vertices[i]).norm();
      if (d < kMinPolygonEdge) {
        return "vertices " + std::to_string(i) + " and " + std::to_string(j) +
               ": expected at least 0.05 m apart, got " + metres(d) + " m";
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& a = vertices[(i + n - 1) % n];
    const Vec2& b = vertices[(i + 1) % n];
    const double off = std::abs(orient(a, b, vertices[i])) / (b - a).norm();
    if (!(off >= b2_linearSlop)) {
      return "vertex " + std::to_string(i) + ": expected no three vertices in a line, this one lies " +
             metres(off) + " m from the line through its neighbours (at least " +
             metres(b2_linearSlop) + " m, Box2D's linear slop)";
    }
  }
  // Edges i (i → i+1) and j (j → j+1) that are not neighbours must not meet.
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours through vertex 0
      if (segmentsMeet(vertices[i], vertices[(i + 1) % n], vertices[j], vertices[(j + 1) % n])) {
        return "edges " + std::to_string(i) + " (vertices " + std::to_string(i) + " to " +
               std::to_string((i + 1) % n) + ") and " + std::to_string(j) + " (vertices " +
               std::to_string(j) + " to " + std::to_string((j + 1) % n) +
               ") cross: expected a simple polygon (no self-crossing outline)";
      }
    }
  }
  if (signedArea(vertices) == 0.0) return "expected a polygon with a non-zero area";
  return "";
}

std::vector<std::vector<Vec2>> convexPieces(const std::vector<Vec2>& vertices,
                                            std::size_t max_vertices) {
  std::vector<Vec2> v = vertices;
  const bool reversed = signedArea(v) < 0.0;
  if (reversed) std::reverse(v.begin(), v.end());
  const int n = static_cast<int>(v.size());
  // The caller's numbering of a counter-clockwise index, for messages.
  auto original = [&](int i) { return reversed ? n - 1 - i : i; };

  std::vector<std::vector<int>> pieces = earClip(v);
  std::vector<bool> alive(pieces.size(), true);
  auto points = [&](const std::vector<int>& piece) {
    std::vector<Vec2> out;
    for (int i : piece) out.push_back(v[static_cast<std::size_t>(i)]);
    return out;
  };
  // Hertel–Mehlhorn: remove a diagonal u–v between piece a (edge u → v) and piece b (edge v → u)
  // when their union is convex and Box2D takes it.
  std::map<std::pair<int, int>, int> owner;  // directed edge → piece
  for (std::size_t a = 0; a < pieces.size(); ++a) {
    for (std::size_t k = 0; k < pieces[a].size(); ++k)
      owner[{pieces[a][k], pieces[a][(k + 1) % pieces[a].size()]}] = static_cast<int>(a);
  }
  for (std::size_t a = 0; a < pieces.size(); ++a) {
    if (!alive[a]) continue;
    bool merged = true;
    while (merged) {
      merged = false;
      const std::vector<int>& pa = pieces[a];
      for (std::size_t k = 0; k < pa.size() && !merged; ++k) {
        const int u = pa[k], w = pa[(k + 1) % pa.size()];
        const auto found = owner.find({w, u});
        if (found == owner.end()) continue;  // a boundary edge
        const auto b = static_cast<std::size_t>(found->second);
        const std::vector<int>& pb = pieces[b];
        if (pa.size() + pb.size() - 2 > max_vertices) continue;
        // a from w round to u, then b's vertices strictly between u and w.
        std::vector<int> joined;
        for (std::size_t s = 0; s < pa.size(); ++s) joined.push_back(pa[(k + 1 + s) % pa.size()]);
        const auto at_u =
            static_cast<std::size_t>(std::find(pb.begin(), pb.end(), u) - pb.begin());
        for (std::size_t s = 1; s + 1 < pb.size(); ++s) joined.push_back(pb[(at_u + s) % pb.size()]);
        if (!isStrictlyConvex(points(joined)) || !box2dPolygonProblem(points(joined)).empty())
          continue;
        owner.erase({u, w});
        owner.erase({w, u});
        for (std::size_t s = 0; s < pb.size(); ++s) {
          const std::pair<int, int> edge{pb[s], pb[(s + 1) % pb.size()]};
          if (auto it = owner.find(edge); it != owner.end()) it->second = static_cast<int>(a);
        }
        pieces[a] = std::move(joined);
        alive[b] = false;
        merged = true;
      }
    }
  }
  std::vector<std::vector<Vec2>> out;
  for (std::size_t a = 0; a < pieces.size(); ++a) {
    if (!alive[a]) continue;
    std::vector<Vec2> piece = points(pieces[a]);
    if (const std::string problem = box2dPolygonProblem(piece); !problem.empty()) {
      std::vector<int> named;
      for (int i : pieces[a]) named.push_back(original(i));
      throw std::invalid_argument("the convex piece made of vertices " + indexList(named) +
                                  " cannot be a Box2D polygon: " + problem);
    }
    out.push_back(std::move(piece));
  }
  return out;
}

}  // namespace canopy::world
