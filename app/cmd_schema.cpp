// `canopy schema [--markdown | --record-markdown]`: the JSON Schema of scenario files, or the
// reference page, both from the loader's own field table (spec/schema.h); or the record's part of
// docs/output-formats.md from the record's field table (sim/record_fields.h).
#include <cstdio>

#include "app/commands.h"
#include "sim/record_fields.h"
#include "spec/schema.h"

namespace canopy::app {

namespace {

class Schema : public Command {
 public:
  explicit Schema(CLI::App& canopy)
      : Command(canopy, "schema", "canopy schema [--markdown | --record-markdown]",
                "Prints the JSON Schema of scenario files (types, ranges, defaults, units, "
                "meaning) from the loader's own field table; --markdown prints "
                "docs/scenario-reference.md; --record-markdown the record's fields (key, type, "
                "unit, compact packing, meaning), the generated part of "
                "docs/output-formats.md.") {
    auto* markdown = options()
                         .add_flag("--markdown", markdown_, "print the reference page instead")
                         ->default_str("off (JSON Schema)");
    options()
        .add_flag("--record-markdown", record_,
                  "print the record's field table (docs/output-formats.md's generated part)")
        ->excludes(markdown);
  }
  int run() override;

 private:
  bool markdown_ = false;
  bool record_ = false;
};

int Schema::run() {
  const std::string text = record_     ? sim::recordFieldsMarkdown()
                           : markdown_ ? spec::scenarioReferenceMarkdown()
                                       : spec::scenarioSchemaJson();
  std::fputs(text.c_str(), stdout);
  return kExitOk;
}

}  // namespace

std::unique_ptr<Command> makeSchema(CLI::App& canopy) {
  return std::make_unique<Schema>(canopy);
}

}  // namespace canopy::app
