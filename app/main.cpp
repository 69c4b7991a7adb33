// canopy: the command line. Thin: parses, calls the libraries, prints.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <new>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/help.h"
#include "core/output_file.h"
#include "core/printable.h"
#include "spec/error.h"

namespace {

using namespace canopy::app;

bool wantsHelp(const Args& args) {
  for (const std::string& arg : args.rest()) {
    if (arg == "--help" || arg == "-h") return true;
  }
  return false;
}

int dispatch(const std::string& command, Args& args) {
  if (command == "help" || command == "--help" || command == "-h") {
    const CommandHelp* about = args.done() ? nullptr : findCommand(args.peek());
    std::fputs(about ? helpText(*about).c_str() : overviewText().c_str(), stdout);
    return kExitOk;
  }
  if (command == "--version" || command == "version") {
    std::printf("%s\n", versionText());
    return kExitOk;
  }
  if (const CommandHelp* about = findCommand(command); about && wantsHelp(args)) {
    std::fputs(helpText(*about).c_str(), stdout);
    return kExitOk;
  }
  if (command == "run") return runCommand(args);
  if (command == "validate") return validateCommand(args);
  if (command == "list") return listCommand(args);
  if (command == "forest") return forestCommand(args);
  if (command == "coverage") return coverageCommand(args);
  if (command == "view") return viewCommand(args);
  if (command == "sweep") return sweepCommand(args);
  if (command == "analyze") return analyzeCommand(args);
  if (command == "reproduce") return reproduceCommand(args);
  if (command == "schema") return schemaCommand(args);
  std::vector<std::string> names;
  for (const CommandHelp& c : commands()) names.emplace_back(c.name);
  const std::string guess = nearest(command, names);
  std::fprintf(stderr, "canopy: unknown command '%s'%s\n\n%s",
               canopy::printable(command, 100).c_str(),
               guess.empty() ? "" : ("; did you mean `canopy " + guess + "`?").c_str(),
               overviewText().c_str());
  return kExitUsage;
}

// Every message may quote the user's text (names, paths, values): shown through printable().
void report(const std::string& message) {
  std::fprintf(stderr, "canopy: %s\n", canopy::printable(message).c_str());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fputs(canopy::app::overviewText().c_str(), stderr);
    return kExitUsage;
  }
  Args args(argc, argv, 2);
  int code = kExitFailure;
  try {
    code = dispatch(argv[1], args);
  } catch (const canopy::spec::ScenarioErrors& e) {
    for (const canopy::spec::ScenarioError& each : e.errors()) report(each.what());
    return kExitUsage;
  } catch (const canopy::spec::ScenarioError& e) {
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
