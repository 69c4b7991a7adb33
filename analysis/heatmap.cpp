#include "analysis/heatmap.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "analysis/figure_png.h"
#include "core/text_file.h"
#include "spec/error.h"

namespace canopy::analysis {
namespace {

std::optional<double> number(const std::string& json) {
  double value = 0.0;
  const char* end = json.data() + json.size();
  const auto [ptr, error] = std::from_chars(json.data(), end, value);
  if (error != std::errc() || ptr != end) return std::nullopt;
  return value;
}

bool numeric(const experiments::SweepAxis& axis) {
  return !axis.values.empty() && std::all_of(axis.values.begin(), axis.values.end(),
                                             [](const std::string& v) { return number(v); });
}

std::string fileSafe(std::string text) {
  for (char& c : text) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '.') c = '_';
  }
  return text;
}

std::string lastComponent(const std::string& path) {
  return path.substr(path.rfind('.') + 1);
}

std::vector<std::string> byNumericValue(std::vector<std::string> values) {
  std::stable_sort(values.begin(), values.end(), [](const std::string& a, const std::string& b) {
    return *number(a) < *number(b);
  });
  return values;
}

std::optional<HeatmapCell> cellOf(const ConfigStatistics& s, const HeatmapMetric& metric,
                                  const spec::ScenarioSpec& spec) {
  HeatmapCell cell;
  cell.trials = s.trials;
  if (!metric.state.empty()) {
    cell.value = s.stateEstimate(metric.state, 4);  // the Sankey's last column, k = L
    return cell;
  }
  if (s.occlusions.empty()) return std::nullopt;
  const OcclusionStatistics& o = s.occlusions.front();  // ordered by target, then first step
  Interval steps = o.hidden;
  if (metric.before_hiding_s > 0.0) {
    // the last ⌈before_hiding_s / dt⌉ steps before the first hidden one, from step 0 on
    const int window = static_cast<int>(std::ceil(metric.before_hiding_s / s.dt - 1e-9));
    steps = Interval{std::max(0, o.hidden.first - window), o.hidden.first - 1};
    if (steps.last < steps.first) return std::nullopt;  // hidden from the first step
  }
  cell.value = s.coverageOver(o.target, steps);
  char detail[96];
  std::snprintf(detail, sizeof detail, "%s %.1f-%.1f s", spec.targets[o.target].name.c_str(),
                steps.first * s.dt, steps.last * s.dt);
  cell.detail = detail;
  return cell;
}

std::string cellText(const std::optional<HeatmapCell>& cell) {
  if (!cell) return "—";
  char text[64];
  if (cell->value.ci.bounded()) {
    std::snprintf(text, sizeof text, "%.2f [%.2f, %.2f]", cell->value.value, cell->value.ci.low,
                  cell->value.ci.high);
  } else {
    std::snprintf(text, sizeof text, "%.2f (1 trial)", cell->value.value);
  }
  return text;
}

std::string formatted(double x) {
  std::ostringstream text;
  text << x;
  return text.str();
}

}  // namespace

std::string displayValue(const std::string& json) {
  const bool quoted = json.size() >= 2 && json.front() == '"' && json.back() == '"';
  return quoted ? json.substr(1, json.size() - 2) : json;
}

std::string displayOverride(const std::string& override_text) {
  const std::size_t eq = override_text.find('=');
  return override_text.substr(0, eq) + " = " + displayValue(override_text.substr(eq + 1));
}

std::optional<HeatmapMetric> heatmapMetric(const SweepAnalysis& analysis,
                                           const HeatmapRequest& request) {
  if (analysis.configs.empty()) return std::nullopt;
  const std::vector<std::string>& states = analysis.configs.front().states;
  const std::string& state = request.state;
  if (!state.empty()) {
    if (std::find(states.begin(), states.end(), state) == states.end()) {
      std::string known;
      for (const std::string& s : states) known += (known.empty() ? "" : ", ") + s;
      throw spec::ScenarioError(
          analysis.dir.string(), "--state",
          "expected one of the ownership states " + known + ", got \"" + state + "\"");
    }
    return HeatmapMetric{state, 0.0, "fraction of trials in " + state + " at L", 1.0};
  }
  const bool occlusions =
      std::any_of(analysis.configs.begin(), analysis.configs.end(),
                  [](const ConfigStatistics& s) { return !s.occlusions.empty(); });
  std::size_t uavs = 1;  // coverage counts footprints: at most the number of UAVs
  for (const auto& spec : analysis.specs) uavs = std::max(uavs, spec.uavs.size());
  if (request.before_hiding_s > 0.0) {
    if (!occlusions)
      throw spec::ScenarioError(analysis.dir.string(), "--before-hiding",
                                "expected a sweep whose targets are hidden at some step");
    return HeatmapMetric{"", request.before_hiding_s,
                         "mean footprints on the occluded target in the " +
                             formatted(request.before_hiding_s) + " s before it is hidden",
                         static_cast<double>(uavs)};
  }
  for (const auto& named : analysis.specs.front().analysis.states) {
    if (named.name == "M*") return HeatmapMetric{"M*", 0.0, "fraction of trials in M* at L", 1.0};
  }
  if (!occlusions) return std::nullopt;
  return HeatmapMetric{"", 0.0, "mean footprints on the occluded target while hidden",
                       static_cast<double>(uavs)};
}

std::vector<Heatmap> sensitivityMaps(const SweepAnalysis& analysis, const HeatmapMetric& metric) {
  std::vector<std::size_t> numeric_axes;
  for (std::size_t a = 0; a < analysis.axes.size(); ++a) {
    if (numeric(analysis.axes[a])) numeric_axes.push_back(a);
  }
  if (numeric_axes.size() < 2) return {};
  const experiments::SweepAxis& x_axis = analysis.axes[numeric_axes[0]];
  const experiments::SweepAxis& y_axis = analysis.axes[numeric_axes[1]];
  std::vector<Heatmap> maps;
  for (std::size_t c = 0; c < analysis.configs.size(); ++c) {
    const ConfigStatistics& s = analysis.configs[c];
    std::vector<std::string> others;
    for (std::size_t a = 0; a < analysis.axes.size(); ++a) {
      if (a == numeric_axes[0] || a == numeric_axes[1]) continue;
      others.push_back(analysis.axes[a].path + "=" + s.axisValue(analysis.axes[a].path));
    }
    auto map = std::find_if(maps.begin(), maps.end(),
                            [&](const Heatmap& m) { return m.others == others; });
    if (map == maps.end()) {
      Heatmap m;
      m.x_path = x_axis.path;
      m.y_path = y_axis.path;
      m.x_values = byNumericValue(x_axis.values);
      m.y_values = byNumericValue(y_axis.values);
      m.others = others;
      m.metric = metric;
      m.cells.assign(m.y_values.size(), std::vector<std::optional<HeatmapCell>>(m.x_values.size()));
      m.stem = "heatmap_" + fileSafe(lastComponent(m.x_path)) + "_vs_" +
               fileSafe(lastComponent(m.y_path));
      for (const std::string& o : others) {
        const std::size_t eq = o.find('=');
        m.stem +=
            "_" + fileSafe(lastComponent(o.substr(0, eq)) + "-" + displayValue(o.substr(eq + 1)));
      }
      map = maps.insert(maps.end(), std::move(m));
    }
    const auto xi = std::find(map->x_values.begin(), map->x_values.end(), s.axisValue(x_axis.path));
    const auto yi = std::find(map->y_values.begin(), map->y_values.end(), s.axisValue(y_axis.path));
    if (xi == map->x_values.end() || yi == map->y_values.end()) continue;
    map->cells[yi - map->y_values.begin()][xi - map->x_values.begin()] =
        cellOf(s, metric, analysis.specs[c]);
  }
  return maps;
}

std::string heatmapCsv(const Heatmap& map) {
  std::ostringstream csv;
  csv << "x_path,x,y_path,y";
  for (const std::string& o : map.others) csv << ",\"" << o.substr(0, o.find('=')) << '"';
  csv << ",metric,trials,value,low,high,width,detail\n";
  for (std::size_t y = 0; y < map.y_values.size(); ++y) {
    for (std::size_t x = 0; x < map.x_values.size(); ++x) {
      csv << '"' << map.x_path << "\"," << map.x_values[x] << ",\"" << map.y_path << "\","
          << map.y_values[y];
      for (const std::string& o : map.others)
        csv << ",\"" << displayValue(o.substr(o.find('=') + 1)) << '"';
      csv << ",\"" << map.metric.label << "\",";
      const std::optional<HeatmapCell>& cell = map.cells[y][x];
      if (!cell) {
        csv << "0,,,,,\n";  // trials, then value, low, high, width and detail empty
        continue;
      }
      const Estimate& e = cell->value;
      csv << cell->trials << ',' << csvNumber(e.value) << ',' << csvNumber(e.ci.low) << ','
          << csvNumber(e.ci.high) << ',' << csvNumber(e.ci.width()) << ",\"" << cell->detail
          << "\"\n";
    }
  }
  return csv.str();
}

std::vector<Heatmap> writeHeatmaps(const SweepAnalysis& analysis,
                                   const std::filesystem::path& out_dir,
                                   const HeatmapRequest& request, const FigureStyle& style) {
  const std::optional<HeatmapMetric> metric = heatmapMetric(analysis, request);
  if (!metric) return {};
  std::vector<Heatmap> maps = sensitivityMaps(analysis, *metric);
  for (const Heatmap& map : maps) {
    const std::filesystem::path stem = out_dir / map.stem;
    writeFileAtomically(stem.string() + ".csv", heatmapCsv(map));
    writeFigure(heatmapFigure(map, analysis.name + ": where the behaviour emerges"), stem, style);
  }
  return maps;
}

std::string heatmapMarkdown(const SweepAnalysis& analysis, const std::string& figures_dir,
                            const std::string& heading, const HeatmapRequest& request) {
  const std::optional<HeatmapMetric> metric = heatmapMetric(analysis, request);
  if (!metric) return "";
  const std::vector<Heatmap> maps = sensitivityMaps(analysis, *metric);
  if (maps.empty()) return "";
  std::ostringstream md;
  md << "### " << heading << "\n\n";
  md << "Each cell: the " << metric->label << " (" << maps.front().x_path << " across, "
     << maps.front().y_path << " up), with its 95 % interval ("
     << (metric->state.empty() ? "Student t" : "Wilson") << ").\n\n";
  for (const Heatmap& map : maps) {
    std::string others;
    for (const std::string& o : map.others)
      others += (others.empty() ? "" : ", ") + displayOverride(o);
    md << "![" << heading << (others.empty() ? "" : " — " + others) << "](" << figures_dir << "/"
       << map.stem << ".png)\n\n";
    md << "| " << lastComponent(map.y_path) << " \\ " << lastComponent(map.x_path) << " |";
    for (const std::string& x : map.x_values) md << ' ' << displayValue(x) << " |";
    md << "\n|---|";
    for (std::size_t x = 0; x < map.x_values.size(); ++x) md << "---:|";
    md << '\n';
    for (std::size_t y = map.y_values.size(); y-- > 0;) {  // the largest y on top, as drawn
      md << "| " << displayValue(map.y_values[y]) << " |";
      for (const auto& cell : map.cells[y]) md << ' ' << cellText(cell) << " |";
      md << '\n';
    }
    md << '\n';
  }
  return md.str();
}

}  // namespace canopy::analysis
