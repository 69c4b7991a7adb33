#pragma once
// What every command says about itself: its synopsis, options and their defaults (`--help`),
// and the nearest known name when a user mistypes one ("did you mean").
#include <span>
#include <string>
#include <vector>

namespace canopy::app {

struct OptionHelp {
  const char* name;           // "--out"
  const char* value;          // "DIR", or "" for a flag
  const char* default_value;  // what applies without the option ("out/NAME", "off")
  const char* meaning;        // one line
};

struct CommandHelp {
  const char* name;      // "run"
  const char* synopsis;  // "canopy run [SCENARIO] [options]"
  const char* summary;   // one paragraph
  std::span<const OptionHelp> options;
};

/// Every command, in the order `canopy --help` lists them.
std::span<const CommandHelp> commands();
/// The command called `name`, or nullptr.
const CommandHelp* findCommand(const std::string& name);
/// `canopy NAME --help`: synopsis, summary and a table of options with their defaults.
std::string helpText(const CommandHelp& command);
/// `canopy --help`: every command's synopsis and summary.
std::string overviewText();

/// The candidate nearest to `word` by edit distance when it is close enough to be a typo (at most
/// one edit per three characters, and at least one), else "".
std::string nearest(const std::string& word, const std::vector<std::string>& candidates);

/// A usage error for an option `command` does not take, suggesting the nearest one it does.
[[noreturn]] void unknownOption(const std::string& command, const std::string& option);

/// The program's version and the git commit it was built from ("unknown" without git).
const char* versionText();

}  // namespace canopy::app
