// `canopy schema [--markdown]`: the JSON Schema of scenario files, or the reference page, both
// from the loader's own field table (spec/schema.h).
#include <cstdio>

#include "app/commands.h"
#include "app/help.h"
#include "spec/schema.h"

namespace canopy::app {

int schemaCommand(Args& args) {
  bool markdown = false;
  while (!args.done()) {
    const std::string arg = args.take();
    if (arg == "--markdown") {
      markdown = true;
    } else {
      unknownOption("schema", arg);
    }
  }
  const std::string text =
      markdown ? spec::scenarioReferenceMarkdown() : spec::scenarioSchemaJson();
  std::fputs(text.c_str(), stdout);
  return kExitOk;
}

}  // namespace canopy::app
