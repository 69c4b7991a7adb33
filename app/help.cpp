#include "app/help.h"

#include <algorithm>

#include "core/nearest_word.h"
#include "core/version.h"

namespace canopy::app {
namespace {

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
  return nearestWord(word, candidates);
}

std::string versionText() {
  return std::string("canopy ") + kVersion + " (git " + kGitCommit + ")";
}

}  // namespace canopy::app
