#include "replay/replay_page.h"

#include <zlib.h>

#include <algorithm>
#include <stdexcept>
#include <string_view>

#include "core/text_file.h"
#include "replay/replay_data.h"
#include "replay/web_assets.h"

namespace canopy::replay {
namespace {

// gzip (RFC 1952) of `text` at zlib's best compression. The header's time is 0, so the same
// text gives the same bytes.
std::string gzipped(std::string_view text) {  // text: any bytes
  z_stream stream{};
  if (deflateInit2(&stream, Z_BEST_COMPRESSION, Z_DEFLATED, 15 + 16, 9, Z_DEFAULT_STRATEGY) != Z_OK)
    throw std::runtime_error("replay page: zlib failed to start");
  std::string out;
  char buffer[1 << 16];
  std::size_t fed = 0;
  int status = Z_OK;
  while (status != Z_STREAM_END) {
    if (stream.avail_in == 0 && fed < text.size()) {  // zlib takes at most 4 GiB at a time
      const std::size_t n = std::min<std::size_t>(text.size() - fed, std::size_t{1} << 30);
      stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.data() + fed));
      stream.avail_in = static_cast<uInt>(n);
      fed += n;
    }
    stream.next_out = reinterpret_cast<Bytef*>(buffer);
    stream.avail_out = sizeof buffer;
    status = deflate(&stream, fed == text.size() ? Z_FINISH : Z_NO_FLUSH);
    if (status != Z_OK && status != Z_STREAM_END && status != Z_BUF_ERROR) break;
    out.append(buffer, sizeof buffer - stream.avail_out);
  }
  deflateEnd(&stream);
  if (status != Z_STREAM_END) throw std::runtime_error("replay page: zlib failed to compress");
  return out;
}

// RFC 4648 base64 (with padding): only letters, digits, '+', '/' and '=', so it is safe inside
// a <script> element as it is.
std::string base64(std::string_view bytes) {
  static constexpr char kDigits[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const auto byte = [&](std::size_t n) {
      return n < bytes.size() ? static_cast<unsigned>(static_cast<unsigned char>(bytes[n])) : 0u;
    };
    const unsigned v = byte(i) << 16 | byte(i + 1) << 8 | byte(i + 2);
    out += kDigits[v >> 18 & 63];
    out += kDigits[v >> 12 & 63];
    out += i + 1 < bytes.size() ? kDigits[v >> 6 & 63] : '=';
    out += i + 2 < bytes.size() ? kDigits[v & 63] : '=';
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

// The name of the folder a run was read from ("out/m/" → "m"), which a page comparing two runs
// shows beside each run's letter.
std::string folderName(const RunFolder& run) {
  std::filesystem::path dir = run.dir.lexically_normal();
  if (dir.filename().empty()) dir = dir.parent_path();
  return dir.filename().string();
}

// The data of `run` in the element `id`: gzipped, in base64 (replay_data.h), which the page
// inflates with the browser's own DecompressionStream (columns.js). `letter` ("A", "B"; empty:
// a page of one run) names the run in a comparison (web/compare.js), with its folder's name.
std::string dataElement(const RunFolder& run, std::string_view id, std::string_view letter = {}) {
  const std::string names = letter.empty()
                                ? std::string()
                                : " data-run=\"" + htmlEscaped(letter) + "\" data-folder=\"" +
                                      htmlEscaped(folderName(run)) + "\"";
  return "<script type=\"application/octet-stream\" id=\"" + std::string(id) + "\"" + names +
         " data-encoding=\"columns-gzip-base64\">" + base64(gzipped(replayData(run))) + "</script>";
}

// The page of `run`, with `overlay` (or none) drawn over it on the same clock. `letter` names
// `run` in a comparison (empty: a page of one run).
std::string pageOf(const RunFolder& run, const RunFolder* overlay, std::string_view letter = {}) {
  std::string page(web::kTemplate);
  fill(page, "title",
       htmlEscaped(overlay ? run.spec.name + " + " + overlay->spec.name : run.spec.name));
  fill(page, "style", "<style>\n" + std::string(web::kStyle) + "</style>");
  fill(page, "data",
       overlay ? dataElement(run, "replay-data", "A") + "\n" +
                     dataElement(*overlay, "replay-data-b", "B")
               : dataElement(run, "replay-data", letter));
  std::string scripts;
  for (std::string_view script : web::scripts())
    scripts += "<script>\n" + std::string(checkedScript(script)) + "</script>\n";
  fill(page, "scripts", scripts);
  return page;
}

}  // namespace

std::string replayPage(const RunFolder& run) {
  return pageOf(run, nullptr);
}

std::string overlayPage(const RunFolder& a, const RunFolder& b) {
  return pageOf(a, &b);
}

std::size_t writeOverlay(const std::filesystem::path& run_a, const std::filesystem::path& run_b,
                         const std::filesystem::path& out) {
  const std::string page = overlayPage(readRunFolder(run_a), readRunFolder(run_b));
  writeFileAtomically(out, page);
  return page.size();
}

std::string sideBySidePage(const RunFolder& a, const RunFolder& b) {
  std::string page(web::kSideBySide);
  fill(page, "title", htmlEscaped(a.spec.name + " | " + b.spec.name));
  fill(page, "scripts",
       "<script>\n" + std::string(checkedScript(web::kSideBySideScript)) + "</script>\n");
  // Escaped for a double-quoted attribute, a page holds no "<" and no slot of its own.
  fill(page, "frames",
       "<iframe id=\"run-a\" title=\"" + htmlEscaped(a.spec.name) + "\" srcdoc=\"" +
           htmlEscaped(pageOf(a, nullptr, "A")) + "\"></iframe>\n<iframe id=\"run-b\" title=\"" +
           htmlEscaped(b.spec.name) + "\" srcdoc=\"" + htmlEscaped(pageOf(b, nullptr, "B")) +
           "\"></iframe>");
  return page;
}

std::size_t writeSideBySide(const std::filesystem::path& run_a, const std::filesystem::path& run_b,
                            const std::filesystem::path& out) {
  const std::string page = sideBySidePage(readRunFolder(run_a), readRunFolder(run_b));
  writeFileAtomically(out, page);
  return page.size();
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
