#pragma once
// What the map's layers (scene_builder.cpp) and the overlay (overlay.cpp) share: the sizes of
// symbols and text, which scale with the image, a rectangle's outline and a body's name.
#include <string>
#include <vector>

#include "core/types.h"

namespace canopy::render::internal {

// Pixel sizes scale with the text: u = 1 at the default 800 px wide frame.
struct Sizes {
  double text;  // font units → px
  double u;     // px per nominal px
};

inline std::vector<Vec2> rectangle(const Vec2& lo, const Vec2& hi) {
  return {lo, Vec2(hi.x(), lo.y()), hi, Vec2(lo.x(), hi.y())};
}

// names[i], or prefix + (i + 1) when it is missing ("uav1", "T2").
inline std::string nameOr(const std::vector<std::string>& names, std::size_t i,
                          const char* prefix) {
  return i < names.size() && !names[i].empty() ? names[i] : prefix + std::to_string(i + 1);
}

}  // namespace canopy::render::internal
