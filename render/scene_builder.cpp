// buildScene: the frame's layout (the legend band, the map's viewport above it) and the map's
// layers in drawing order — trees, footprints, occlusion maps and plans, estimates, the bodies
// and their names. What it draws over the map in pixels is internal/overlay.cpp; the outlines it
// draws (ellipses, footprints) are outlines.cpp.
#include "render/scene_builder.h"

#include <algorithm>
#include <cmath>

#include "render/internal/overlay.h"
#include "render/internal/scene_sizes.h"
#include "render/internal/text.h"

namespace canopy::render {

double textWidthPx(const std::string& text, double scale) {
  return internal::textWidth(text) * scale;
}

namespace {

using internal::addLegend;
using internal::addScaleBar;
using internal::addTimeStamp;
using internal::kTextLineHeight;
using internal::legendEntries;
using internal::nameOr;
using internal::rectangle;
using internal::Sizes;
using internal::textWidth;

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

}  // namespace

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
