// buildScene: the frame's layout (the legend band, the map's viewport above it) and the map's
// layers in drawing order — trees, footprints, occlusion maps and plans, estimates, the bodies
// and their names. What it draws over the map in pixels is internal/overlay.cpp; the outlines it
// draws (ellipses, footprints) are outlines.cpp.
#include "render/scene_builder.h"

#include <algorithm>
#include <cmath>

#include "render/internal/label_space.h"
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
using internal::kTextLineHeight;
using internal::LabelSpace;
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
  // Trunks, what stops a ground robot (world/tree.h), where there are ground robots.
  const bool robots = std::any_of(model.sensors.begin(), model.sensors.end(),
                                  [](const sensing::SensorDef& s) { return s.ground_level; });
  if (!robots) return;
  for (const world::TreeDef& tree : model.trees) {
    if (!world::isWall(tree) && tree.trunk_radius > 0.0)
      add(out, Disc{tree.centre, tree.trunk_radius, palette::kTrunk, palette::kTrunk, 0.0});
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

void addBodies(const world::WorldSnapshot& truth, const TargetTrails& trails, const Sizes& z,
               double pixel_size, std::vector<Primitive>& out) {
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
    // A body that touched a trunk, a wall or another agent over the step: a red ring round it.
    if (!uav.contacts.empty())
      add(out, Ring{uav.position, 13.0 * z.u * pixel_size, 2.5 * z.u, palette::kContact});
  }
}

// What the title box and the names should not cover, in image pixels: the trees, the targets'
// trails, the UAVs' plans, the bodies' and estimates' markers.
LabelSpace labelSpace(const SceneModel& model, const world::WorldSnapshot& truth,
                      std::span<const agents::AgentBelief> beliefs, const TargetTrails& trails,
                      const Viewport& v, ImageSize size, double band, const Sizes& z) {
  LabelSpace space(Aabb{Vec2::Zero(), Vec2(size.width, size.height - band)});
  for (const world::TreeDef& tree : model.trees) {
    if (tree.shape == world::TreeShape::disc) {
      space.addDisc(v.toPixel(tree.centre), tree.radius / v.pixel_size, internal::kCoverTree);
    } else {
      std::vector<Vec2> px;
      for (const Vec2& p : tree.vertices) px.push_back(v.toPixel(p));
      space.addPolygon(std::move(px), internal::kCoverTree);
    }
  }
  for (int t = 0; t < static_cast<int>(truth.targets.size()); ++t) {
    const std::vector<Vec2>& trail = trails.trail(t);
    for (std::size_t k = 0; k + 1 < trail.size(); ++k)
      space.addSegment(v.toPixel(trail[k]), v.toPixel(trail[k + 1]), internal::kCoverTrail);
  }
  for (std::size_t i = 0; i < beliefs.size() && i < truth.uavs.size(); ++i) {
    Vec2 from = truth.uavs[i].position;
    for (const Vec2& to : beliefs[i].planned_path) {
      space.addSegment(v.toPixel(from), v.toPixel(to), internal::kCoverPlan);
      from = to;
    }
  }
  const auto marker = [&](const Vec2& at, double half) {
    const Vec2 px = v.toPixel(at);
    space.addBox({px - Vec2(half, half), px + Vec2(half, half)}, internal::kCoverMarker);
  };
  for (const world::TargetState& target : truth.targets) marker(target.position, 6.5 * z.u);
  for (const world::UavState& uav : truth.uavs) marker(uav.position, 9.0 * z.u);
  for (const agents::AgentBelief& belief : beliefs) {
    for (const agents::TrackEstimate& track : belief.tracks)
      marker(track.belief.x.head<2>(), 5.0 * z.u);
  }
  return space;
}

// The title box at the first corner of the map (top left, top right, then down either edge)
// that covers nothing in `space`, or the one that covers least; it joins `space` as a name.
void placeTimeStamp(const SceneModel& model, const world::WorldSnapshot& truth, ImageSize size,
                    double band, const Sizes& z, LabelSpace& space, std::vector<Primitive>& out) {
  const std::string text = internal::timeStampText(model, truth);
  const Vec2 box = internal::timeStampSize(text, z);
  const double pad = 4.0 * z.u;
  std::vector<Aabb> candidates;
  const double left = pad, right = size.width - pad - box.x();
  for (double y = pad; y + box.y() <= size.height - band - pad; y += box.y() + pad) {
    candidates.push_back({Vec2(left, y), Vec2(left, y) + box});
    if (right > left) candidates.push_back({Vec2(right, y), Vec2(right, y) + box});
  }
  if (candidates.empty()) candidates.push_back({Vec2(pad, pad), Vec2(pad, pad) + box});
  const Aabb chosen = candidates[space.best(candidates)];
  space.addBox(chosen, internal::kCoverName);
  internal::addTimeStamp(text, chosen.lo, z, out);
}

// Names last, on top of every symbol. Each tries the places around its symbol, near ones first
// (targets first above right, UAVs below right, so that a UAV over its target hides neither),
// and takes the first that covers nothing in `space` (other names, the title box, markers,
// trails, trees), or the one that covers least.
void addNames(const SceneModel& model, const world::WorldSnapshot& truth, const Viewport& v,
              const Sizes& z, LabelSpace& space, std::vector<Primitive>& out) {
  const double line = kTextLineHeight * z.text;
  const auto place = [&](const Vec2& at, const std::string& name, double gap, bool above_first) {
    const Vec2 px = v.toPixel(at);
    const double width = textWidth(name) * z.text;
    std::vector<Vec2> offsets;
    for (const double g : {gap, 2.5 * gap, 4.5 * gap}) {
      const Vec2 above_right(g, -line - g), below_right(g, g), above_left(-g - width, -line - g),
          below_left(-g - width, g), far_above(-0.5 * width, -2.0 * line - g),
          far_below(-0.5 * width, line + g);
      const std::vector<Vec2> ring = above_first
                                         ? std::vector<Vec2>{above_right, above_left, below_right,
                                                             below_left,  far_above,  far_below}
                                         : std::vector<Vec2>{below_right, below_left, above_right,
                                                             above_left,  far_below,  far_above};
      offsets.insert(offsets.end(), ring.begin(), ring.end());
    }
    std::vector<Aabb> boxes;
    for (const Vec2& offset : offsets)
      boxes.push_back({px + offset, px + offset + Vec2(width, line)});
    const std::size_t chosen = space.best(boxes);
    space.addBox(boxes[chosen], internal::kCoverName);
    add(out, Text{at, offsets[chosen], name, z.text, palette::kText});
  };
  for (std::size_t t = 0; t < truth.targets.size(); ++t)
    place(truth.targets[t].position, nameOr(model.target_names, t, "T"), 6.0 * z.u, true);
  for (std::size_t i = 0; i < truth.uavs.size(); ++i) {
    std::string name = nameOr(model.uav_names, i, "uav");
    // A UAV at a chosen altitude (issue 53) carries it: "UAV1 40 m".
    if (i < model.sensors.size() && model.sensors[i].camera)
      name += " " + std::to_string(static_cast<long>(std::lround(truth.uavs[i].z))) + " m";
    place(truth.uavs[i].position, name, 9.0 * z.u, false);
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
  addBodies(truth, trails, z, v.pixel_size, w);
  LabelSpace space = labelSpace(model, truth, beliefs, trails, v, size, band, z);
  if (options.labels) addNames(model, truth, v, z, space, w);
  addScaleBar(v, size, band, z, scene.overlay);
  placeTimeStamp(model, truth, size, band, z, space, scene.overlay);
  return scene;
}

}  // namespace canopy::render
