#include "app/cli.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "core/printable.h"
#include "spec/error.h"

namespace canopy::app {

void usageError(const std::string& what, const std::string& message) {
  throw spec::ScenarioError("command line", what, message);
}

Args::Args(int argc, char** argv, int first) : args_(argv, argv + argc), next_(first) {}

void checkOutputDir(const std::filesystem::path& dir, const std::string& source) {
  namespace fs = std::filesystem;
  const std::string shown = "'" + printable(dir.string(), 200) + "'";
  if (dir.empty()) usageError(source, "expected a directory, got an empty path");
  std::error_code error;
  const fs::file_status status = fs::status(dir, error);  // follows a link the user named
  if (error == std::errc::not_a_directory) {
    usageError(source, "expected a directory, got " + shown + ", a path through a file");
  }
  if (fs::exists(status) && !fs::is_directory(status)) {
    usageError(source, "expected a directory (new or existing), got " + shown +
                           ", which exists and is not a directory");
  }
}

std::string Args::outputDirValue(const std::string& name) {
  std::string text = value(name);
  checkOutputDir(text, name);
  return text;
}

std::string Args::value(const std::string& name) {
  if (done()) usageError(name, "expected a value after " + name);
  return take();
}

std::uint64_t Args::unsignedValue(const std::string& name) {
  const std::string text = value(name);
  std::uint64_t x = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), x);
  if (error != std::errc() || end != text.data() + text.size()) {
    usageError(name, "expected a non-negative integer, got '" + printable(text, 100) + "'");
  }
  return x;
}

int Args::intValue(const std::string& name, int min_value, int max_value) {
  const std::string text = value(name);
  int x = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), x);
  if (error != std::errc() || end != text.data() + text.size() || x < min_value || x > max_value) {
    usageError(name, "expected an integer in [" + std::to_string(min_value) + ", " +
                         std::to_string(max_value) + "], got '" + printable(text, 100) + "'");
  }
  return x;
}

double Args::doubleValue(const std::string& name) {
  const std::string text = value(name);
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(x)) {
    usageError(name, "expected a finite number, got '" + printable(text, 100) + "'");
  }
  return x;
}

std::vector<double> Args::listValue(const std::string& name, std::size_t count) {
  const std::string text = value(name);
  std::vector<double> numbers;
  std::stringstream stream(text);
  std::string item;
  const std::string expected = "expected " + std::to_string(count) +
                               " comma-separated finite numbers, got '" + printable(text, 100) +
                               "'";
  while (std::getline(stream, item, ',')) {
    char* end = nullptr;
    const double x = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !std::isfinite(x)) usageError(name, expected);
    numbers.push_back(x);
  }
  if (numbers.size() != count) usageError(name, expected);
  return numbers;
}

std::string Args::joined() const {
  std::string text;
  for (const std::string& a : args_) text += (text.empty() ? "" : " ") + a;
  return text;
}

bool takeLoadOption(Args& args, const std::string& arg, spec::LoadOptions& load) {
  if (arg == "--budget") {
    load.budget_scale = args.doubleValue(arg);
    if (!(load.budget_scale > 0.0) || load.budget_scale > 1e12)
      usageError(arg, "expected a factor K in (0, 1e12] on every work limit");
    return true;
  }
  if (arg == "--allow-path") {
    const std::string dir = args.value(arg);
    std::error_code error;
    if (!std::filesystem::is_directory(dir, error))
      usageError(arg, "expected an existing folder, got '" + printable(dir, 200) + "'");
    load.allowed_roots.emplace_back(dir);
    return true;
  }
  return false;
}

}  // namespace canopy::app
