#pragma once
// Whole-file text I/O, shared by every folder that reads or writes result files.
#include <filesystem>
#include <optional>
#include <string>

namespace canopy {

/// The file's bytes, or nothing when it cannot be opened or read.
std::optional<std::string> readTextFile(const std::filesystem::path& path);

/// Writes `text` to a temporary file beside `path` and renames it over `path`, so that a reader
/// (or a process killed mid-write) never leaves a half-written file. Creates missing parent
/// directories; throws std::runtime_error when it cannot write.
void writeFileAtomically(const std::filesystem::path& path, const std::string& text);

}  // namespace canopy
