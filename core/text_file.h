#pragma once
// Whole-file text I/O, shared by every folder that reads or writes result files.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

namespace canopy {

/// The bytes of the regular file at `path`, at most `max_bytes`: never through a symbolic link
/// as its last component (O_NOFOLLOW), never waiting on a FIFO (O_NONBLOCK, then fstat says
/// whether it is a regular file). Nothing, with the reason in `why`, otherwise.
std::optional<std::string> readRegularFile(const std::filesystem::path& path,
                                           std::size_t max_bytes, std::string& why);

/// readRegularFile with a 1 GiB limit, for result files (trials, manifests, records).
std::optional<std::string> readTextFile(const std::filesystem::path& path);

/// Writes `text` to a new temporary file beside `path` and renames it over `path` (an AtomicFile,
/// core/output_file.h), so that a reader never sees a half-written file and a link planted at
/// `path` or at a temporary name is never followed. Creates missing parent directories; throws
/// WriteError (a std::runtime_error) naming the file when it cannot write.
void writeFileAtomically(const std::filesystem::path& path, const std::string& text);

}  // namespace canopy
