#include "render/internal/overlay.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <type_traits>
#include <variant>

#include "render/internal/text.h"

namespace canopy::render {

// Declared in scene_builder.h: the scale bar's length and label, beside the bar that uses them.
double scaleBarLength(double width_m) {
  if (!(width_m > 0.0) || !std::isfinite(width_m)) return 0.0;
  const double limit = 0.25 * width_m;
  const double decade = std::pow(10.0, std::floor(std::log10(limit)));
  for (const double step : {5.0, 2.0, 1.0}) {
    if (step * decade <= limit * (1.0 + 1e-12)) return step * decade;
  }
  return decade;
}

std::string scaleBarLabel(double length_m) {
  char text[32];
  if (length_m >= 1000.0) {
    std::snprintf(text, sizeof text, "%g km", length_m / 1000.0);
  } else {
    std::snprintf(text, sizeof text, "%g m", length_m);
  }
  return text;
}

namespace internal {
namespace {

constexpr Rgba kLegendInk{70, 70, 70, 255};  // neutral colour of the legend's belief symbols

// Moves a legend symbol from (0, 0) to `at` (px).
Primitive placed(Primitive p, const Vec2& at) {
  std::visit(
      [&](auto& q) {
        using T = std::decay_t<decltype(q)>;
        if constexpr (std::is_same_v<T, Polygon>) {
          for (Vec2& v : q.vertices) v += at;
        } else if constexpr (std::is_same_v<T, Polyline>) {
          for (Vec2& v : q.points) v += at;
        } else if constexpr (std::is_same_v<T, Disc> || std::is_same_v<T, Ring>) {
          q.centre += at;

        } else {
          q.at += at;
        }
      },
      p);
  return p;
}

}  // namespace

std::vector<LegendEntry> legendEntries(const SceneModel& model, std::size_t uavs, double u) {
  std::vector<LegendEntry> entries;
  const auto entry = [&entries](std::string label) -> std::vector<Primitive>& {
    entries.push_back({std::move(label), {}});
    return entries.back().symbol;
  };
  const Vec2 o = Vec2::Zero();
  for (std::size_t i = 0; i < uavs; ++i) {
    const Rgba c = uavColour(static_cast<int>(i));
    std::vector<Primitive>& symbol = entry(nameOr(model.uav_names, i, "uav"));
    add(symbol, Marker{o, MarkerShape::square, 14.0 * u, 0.0, withAlpha(c, 60), c, 1.5 * u});
    add(symbol,
        Marker{o, MarkerShape::arrow, 11.0 * u, 0.5 * std::numbers::pi, c, palette::kTarget, u});
  }
  std::vector<Primitive>& person = entry("person + trail");
  add(person, Polyline{{Vec2(-8.0 * u, 4.0 * u), o}, 2.0 * u, palette::kTrail, false});
  add(person,
      Marker{o, MarkerShape::dot, 10.0 * u, 0.0, palette::kTarget, palette::kWhite, 1.5 * u});
  std::vector<Primitive>& tree = entry("tree");
  add(tree, Disc{o, 6.0 * u, palette::kTreeFill, palette::kTreeEdge, u});
  // Every entry a run can need, whatever this step holds: the band keeps its height.
  std::vector<Primitive>& estimate = entry("estimate, 2-sigma");
  add(estimate, Ring{o, 7.0 * u, 1.5 * u, kLegendInk});
  add(estimate, Marker{o, MarkerShape::cross, 10.0 * u, 0.0, kLegendInk, palette::kWhite, u});
  add(entry("occlusion map"), Ring{o, 6.0 * u, 1.2 * u, kLegendInk});
  if (model.contacts) {  // the ring drawn around an agent touching a trunk, wall or agent
    std::vector<Primitive>& contact = entry("contact");
    add(contact, Marker{o, MarkerShape::dot, 6.0 * u, 0.0, kLegendInk, kLegendInk, 0.0});
    add(contact, Ring{o, 7.0 * u, 2.0 * u, palette::kContact});
  }
  if (model.plans) {
    std::vector<Primitive>& plan = entry("plan");
    add(plan, Polyline{{Vec2(-8.0 * u, 0.0), Vec2(8.0 * u, 0.0)}, 1.5 * u, kLegendInk, false});
    add(plan,
        Marker{Vec2(8.0 * u, 0.0), MarkerShape::dot, 5.0 * u, 0.0, kLegendInk, kLegendInk, 0.0});
  }
  return entries;
}

double addLegend(const std::vector<LegendEntry>& entries, ImageSize size, const Sizes& z,
                 std::vector<Primitive>& out) {
  const double pad = 4.0 * z.u, row = kTextLineHeight * z.text + 10.0 * z.u, symbol = 20.0 * z.u;
  const double gap = 14.0 * z.u;
  std::vector<Vec2> origins;  // top-left of each entry, relative to the band's top-left
  double x = pad, y = pad;
  for (const LegendEntry& e : entries) {
    const double w = symbol + 4.0 * z.u + textWidth(e.label) * z.text;
    if (x > pad && x + w > size.width - pad) {
      x = pad;
      y += row;
    }
    origins.push_back(Vec2(x, y));
    x += w + gap;
  }
  const double band = y + row + pad;
  const double top = size.height - band;
  add(out, Polygon{rectangle(Vec2(0.0, top), Vec2(size.width, size.height)), palette::kPanel});
  add(out, Polyline{{Vec2(0.0, top), Vec2(size.width, top)}, z.u, palette::kPanelEdge, false});
  for (std::size_t k = 0; k < entries.size(); ++k) {
    const Vec2 at = origins[k] + Vec2(0.0, top);
    for (const Primitive& p : entries[k].symbol)
      out.push_back(placed(p, at + Vec2(0.5 * symbol, 0.5 * row)));
    add(out, Text{at + Vec2(symbol + 4.0 * z.u, 0.5 * (row - kTextLineHeight * z.text)),
                  Vec2::Zero(), entries[k].label, z.text, palette::kText});
  }
  return band;
}

std::string timeStampText(const SceneModel& model, const world::WorldSnapshot& truth) {
  char text[160];
  std::snprintf(text, sizeof text, "%s%st = %.2f s   k = %d", model.title.c_str(),
                model.title.empty() ? "" : "   ", truth.time, truth.step);
  return text;
}

Vec2 timeStampSize(const std::string& text, const Sizes& z) {
  const double pad = 4.0 * z.u;
  return {textWidth(text) * z.text + 2.0 * pad, kTextLineHeight * z.text + 2.0 * pad};
}

void addTimeStamp(const std::string& text, const Vec2& lo, const Sizes& z,
                  std::vector<Primitive>& out) {
  const double pad = 4.0 * z.u;
  const Vec2 hi = lo + timeStampSize(text, z);
  add(out, Polygon{rectangle(lo, hi), palette::kPanel});
  add(out, Polyline{rectangle(lo, hi), z.u, palette::kPanelEdge, true});
  add(out, Text{lo + Vec2(pad, pad), Vec2::Zero(), text, z.text, palette::kText});
}

void addScaleBar(const Viewport& v, ImageSize size, double band, const Sizes& z,
                 std::vector<Primitive>& out) {
  const double length = scaleBarLength(size.width * v.pixel_size);
  if (!(length > 0.0)) return;
  const double px = length / v.pixel_size, pad = 8.0 * z.u, tick = 5.0 * z.u;
  const double y = size.height - band - pad;
  const Vec2 left(pad + 4.0 * z.u, y), right = left + Vec2(px, 0.0);
  const std::string label = scaleBarLabel(length);
  const double line = kTextLineHeight * z.text;
  const Vec2 lo(pad, y - line - tick - 6.0 * z.u),
      hi(std::max(right.x(), left.x() + textWidth(label) * z.text) + 4.0 * z.u, y + 3.0 * z.u);
  add(out, Polygon{rectangle(lo, hi), palette::kPanel});
  add(out, Polyline{{left - Vec2(0, tick), left, right, right - Vec2(0, tick)},
                    2.0 * z.u,
                    palette::kText,
                    false});
  add(out, Text{Vec2(left.x(), y - tick - line - 2.0 * z.u), Vec2::Zero(), label, z.text,
                palette::kText});
}

}  // namespace internal
}  // namespace canopy::render
