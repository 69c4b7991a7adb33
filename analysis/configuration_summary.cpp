#include "analysis/configuration_summary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "analysis/heatmap.h"
#include "analysis/plots.h"

namespace canopy::analysis {
namespace {

// "path-or-name=value" → "name = value" with its last path component.
std::string pointText(const std::string& point) {
  const std::size_t eq = point.find('=');
  std::string name = point.substr(0, eq);
  const std::size_t dot = name.rfind('.');
  if (dot != std::string::npos) name = name.substr(dot + 1);
  return name + " = " + displayValue(point.substr(eq + 1));
}

std::string estimateText(const Estimate& e, const char* format) {
  if (e.trials == 0) return "—";
  char value[32], low[32], high[32];
  std::snprintf(value, sizeof value, format, e.value);
  if (!e.ci.bounded()) return std::string(value) + " (" + std::to_string(e.trials) + " trial)";
  std::snprintf(low, sizeof low, format, e.ci.low);
  std::snprintf(high, sizeof high, format, e.ci.high);
  return std::string(value) + " [" + low + ", " + high + "]";
}

}  // namespace

std::vector<ConfigurationSummary> summariseConfigurations(const SweepAnalysis& analysis) {
  std::vector<ConfigurationSummary> rows;
  for (const ConfigStatistics& s : analysis.configs) {
    std::string category = s.id, series;
    if (!s.point.empty())
      category = displayValue(s.point.front().substr(s.point.front().find('=') + 1));
    for (std::size_t a = 1; a < s.point.size(); ++a) {
      if (a > 1) series += ", ";
      series += pointText(s.point[a]);
    }
    std::vector<double> covered;  // per trial: the pairs (t, k) with a footprint on t
    for (const auto& trial : s.trial_coverage) {
      long long in = 0, pairs = 0;
      for (const auto& curve : trial) {
        for (const int footprints : curve) {
          in += footprints > 0;
          ++pairs;
        }
      }
      if (pairs > 0) covered.push_back(static_cast<double>(in) / static_cast<double>(pairs));
    }
    Estimate team_ospa, held;
    if (!s.trial_team_ospa.empty()) {
      team_ospa = meanOf(s.trial_team_ospa);
      team_ospa.ci = clipped(team_ospa.ci, 0.0, INFINITY);
      held = boundedMeanOf(s.trial_held, 0.0, 1.0);
    }
    rows.push_back({s.id, std::move(category), std::move(series), boundedMeanOf(covered, 0.0, 1.0),
                    team_ospa, held});
  }
  return rows;
}

Figure configurationFigure(const std::vector<ConfigurationSummary>& rows,
                           const std::string& title) {
  Figure f;
  std::vector<std::string> categories, series;
  for (const ConfigurationSummary& r : rows) {
    if (std::find(categories.begin(), categories.end(), r.category) == categories.end())
      categories.push_back(r.category);
    if (std::find(series.begin(), series.end(), r.series) == series.end())
      series.push_back(r.series);
  }
  const double left = 80, right = 30, panel_h = 180, panel_gap = 60, legend_row = 18;
  const double top = 60 + legend_row * static_cast<double>(series.size());
  f.width = 900;
  f.height = static_cast<int>(top + 3 * (panel_h + panel_gap) + 10);
  f.shapes.push_back(Label{Vec2(f.width / 2.0, 28), title, 14, Anchor::middle, kInk});
  for (std::size_t s = 0; s < series.size(); ++s) {  // legend
    const double ly = 50 + legend_row * static_cast<double>(s);
    const int c = static_cast<int>(s);
    f.shapes.push_back(FilledPolygon{seriesMarker(c, Vec2(left + 10, ly), 5.0), seriesColour(c)});
    f.shapes.push_back(Label{Vec2(left + 24, ly + 4), series[s].empty() ? "all" : series[s], 10,
                             Anchor::start, kInk});
  }
  f.shapes.push_back(Label{Vec2(f.width - right, 54),
                           "markers: mean over trials; bars: 95 % interval", 10, Anchor::end,
                           kInk});
  struct Panel {
    const char* heading;
    Estimate ConfigurationSummary::*value;
    bool fraction;  // in [0, 1]; else from 0 to the largest interval end
  };
  const Panel panels[] = {
      {"team coverage: fraction of (person, step) pairs in some footprint",
       &ConfigurationSummary::coverage, true},
      {"team OSPA (m), mean over the run", &ConfigurationSummary::team_ospa, false},
      {"people held: fraction, mean over the run", &ConfigurationSummary::held, true}};
  const double plot_w = f.width - left - right;
  const double column =
      categories.empty() ? plot_w : plot_w / static_cast<double>(categories.size());
  for (int p = 0; p < 3; ++p) {
    const double y0 = top + p * (panel_h + panel_gap);
    double y_max = 1.0;
    if (!panels[p].fraction) {
      y_max = 0.0;
      for (const ConfigurationSummary& r : rows) {
        const Estimate& e = r.*panels[p].value;
        if (e.trials == 0) continue;
        y_max = std::max(y_max, e.ci.bounded() ? e.ci.high : e.value);
      }
      // The next of 1, 2, 2.5, 5 × 10^n at or above it, so that the quarters are round.
      double nice = 1.0;
      if (y_max > 0.0) {
        const double decade = std::pow(10.0, std::floor(std::log10(y_max)));
        nice = 10.0 * decade;
        for (const double step : {1.0, 2.0, 2.5, 5.0}) {
          if (step * decade >= y_max) {
            nice = step * decade;
            break;
          }
        }
      }
      y_max = nice;
    }
    auto py = [&](double v) { return y0 + panel_h * (1.0 - std::clamp(v / y_max, 0.0, 1.0)); };
    for (int g = 0; g <= 4; ++g) {  // grid and values
      const double v = y_max * g / 4.0;
      f.shapes.push_back(
          Line{{Vec2(left, py(v)), Vec2(left + plot_w, py(v))}, 1, Colour{200, 200, 200}});
      char text[16];
      std::snprintf(text, sizeof text, "%.2f", v);
      f.shapes.push_back(Label{Vec2(left - 8, py(v) + 4), text, 9, Anchor::end, kInk});
    }
    f.shapes.push_back(Line{
        {Vec2(left, y0), Vec2(left, y0 + panel_h), Vec2(left + plot_w, y0 + panel_h)}, 1.5, kInk});
    f.shapes.push_back(Label{Vec2(left, y0 - 10), panels[p].heading, 10, Anchor::start, kInk});
    for (std::size_t c = 0; c < categories.size(); ++c) {
      const double x = left + column * (static_cast<double>(c) + 0.5);
      f.shapes.push_back(
          Label{Vec2(x, y0 + panel_h + 16), categories[c], 10, Anchor::middle, kInk});
    }
    for (const ConfigurationSummary& r : rows) {
      const Estimate& e = r.*panels[p].value;
      if (e.trials == 0) continue;
      const auto c =
          std::find(categories.begin(), categories.end(), r.category) - categories.begin();
      const auto s = std::find(series.begin(), series.end(), r.series) - series.begin();
      // Series side by side within the category's column.
      const double x =
          left + column * (static_cast<double>(c) + 0.5) +
          column * 0.5 *
              ((static_cast<double>(s) + 0.5) / static_cast<double>(series.size()) - 0.5);
      const Colour colour = seriesColour(static_cast<int>(s));
      if (e.ci.bounded()) {
        f.shapes.push_back(Line{{Vec2(x, py(e.ci.low)), Vec2(x, py(e.ci.high))}, 2, colour});
        for (const double end : {e.ci.low, e.ci.high})
          f.shapes.push_back(Line{{Vec2(x - 5, py(end)), Vec2(x + 5, py(end))}, 2, colour});
      }
      f.shapes.push_back(
          FilledPolygon{seriesMarker(static_cast<int>(s), Vec2(x, py(e.value)), 5.0), colour});
    }
  }
  return f;
}

std::string configurationMarkdown(const std::vector<ConfigurationSummary>& rows,
                                  const std::string& heading, const std::string& figures_dir,
                                  const std::string& stem) {
  std::ostringstream md;
  md << "### " << heading << "\n\n";
  int least = rows.empty() ? 0 : rows.front().coverage.trials, most = least;
  for (const ConfigurationSummary& r : rows) {
    least = std::min(least, r.coverage.trials);
    most = std::max(most, r.coverage.trials);
  }
  md << "Per configuration, over " << least;
  if (most != least) md << "–" << most;
  md << " trials: each figure's mean with its 95 % interval (Student t; coverage and held on "
        "the logit scale, inside [0, 1]).\n\n";
  md << "![" << heading << "](" << figures_dir << "/" << stem << ".png)\n\n";
  md << "| configuration | team coverage | team OSPA (m) | people held |\n|---|---:|---:|---:|\n";
  for (const ConfigurationSummary& r : rows) {
    md << "| " << r.category << (r.series.empty() ? "" : ", " + r.series) << " | "
       << estimateText(r.coverage, "%.3f") << " | " << estimateText(r.team_ospa, "%.2f") << " | "
       << estimateText(r.held, "%.3f") << " |\n";
  }
  md << '\n';
  return md.str();
}

}  // namespace canopy::analysis
