// canopy: the command line. Thin: parses (CLI11), calls the libraries, prints.
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <mutex>
#include <new>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/help.h"
#include "core/output_file.h"
#include "core/printable.h"
#include "core/progress.h"
#include "spec/error.h"

namespace canopy::app {

std::vector<std::unique_ptr<Command>> makeCommands(CLI::App& canopy,
                                                   const std::string& command_line) {
  std::vector<std::unique_ptr<Command>> commands;
  commands.push_back(makeRun(canopy, command_line));
  commands.push_back(makeValidate(canopy));
  commands.push_back(makeCoverage(canopy));
  commands.push_back(makeView(canopy));
  commands.push_back(makeRecord(canopy));
  commands.push_back(makeSweep(canopy));
  commands.push_back(makeAnalyze(canopy));
  commands.push_back(makeReproduce(canopy));
  commands.push_back(makeImitate(canopy));
  commands.push_back(makeForest(canopy));
  commands.push_back(makeImport(canopy));
  commands.push_back(makeSchema(canopy));
  commands.push_back(makeList(canopy));
  return commands;
}

}  // namespace canopy::app

namespace {

using namespace canopy::app;

// Every message may quote the user's text (names, paths, values): shown through printable().
void report(const std::string& message) {
  std::fprintf(stderr, "canopy: %s\n", canopy::printable(message).c_str());
}

// The words CLI11 left over: an option `command` does not take (with the nearest it does), or a
// second positional. Throws the usage error.
void refuseLeftovers(const CLI::App& command) {
  bool options_ended = false;
  for (const std::string& word : command.remaining()) {
    if (word == "--" && !options_ended) {  // the end of options, kept by CLI11
      options_ended = true;
      continue;
    }
    if (!options_ended && word.size() > 1 && word[0] == '-') {
      const std::string guess = nearest(word, optionNames(command));
      const std::string name = command.get_name();
      usageError(word, "unknown option for `canopy " + name + "`" +
                           (guess.empty() ? "" : "; did you mean " + guess + "?") + " (`canopy " +
                           name + " --help` lists them)");
    }
    const std::vector<const CLI::Option*> positionals =
        command.get_options([](const CLI::Option* o) { return o->get_positional(); });
    if (positionals.empty()) {
      usageError(word, "`canopy " + command.get_name() + "` takes no " +
                           (command.get_options().size() > 1 ? "positional " : "") + "arguments");
    }
    usageError(word, "expected one " + positionals.front()->get_name(true) + ", got a second one");
  }
}

// CLI11's own refusals in our words: the option, then what it expected. CLI11's messages start
// with the option's name ("--seed: 1 required N missing", "--aoi is required"); those two are
// said plainly, any other is shown as CLI11 words it.
std::string parseErrorMessage(const CLI::ParseError& e, const CLI::App* command) {
  const std::string what = e.what();
  if (!command) return what;
  for (const CLI::Option* o : command->get_options()) {
    const std::string name = o->get_name();
    if (name.empty() || what.rfind(name, 0) != 0) continue;
    const std::string value = name + " " + o->get_type_name();
    if (dynamic_cast<const CLI::ArgumentMismatch*>(&e) &&
        what.find(" missing") != std::string::npos)
      return name + ": expected a value after " + name + " (" + value + ")";
    if (dynamic_cast<const CLI::RequiredError*>(&e)) return name + ": required, expected " + value;
  }
  return what;
}

// Long work shows how far it got: a line on stderr 2 s after the start, then every 2 s while
// stages report (core/progress.h), from whichever thread reports.
void showProgress(const char* stage, double done, double total) {
  using Clock = std::chrono::steady_clock;
  static const Clock::time_point start = Clock::now();
  static canopy::ProgressThrottle throttle(0.0, 2.0, 2.0);
  static std::mutex mutex;
  const double now = std::chrono::duration<double>(Clock::now() - start).count();
  const std::lock_guard lock(mutex);
  if (!throttle.due(now)) return;
  if (total > 0.0) {
    std::fprintf(stderr, "canopy: %s: %.0f of %.0f (%.0f %%), %.0f s\n", stage, done, total,
                 100.0 * done / total, now);
  } else {
    std::fprintf(stderr, "canopy: %s: %.0f, %.0f s\n", stage, done, now);
  }
}

int unknownCommand(const std::string& word, std::span<const std::unique_ptr<Command>> commands) {
  std::vector<std::string> names;
  for (const std::unique_ptr<Command>& c : commands) names.push_back(c->app().get_name());
  const std::string guess = nearest(word, names);
  std::fprintf(stderr, "canopy: unknown command '%s'%s\n\n%s", canopy::printable(word, 100).c_str(),
               guess.empty() ? "" : ("; did you mean `canopy " + guess + "`?").c_str(),
               overviewText(commands).c_str());
  return kExitUsage;
}

}  // namespace

namespace {

// Parses argv and runs the command it names; the exit code.
int dispatch(int argc, char** argv) {
  std::string command_line;
  for (int i = 0; i < argc; ++i) command_line += (i ? " " : "") + std::string(argv[i]);
  CLI::App canopy("multi-UAV target tracking under unknown occlusions", "canopy");
  canopy.set_help_flag("-h,--help", "this text");
  canopy.set_version_flag("--version", versionText());
  canopy.allow_extras();  // left over words are refused by refuseLeftovers, in our words
  canopy.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  const std::vector<std::unique_ptr<Command>> commands = makeCommands(canopy, command_line);
  // `canopy help [COMMAND]` and `canopy version`, older spellings of --help and --version.
  CLI::App* help = canopy.add_subcommand("help")->group("")->allow_extras();
  CLI::App* version = canopy.add_subcommand("version")->group("");

  const auto helpOf = [&](const CLI::App* app) -> std::string {
    for (const std::unique_ptr<Command>& c : commands) {
      if (&c->app() == app) return helpText(*c);
    }
    return overviewText(commands);
  };
  try {
    canopy.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    const std::vector<CLI::App*> parsed = canopy.get_subcommands();
    std::fputs(helpOf(parsed.empty() ? nullptr : parsed.front()).c_str(), stdout);
    return kExitOk;
  } catch (const CLI::CallForVersion& e) {
    std::printf("%s\n", e.what());
    return kExitOk;
  } catch (const CLI::ParseError& e) {
    const std::vector<CLI::App*> parsed = canopy.get_subcommands();
    if (!parsed.empty())
      refuseLeftovers(*parsed.front());  // a typo first: "--lamda" before "--lambda is required"
    usageError("", parseErrorMessage(e, parsed.empty() ? nullptr : parsed.front()));
  }
  const std::vector<CLI::App*> parsed = canopy.get_subcommands();
  if (parsed.empty()) {
    if (canopy.remaining().empty()) {
      std::fputs(overviewText(commands).c_str(), stderr);
      return kExitUsage;
    }
    return unknownCommand(canopy.remaining().front(), commands);
  }
  if (!canopy.remaining().empty()) return unknownCommand(canopy.remaining().front(), commands);
  const CLI::App* chosen = parsed.front();
  if (chosen == help) {
    // CLI11 reads the word after `help` as a second subcommand when it names one.
    std::fputs(helpOf(parsed.size() > 1 ? parsed[1] : nullptr).c_str(), stdout);
    return kExitOk;
  }
  if (parsed.size() > 1) {  // CLI11 takes a command's name anywhere on the line as that command
    usageError(parsed[1]->get_name(), "a second command after `canopy " + chosen->get_name() +
                                          "`; a file of that name is ./" + parsed[1]->get_name());
  }
  if (chosen == version) {
    std::printf("%s\n", versionText().c_str());
    return kExitOk;
  }
  refuseLeftovers(*chosen);
  for (const std::unique_ptr<Command>& c : commands) {
    if (&c->app() == chosen) return c->run();
  }
  return kExitFailure;  // every subcommand is a Command, help or version
}

}  // namespace

int main(int argc, char** argv) {
  showProgress("starting", 0.0, 0.0);  // the clock starts here (nothing is due yet)
  canopy::setProgressHook(&showProgress);
  int code = kExitFailure;
  try {
    code = dispatch(argc, argv);
  } catch (const canopy::spec::ScenarioErrors& e) {
    for (const canopy::spec::ScenarioError& each : e.errors()) report(each.what());
    return kExitUsage;
  } catch (const canopy::spec::ScenarioError& e) {
    report(e.what());
    return kExitUsage;
  } catch (const canopy::OutputRefused& e) {  // an output path that is not ours: bad input
    report(e.what());
    return kExitUsage;
  } catch (const canopy::WriteError& e) {
    report(e.what());
    return kExitFailure;
  } catch (const std::filesystem::filesystem_error& e) {
    // Not e.what(), the library's own wording: the path and the system's reason.
    report("cannot access '" + e.path1().string() + "': " + e.code().message());
    return kExitFailure;
  } catch (const std::bad_alloc&) {
    report("out of memory");
    return kExitFailure;
  } catch (const std::exception& e) {
    report(std::string("error: ") + e.what());
    return kExitFailure;
  }
  // Results printed on stdout are output too: a full disk or a closed pipe must not exit 0.
  const bool flushed = std::fflush(stdout) == 0;
  const int error = errno;
  if (!flushed || std::ferror(stdout)) {
    report(std::string("cannot write the standard output: ") +
           (flushed ? "a write failed" : std::strerror(error)));
    return code == kExitOk ? kExitFailure : code;
  }
  return code;
}
