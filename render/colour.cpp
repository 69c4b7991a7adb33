#include "render/colour.h"

namespace canopy::render {

Rgba uavColour(int uav) {
  static constexpr Rgba kPalette[] = {
      {31, 119, 180, 255}, {230, 120, 20, 255}, {148, 103, 189, 255}, {214, 39, 40, 255},
      {23, 170, 190, 255}, {140, 86, 75, 255},  {227, 119, 194, 255}, {188, 170, 34, 255}};
  constexpr int n = sizeof kPalette / sizeof kPalette[0];
  return kPalette[((uav % n) + n) % n];
}

}  // namespace canopy::render
