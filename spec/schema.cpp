#include "spec/schema.h"

#include <algorithm>
#include <filesystem>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>

#include "spec/loader.h"

namespace canopy::spec {
namespace {

using Json = nlohmann::json;

// "uavs[].path.waypoints[]" → ["uavs", "[]", "path", "waypoints", "[]"].
std::vector<std::string> steps(const std::string& path) {
  std::vector<std::string> out;
  std::string part;
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (path[i] == '.') {
      if (!part.empty()) out.push_back(part);
      part.clear();
    } else if (path.compare(i, 2, "[]") == 0) {
      if (!part.empty()) out.push_back(part);
      part.clear();
      out.emplace_back("[]");
      ++i;
    } else {
      part += path[i];
    }
  }
  if (!part.empty()) out.push_back(part);
  return out;
}

// Numeric bounds of a range text as JSON Schema keywords.
void addRange(Json& node, const std::string& range) {
  if (range == "> 0") node["exclusiveMinimum"] = 0;
  if (range == ">= 0") node["minimum"] = 0;
  if (range.size() > 2 && (range[0] == '[' || range[0] == '(') &&
      range.find(',') != std::string::npos) {
    const double lo = std::stod(range.substr(1));
    const double hi = std::stod(range.substr(range.find(',') + 1));
    node[range[0] == '[' ? "minimum" : "exclusiveMinimum"] = lo;
    node[range.back() == ']' ? "maximum" : "exclusiveMaximum"] = hi;
  }
}

}  // namespace

FieldLog loggedFields() {
  FieldLog log;
  LoadOptions options;
  options.field_log = &log;
  // The built-in library only (not CANOPY_PATH's folders): the page must not depend on the user.
  const std::filesystem::path dir = builtinScenarioDir();
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "library")) {
    if (entry.is_regular_file() && entry.path().extension() == ".json")
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  files.push_back(dir / "schema_probe.json");
  files.push_back(dir / "schema_probe_2uav.json");
  files.push_back(dir / "schema_probe_learned.json");
  for (const std::filesystem::path& file : files) loadScenario(file.string(), options);
  return log;  // "" is the document itself
}

std::vector<DocumentedField> documentedFields() {
  const FieldLog log = loggedFields();
  std::map<std::string, const FieldDoc*> docs;
  for (const FieldDoc& doc : fieldDocs()) docs[doc.path] = &doc;
  std::string undocumented, unread;
  std::vector<DocumentedField> out;
  for (const auto& [path, info] : log) {
    if (path.empty() || path.ends_with("]")) continue;  // the document; a list's elements
    const auto it = docs.find(path);
    if (it == docs.end()) {
      undocumented += " " + path;
      continue;
    }
    out.push_back({info, it->second->unit, it->second->meaning});
  }
  for (const auto& [path, doc] : docs) {
    if (!log.count(path)) unread += " " + path;
  }
  if (!undocumented.empty() || !unread.empty()) {
    throw std::logic_error("spec/field_docs.cpp: read but undocumented:" + undocumented +
                           "; documented but never read:" + unread);
  }
  return out;
}

namespace {

// The node of `schema` that describes `pattern` ("uavs[].fov"), made on the way when absent.
Json& nodeAt(Json& schema, const std::string& pattern) {
  Json* node = &schema;
  for (const std::string& part : steps(pattern))
    node = part == "[]" ? &(*node)["items"] : &(*node)["properties"][part];
  return *node;
}

// Array sizes as the loader logs them ("2 elements", "1+ elements", "3 to 8 elements").
void addItemCount(Json& node, const std::string& range) {
  if (!range.ends_with(" elements")) return;
  const std::size_t to = range.find(" to ");
  if (range.find('+') != std::string::npos) {
    node["minItems"] = std::stoi(range);
  } else if (to != std::string::npos) {
    node["minItems"] = std::stoi(range);
    node["maxItems"] = std::stoi(range.substr(to + 4));
  } else {
    node["minItems"] = node["maxItems"] = std::stoi(range);
  }
}

// A value's own keywords: type(s), bounds, spellings.
void describeValue(Json& node, const FieldInfo& info) {
  std::vector<std::string> types;
  for (std::size_t at = 0; at != std::string::npos && !info.type.empty();) {
    const std::size_t bar = info.type.find(" | ", at);
    types.push_back(info.type.substr(at, bar == std::string::npos ? bar : bar - at));
    at = bar == std::string::npos ? bar : bar + 3;
  }
  if (!info.choices.empty() && types.size() > 1) {
    // A number or a spelling ("yaw": 0.5 or "velocity"): the spellings bind only strings.
    Json alternatives = Json::array();
    for (const std::string& type : types) {
      alternatives.push_back(type == "string" ? Json{{"type", "string"}, {"enum", info.choices}}
                                              : Json{{"type", type}});
    }
    node["anyOf"] = alternatives;
  } else if (types.size() > 1) {
    node["type"] = types;
  } else if (types.size() == 1) {
    node["type"] = types.front();
  }
  if (!info.choices.empty() && types.size() <= 1) node["enum"] = info.choices;
  if (!info.range_varies) {
    addRange(node, info.range);
    addItemCount(node, info.range);
  }
  if (info.type == "object" || (node.contains("properties") && types.size() <= 1)) {
    node["type"] = "object";
    node["additionalProperties"] = false;
  }
}

// A field's keywords: its value's, its default and meaning.
void describeField(Json& node, const DocumentedField& field) {
  const FieldInfo& info = field.info;
  describeValue(node, info);
  if (info.default_json && !info.default_varies) node["default"] = Json::parse(*info.default_json);
  node["description"] = field.meaning + (field.unit.empty() ? "" : " (" + field.unit + ")");
  if (!field.unit.empty()) node["x-unit"] = field.unit;
}

// What an object requires, from its instances: the members every instance required; when the
// instances require different members (a disc needs a centre, a grid an origin), one variant per
// set of required members, each allowing only the members its instances read, and distinguished
// by the member whose spelling tells them apart ("type"), when one does.
void addRequirements(Json& node, const FieldInfo& info) {
  struct Variant {
    std::set<std::string> allowed;
    std::map<std::string, std::set<std::string>> choices;
  };
  std::map<std::set<std::string>, Variant> variants;
  for (const auto& [where, shape] : info.instances) {
    Variant& v = variants[shape.required];
    v.allowed.insert(shape.allowed.begin(), shape.allowed.end());
    for (const auto& [key, value] : shape.choices) v.choices[key].insert(value);
  }
  if (variants.empty()) return;
  std::set<std::string> common = variants.begin()->first;
  for (const auto& [required, v] : variants) {
    std::set<std::string> both;
    std::set_intersection(common.begin(), common.end(), required.begin(), required.end(),
                          std::inserter(both, both.end()));
    common = both;
  }
  if (!common.empty()) node["required"] = common;
  if (variants.size() == 1) return;
  // The discriminator: a choice member no spelling of which is in two variants (a variant
  // without it must not allow it: an occluder's "include" has no "type").
  std::set<std::string> keys;
  for (const auto& [required, v] : variants) {
    for (const auto& [key, values] : v.choices) keys.insert(key);
  }
  std::string discriminator;
  for (const std::string& key : keys) {
    std::set<std::string> seen;
    bool separates = true;
    for (const auto& [required, v] : variants) {
      const auto it = v.choices.find(key);
      if (it == v.choices.end()) {
        separates &= !v.allowed.count(key);
        continue;
      }
      for (const std::string& value : it->second) separates &= seen.insert(value).second;
    }
    if (separates) {
      discriminator = key;
      break;
    }
  }
  Json one_of = Json::array();
  for (const auto& [required, v] : variants) {
    Json variant = {{"additionalProperties", false}};
    if (!required.empty()) variant["required"] = required;
    Json& properties = variant["properties"] = Json::object();
    for (const std::string& key : v.allowed) properties[key] = true;
    if (v.choices.count(discriminator))
      properties[discriminator] = {{"enum", v.choices.at(discriminator)}};
    one_of.push_back(variant);
  }
  node["oneOf"] = one_of;
}

}  // namespace

std::string scenarioSchemaJson() {
  Json schema = {{"$schema", "https://json-schema.org/draft/2020-12/schema"},
                 {"title", "canopy scenario"},
                 {"description", "Generated by `canopy schema` from the loader's field table."},
                 {"type", "object"},
                 {"additionalProperties", false}};
  for (const DocumentedField& field : documentedFields()) {
    // Every list and object on the way is typed, so that a value of the wrong kind is refused.
    const std::vector<std::string> parts = steps(field.info.path);
    Json* node = &schema;
    for (const std::string& part : parts) {
      if (part == "[]") {
        (*node)["type"] = "array";
        node = &(*node)["items"];
      } else {
        if (!node->contains("type")) (*node)["type"] = "object";
        if ((*node)["type"] == "object") (*node)["additionalProperties"] = false;
        node = &(*node)["properties"][part];
      }
    }
    describeField(*node, field);
  }
  // Objects' requirements and variants, from what the loader read of each instance.
  // A list's elements ("[]": described by the list in the reference) get their own type here.
  for (const auto& [pattern, info] : loggedFields()) {
    Json& node = pattern.empty() ? schema : nodeAt(schema, pattern);
    if (pattern.ends_with("]")) describeValue(node, info);
    if (!info.instances.empty()) addRequirements(node, info);
  }
  // A layout file (scenarios/library/layouts/, named by an occluder's "include") holds occluders
  // as the scenario's list does, bare or as {"description": …, "occluders": [...], "source": …,
  // "footpaths": [...]}
  // (spec/internal/occluders.cpp, readOccluders).
  const Json& occluders = schema["properties"]["occluders"];
  // Footpath polylines [[x, y], …] (m) that a target's {"footpaths": …} path walks.
  const Json point = {{"type", "array"}, {"minItems", 2}, {"maxItems", 2},
                      {"items", {{"type", "number"}}}};
  const Json line = {{"type", "array"}, {"minItems", 2}, {"items", point}};
  const Json footpaths = {{"type", "array"}, {"minItems", 1}, {"items", line}};
  Json properties = {{"description", {{"type", "string"}}}, {"occluders", occluders}};
  properties["source"] = {{"type", "object"}};  // what `canopy import` recorded, kept as it is
  properties["footpaths"] = footpaths;
  schema["$defs"]["layout"] = {
      {"description", "A layout file: the occluders an occluder's \"include\" names."},
      {"oneOf",
       {occluders,
        {{"type", "object"},
         {"additionalProperties", false},
         {"required", {"occluders"}},
         {"properties", properties}}}}};
  return schema.dump(2) + "\n";
}

std::string scenarioReferenceMarkdown() {
  std::string text =
      "# Scenario file reference\n\n"
      "Generated by `canopy schema --markdown` from the loader's own field table (every field the "
      "loader reads, its type, range and default, with a unit and a one-line meaning from "
      "`spec/field_docs.cpp`); `tests/sim/output_formats_test.cpp` fails when this page is "
      "stale. Regenerate with `build/release/app/canopy schema --markdown > "
      "docs/scenario-reference.md`. `[]` stands for every element of a list; \"required\" fields "
      "must be given where their parent is, \"optional\" ones may be left out (the section or "
      "feature is then off or empty).\n\n"
      "| field | type | range | default | unit | meaning |\n|---|---|---|---|---|---|\n";
  for (const DocumentedField& field : documentedFields()) {
    const FieldInfo& info = field.info;
    std::string type;
    for (const char c : info.type) type += c == '|' ? std::string("\\|") : std::string(1, c);
    if (!info.choices.empty()) {
      type.clear();
      for (const std::string& c : info.choices)
        type += (type.empty() ? "" : " \\| ") + ("`" + c + "`");
    }
    const std::string range = info.range_varies ? "(see meaning)" : info.range;
    std::string fallback = info.required ? "required" : "optional";
    if (info.default_json) fallback = "`" + *info.default_json + "`";
    if (info.default_varies || (info.default_json && info.default_json->size() > 40))
      fallback = "(see meaning)";
    text += "| `" + info.path + "` | " + type + " | " + range + " | " + fallback + " | " +
            field.unit + " | " + field.meaning + " |\n";
  }
  return text;
}

}  // namespace canopy::spec
