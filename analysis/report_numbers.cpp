#include "analysis/report_numbers.h"

#include <cmath>
#include <cstdio>

namespace canopy::analysis {

std::string num(double x, const char* format) {
  char text[32];
  std::snprintf(text, sizeof text, format, x);
  return text;
}

std::string percentWithInterval(const Estimate& e) {
  char text[64];
  if (!e.ci.bounded()) {  // one trial, or fewer than kMinTrialsForPoint agreeing ones
    std::snprintf(text, sizeof text, "%.1f %% [too few trials: %d]", 100.0 * e.value, e.trials);
    return text;
  }
  std::snprintf(text, sizeof text, "%.1f %% [%.1f, %.1f]", 100.0 * e.value, 100.0 * e.ci.low,
                100.0 * e.ci.high);
  return text;
}

std::string numberWithInterval(const Estimate& e, const char* format) {
  char value[32], low[32], high[32];
  std::snprintf(value, sizeof value, format, e.value);
  if (!e.ci.bounded())
    return std::string(value) + " [too few trials: " + std::to_string(e.trials) + "]";
  std::snprintf(low, sizeof low, format, e.ci.low);
  std::snprintf(high, sizeof high, format, e.ci.high);
  return std::string(value) + " [" + low + ", " + high + "]";
}

std::string paperVerdict(double paper, const Estimate& ours) {
  constexpr double kTolerance = 0.15;  // ±15 percentage points, issue 10's "Done when"
  const double delta = paper - ours.value;
  // Round to 0.1 pt first, so that the sign and the tolerance test agree with what is printed.
  const double delta_pts = std::round(1000.0 * delta) / 10.0;
  char text[64];
  std::snprintf(text, sizeof text, "Δ %s%.1f pts",
                delta_pts > 0   ? "+"
                : delta_pts < 0 ? "−"
                                : "±",
                std::fabs(delta_pts));
  if (ours.ci.contains(paper)) return std::string("yes; ") + text;
  return std::string("no; ") + text +
         (std::fabs(delta_pts) <= 100.0 * kTolerance ? " (within ±15)" : " (beyond ±15)");
}

namespace {
std::string secondsText(double t) {
  if (!std::isfinite(t)) return "never";
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", t);
  return text;
}
}  // namespace

std::string timeWithInterval(const CrossingTime& t) {
  if (!t.time_s) return "never";
  std::string text = secondsText(*t.time_s) + " s";
  if (!std::isfinite(t.ci.low)) return text + " [too few trials]";
  return text + " [" + secondsText(t.ci.low) + ", " + secondsText(t.ci.high) + "]";
}

std::string timeVerdict(double paper_s, const CrossingTime& ours) {
  if (!ours.time_s) return "no (never crosses)";
  const double delta = std::round(10.0 * (paper_s - *ours.time_s)) / 10.0;  // as printed
  char text[48];
  std::snprintf(text, sizeof text, "Δ %s%.1f s", delta > 0 ? "+" : delta < 0 ? "−" : "±",
                std::fabs(delta));
  return std::string(ours.contains(paper_s) ? "yes; " : "no; ") + text;
}

}  // namespace canopy::analysis
