#include "analysis/plots.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace canopy::analysis {
namespace {

constexpr Colour kGrid{200, 200, 200};
constexpr Colour kShade{170, 170, 170, 0.45};

std::string percent(double fraction) {
  char text[16];
  std::snprintf(text, sizeof text, "%.0f%%", 100.0 * fraction);
  return text;
}

// A band from the vertical edge (x0, [a0, b0]) to (x1, [a1, b1]) along a smoothstep, as convex
// quads.
void addBand(Figure& f, double x0, double a0, double b0, double x1, double a1, double b1,
             Colour fill) {
  constexpr int kSegments = 24;
  auto at = [&](int i) {
    const double u = static_cast<double>(i) / kSegments;
    const double s = u * u * (3.0 - 2.0 * u);  // smoothstep
    return std::array<double, 3>{x0 + u * (x1 - x0), a0 + s * (a1 - a0), b0 + s * (b1 - b0)};
  };
  for (int i = 0; i < kSegments; ++i) {
    const auto p = at(i), q = at(i + 1);
    // Built in place: GCC 12 reports moving a temporary Shape holding a polygon as reading the
    // Line alternative's members uninitialised (-Wmaybe-uninitialized, a false positive).
    f.shapes.emplace_back(
        std::in_place_type<FilledPolygon>,
        FilledPolygon{{Vec2(p[0], p[1]), Vec2(q[0], q[1]), Vec2(q[0], q[2]), Vec2(p[0], p[2])},
                      fill});
  }
}

// The 95 % interval of a curve as one convex quad per step, clipped to [0, y_max]; steps whose
// interval is unbounded (a single trial) get none.
template <typename ToPixel>
void addIntervalBand(Figure& f, const std::vector<ConfidenceInterval>& ci, double dt, double y_max,
                     const ToPixel& px, Colour fill) {
  auto clip = [&](double v) { return std::clamp(v, 0.0, y_max); };
  for (int k = 0; k + 1 < static_cast<int>(ci.size()); ++k) {
    if (!ci[k].bounded() || !ci[k + 1].bounded()) continue;
    const double t0 = k * dt, t1 = (k + 1) * dt;
    f.shapes.push_back(FilledPolygon{{px(t0, clip(ci[k].low)), px(t1, clip(ci[k + 1].low)),
                                      px(t1, clip(ci[k + 1].high)), px(t0, clip(ci[k].high))},
                                     fill});
  }
}

}  // namespace

Colour stateColour(const ConfigStatistics& stats, int index) {
  const std::string& name = stats.states[index];
  if (name == "Miss 1") return {253, 141, 60};
  if (name == "Miss >1") return {215, 48, 39};
  if (name == "Other") return {150, 150, 150};
  static const Colour kNamed[] = {
      {49, 130, 189}, {49, 163, 84}, {117, 107, 177}, {23, 190, 207}, {140, 86, 75}};
  return kNamed[index % 5];
}

Figure sankeyFigure(const ConfigStatistics& stats, const std::string& title) {
  Figure f;
  f.width = 900;
  f.height = 520;
  const double left = 70, right = 150, top = 70, bottom = 60, node_w = 16, gap = 10;
  const double plot_h = f.height - top - bottom;
  const int n_states = static_cast<int>(stats.states.size());
  f.shapes.push_back(Label{Vec2(f.width / 2.0, 32), title, 14, Anchor::middle, kInk});
  if (stats.trials == 0) return f;

  std::array<double, 5> x{};
  for (int c = 0; c < 5; ++c) x[c] = left + c * (f.width - left - right - node_w) / 4.0;
  // Node extents: [top, bottom] px per column and state; heights ∝ frequency.
  std::array<std::vector<double>, 5> node_top, node_bottom;
  for (int c = 0; c < 5; ++c) {
    int present = 0;
    for (int s = 0; s < n_states; ++s) present += stats.state_counts[c][s] > 0;
    const double scale = (plot_h - gap * (present - 1)) / stats.trials;  // px per trial
    double y = top;
    node_top[c].assign(n_states, y);
    node_bottom[c].assign(n_states, y);
    for (int s = 0; s < n_states; ++s) {
      if (stats.state_counts[c][s] == 0) continue;
      node_top[c][s] = y;
      node_bottom[c][s] = y + stats.state_counts[c][s] * scale;
      y = node_bottom[c][s] + gap;
    }
  }
  // Bands: leave a source node ordered by target state, enter a target node ordered by source.
  for (int g = 0; g < 4; ++g) {
    std::vector<double> out_y(node_top[g]), in_y(node_top[g + 1]);
    const double scale_out = [&] {
      for (int s = 0; s < n_states; ++s) {
        if (stats.state_counts[g][s])
          return (node_bottom[g][s] - node_top[g][s]) / stats.state_counts[g][s];
      }
      return 0.0;
    }();
    const double scale_in = [&] {
      for (int s = 0; s < n_states; ++s) {
        if (stats.state_counts[g + 1][s])
          return (node_bottom[g + 1][s] - node_top[g + 1][s]) / stats.state_counts[g + 1][s];
      }
      return 0.0;
    }();
    for (int a = 0; a < n_states; ++a) {
      for (int b = 0; b < n_states; ++b) {
        const int count = stats.flows[g][a][b];
        if (count == 0) continue;
        // Incoming bands must be stacked by source order: precompute the offset at the target.
        double in_offset = 0.0;
        for (int a2 = 0; a2 < a; ++a2) in_offset += stats.flows[g][a2][b] * scale_in;
        Colour fill = stateColour(stats, a);
        fill.alpha = 0.45;
        addBand(f, x[g] + node_w, out_y[a], out_y[a] + count * scale_out, x[g + 1],
                node_top[g + 1][b] + in_offset, node_top[g + 1][b] + in_offset + count * scale_in,
                fill);
        out_y[a] += count * scale_out;
      }
    }
  }
  static const char* kColumnNames[] = {"k = 0", "L/4", "L/2", "3L/4", "L"};
  for (int c = 0; c < 5; ++c) {
    for (int s = 0; s < n_states; ++s) {
      if (stats.state_counts[c][s] == 0) continue;
      addRect(f, x[c], node_top[c][s], x[c] + node_w, node_bottom[c][s], stateColour(stats, s));
      const double fraction = static_cast<double>(stats.state_counts[c][s]) / stats.trials;
      f.shapes.push_back(
          Label{Vec2(x[c] + node_w + 4, 0.5 * (node_top[c][s] + node_bottom[c][s]) + 4),
                percent(fraction), 9, Anchor::start, kInk});
    }
    char caption[48];
    std::snprintf(caption, sizeof caption, "%s (%.1f s)", kColumnNames[c],
                  stats.columns[c] * stats.dt);
    f.shapes.push_back(
        Label{Vec2(x[c] + node_w / 2, f.height - bottom + 28), caption, 10, Anchor::middle, kInk});
  }
  double legend_y = top + 10;
  for (int s = 0; s < n_states; ++s) {
    addRect(f, f.width - right + 30, legend_y - 10, f.width - right + 42, legend_y + 2,
            stateColour(stats, s));
    f.shapes.push_back(
        Label{Vec2(f.width - right + 50, legend_y), stats.states[s], 10, Anchor::start, kInk});
    legend_y += 22;
  }
  char trials[32];
  std::snprintf(trials, sizeof trials, "%d trials", stats.trials);
  f.shapes.push_back(
      Label{Vec2(f.width - right + 30, legend_y + 10), trials, 9, Anchor::start, kInk});
  return f;
}

namespace {

// Each series of a panel is told apart by its line and marker as well as by its colour (for
// readers and printers without colour, and so that equal curves do not hide each other: the
// markers are staggered along the time axis).
constexpr Dash kDashes[kSeriesPerPanel] = {Dash::solid, Dash::dashed, Dash::dotted, Dash::dash_dot};

}  // namespace

std::vector<Vec2> seriesMarker(int index, const Vec2& at, double r) {
  switch (index % kSeriesPerPanel) {
    case 0: {  // disc (an octagon)
      std::vector<Vec2> ring;
      for (int i = 0; i < 8; ++i) {
        const double a = (i + 0.5) * std::acos(-1.0) / 4.0;
        ring.push_back(at + r * Vec2(std::cos(a), std::sin(a)));
      }
      return ring;
    }
    case 1:  // square
      return {at + Vec2(-r, -r), at + Vec2(r, -r), at + Vec2(r, r), at + Vec2(-r, r)};
    case 2:  // triangle, point up
      return {at + Vec2(0, -1.2 * r), at + Vec2(1.1 * r, 0.8 * r), at + Vec2(-1.1 * r, 0.8 * r)};
    default:  // diamond
      return {at + Vec2(0, -1.3 * r), at + Vec2(1.3 * r, 0), at + Vec2(0, 1.3 * r),
              at + Vec2(-1.3 * r, 0)};
  }
}

std::vector<int> coverageFacets(int configs) {
  const int facets = std::max(1, (configs + kSeriesPerPanel - 1) / kSeriesPerPanel);
  std::vector<int> facet_of(configs);
  // Balanced: 6 configurations → 3 + 3, not 4 + 2.
  for (int c = 0; c < configs; ++c) facet_of[c] = c * facets / std::max(configs, 1);
  return facet_of;
}

Figure coverageFigure(const std::vector<const ConfigStatistics*>& configs,
                      const std::vector<std::string>& labels,
                      const std::vector<std::string>& target_names, const std::string& title) {
  Figure f;
  const int n = static_cast<int>(configs.size());
  const std::vector<int> facet_of = coverageFacets(n);
  const int facets = n ? facet_of.back() + 1 : 1;
  // A series' place among its panel's, which picks its line and marker.
  std::vector<int> slot(n);
  for (int c = 0; c < n; ++c)
    slot[c] = c == 0 || facet_of[c] != facet_of[c - 1] ? 0 : slot[c - 1] + 1;
  const int panels = static_cast<int>(target_names.size()) * facets;
  const double left = 70, right = 30, panel_h = 170, panel_gap = 45, legend_row = 18;
  const double top = 75 + legend_row * static_cast<double>(n);  // legend above the panels
  f.width = 900;
  f.height = static_cast<int>(top + panels * (panel_h + panel_gap) + 20);
  f.shapes.push_back(Label{Vec2(f.width / 2.0, 30), title, 14, Anchor::middle, kInk});
  const auto styled = [&](int c, std::vector<Vec2> points, double width) {
    return Line{std::move(points), width, seriesColour(c), kDashes[slot[c]]};
  };
  const auto marker = [&](int c, const Vec2& at) {
    return FilledPolygon{seriesMarker(slot[c], at, 4.0), seriesColour(c)};
  };
  for (int c = 0; c < n; ++c) {  // one legend row per configuration
    const double ly = 55 + legend_row * static_cast<double>(c);
    f.shapes.push_back(styled(c, {Vec2(left, ly), Vec2(left + 40, ly)}, 2.5));
    f.shapes.push_back(marker(c, Vec2(left + 20, ly)));
    std::string text = labels[c];
    if (facets > 1) text += "  (panel " + std::to_string(facet_of[c] + 1) + ")";
    f.shapes.push_back(Label{Vec2(left + 48, ly + 5), text, 10, Anchor::start, kInk});
  }
  f.shapes.push_back(FilledPolygon{{Vec2(f.width - 250.0, 48), Vec2(f.width - 220.0, 48),
                                    Vec2(f.width - 220.0, 62), Vec2(f.width - 250.0, 62)},
                                   kShade});
  f.shapes.push_back(
      Label{Vec2(f.width - 212.0, 60), "target under a crown", 10, Anchor::start, kInk});
  f.shapes.push_back(
      Label{Vec2(f.width - 250.0, 80), "bands: 95 % interval", 10, Anchor::start, kInk});
  if (configs.empty() || configs.front()->coverage.empty()) return f;
  const int steps = static_cast<int>(configs.front()->coverage.front().size());
  const double dt = configs.front()->dt;
  const double t_end = (steps - 1) * dt;
  double y_max = 1.0;
  for (const ConfigStatistics* c : configs) {
    for (const auto& curve : c->coverage)
      y_max = std::max(y_max, *std::max_element(curve.begin(), curve.end()));
  }
  y_max = std::ceil(y_max * 2.0) / 2.0;  // to the next 0.5
  const double plot_w = f.width - left - right;
  // About ten markers per curve, each series' shifted by a quarter of the spacing (at least one
  // step), so that no two series of a panel put a marker at the same time.
  const int marker_every = std::max(kSeriesPerPanel, steps / 10);

  for (int p = 0; p < panels; ++p) {
    const int t = p / facets, facet = p % facets;
    const double y0 = top + p * (panel_h + panel_gap);  // panel's top
    auto px = [&](double time, double value) {
      return Vec2(left + plot_w * time / t_end, y0 + panel_h * (1.0 - value / y_max));
    };
    for (const OcclusionStatistics& o : configs.front()->occlusions) {
      if (o.target != t) continue;
      const Vec2 a = px(o.hidden.first * dt, y_max), b = px(o.hidden.last * dt, 0.0);
      addRect(f, a.x(), a.y(), b.x(), b.y(), kShade);
    }
    for (double v = 0.0; v <= y_max + 1e-9; v += 0.5) {
      f.shapes.push_back(Line{{px(0, v), px(t_end, v)}, 1, kGrid});
      char text[16];
      std::snprintf(text, sizeof text, "%.1f", v);
      f.shapes.push_back(Label{px(0, v) + Vec2(-8, 4), text, 9, Anchor::end, kInk});
    }
    for (double time = 0.0; time <= t_end + 1e-9; time += 2.0) {
      char text[16];
      std::snprintf(text, sizeof text, "%.0f s", time);
      f.shapes.push_back(Label{px(time, 0) + Vec2(0, 16), text, 9, Anchor::middle, kInk});
    }
    f.shapes.push_back(Line{{px(0, y_max), px(0, 0), px(t_end, 0)}, 1.5, kInk});
    std::string heading = "trajectory " + target_names[t] + ": mean number of footprints";
    if (facets > 1) heading += " (panel " + std::to_string(facet + 1) + ")";
    f.shapes.push_back(Label{Vec2(left, y0 - 8), heading, 10, Anchor::start, kInk});
    for (int c = 0; c < n; ++c) {  // bands first, so every line stays on top
      if (facet_of[c] != facet) continue;
      Colour band = seriesColour(c);
      band.alpha = 0.18;
      addIntervalBand(f, configs[c]->coverage_ci[t], dt, y_max, px, band);
    }
    for (int c = 0; c < n; ++c) {
      if (facet_of[c] != facet) continue;
      std::vector<Vec2> curve;
      for (int k = 0; k < steps; ++k) curve.push_back(px(k * dt, configs[c]->coverage[t][k]));
      f.shapes.push_back(styled(c, curve, 2.5));
      for (int k = slot[c] * marker_every / kSeriesPerPanel; k < steps; k += marker_every)
        f.shapes.push_back(marker(c, curve[k]));
    }
  }
  return f;
}

}  // namespace canopy::analysis
