#pragma once
// "Did you mean": the known word nearest to a mistyped one, for the command line's commands and
// options (app/help.h) and a scenario file's field names and choices (spec/json_reader.cpp).
#include <cstddef>
#include <string>
#include <vector>

namespace canopy {

/// Optimal string alignment distance: insertions, deletions, substitutions and transpositions of
/// neighbours ("rnu" → "run") each cost one.
std::size_t editDistance(const std::string& a, const std::string& b);

/// The candidate nearest to `word` by edit distance when it is close enough to be a typo (at most
/// max(1, |word| / 3) edits), else "" (also for words over 100 characters).
std::string nearestWord(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace canopy
