#pragma once
// Small helpers for the command line: argument cursor and typed option values.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/types.h"
#include "spec/loader.h"

namespace canopy::app {

/// Exit codes: 0 success, 1 a failure of the run itself (I/O), 2 bad user input.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;

/// Walks argv; option values are checked as they are taken, failures throw ScenarioError
/// naming the option (exit code 2).
class Args {
 public:
  Args(int argc, char** argv, int first);
  bool done() const { return next_ >= args_.size(); }
  const std::string& peek() const { return args_[next_]; }
  std::string take() { return args_[next_++]; }
  /// The value after option `name`.
  std::string value(const std::string& name);
  std::uint64_t unsignedValue(const std::string& name);
  int intValue(const std::string& name, int min_value, int max_value);
  double doubleValue(const std::string& name);
  /// The value after option `name` as an output directory (checkOutputDir).
  std::string outputDirValue(const std::string& name);
  /// "a,b,c,d" as numbers.
  std::vector<double> listValue(const std::string& name, std::size_t count);
  /// The arguments not taken yet.
  std::vector<std::string> rest() const {
    return {args_.begin() + static_cast<long>(next_), args_.end()};
  }
  /// The whole command line, for manifests.
  std::string joined() const;

 private:
  std::vector<std::string> args_;
  std::size_t next_;
};

/// Throws ScenarioError("command line", what, message); `what` and `message` are shown through
/// printable() by main.
[[noreturn]] void usageError(const std::string& what, const std::string& message);

/// The options shared by every command that loads scenarios: `--budget K` (every work limit of
/// spec/budget.h times K) and `--allow-path DIR` (includes and track files may also be read
/// from DIR). Takes its value and returns true when `arg` is one of them.
bool takeLoadOption(Args& args, const std::string& arg, spec::LoadOptions& load);

/// A usage error naming `source` (the option) when `dir` cannot be an output directory: it exists
/// and is not a directory (a link to one is fine), or one of its parents is not a directory.
void checkOutputDir(const std::filesystem::path& dir, const std::string& source);

}  // namespace canopy::app
