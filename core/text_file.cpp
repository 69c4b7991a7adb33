#include "core/text_file.h"

#include <fstream>
#include <sstream>

#include "core/output_file.h"

namespace canopy {

std::optional<std::string> readTextFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) return std::nullopt;
  return text.str();
}

void writeFileAtomically(const std::filesystem::path& path, const std::string& text) {
  if (path.has_parent_path()) {
    std::error_code error;
    std::filesystem::create_directories(path.parent_path(), error);
    if (error) throw WriteError(path.parent_path(), error.message());
  }
  AtomicFile file(path);
  file.write(text);
  file.commit();
}

}  // namespace canopy
