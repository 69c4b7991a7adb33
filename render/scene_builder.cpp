#include "render/scene_builder.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "render/internal/text.h"

namespace canopy::render {

double textWidthPx(const std::string& text, double scale) {
  return internal::textWidth(text) * scale;
}

namespace {

using internal::kTextLineHeight;
using internal::textWidth;

constexpr Rgba kLegendInk{70, 70, 70, 255};  // neutral colour of the legend's belief symbols

std::string nameOr(const std::vector<std::string>& names, std::size_t i, const char* prefix) {
  return i < names.size() && !names[i].empty() ? names[i] : prefix + std::to_string(i + 1);
}

std::vector<Vec2> rectangle(const Vec2& lo, const Vec2& hi) {
  return {lo, Vec2(hi.x(), lo.y()), hi, Vec2(lo.x(), hi.y())};
}

// Pixel sizes scale with the text: u = 1 at the default 800 px wide frame.
struct Sizes {
  double text;  // font units → px
  double u;     // px per nominal px
};

// Disc crowns, then polygon crowns, then the polygons' outlines: grouped so that the canvas
// switches GL state a few times rather than per tree (crowns share one colour, so the order
// between them does not show).
void addTrees(const SceneModel& model, const Sizes& z, std::vector<Primitive>& out) {
  for (const world::TreeDef& tree : model.trees) {
    if (tree.shape == world::TreeShape::disc) {
      add(out, Disc{tree.centre, tree.radius, palette::kTreeFill, palette::kTreeEdge, z.u});
    }
  }
  for (const world::TreeDef& tree : model.trees) {
    if (tree.shape == world::TreeShape::polygon)
      add(out, Polygon{tree.vertices, palette::kTreeFill});
  }
  for (const world::TreeDef& tree : model.trees) {
    if (tree.shape == world::TreeShape::polygon) {
      add(out, Polyline{tree.vertices, z.u, palette::kTreeEdge, true});
    }
  }
}

void addFootprints(const SceneModel& model, const world::WorldSnapshot& truth, const Sizes& z,
                   std::vector<Primitive>& out) {
  const std::size_t n = std::min(model.sensors.size(), truth.uavs.size());
  for (std::size_t i = 0; i < n; ++i) {
    const Rgba colour = uavColour(static_cast<int>(i));
    const sensing::Footprint f = sensing::footprintOf(truth, static_cast<int>(i), model.sensors[i]);
    if (f.shape == sensing::FootprintShape::disc) {
      add(out, Disc{f.centre, f.radius, withAlpha(colour, 60), colour, 1.5 * z.u});
    } else if (f.shape == sensing::FootprintShape::sector) {
      // The sector in shadow, the part the camera sees over it, then the sector's outline.
      std::vector<Vec2> outline = footprintCorners(f);
      add(out, Polygon{outline, palette::kShadow});
      add(out, Polygon{visibleSector(f, model.trees), withAlpha(colour, 60)});
      add(out, Polyline{std::move(outline), 1.5 * z.u, colour, true});
    } else {
      std::vector<Vec2> corners = footprintCorners(f);
      add(out, Polygon{corners, withAlpha(colour, 60)});
      add(out, Polyline{std::move(corners), 1.5 * z.u, colour, true});
    }
  }
}

void addBeliefs(const world::WorldSnapshot& truth, std::span<const agents::AgentBelief> beliefs,
                const Sizes& z, std::vector<Primitive>& out) {
  // Occlusion maps first, then plans, so that estimates stay on top.
  for (std::size_t i = 0; i < beliefs.size(); ++i) {
    const Rgba colour = uavColour(static_cast<int>(i));
    for (const agents::TreeEstimate& tree : beliefs[i].trees) {
      const Vec2 centre = tree.belief.x.head<2>();
      if (tree.outline.vertices > 0) {  // a polygonal crown or wall: its estimated outline
        std::vector<Vec2> outline;
        for (int v = 0; v < tree.outline.vertices; ++v)
          outline.push_back(centre + tree.outline.offsets[v]);
        add(out, Polyline{std::move(outline), 1.2 * z.u, colour, true});
      } else {
        add(out, Ring{centre, std::max(tree.belief.x(2), 0.1), 1.2 * z.u, colour});
      }
    }
  }
  for (std::size_t i = 0; i < beliefs.size(); ++i) {
    const std::vector<Vec2>& plan = beliefs[i].planned_path;
    if (plan.empty()) continue;
    const Rgba colour = withAlpha(uavColour(static_cast<int>(i)), 200);
    std::vector<Vec2> path;
    if (i < truth.uavs.size()) path.push_back(truth.uavs[i].position);
    path.insert(path.end(), plan.begin(), plan.end());
    add(out, Polyline{std::move(path), 1.5 * z.u, colour, false});
    for (const Vec2& p : plan)
      add(out, Marker{p, MarkerShape::dot, 5.0 * z.u, 0.0, colour, colour, 0.0});
  }
}

void addEstimates(std::span<const agents::AgentBelief> beliefs, const Sizes& z,
                  std::vector<Primitive>& out) {
  for (std::size_t i = 0; i < beliefs.size(); ++i) {
    for (const agents::TrackEstimate& track : beliefs[i].tracks) {
      const Rgba colour = withAlpha(uavColour(static_cast<int>(i)), track.confirmed ? 255 : 110);
      const Vec2 mean = track.belief.x.head<2>();
      std::vector<Vec2> ellipse = covarianceEllipse(mean, track.belief.P.topLeftCorner<2, 2>());
      if (!ellipse.empty()) add(out, Polyline{std::move(ellipse), 1.5 * z.u, colour, true});
      add(out, Marker{mean, MarkerShape::cross, 10.0 * z.u, 0.0, colour,
                      withAlpha(palette::kWhite, colour.a), z.u});
    }
  }
}

void addBodies(const SceneModel& model, const world::WorldSnapshot& truth,
               const TargetTrails& trails, const Viewport& v, const Sizes& z, bool labels,
               std::vector<Primitive>& out) {
  for (int t = 0; t < static_cast<int>(truth.targets.size()); ++t) {
    const std::vector<Vec2>& trail = trails.trail(t);
    if (trail.size() > 1) add(out, Polyline{trail, 2.0 * z.u, palette::kTrail, false});
  }
  for (const world::TargetState& target : truth.targets) {
    add(out, Marker{target.position, MarkerShape::dot, 10.0 * z.u, 0.0, palette::kTarget,
                    palette::kWhite, 1.5 * z.u});
  }
  for (std::size_t i = 0; i < truth.uavs.size(); ++i) {
    const world::UavState& uav = truth.uavs[i];
    add(out, Marker{uav.position, MarkerShape::arrow, 18.0 * z.u, uav.yaw,
                    uavColour(static_cast<int>(i)), palette::kTarget, 1.2 * z.u});
  }
  if (!labels) return;
  // Names last, on top of every symbol. Each tries, in order, the places around its symbol
  // (targets first above right, UAVs below right, so that a UAV over its target hides neither)
  // and takes the first whose box overlaps no name placed before it; the first place if none.
  const double line = kTextLineHeight * z.text;
  std::vector<Aabb> placed_boxes;  // px, relative to the image, of the names placed so far
  const auto place = [&](const Vec2& at, const std::string& name,
                         const std::vector<Vec2>& offsets) {
    const Vec2 px = v.toPixel(at);
    const double width = textWidth(name) * z.text;
    Vec2 chosen = offsets.front();
    for (const Vec2& offset : offsets) {
      const Aabb box{px + offset, px + offset + Vec2(width, line)};
      const bool clear = std::none_of(placed_boxes.begin(), placed_boxes.end(), [&](const Aabb& b) {
        return box.lo.x() < b.hi.x() && b.lo.x() < box.hi.x() && box.lo.y() < b.hi.y() &&
               b.lo.y() < box.hi.y();
      });
      if (clear) {
        chosen = offset;
        break;
      }
    }
    placed_boxes.push_back({px + chosen, px + chosen + Vec2(width, line)});
    add(out, Text{at, chosen, name, z.text, palette::kText});
  };
  const auto around = [&](double gap, bool above_first, double width) {
    const Vec2 above_right(gap, -line - gap), below_right(gap, gap),
        above_left(-gap - width, -line - gap), below_left(-gap - width, gap),
        far_above(-0.5 * width, -2.0 * line - gap), far_below(-0.5 * width, line + gap);
    return above_first ? std::vector<Vec2>{above_right, above_left, below_right,
                                           below_left,  far_above,  far_below}
                       : std::vector<Vec2>{below_right, below_left, above_right,
                                           above_left,  far_below,  far_above};
  };
  for (std::size_t t = 0; t < truth.targets.size(); ++t) {
    const std::string name = nameOr(model.target_names, t, "T");
    place(truth.targets[t].position, name, around(6.0 * z.u, true, textWidth(name) * z.text));
  }
  for (std::size_t i = 0; i < truth.uavs.size(); ++i) {
    const std::string name = nameOr(model.uav_names, i, "uav");
    place(truth.uavs[i].position, name, around(9.0 * z.u, false, textWidth(name) * z.text));
  }
}

// One entry of the legend band: a symbol drawn by `draw` at a centre, then a label.
struct LegendEntry {
  std::string label;
  std::vector<Primitive> symbol;  // around (0, 0), px
};

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
  if (model.plans) {
    std::vector<Primitive>& plan = entry("plan");
    add(plan, Polyline{{Vec2(-8.0 * u, 0.0), Vec2(8.0 * u, 0.0)}, 1.5 * u, kLegendInk, false});
    add(plan,
        Marker{Vec2(8.0 * u, 0.0), MarkerShape::dot, 5.0 * u, 0.0, kLegendInk, kLegendInk, 0.0});
  }
  return entries;
}

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

// Lays the entries out left to right in rows along the bottom; returns the band's height (px).
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

void addTimeStamp(const SceneModel& model, const world::WorldSnapshot& truth, const Sizes& z,
                  std::vector<Primitive>& out) {
  char text[160];
  std::snprintf(text, sizeof text, "%s%st = %.2f s   k = %d", model.title.c_str(),
                model.title.empty() ? "" : "   ", truth.time, truth.step);
  const double pad = 4.0 * z.u;
  const Vec2 lo(pad, pad),
      hi = lo + Vec2(textWidth(text) * z.text + 2.0 * pad, kTextLineHeight * z.text + 2.0 * pad);
  add(out, Polygon{rectangle(lo, hi), palette::kPanel});
  add(out, Polyline{rectangle(lo, hi), z.u, palette::kPanelEdge, true});
  add(out, Text{lo + Vec2(pad, pad), Vec2::Zero(), text, z.text, palette::kText});
}

// A bar of scaleBarLength(map width) metres at the bottom left of the map, above the legend.
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

}  // namespace

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

std::vector<Vec2> covarianceEllipse(const Vec2& centre, const Mat2& P, int points) {
  if (!P.allFinite() || !centre.allFinite() || points < 3) return {};
  const Eigen::SelfAdjointEigenSolver<Mat2> eigen(0.5 * (P + P.transpose()));
  Mat2 V = eigen.eigenvectors();
  if (V.determinant() < 0.0)
    V.col(1) = -V.col(1);  // a rotation, so the points run counter-clockwise
  // P = V Λ Vᵀ: the points c + V (2√λ₁ cos θ, 2√λ₂ sin θ) satisfy (p − c)ᵀ P⁻¹ (p − c) = 4.
  const Vec2 axes = 2.0 * eigen.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  std::vector<Vec2> out;
  out.reserve(static_cast<std::size_t>(points));
  for (int k = 0; k < points; ++k) {
    const double theta = 2.0 * std::numbers::pi * k / points;
    out.push_back(centre + V * Vec2(axes.x() * std::cos(theta), axes.y() * std::sin(theta)));
  }
  return out;
}

std::vector<Vec2> footprintCorners(const sensing::Footprint& f) {
  if (f.shape == sensing::FootprintShape::disc) return {};
  if (f.shape == sensing::FootprintShape::sector) {
    constexpr double kArcStep = std::numbers::pi / 180.0;  // rad, 1°
    const int arcs = std::max(2, static_cast<int>(std::ceil(2.0 * f.half_angle / kArcStep)));
    std::vector<Vec2> out{f.centre};
    for (int k = 0; k <= arcs; ++k)
      out.push_back(f.sectorPoint(f.half_angle * (2.0 * k / arcs - 1.0)));
    return out;
  }
  const Vec2 along = f.half.x() * Vec2(f.cos_yaw, f.sin_yaw);
  const Vec2 across = f.half.y() * Vec2(-f.sin_yaw, f.cos_yaw);
  return {f.centre + along + across, f.centre - along + across, f.centre - along - across,
          f.centre + along - across};
}

std::vector<Vec2> visibleSector(const sensing::Footprint& sector,
                                const std::vector<world::TreeDef>& trees) {
  std::vector<Vec2> out = footprintCorners(sector);
  if (out.empty()) return out;
  const Aabb box = sector.bounds();
  std::vector<const world::TreeDef*> near;
  for (const world::TreeDef& tree : trees) {
    const Aabb b = world::bounds(tree);
    if (b.lo.x() <= box.hi.x() && box.lo.x() <= b.hi.x() && b.lo.y() <= box.hi.y() &&
        box.lo.y() <= b.hi.y())
      near.push_back(&tree);
  }
  const Vec2 apex = out.front();
  for (std::size_t k = 1; k < out.size(); ++k) {
    double first = 1.0;  // the fraction of the ray apex → arc point before any crown
    for (const world::TreeDef* tree : near) {
      const double s = world::segmentEntry(*tree, apex, out[k]);
      if (s >= 0.0 && s < first) first = s;
    }
    out[k] = apex + first * (out[k] - apex);
  }
  return out;
}

Scene buildScene(const SceneModel& model, const world::WorldSnapshot& truth,
                 std::span<const agents::AgentBelief> beliefs, const TargetTrails& trails,
                 ImageSize size, const SceneOptions& options) {
  Sizes z;
  z.text =
      options.text_scale > 0.0 ? options.text_scale : std::max(1.0, std::ceil(size.width / 500.0));
  z.u = z.text / 2.0;

  Scene scene;
  double band = 0.0;
  if (options.legend) {
    std::vector<Primitive> legend;
    band = addLegend(legendEntries(model, model.sensors.size(), z.u), size, z, legend);
    if (band < 0.5 * size.height) {
      scene.overlay = std::move(legend);
    } else {
      band = 0.0;  // too small an image for a legend
    }
  }
  // The map fills the image above the band; the band hides whatever the projection puts below.
  const ImageSize map{size.width, std::max(1, size.height - static_cast<int>(std::ceil(band)))};
  scene.viewport = Viewport::fit(withMargin(model.shown(), options.margin), map);
  scene.viewport.size = size;

  // The image is cleared to the ground's colour and only the margins outside the AOI are
  // filled: large fills are the costliest thing llvmpipe draws here.
  scene.background = palette::kGround;
  std::vector<Primitive>& w = scene.world;
  const Viewport& v = scene.viewport;
  const Vec2 lo = v.toWorld(Vec2(0.0, size.height)), hi = v.toWorld(Vec2(size.width, 0.0));
  const Aabb& a = model.aoi;
  const Aabb margins[4] = {{lo, Vec2(a.lo.x(), hi.y())},
                           {Vec2(a.hi.x(), lo.y()), hi},
                           {Vec2(a.lo.x(), lo.y()), Vec2(a.hi.x(), a.lo.y())},
                           {Vec2(a.lo.x(), a.hi.y()), Vec2(a.hi.x(), hi.y())}};
  for (const Aabb& m : margins) {
    if (m.width() > 0.0 && m.height() > 0.0)
      add(w, Polygon{rectangle(m.lo, m.hi), palette::kOutside});
  }
  add(w, Polyline{rectangle(a.lo, a.hi), z.u, palette::kAoiEdge, true});
  addTrees(model, z, w);
  addFootprints(model, truth, z, w);
  addBeliefs(truth, beliefs, z, w);
  addEstimates(beliefs, z, w);
  addBodies(model, truth, trails, v, z, options.labels, w);
  addScaleBar(v, size, band, z, scene.overlay);
  addTimeStamp(model, truth, z, scene.overlay);
  return scene;
}

}  // namespace canopy::render
