#pragma once
// Scene → triangles in output pixels (pure; no GL). Two kinds of triangles:
//  - solid (polygons, text, marker bodies): every fragment whose centre is inside, one colour;
//  - round quads (discs, rings, line segments): the fragment shader measures the distance to the
//    shape's edges in the quad's own coordinates and turns it into coverage, so circles are
//    exact at any size and their edges and lines are anti-aliased analytically. A line segment
//    is a round quad with u = 0: its coverage depends on the distance across the line only.
#include <cstdint>
#include <vector>

#include "render/scene.h"

namespace canopy::render::internal {

/// One vertex. For a round quad, r = √(u² + v²) is the distance from the shape's centre (line)
/// in units of its outer radius (half-width) R = `scale` px: the shape covers inner ≤ r ≤ 1
/// and takes the edge colour where r ≥ edge. Solid triangles carry u = v = 0, inner = −1,
/// edge = 2 and scale = 0.
struct Vertex {
  float x = 0.0f, y = 0.0f;  // output px, (0, 0) top-left, y down
  float u = 0.0f, v = 0.0f;
  float inner = -1.0f;
  float edge = 2.0f;
  float scale = 0.0f;  // px per unit of r; 0 for solid triangles
  std::uint8_t rgba[4] = {0, 0, 0, 255};
  std::uint8_t edge_rgba[4] = {0, 0, 0, 255};
};
static_assert(sizeof(Vertex) == 36);

/// A run of consecutive triangles drawn with the same GL state. Solid triangles use a program
/// without the per-fragment distance test and skip blending when opaque, which llvmpipe fills
/// several times faster; round quads always blend (their edges are partly covered).
struct Batch {
  int first = 0;       // first vertex
  int count = 0;       // vertices (three per triangle)
  bool round = false;  // round quads (else solid triangles)
  bool blend = false;
};

struct Mesh {
  std::vector<Vertex> vertices;  // triangles, in drawing order
  std::vector<Batch> batches;    // cover `vertices` in order

  void clear() {
    vertices.clear();
    batches.clear();
  }
};

/// Appends the scene's triangles, in drawing order.
void tessellate(const Scene& scene, Mesh& out);

}  // namespace canopy::render::internal
