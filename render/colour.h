#pragma once
// Colours of the top-down frames: 8-bit sRGB with straight (non-premultiplied) alpha.
#include <cstdint>

namespace canopy::render {

struct Rgba {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
  friend bool operator==(const Rgba&, const Rgba&) = default;
};

/// The same colour with another opacity (0 transparent … 255 opaque).
constexpr Rgba withAlpha(Rgba c, std::uint8_t a) {
  return {c.r, c.g, c.b, a};
}

namespace palette {
inline constexpr Rgba kOutside{186, 188, 182, 255};  // ground outside the AOI
inline constexpr Rgba kGround{238, 234, 222, 255};   // ground inside the AOI
inline constexpr Rgba kAoiEdge{120, 120, 112, 255};
inline constexpr Rgba kTreeFill{92, 150, 72, 255};
inline constexpr Rgba kTreeEdge{46, 92, 38, 255};
inline constexpr Rgba kTarget{24, 24, 24, 255};
inline constexpr Rgba kTrunk{92, 64, 40, 255};     // a trunk, where ground robots drive
inline constexpr Rgba kContact{214, 40, 40, 255};  // the ring round a body in contact
inline constexpr Rgba kTrail{70, 70, 70, 200};
inline constexpr Rgba kShadow{60, 60, 60, 70};  // the part of a ground camera's sector crowns hide
inline constexpr Rgba kText{20, 20, 20, 255};
inline constexpr Rgba kPanel{250, 250, 246, 255};
inline constexpr Rgba kPanelEdge{90, 90, 90, 255};
inline constexpr Rgba kWhite{255, 255, 255, 255};
}  // namespace palette

/// UAV i's colour: a qualitative palette without green (the trees' colour), repeating after 8.
Rgba uavColour(int uav);

}  // namespace canopy::render
