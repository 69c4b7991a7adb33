#pragma once
// The outline of a polygonal crown or wall, as offsets of its vertices from its area centroid.
#include <array>

#include "core/types.h"

namespace canopy::sensing {

struct Outline {
  static constexpr int kMaxVertices = 8;  // as world::TreeDef::polygon
  std::array<Vec2, kMaxVertices> offsets = zeros();  // m, vertex − centroid, in vertex order
  int vertices = 0;  // 0: no outline (a disc)

 private:
  static std::array<Vec2, kMaxVertices> zeros() {
    std::array<Vec2, kMaxVertices> z;
    z.fill(Vec2::Zero());
    return z;
  }
};

}  // namespace canopy::sensing
