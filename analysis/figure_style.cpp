#include "analysis/figure_style.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "spec/error.h"

namespace canopy::analysis {
namespace {

using Json = nlohmann::json;

constexpr double kMinStyleScale = 0.25, kMaxStyleScale = 4.0;

bool sameStyleRgb(const Colour& a, const Colour& b) {
  return a.r == b.r && a.g == b.g && a.b == b.b;
}

[[noreturn]] void styleError(const std::filesystem::path& path, const std::string& field,
                             const std::string& message) {
  throw spec::ScenarioError(path.string(), field, message);
}

Colour readStyleColour(const Json& value, const std::filesystem::path& path,
                       const std::string& field) {
  const std::string text = value.is_string() ? value.get<std::string>() : std::string();
  unsigned r = 0, g = 0, b = 0;
  const bool hex = text.size() == 7 && text[0] == '#' &&
                   std::all_of(text.begin() + 1, text.end(),
                               [](char c) { return std::isxdigit(static_cast<unsigned char>(c)); });
  if (!hex || std::sscanf(text.c_str(), "#%2x%2x%2x", &r, &g, &b) != 3)
    styleError(path, field, "expected a colour \"#rrggbb\", got " + value.dump());
  return {static_cast<std::uint8_t>(r), static_cast<std::uint8_t>(g), static_cast<std::uint8_t>(b)};
}

double readStyleScale(const Json& value, const std::filesystem::path& path,
                      const std::string& field) {
  if (!value.is_number() ||
      !(value.get<double>() >= kMinStyleScale && value.get<double>() <= kMaxStyleScale))
    styleError(path, field, "expected a number in [0.25, 4], got " + value.dump());
  return value.get<double>();
}

// The style's colour for `c`: the same index's when c is a default series colour.
std::optional<Colour> seriesReplacement(const Colour& c, const FigureStyle& style) {
  for (int i = 0; i < 8; ++i) {
    if (!sameStyleRgb(c, seriesColour(i))) continue;
    Colour styled = style.series[i];
    styled.alpha = c.alpha;
    return styled;
  }
  return std::nullopt;
}

void recolour(Colour& c, const FigureStyle& style) {
  if (const std::optional<Colour> styled = seriesReplacement(c, style)) {
    c = *styled;
  } else if (sameStyleRgb(c, kInk)) {
    const double alpha = c.alpha;
    c = style.ink;
    c.alpha = alpha;
  }
}

}  // namespace

FigureStyle::FigureStyle() {
  for (int i = 0; i < 8; ++i) series[i] = seriesColour(i);
}

FigureStyle readFigureStyle(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) styleError(path, "", "cannot be read");
  Json json;
  try {
    json = Json::parse(in);
  } catch (const Json::exception& e) {
    styleError(path, "", std::string("not JSON: ") + e.what());
  }
  if (!json.is_object()) styleError(path, "", "expected a JSON object");
  FigureStyle style;
  for (const auto& [key, value] : json.items()) {
    if (key == "series") {
      if (!value.is_array() || value.empty() || value.size() > 8)
        styleError(path, key, "expected a list of 1 to 8 colours");
      for (std::size_t i = 0; i < value.size(); ++i)
        style.series[i] = readStyleColour(value[i], path, key + "[" + std::to_string(i) + "]");
    } else if (key == "ink") {
      style.ink = readStyleColour(value, path, key);
    } else if (key == "background") {
      style.background = readStyleColour(value, path, key);
    } else if (key == "font_scale") {
      style.font_scale = readStyleScale(value, path, key);
    } else if (key == "line_scale") {
      style.line_scale = readStyleScale(value, path, key);
    } else {
      styleError(path, key,
                 "unknown field (expected series, ink, background, font_scale, line_scale)");
    }
  }
  return style;
}

void restyle(Figure& figure, const FigureStyle& style) {
  if (sameStyleRgb(figure.background, FigureStyle().background))
    figure.background = style.background;
  for (Shape& shape : figure.shapes) {
    if (auto* p = std::get_if<FilledPolygon>(&shape)) {
      recolour(p->fill, style);
    } else if (auto* l = std::get_if<Line>(&shape)) {
      recolour(l->colour, style);
      l->width *= style.line_scale;
    } else if (auto* t = std::get_if<Label>(&shape)) {
      recolour(t->colour, style);
      t->size *= style.font_scale;
    }
  }
}

}  // namespace canopy::analysis
