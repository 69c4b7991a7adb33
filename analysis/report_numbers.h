#pragma once
// How report.md writes a number with its uncertainty, and how it compares it with the paper's.
#include <string>
#include <vector>

#include "analysis/intervals.h"
#include "analysis/reaction.h"

namespace canopy::analysis {

/// The paper ran 40 trials per configuration; fewer are flagged in the report.
constexpr int kPaperTrials = 40;

/// "72.5 % [57.2, 83.9]": a proportion in percent with its interval in percent ("… [no interval:
/// 1 trial]" when unbounded).
std::string percentWithInterval(const Estimate& e);

/// "0.99 [0.95, 1.03]" with `format` for each number; "0.99 [no interval: 1 trial]" when the
/// interval is unbounded.
std::string numberWithInterval(const Estimate& e, const char* format = "%.2f");

/// Whether the paper's proportion lies inside our interval, and how far it is from our value in
/// percentage points: "yes; Δ +2.5 pts" or "no; Δ −12.5 pts (within ±15)" or
/// "no; Δ −27.5 pts (beyond ±15)", Δ = paper − ours.
std::string paperVerdict(double paper, const Estimate& ours);

/// "holds" when every case holds(), else "holds in k of n cases".
template <typename Case>
std::string verdictOf(const std::vector<Case>& cases) {
  long holds = 0;
  for (const Case& c : cases) holds += c.holds();
  if (!cases.empty() && holds == static_cast<long>(cases.size())) return "holds";
  return "holds in " + std::to_string(holds) + " of " + std::to_string(cases.size()) + " cases";
}

/// "1.8 s [1.6, 2.0]"; "never" when the mean curve never crosses; an interval end of +∞ reads
/// "never" ("3.0 s [2.6, never]").
std::string timeWithInterval(const CrossingTime& t);

/// Whether the paper's time lies inside our interval, and Δ = paper − ours in seconds:
/// "yes; Δ −0.2 s", "no; Δ +1.4 s"; "no (never crosses)" when our curve never does.
std::string timeVerdict(double paper_s, const CrossingTime& ours);

}  // namespace canopy::analysis
