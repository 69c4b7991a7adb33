#include "replay/replay_page.h"

#include <stdexcept>
#include <string_view>

#include "core/text_file.h"
#include "replay/replay_data.h"
#include "replay/web_assets.h"

namespace canopy::replay {
namespace {

// Inside a <script> element only "</" and "<!--" change how the HTML parser reads on. The data is
// JSON, where these can only stand inside strings: "<\/" means "</" there, and "\u003c!" "<!".
std::string scriptSafeJson(std::string_view json) {
  std::string out;
  out.reserve(json.size());
  for (std::size_t i = 0; i < json.size(); ++i) {
    const bool next_special = i + 1 < json.size() && (json[i + 1] == '/' || json[i + 1] == '!');
    if (json[i] == '<' && next_special) {
      out += json[i + 1] == '/' ? "<\\" : "\\u003c";
      continue;
    }
    out += json[i];
  }
  return out;
}

// The scripts are ours: they must not hold either sequence at all (checked, not rewritten, since
// outside a string a rewrite would change the program).
std::string_view checkedScript(std::string_view script) {
  if (script.find("</") != std::string_view::npos || script.find("<!--") != std::string_view::npos)
    throw std::logic_error("a replay script holds \"</\" or \"<!--\"");
  return script;
}

// Replaces the one slot `<!--canopy:NAME-->` of the template.
void fill(std::string& page, std::string_view name, const std::string& content) {
  const std::string slot = "<!--canopy:" + std::string(name) + "-->";
  const std::size_t at = page.find(slot);
  if (at == std::string::npos || page.find(slot, at + 1) != std::string::npos)
    throw std::logic_error("replay.html must hold the slot " + slot + " once");
  page.replace(at, slot.size(), content);
}

}  // namespace

std::string replayPage(const RunFolder& run) {
  std::string page(web::kTemplate);
  fill(page, "title", htmlEscaped(run.spec.name));
  fill(page, "style", "<style>\n" + std::string(web::kStyle) + "</style>");
  fill(page, "data",
       "<script type=\"application/json\" id=\"replay-data\">" +
           scriptSafeJson(replayDataJson(run)) + "</script>");
  std::string scripts;
  for (std::string_view script : web::scripts())
    scripts += "<script>\n" + std::string(checkedScript(script)) + "</script>\n";
  fill(page, "scripts", scripts);
  return page;
}

std::size_t writeReplay(const std::filesystem::path& run_dir, const std::filesystem::path& out) {
  const std::string page = replayPage(readRunFolder(run_dir));
  writeFileAtomically(out, page);
  return page.size();
}

std::string htmlEscaped(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace canopy::replay
