#pragma once
// The command line's shared pieces on CLI11: exit codes, options whose text is read and checked
// by our own readers (so every message names the option and the value it expected), the options
// of every command that loads scenarios, and output directories.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "analysis/figure_style.h"
#include "core/printable.h"
#include "sim/record_lines.h"
#include "spec/loader.h"

namespace canopy::app {

/// Exit codes: 0 success, 1 a failure of the run itself (I/O), 2 bad user input.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;

/// Throws ScenarioError("command line", what, message); `what` and `message` are shown through
/// printable() by main.
[[noreturn]] void usageError(const std::string& what, const std::string& message);

/// How an option's text becomes a value of type T: `read` gives the value, or nullopt when the
/// text is not one; `expected` says what was expected ("an integer in [1, 1024]").
template <class T>
struct Reader {
  std::function<std::optional<T>(const std::string& text)> read;
  std::string expected;
};

Reader<int> integerIn(int min_value, int max_value);
Reader<std::uint64_t> nonNegativeInteger();
/// `--steps A:B`: "A:B" (steps A to B − 1), "A:" (from A) or ":B" (before B), integers A < B.
Reader<sim::LineRange> stepRange();
/// A finite number for which `in_range` holds; `expected` names the range.
Reader<double> finiteNumber(std::string expected, std::function<bool(double)> in_range);

/// Declares `NAME VALUE` on `command` (VALUE: `value_name` in --help), read into `target` (the
/// last one given wins). Text the reader refuses is a usage error, "NAME: expected …, got 'TEXT'".
template <class Target, class T>
CLI::Option* addValue(CLI::App& command, const std::string& name, const std::string& value_name,
                      Target& target, const Reader<T>& reader, const std::string& meaning) {
  CLI::Option* option = command.add_option_function<std::string>(
      name, [&target, read = reader.read](const std::string& text) { target = *read(text); },
      meaning);
  option->check(CLI::Validator(
      [reader](std::string& text) {
        return reader.read(text)
                   ? std::string()
                   : "expected " + reader.expected + ", got '" + printable(text, 100) + "'";
      },
      ""));
  return option->type_name(value_name);
}

/// Declares `NAME DIR` on `command`, a directory to write into: a usage error when
/// outputDirProblem(DIR) is not empty.
CLI::Option* addOutputDir(CLI::App& command, const std::string& name, std::string& target,
                          const std::string& meaning);

/// Declares `--style FILE` (the figures' style, analysis/figure_style.h) on `command`.
CLI::Option* addStyleOption(CLI::App& command, std::string& target);
/// The style in `file` ("": the default style); a bad file is a ScenarioError (exit 2).
analysis::FigureStyle readStyleOption(const std::string& file);

/// Declares `--budget K` (every work limit of spec/budget.h times K) on `command`, and with
/// `allow_path` also `--allow-path DIR` (includes and track files may also be read from DIR).
void addLoadOptions(CLI::App& command, spec::LoadOptions& load, bool allow_path = true);

/// Why `dir` cannot be an output directory ("" when it can): it exists and is not a directory
/// (a link to one is fine), or one of its parents is not a directory.
std::string outputDirProblem(const std::filesystem::path& dir);
/// A usage error naming `source` (the option) when outputDirProblem(dir) is not empty.
void checkOutputDir(const std::filesystem::path& dir, const std::string& source);

}  // namespace canopy::app
