#include "spec/json_progress.h"

#include <cstddef>

#include "core/progress.h"

namespace canopy::spec {
namespace {

// The elements of the top-level arrays: the units both stages count.
double topLevelElements(const Json& value) {
  double total = 0.0;
  for (const auto& item : value.items())
    if (item.value().is_array()) total += static_cast<double>(item.value().size());
  return total;
}

// Appends `text`, a value dumped with indent 2 at depth 0, as a value `indent` spaces deep: the
// library's indented output differs only by those spaces after every line break (a string's
// line breaks are escaped, so every '\n' in the text is one of the layout's).
void appendShifted(std::string& out, const std::string& text, std::size_t indent) {
  for (const char c : text) {
    out += c;
    if (c == '\n') out.append(indent, ' ');
  }
}

}  // namespace

std::string dumpIndented2(const Json& value, const char* stage) {
  if (!value.is_object() || value.empty()) return value.dump(2);
  ProgressCounter progress(stage, topLevelElements(value), 1024);
  std::string out = "{\n";
  bool first_key = true;
  for (const auto& item : value.items()) {
    out += first_key ? "  " : ",\n  ";
    first_key = false;
    out += Json(item.key()).dump();  // the key, quoted and escaped as the library does
    out += ": ";
    const Json& member = item.value();
    if (!member.is_array() || member.empty()) {
      appendShifted(out, member.dump(2), 2);
      continue;
    }
    out += "[\n";
    for (std::size_t i = 0; i < member.size(); ++i) {
      out += i == 0 ? "    " : ",\n    ";
      appendShifted(out, member[i].dump(2), 4);
      progress.add();
    }
    out += "\n  ]";
  }
  out += "\n}";
  return out;
}

void releaseReporting(Json& value, const char* stage) {
  if (value.is_object()) {
    ProgressCounter progress(stage, topLevelElements(value), 1024);
    for (auto item : value.items()) {
      if (!item.value().is_array()) continue;
      Json::array_t& elements = item.value().get_ref<Json::array_t&>();
      while (!elements.empty()) {
        elements.pop_back();
        progress.add();
      }
    }
  }
  value = Json();
}

}  // namespace canopy::spec
