#pragma once
// Errors in user input: a scenario file, a layout file, a --set override or a command-line value.
#include <stdexcept>
#include <string>

namespace canopy::scenarios {

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

}  // namespace canopy::scenarios
