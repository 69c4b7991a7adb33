#pragma once
// Whole-file text I/O, shared by every folder that reads or writes result files.
#include <filesystem>
#include <optional>
#include <string>

namespace canopy {

/// The file's bytes, or nothing when it cannot be opened or read.
std::optional<std::string> readTextFile(const std::filesystem::path& path);

/// Writes `text` to a new temporary file beside `path` and renames it over `path` (an AtomicFile,
/// core/output_file.h), so that a reader never sees a half-written file and a link planted at
/// `path` or at a temporary name is never followed. Creates missing parent directories; throws
/// WriteError (a std::runtime_error) naming the file when it cannot write.
void writeFileAtomically(const std::filesystem::path& path, const std::string& text);

}  // namespace canopy
