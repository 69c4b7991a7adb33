#pragma once
// How report.md writes a number with its uncertainty, and how it compares it with the paper's.
#include <string>

#include "analysis/intervals.h"

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

}  // namespace canopy::analysis
