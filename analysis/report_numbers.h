#pragma once
// How report.md writes a number with its uncertainty, and how it compares it with the paper's.
#include <string>
#include <vector>

#include "analysis/findings.h"
#include "analysis/intervals.h"
#include "analysis/reaction.h"

namespace canopy::analysis {

/// The paper ran 40 trials per configuration; fewer are flagged in the report.
constexpr int kPaperTrials = 40;

/// x printed with a printf `format` for one double ("0.73").
std::string num(double x, const char* format = "%.2f");

/// "72.5 % [57.2, 83.9]": a proportion in percent with its interval in percent ("… [too few
/// trials: 2]" when there is none).
std::string percentWithInterval(const Estimate& e);

/// "0.99 [0.95, 1.00]" with `format` for each number; "0.99 [too few trials: 2]" when there is
/// no interval.
std::string numberWithInterval(const Estimate& e, const char* format = "%.2f");

/// Whether the paper's proportion lies inside our interval, and how far it is from our value in
/// percentage points: "yes; Δ +2.5 pts" or "no; Δ −12.5 pts (within ±15)" or
/// "no; Δ −27.5 pts (beyond ±15)", Δ = paper − ours.
std::string paperVerdict(double paper, const Estimate& ours);

/// A finding's verdict over its cases (each case's verdict(), analysis/findings.h): "holds" when
/// every case holds, else the count of each verdict given, "holds in 2, consistent in 3, fails in
/// 1 of 6 cases".
template <typename Case>
std::string verdictOf(const std::vector<Case>& cases) {
  int count[4] = {0, 0, 0, 0};
  for (const Case& c : cases) ++count[static_cast<int>(c.verdict())];
  if (!cases.empty() && count[0] == static_cast<int>(cases.size())) return "holds";
  std::string text;
  for (const Verdict v :
       {Verdict::holds, Verdict::consistent, Verdict::fails, Verdict::too_few_trials}) {
    if (!count[static_cast<int>(v)]) continue;
    text += (text.empty() ? "" : ", ") + std::string(verdictText(v)) + " in " +
            std::to_string(count[static_cast<int>(v)]);
  }
  return text + " of " + std::to_string(cases.size()) + " cases";
}

/// "1.8 s [1.6, 2.0]"; "never" when the mean curve never crosses; an interval end of +∞ reads
/// "never" ("3.0 s [2.6, never]").
std::string timeWithInterval(const CrossingTime& t);

/// Whether the paper's time lies inside our interval, and Δ = paper − ours in seconds:
/// "yes; Δ −0.2 s", "no; Δ +1.4 s"; "no (never crosses)" when our curve never does.
std::string timeVerdict(double paper_s, const CrossingTime& ours);

}  // namespace canopy::analysis
