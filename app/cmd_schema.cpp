// `canopy schema [--markdown]`: the JSON Schema of scenario files, or the reference page, both
// from the loader's own field table (spec/schema.h).
#include <cstdio>

#include "app/commands.h"
#include "spec/schema.h"

namespace canopy::app {

namespace {

class Schema : public Command {
 public:
  explicit Schema(CLI::App& canopy)
      : Command(canopy, "schema", "canopy schema [--markdown]",
                "Prints the JSON Schema of scenario files (types, ranges, defaults, units, "
                "meaning) from the loader's own field table; --markdown prints "
                "docs/scenario-reference.md.") {
    options()
        .add_flag("--markdown", markdown_, "print the reference page instead")
        ->default_str("off (JSON Schema)");
  }
  int run() override;

 private:
  bool markdown_ = false;
};

int Schema::run() {
  const std::string text =
      markdown_ ? spec::scenarioReferenceMarkdown() : spec::scenarioSchemaJson();
  std::fputs(text.c_str(), stdout);
  return kExitOk;
}

}  // namespace

std::unique_ptr<Command> makeSchema(CLI::App& canopy) {
  return std::make_unique<Schema>(canopy);
}

}  // namespace canopy::app
