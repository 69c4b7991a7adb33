#pragma once
// The replay data's text as it is built (replay_data.cpp): JSON values appended to one string,
// numbers rounded as replay_data.h says, and a table of distinct strings (track keys, labels)
// sent once and referred to by index.
#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "replay/replay_data.h"

namespace canopy::replay {

// Appends JSON values to one text. Numbers are written rounded, never as -0, non-finite as null.
class Writer {
 public:
  std::string text;

  void raw(const char* s) { text += s; }
  void comma(bool& first) {
    if (!first) text += ',';
    first = false;
  }
  void fixed(double x, int decimals) {
    if (!std::isfinite(x)) return raw("null");
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, x);
    trimmed(buffer);
  }
  void significant(double x) {
    if (!std::isfinite(x)) return raw("null");
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "%.*g", kSignificantDigits, x);
    trimmed(buffer);
  }
  void integer(long long x) { text += std::to_string(x); }
  void string(const std::string& s) { text += nlohmann::json(s).dump(); }
  void position(double x) { fixed(x, kPositionDecimals); }

 private:
  // "12.500" → "12.5", "3.000" → "3", "-0.00" → "0"; exponents ("1.2e-05") are kept.
  void trimmed(char* s) {
    std::string v(s);
    if (v.find('e') == std::string::npos && v.find('.') != std::string::npos) {
      while (v.back() == '0') v.pop_back();
      if (v.back() == '.') v.pop_back();
    }
    if (v == "-0") v = "0";
    text += v;
  }
};

// An index per distinct string, in order of first use.
class Table {
 public:
  int index(const std::string& s) {
    const auto [it, added] = ids_.try_emplace(s, static_cast<int>(names_.size()));
    if (added) names_.push_back(s);
    return it->second;
  }
  const std::vector<std::string>& names() const { return names_; }

 private:
  std::map<std::string, int> ids_;
  std::vector<std::string> names_;
};

}  // namespace canopy::replay
