#include "analysis/figure.h"

#include <cstdio>
#include <sstream>

namespace canopy::analysis {
namespace {

std::string rgb(const Colour& c) {
  char text[32];
  std::snprintf(text, sizeof text, "rgb(%d,%d,%d)", c.r, c.g, c.b);
  return text;
}

std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else
      out += c;
  }
  return out;
}

std::string points(const std::vector<Vec2>& ps) {
  std::ostringstream text;
  for (const Vec2& p : ps) text << p.x() << ',' << p.y() << ' ';
  return text.str();
}

}  // namespace

std::vector<double> dashPattern(Dash dash) {
  switch (dash) {
    case Dash::solid:
      return {};
    case Dash::dashed:
      return {10, 5};
    case Dash::dotted:
      return {2, 4};
    case Dash::dash_dot:
      return {10, 4, 2, 4};
  }
  return {};
}

std::vector<std::vector<Vec2>> dashPieces(const Line& line) {
  const std::vector<double> pattern = dashPattern(line.dash);
  const std::size_t count = pattern.size();
  if (count == 0 || line.points.size() < 2) return {line.points};
  std::vector<std::vector<Vec2>> pieces;
  std::size_t phase = 0;            // index into dash: even = drawn, odd = skipped
  double left = pattern.front();    // px left in this phase
  std::vector<Vec2> piece{line.points.front()};
  for (std::size_t i = 0; i + 1 < line.points.size(); ++i) {
    Vec2 a = line.points[i];
    const Vec2 b = line.points[i + 1];
    double length = (b - a).norm();
    while (length > left) {  // the phase ends inside this segment
      a += (b - a) * (left / length);
      length -= left;
      if (phase % 2 == 0) {
        piece.push_back(a);
        pieces.push_back(std::move(piece));
      }
      piece = {a};
      phase = (phase + 1) % count;
      left = pattern[phase];
    }
    left -= length;
    if (phase % 2 == 0) piece.push_back(b);
  }
  if (phase % 2 == 0 && piece.size() > 1) pieces.push_back(std::move(piece));
  return pieces;
}

std::string toSvg(const Figure& figure) {
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << figure.width << "\" height=\""
      << figure.height << "\" viewBox=\"0 0 " << figure.width << ' ' << figure.height << "\">\n";
  svg << "<rect width=\"100%\" height=\"100%\" fill=\"" << rgb(figure.background) << "\"/>\n";
  for (const Shape& shape : figure.shapes) {
    if (const auto* p = std::get_if<FilledPolygon>(&shape)) {
      svg << "<polygon points=\"" << points(p->points) << "\" fill=\"" << rgb(p->fill)
          << "\" fill-opacity=\"" << p->fill.alpha << "\"/>\n";
    } else if (const auto* l = std::get_if<Line>(&shape)) {
      svg << "<polyline points=\"" << points(l->points) << "\" fill=\"none\" stroke=\""
          << rgb(l->colour) << "\" stroke-opacity=\"" << l->colour.alpha << "\" stroke-width=\""
          << l->width << "\" stroke-linejoin=\"round\"";
      if (const std::vector<double> pattern = dashPattern(l->dash); !pattern.empty()) {
        svg << " stroke-dasharray=\"";
        for (std::size_t i = 0; i < pattern.size(); ++i) svg << (i ? "," : "") << pattern[i];
        svg << '"';
      }
      svg << "/>\n";
    } else if (const auto* t = std::get_if<Label>(&shape)) {
      const char* anchor = t->anchor == Anchor::start    ? "start"
                           : t->anchor == Anchor::middle ? "middle"
                                                         : "end";
      // A capital letter is about 0.7 em high in sans-serif fonts.
      svg << "<text x=\"" << t->at.x() << "\" y=\"" << t->at.y()
          << "\" font-family=\"sans-serif\" font-size=\"" << t->size / 0.7 << "\" text-anchor=\""
          << anchor << "\" fill=\"" << rgb(t->colour) << "\">" << escaped(t->text) << "</text>\n";
    }
  }
  svg << "</svg>\n";
  return svg.str();
}

void addRect(Figure& f, double x0, double y0, double x1, double y1, Colour fill) {
  f.shapes.emplace_back(std::in_place_type<FilledPolygon>,
                        std::vector<Vec2>{Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)},
                        fill);
}

Colour seriesColour(int index) {
  static const Colour kColours[] = {{31, 119, 180}, {214, 39, 40},   {44, 160, 44},
                                    {255, 127, 14}, {148, 103, 189}, {23, 190, 207},
                                    {140, 86, 75},  {227, 119, 194}};
  return kColours[index % 8];
}

}  // namespace canopy::analysis
