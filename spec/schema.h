#pragma once
// The scenario format described from the loader itself: every field it reads (scenarios/
// field_log.h: path, type, range, default) with its unit and meaning (field_docs.cpp), as a JSON
// Schema (`canopy schema`) and as docs/scenario-reference.md (`canopy schema --markdown`).
#include <string>
#include <vector>

#include "spec/field_log.h"

namespace canopy::spec {

struct FieldDoc {
  const char* path;     // fieldPattern() form
  const char* unit;     // "m", "m/s", "s", "" when none
  const char* meaning;  // one line
};

/// The units and meanings, one per field the loader reads (field_docs.cpp).
const std::vector<FieldDoc>& fieldDocs();

/// What the loader reads while loading every built-in scenario and the schema probe
/// (scenarios/schema_probe*.json, which touch the branches the library does not).
FieldLog loggedFields();

struct DocumentedField {
  FieldInfo info;
  std::string unit;
  std::string meaning;
};

/// loggedFields() joined with fieldDocs(), in path order. Throws std::logic_error naming the
/// fields read but undocumented, or documented but never read.
std::vector<DocumentedField> documentedFields();

/// A JSON Schema (draft 2020-12) of scenario files.
std::string scenarioSchemaJson();
/// The text of docs/scenario-reference.md.
std::string scenarioReferenceMarkdown();

}  // namespace canopy::spec
