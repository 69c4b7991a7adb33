#include "render/viewport.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace canopy::render {

Viewport Viewport::fit(const Aabb& view, ImageSize size) {
  Viewport v;
  v.size = size;
  v.pixel_size = std::max(view.width() / size.width, view.height() / size.height);
  // Centre the view: the image spans size · pixel_size metres, the view fills one direction.
  const Vec2 extent(size.width * v.pixel_size, size.height * v.pixel_size);
  const Vec2 centre = 0.5 * (view.lo + view.hi);
  v.top_left = Vec2(centre.x() - 0.5 * extent.x(), centre.y() + 0.5 * extent.y());
  return v;
}

std::optional<ImageSize> parseImageSize(std::string_view text) {
  const std::size_t x = text.find('x');
  if (x == std::string_view::npos) return std::nullopt;
  const auto side = [](std::string_view s) -> std::optional<int> {
    int v = 0;
    const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || error != std::errc() || end != s.data() + s.size()) return std::nullopt;
    if (s[0] == '0' || s[0] == '-') return std::nullopt;  // plain digits: no "0800", no sign
    if (v < kMinImageSide || v > kMaxImageSide) return std::nullopt;
    return v;
  };
  const auto w = side(text.substr(0, x)), h = side(text.substr(x + 1));
  if (!w || !h) return std::nullopt;
  return ImageSize{*w, *h};
}

Aabb withMargin(const Aabb& box, double fraction) {
  const double m = fraction * std::max(box.width(), box.height());
  return {box.lo - Vec2(m, m), box.hi + Vec2(m, m)};
}

ImageSize fitSize(const Aabb& view, int long_side) {
  const auto even = [](double x) {
    return std::max(2, 2 * static_cast<int>(std::lround(0.5 * x)));
  };
  if (view.width() >= view.height()) {
    return {even(long_side), even(long_side * view.height() / view.width())};
  }
  return {even(long_side * view.width() / view.height()), even(long_side)};
}

}  // namespace canopy::render
