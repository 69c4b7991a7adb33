#pragma once
// Output files written honestly: every write checked, nothing half-written under a final name,
// never through a link planted where the output goes.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace canopy {

/// A failed write of an output file (disk full, no permission, a link or a directory in the way).
/// Not bad input: the command line prints what() and exits with code 1. what() reads
/// "cannot write 'FILE': REASON" with FILE made printable.
class WriteError : public std::runtime_error {
 public:
  WriteError(const std::filesystem::path& path, const std::string& reason);
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

/// An output path that is not canopy's to replace: it exists and is neither a regular file nor a
/// symbolic link (a device, FIFO, socket or directory). Bad input, not a failed write: the
/// command line exits with code 2; what() names the path and what it is.
class OutputRefused : public WriteError {
 public:
  using WriteError::WriteError;
};

/// Throws OutputRefused when `path` exists and is not a regular file or a symbolic link (lstat:
/// a link is replaced, never followed). Renaming over a device node would replace the system's
/// device (as root, `--out /dev/null`); over a FIFO or socket, another program's endpoint.
void checkOutputFile(const std::filesystem::path& path);
/// checkOutputFile for every entry directly inside the folder `dir` (none when it does not exist):
/// an output folder holds files, folders and links only.
void checkOutputEntries(const std::filesystem::path& dir);

/// A file written in pieces and published whole. The bytes go to a new temporary beside `path`
/// ("NAME.PID-N.tmp", opened with O_CREAT | O_EXCL | O_NOFOLLOW, so never through a planted link
/// or into a file that was already there); commit() renames it over `path`, which replaces a link
/// at `path` instead of following it. Without commit() (a failed write, an exception) the
/// destructor removes the temporary, so no reader ever sees a partial file under `path`. Every
/// write is checked; failures throw WriteError naming `path`. `path` is checked with
/// checkOutputFile when the temporary is made and again just before the rename (OutputRefused).
class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path path);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();

  /// Appends `bytes` (buffered).
  void write(std::string_view bytes);
  /// Writes what is buffered, closes, and renames the temporary over path(). Call once.
  void commit();

  const std::filesystem::path& path() const { return path_; }
  /// The temporary, for a child process that writes the file by name (ffmpeg): commit() then
  /// publishes what it wrote. Nothing else should be written through this name.
  const std::filesystem::path& temporary() const { return temporary_; }

 private:
  void flush();
  void writeAll(std::string_view bytes);
  void discard() noexcept;

  std::filesystem::path path_;
  std::filesystem::path temporary_;
  int fd_ = -1;
  std::string buffer_;
};

/// Creates `dir` and its missing parents, like `mkdir -p`. Each component of `dir` strictly below
/// `root` that already exists must be a directory and not a symbolic link: a link planted in an
/// output directory would lead the writes that follow out of it. `root` itself (the directory the
/// user named) may be a link to a directory; `dir` must lie lexically under `root` (or be it).
/// Throws WriteError naming the component at fault.
void makeOutputDirectories(const std::filesystem::path& dir, const std::filesystem::path& root);
/// The checks of makeOutputDirectories without creating anything (components that do not exist
/// yet pass), for a command that must refuse before it writes.
void checkOutputDirectories(const std::filesystem::path& dir, const std::filesystem::path& root);

/// Removes the file `path` if it exists: a link itself, never its target. Throws OutputRefused
/// when it is not a regular file or a link (checkOutputFile), WriteError when it cannot be removed.
void removeOutputFile(const std::filesystem::path& path);

/// `name` as one file-name component that cannot leave the directory it is put in: ASCII letters,
/// digits, '-', '_' and '.' stay, every other byte becomes '_', a leading '.' becomes '_' (never
/// ".", ".." or a hidden file), an empty name becomes "_"; at most kMaxSafeFileName bytes.
std::string safeFileName(std::string_view name);
inline constexpr std::size_t kMaxSafeFileName = 100;

}  // namespace canopy
