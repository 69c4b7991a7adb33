#pragma once
// Errors in user input: a scenario file, a layout file, a --set override or a command-line value.
#include <stdexcept>
#include <string>
#include <vector>

namespace canopy::spec {

/// Thrown at load time only. what() reads "FILE: FIELD: expected …, got …"; the command line
/// prints it and exits with code 2.
class ScenarioError : public std::runtime_error {
 public:
  ScenarioError(std::string file, std::string field, std::string message)
      : std::runtime_error(format(file, field, message)),
        file_(std::move(file)),
        field_(std::move(field)),
        message_(std::move(message)) {}

  const std::string& file() const { return file_; }
  const std::string& field() const { return field_; }
  const std::string& message() const { return message_; }

 private:
  static std::string format(const std::string& file, const std::string& field,
                            const std::string& message) {
    std::string text = file;
    if (!field.empty()) text += (text.empty() ? "" : ": ") + field;
    return text + (text.empty() ? "" : ": ") + message;
  }
  std::string file_, field_, message_;
};

/// Several independent errors of one file, found in one pass (the loader reads each section even
/// when an earlier one failed). The first is this error's file, field and message; what() lists
/// every error, one per line.
class ScenarioErrors : public ScenarioError {
 public:
  explicit ScenarioErrors(std::vector<ScenarioError> errors)
      : ScenarioError(errors.at(0).file(), errors.at(0).field(), joined(errors)),
        errors_(std::move(errors)) {}

  const std::vector<ScenarioError>& errors() const { return errors_; }

 private:
  static std::string joined(const std::vector<ScenarioError>& errors) {
    std::string text = errors[0].message();
    for (std::size_t i = 1; i < errors.size(); ++i) text += std::string("\n") + errors[i].what();
    return text;
  }
  std::vector<ScenarioError> errors_;
};

}  // namespace canopy::spec
