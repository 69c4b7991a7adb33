#include "app/help.h"

#include <algorithm>

#include "core/version.h"

namespace canopy::app {
namespace {

// Optimal string alignment distance: insertions, deletions, substitutions and transpositions of
// neighbours ("rnu" → "run") each cost one.
std::size_t editDistance(const std::string& a, const std::string& b) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    for (std::size_t j = 1; j <= m; ++j) {
      d[i][j] = std::min(
          {d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[n][m];
}

// "--out DIR", or "--json" for a flag.
std::string flagWithValue(const CLI::Option& option) {
  const std::string name = option.get_name();
  return option.get_expected_max() == 0 ? name : name + " " + option.get_type_name();
}

}  // namespace

std::string helpText(const Command& command) {
  const CLI::App& app = command.app();
  std::string text = "usage: " + command.synopsis() + "\n\n" + app.get_description() + "\n";
  // The options as declared, --help last; positionals are in the synopsis.
  std::vector<const CLI::Option*> options;
  for (const CLI::Option* o : app.get_options()) {
    if (!o->get_positional() && o != app.get_help_ptr()) options.push_back(o);
  }
  if (options.empty()) return text;
  std::size_t width = 0;  // a flag's column is as wide as "NAME " with an empty value
  for (const CLI::Option* o : options)
    width = std::max(width, o->get_name().size() + 1 + o->get_type_name().size());
  text += "\noptions (default in brackets):\n";
  for (const CLI::Option* o : options) {
    std::string flag = flagWithValue(*o);
    flag.resize(width, ' ');
    const std::string fallback = o->get_expected_max() == 0 ? "off" : "none";
    const std::string default_value = o->get_default_str();
    text += "  " + flag + "  " + o->get_description() + " [" +
            (default_value.empty() ? fallback : default_value) + "]\n";
  }
  text += "  --help" + std::string(width - 6, ' ') + "  this text\n";
  return text;
}

std::string overviewText(std::span<const std::unique_ptr<Command>> commands) {
  std::string text = "canopy — multi-UAV target tracking under unknown occlusions\n\ncommands:\n";
  for (const std::unique_ptr<Command>& c : commands)
    text += "  " + c->synopsis() + "\n      " + c->app().get_description() + "\n";
  text +=
      "\n`canopy COMMAND --help` lists a command's options with their defaults; `canopy "
      "--version` prints the version.\nBad input exits with code 2, a failed write with code 1.\n";
  return text;
}

std::vector<std::string> optionNames(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::Option* o : command.get_options()) {
    for (const std::string& name : o->get_lnames()) names.push_back("--" + name);
  }
  return names;
}

std::string nearest(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_distance = std::max<std::size_t>(1, word.size() / 3) + 1;
  for (const std::string& c : candidates) {
    const std::size_t d = editDistance(word, c);
    if (d < best_distance) {
      best = c;
      best_distance = d;
    }
  }
  return best;
}

std::string versionText() {
  return std::string("canopy ") + kVersion + " (git " + kGitCommit + ")";
}

}  // namespace canopy::app
