#include "render/internal/font.h"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_ADVANCES_H

#include <cmath>
#include <cstdint>
#include <mutex>
#include <vector>

namespace canopy::render::internal {
namespace {

// UTF-8 → code points; a malformed byte becomes U+FFFD.
std::vector<char32_t> codePoints(const std::string& text) {
  std::vector<char32_t> out;
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    int extra = c < 0x80 ? 0 : (c >> 5) == 6 ? 1 : (c >> 4) == 14 ? 2 : (c >> 3) == 30 ? 3 : -1;
    if (extra < 0 || i + static_cast<std::size_t>(extra) >= text.size()) {
      out.push_back(0xFFFD);
      ++i;
      continue;
    }
    char32_t cp = extra == 0 ? c : c & (0x3F >> extra);
    bool ok = true;
    for (int k = 1; k <= extra; ++k) {
      const auto d = static_cast<unsigned char>(text[i + static_cast<std::size_t>(k)]);
      ok = ok && (d >> 6) == 2;
      cp = (cp << 6) | (d & 0x3F);
    }
    out.push_back(ok ? cp : 0xFFFD);
    i += ok ? static_cast<std::size_t>(extra) + 1 : 1;
  }
  return out;
}

std::mutex font_mutex;  // FreeType faces are not thread-safe

}  // namespace

struct Font::Face {
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  ~Face() {
    if (face) FT_Done_Face(face);
    if (library) FT_Done_FreeType(library);
  }
};

Font::~Font() = default;

Font* Font::instance() {
  static const std::unique_ptr<Font> font = []() -> std::unique_ptr<Font> {
    auto face = std::make_unique<Face>();
    if (FT_Init_FreeType(&face->library) != 0) return nullptr;
    if (FT_New_Face(face->library, kFontPath, 0, &face->face) != 0) return nullptr;
    std::unique_ptr<Font> f(new Font());
    f->face_ = std::move(face);
    return f;
  }();
  return font.get();
}

double Font::advance(const std::string& text) const {
  const std::lock_guard<std::mutex> lock(font_mutex);
  FT_Face face = face_->face;
  double units = 0.0;
  for (const char32_t c : codePoints(text)) {
    FT_Fixed advance = 0;
    if (FT_Get_Advance(face, FT_Get_Char_Index(face, c), FT_LOAD_NO_SCALE, &advance) == 0)
      units += static_cast<double>(advance);
  }
  return units * kUnitsPerEm / face->units_per_EM;
}

void Font::draw(Image& image, const Vec2& top_left, const std::string& text, double scale,
                Rgba colour) {
  const std::lock_guard<std::mutex> lock(font_mutex);
  FT_Face face = face_->face;
  const double em = kUnitsPerEm * scale;  // px
  if (FT_Set_Pixel_Sizes(face, 0, static_cast<FT_UInt>(std::max(1.0, std::round(em)))) != 0) return;
  const double baseline = std::round(top_left.y() + em * face->ascender / face->units_per_EM);
  double pen = top_left.x();
  const int w = image.size.width, h = image.size.height;
  for (const char32_t c : codePoints(text)) {
    const FT_UInt glyph = FT_Get_Char_Index(face, c);
    FT_Fixed advance = 0;
    FT_Get_Advance(face, glyph, FT_LOAD_NO_SCALE, &advance);
    if (FT_Load_Glyph(face, glyph, FT_LOAD_RENDER) == 0) {
      const FT_Bitmap& bitmap = face->glyph->bitmap;
      const int x0 = static_cast<int>(std::round(pen)) + face->glyph->bitmap_left;
      const int y0 = static_cast<int>(baseline) - face->glyph->bitmap_top;
      for (unsigned row = 0; row < bitmap.rows; ++row) {
        const int y = y0 + static_cast<int>(row);
        if (y < 0 || y >= h) continue;
        for (unsigned col = 0; col < bitmap.width; ++col) {
          const int x = x0 + static_cast<int>(col);
          if (x < 0 || x >= w) continue;
          const unsigned coverage = bitmap.buffer[row * static_cast<unsigned>(bitmap.pitch) + col];
          if (coverage == 0) continue;
          // out = a·colour + (1 − a)·dst with a = coverage · alpha.
          const unsigned a = coverage * colour.a / 255u;
          std::uint8_t* px = image.rgb.data() + (static_cast<std::size_t>(y) * w + x) * 3;
          const std::uint8_t src[3] = {colour.r, colour.g, colour.b};
          for (int k = 0; k < 3; ++k)
            px[k] = static_cast<std::uint8_t>((src[k] * a + px[k] * (255u - a) + 127u) / 255u);
        }
      }
    }
    pen += static_cast<double>(advance) * em / face->units_per_EM;
  }
}

}  // namespace canopy::render::internal
