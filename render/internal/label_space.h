#pragma once
// Where a frame's names and its title box may go: what they should not cover (other names, the
// title box, the bodies' markers, the targets' trails, the UAVs' plans, the trees), each in image
// pixels with a weight, and the cost of a candidate box, the sum of the weights it touches.
// scene_builder.cpp places the title box and each name at its first candidate of least cost: the
// first clear one when there is one.
#include <vector>

#include "core/types.h"

namespace canopy::render::internal {

/// Weights: what is worst to cover costs most.
inline constexpr double kCoverName = 1000.0;   // a name or the title box: text over text
inline constexpr double kCoverMarker = 100.0;  // a target's dot, a UAV's arrow, an estimate
inline constexpr double kCoverTrail = 10.0;    // one segment of a target's trail
inline constexpr double kCoverPlan = 5.0;      // one segment of a UAV's plan
inline constexpr double kCoverTree = 1.0;      // a crown
inline constexpr double kOffImage = 1e6;       // a box not wholly inside the image

class LabelSpace {
 public:
  explicit LabelSpace(Aabb image) : image_(image) {}
  void addBox(const Aabb& box, double weight) { boxes_.push_back({box, weight}); }
  void addSegment(const Vec2& a, const Vec2& b, double weight) {
    segments_.push_back({a, b, weight});
  }
  void addDisc(const Vec2& centre, double radius, double weight) {
    discs_.push_back({centre, radius, weight});
  }
  /// A convex polygon, its vertices in order.
  void addPolygon(std::vector<Vec2> vertices, double weight) {
    polygons_.push_back({std::move(vertices), weight});
  }
  /// The summed weights of everything `box` touches (kOffImage if it leaves the image).
  double cost(const Aabb& box) const;
  /// The first of `candidates` of least cost.
  std::size_t best(const std::vector<Aabb>& candidates) const;

 private:
  struct Box {
    Aabb box;
    double weight;
  };
  struct Segment {
    Vec2 a, b;
    double weight;
  };
  struct Circle {
    Vec2 centre;
    double radius, weight;
  };
  struct ConvexPolygon {
    std::vector<Vec2> vertices;
    double weight;
  };
  Aabb image_;
  std::vector<Box> boxes_;
  std::vector<Segment> segments_;
  std::vector<Circle> discs_;
  std::vector<ConvexPolygon> polygons_;
};

/// Whether two boxes share interior (touching edges do not count).
bool boxesOverlap(const Aabb& a, const Aabb& b);
/// Whether the segment ab passes through the box's interior or touches it (Liang–Barsky clip).
bool segmentHitsBox(const Vec2& a, const Vec2& b, const Aabb& box);
/// Whether the disc and the box overlap: the box's nearest point is within the radius.
bool discHitsBox(const Vec2& centre, double radius, const Aabb& box);
/// Whether a convex polygon and the box overlap: a vertex inside the box, a box corner inside
/// the polygon, or an edge through the box.
bool polygonHitsBox(const std::vector<Vec2>& vertices, const Aabb& box);

}  // namespace canopy::render::internal
