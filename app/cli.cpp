#include "app/cli.h"

#include <charconv>
#include <cmath>
#include <cstdlib>

#include "core/number_text.h"
#include "spec/error.h"

namespace canopy::app {

void usageError(const std::string& what, const std::string& message) {
  throw spec::ScenarioError("command line", what, message);
}

namespace {

// The whole text as a base-10 integer in JSON's grammar: digits after an optional '-' (none for
// unsigned types), no '+', no blanks, no leading zeros ("007").
template <class T>
std::optional<T> wholeInteger(const std::string& text) {
  const std::size_t first = !text.empty() && text[0] == '-' ? 1 : 0;
  if (text.size() > first + 1 && text[first] == '0') return std::nullopt;
  T x = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), x);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return x;
}

}  // namespace

Reader<int> integerIn(int min_value, int max_value) {
  return {[=](const std::string& text) -> std::optional<int> {
            const std::optional<int> x = wholeInteger<int>(text);
            if (!x || *x < min_value || *x > max_value) return std::nullopt;
            return x;
          },
          "an integer in [" + std::to_string(min_value) + ", " + std::to_string(max_value) + "]"};
}

Reader<std::uint64_t> nonNegativeInteger() {
  return {wholeInteger<std::uint64_t>, "a non-negative integer"};
}

namespace {

std::optional<sim::LineRange> stepRangeOf(const std::string& text) {
  const std::size_t colon = text.find(':');
  if (colon == std::string::npos || text.find(':', colon + 1) != std::string::npos)
    return std::nullopt;
  sim::LineRange range;
  const auto number = [](const std::string& digits) -> std::optional<std::uint64_t> {
    if (digits.empty() || digits.size() > 12 ||
        digits.find_first_not_of("0123456789") != std::string::npos)
      return std::nullopt;
    return std::stoull(digits);
  };
  const std::string first = text.substr(0, colon), end = text.substr(colon + 1);
  if (!first.empty()) {
    const std::optional<std::uint64_t> a = number(first);
    if (!a) return std::nullopt;
    range.first = *a;
  }
  if (!end.empty()) {
    const std::optional<std::uint64_t> b = number(end);
    if (!b || *b <= range.first) return std::nullopt;
    range.end = *b;
  }
  return range;
}

}  // namespace

Reader<sim::LineRange> stepRange() {
  return {stepRangeOf, "A:B, A: or :B with integers A < B"};
}

Reader<double> finiteNumber(std::string expected, std::function<bool(double)> in_range) {
  return {[in_range = std::move(in_range)](const std::string& text) -> std::optional<double> {
            // JSON's grammar: no blanks, '+', hexadecimal, inf or nan.
            const std::optional<double> x = strictNumber(text);
            if (!x || !in_range(*x)) return std::nullopt;
            return x;
          },
          std::move(expected)};
}

CLI::Option* addOutputDir(CLI::App& command, const std::string& name, std::string& target,
                          const std::string& meaning) {
  return command.add_option(name, target, meaning)
      ->check(CLI::Validator([](std::string& text) { return outputDirProblem(text); }, ""))
      ->type_name("DIR");
}

CLI::Option* addStyleOption(CLI::App& command, std::string& target) {
  return command
      .add_option("--style", target,
                  "the figures' colours, ink, background and text and line scales (JSON; "
                  "docs/figure-style.json holds the defaults)")
      ->type_name("FILE")
      ->default_str("the defaults");
}

analysis::FigureStyle readStyleOption(const std::string& file) {
  return file.empty() ? analysis::FigureStyle{} : analysis::readFigureStyle(file);
}

void addLoadOptions(CLI::App& command, spec::LoadOptions& load, bool allow_path) {
  addValue(command, "--budget", "K", load.budget_scale,
           finiteNumber("a factor K in (0, 1e12] on every work limit",
                        [](double k) { return k > 0.0 && k <= 1e12; }),
           allow_path ? "multiply every load-time work limit (spec/budget.h) by K"
                      : "multiply the tree limit by K")
      ->default_str("1");
  if (!allow_path) return;
  command
      .add_option_function<std::vector<std::string>>(
          "--allow-path",
          [&load](const std::vector<std::string>& dirs) {
            load.allowed_roots.assign(dirs.begin(), dirs.end());
          },
          "also read layout includes and track files from DIR (repeatable)")
      ->check(CLI::Validator(
          [](std::string& dir) {
            std::error_code error;
            return std::filesystem::is_directory(dir, error)
                       ? std::string()
                       : "expected an existing folder, got '" + printable(dir, 200) + "'";
          },
          ""))
      ->type_name("DIR")
      ->default_str("none")
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

std::string outputDirProblem(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  const std::string shown = "'" + printable(dir.string(), 200) + "'";
  if (dir.empty()) return "expected a directory, got an empty path";
  std::error_code error;
  const fs::file_status status = fs::status(dir, error);  // follows a link the user named
  if (error == std::errc::not_a_directory)
    return "expected a directory, got " + shown + ", a path through a file";
  if (fs::exists(status) && !fs::is_directory(status)) {
    return "expected a directory (new or existing), got " + shown +
           ", which exists and is not a directory";
  }
  return "";
}

void checkOutputDir(const std::filesystem::path& dir, const std::string& source) {
  if (const std::string problem = outputDirProblem(dir); !problem.empty())
    usageError(source, problem);
}

}  // namespace canopy::app
