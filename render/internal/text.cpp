#include "render/internal/text.h"

#include <stb/stb_easy_font.h>

#include <cstring>

#include "render/internal/font.h"

namespace canopy::render::internal {
namespace {

// stb_easy_font indexes a table by (c − 32) and takes mutable strings: printable ASCII only.
std::string printable(const std::string& text) {
  std::string s = text;
  for (char& c : s) {
    if (c < 32 || c > 126) c = '?';
  }
  return s;
}

// Layout of stb_easy_font's vertex buffer: x, y, z as floats, then four colour bytes.
struct FontVertex {
  float x, y, z;
  unsigned char rgba[4];
};
static_assert(sizeof(FontVertex) == 16);

}  // namespace

double textWidth(const std::string& text) {
  if (const Font* font = Font::instance()) return font->advance(text);
  std::string s = printable(text);
  return stb_easy_font_width(s.data());
}

void textBoxes(const std::string& text, std::vector<Aabb>& out) {
  std::string s = printable(text);
  // At most 11 quads (44 vertices) per printable character; every quad is 4 vertices.
  std::vector<FontVertex> buffer(s.size() * 48 + 4);
  const int bytes = static_cast<int>(buffer.size() * sizeof(FontVertex));
  const int quads = stb_easy_font_print(0.0f, 0.0f, s.data(), nullptr, buffer.data(), bytes);
  for (int q = 0; q < quads; ++q) {
    // Corners come as (x0,y0), (x1,y0), (x1,y1), (x0,y1).
    const FontVertex& a = buffer[4 * q];
    const FontVertex& c = buffer[4 * q + 2];
    out.push_back({Vec2(a.x, a.y), Vec2(c.x, c.y)});
  }
}

}  // namespace canopy::render::internal
