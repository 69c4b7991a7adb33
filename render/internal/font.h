#pragma once
// Real text: DejaVu Sans (Debian fonts-dejavu-core) rasterised by FreeType (libfreetype-dev),
// anti-aliased and composited onto the finished image. When the font file is missing, text falls
// back to stb_easy_font's boxes (text.h). FreeType's headers stay in font.cpp.
#include <memory>
#include <string>

#include "core/types.h"
#include "render/colour.h"
#include "render/image.h"

namespace canopy::render::internal {

/// The font file canopy looks for.
inline constexpr const char* kFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

/// Font units per em: a Text of scale s is set at 8·s px per em, so that DejaVu's ascender and
/// descender (0.93 and 0.24 em) fill about the stb_easy_font line of 9·s px it replaces.
inline constexpr double kUnitsPerEm = 8.0;

class Font {
 public:
  /// The process's font, loaded once; nullptr when the file cannot be loaded.
  static Font* instance();
  ~Font();

  /// Advance width of a UTF-8 line in font units (unhinted design advances, no kerning).
  double advance(const std::string& text) const;
  /// Draws a UTF-8 line whose top-left corner is `top_left` (px) at `scale` px per font unit,
  /// blending `colour` by each pixel's coverage.
  void draw(Image& image, const Vec2& top_left, const std::string& text, double scale, Rgba colour);

 private:
  Font() = default;
  struct Face;
  std::unique_ptr<Face> face_;
};

}  // namespace canopy::render::internal
