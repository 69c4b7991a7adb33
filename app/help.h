#pragma once
// What `canopy --help` and `canopy COMMAND --help` print, made from the options each command
// declares on CLI11 (name, value, default, meaning), and the nearest known name when a user
// mistypes one ("did you mean"; CLI11 has none of its own).
#include <CLI/CLI.hpp>
#include <span>
#include <string>
#include <vector>

#include "app/commands.h"

namespace canopy::app {

/// `canopy NAME --help`: synopsis, summary and a table of options with their defaults.
std::string helpText(const Command& command);
/// `canopy --help`: every command's synopsis and summary.
std::string overviewText(std::span<const std::unique_ptr<Command>> commands);

/// The long option names `command` takes ("--out", …, "--help").
std::vector<std::string> optionNames(const CLI::App& command);

/// The candidate nearest to `word` by edit distance when it is close enough to be a typo (at most
/// one edit per three characters, and at least one), else "".
std::string nearest(const std::string& word, const std::vector<std::string>& candidates);

/// The program's version and the git commit it was built from ("unknown" without git).
std::string versionText();

}  // namespace canopy::app
