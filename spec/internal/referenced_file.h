#pragma once
// Private to scenarios/: reading a file that a scenario names (a layout include, a track CSV).
// The name resolves against the naming file's folder; the file must lie inside one of the
// field's LoadContext roots (symbolic links resolved first), be a regular file (not a FIFO, a
// device or a folder) and hold at most kMaxReferencedBytes. Every refusal names the field.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include "spec/json_reader.h"

namespace canopy::spec::internal {

constexpr std::size_t kMaxReferencedBytes = std::size_t{64} << 20;  // 64 MiB

struct ReferencedFile {
  std::filesystem::path path;  // canonical
  std::string shown;           // the path as named, for messages (printable)
  std::string quoted;          // 'shown', and where it leads when that is through a link
  std::string text;
};

/// `field` holds the file name (a string); `what` says what the file is ("track file"). A relative
/// name that is not found beside the naming file is looked up in `fallback_dir`, when given.
ReferencedFile readReferencedFile(const Field& field, const std::string& what,
                                  const std::filesystem::path& fallback_dir = {});

/// The LoadContext of a scenario file: its own folder, the scenario library, and `allowed`.
LoadContext loadContextFor(const std::filesystem::path& scenario_file,
                           const std::vector<std::filesystem::path>& allowed);

}  // namespace canopy::spec::internal
