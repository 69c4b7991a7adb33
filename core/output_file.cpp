#include "core/output_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "core/printable.h"

namespace canopy {
namespace fs = std::filesystem;
namespace {

constexpr std::size_t kBufferBytes = 1 << 16;
constexpr int kTemporaryAttempts = 100;

std::string systemReason(int error) {
  return std::strerror(error);
}

// Opens a new temporary beside `path`; O_EXCL fails on any existing name, a link included, so
// a name planted in advance is skipped rather than written through.
int openTemporary(const fs::path& path, fs::path& temporary) {
  static std::atomic<unsigned> counter{0};
  for (int attempt = 0; attempt < kTemporaryAttempts; ++attempt) {
    temporary = path;
    temporary += "." + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ".tmp";
    const int fd =
        ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd >= 0) return fd;
    if (errno != EEXIST) throw WriteError(path, systemReason(errno));
  }
  throw WriteError(path, "no free temporary name beside it");
}

}  // namespace

WriteError::WriteError(const fs::path& path, const std::string& reason)
    : std::runtime_error("cannot write '" + printable(path.string(), 300) + "': " + reason),
      path_(path) {}

void checkOutputFile(const fs::path& path) {
  struct stat info {};
  if (::lstat(path.c_str(), &info) != 0) return;  // absent (or unreachable: the write will say)
  if (S_ISREG(info.st_mode) || S_ISLNK(info.st_mode)) return;
  const char* what = S_ISDIR(info.st_mode)    ? "a directory"
                     : S_ISFIFO(info.st_mode) ? "a FIFO"
                     : S_ISSOCK(info.st_mode) ? "a socket"
                     : S_ISCHR(info.st_mode)  ? "a character device"
                     : S_ISBLK(info.st_mode)  ? "a block device"
                                              : "not a regular file";
  throw OutputRefused(path, std::string("exists and is ") + what +
                                "; canopy replaces only regular files (choose another path)");
}

void checkOutputEntries(const fs::path& dir) {
  std::error_code error;
  if (!fs::is_directory(fs::symlink_status(dir, error))) return;
  for (const auto& entry : fs::directory_iterator(dir, error)) {
    const fs::file_status status = entry.symlink_status(error);
    if (error || fs::is_regular_file(status) || fs::is_directory(status) || fs::is_symlink(status))
      continue;
    checkOutputFile(entry.path());
  }
}

AtomicFile::AtomicFile(fs::path path) : path_(std::move(path)) {
  checkOutputFile(path_);
  fd_ = openTemporary(path_, temporary_);
  buffer_.reserve(kBufferBytes);
}

AtomicFile::~AtomicFile() {
  discard();
}

void AtomicFile::write(std::string_view bytes) {
  if (fd_ < 0) throw WriteError(path_, "already closed");
  if (buffer_.size() + bytes.size() <= kBufferBytes) {
    buffer_.append(bytes);
    return;
  }
  flush();
  if (bytes.size() < kBufferBytes) {
    buffer_.append(bytes);
  } else {
    writeAll(bytes);  // large pieces (a PNG) skip the buffer
  }
}

void AtomicFile::flush() {
  writeAll(buffer_);
  buffer_.clear();
}

void AtomicFile::writeAll(std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = n < 0 ? errno : EIO;
      discard();
      throw WriteError(path_, systemReason(error));
    }
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
}

void AtomicFile::commit() {
  if (fd_ < 0) throw WriteError(path_, "already closed");
  flush();
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) {
    const int error = errno;
    ::unlink(temporary_.c_str());
    temporary_.clear();
    throw WriteError(path_, systemReason(error));
  }
  try {
    checkOutputFile(path_);  // again: something may have been put there while we wrote
  } catch (...) {
    ::unlink(temporary_.c_str());
    temporary_.clear();
    throw;
  }
  if (::rename(temporary_.c_str(), path_.c_str()) != 0) {
    const int error = errno;
    ::unlink(temporary_.c_str());
    temporary_.clear();
    throw WriteError(path_, systemReason(error));
  }
  temporary_.clear();
}

void AtomicFile::discard() noexcept {
  if (fd_ >= 0) {
    ::close(fd_);
    fd_ = -1;
  }
  if (!temporary_.empty()) {
    ::unlink(temporary_.c_str());
    temporary_.clear();
  }
}

namespace {

// Walks `dir` from `root` down: each component below root that exists must be a real directory
// (lstat: a link is refused, not followed); a missing one is made (`create`) or ends the walk.
void walkOutputDirectories(const fs::path& dir, const fs::path& root, bool create) {
  const fs::path base = root.empty() ? fs::path(".") : root;
  std::error_code error;
  if (!fs::exists(base, error)) {
    if (!create) return;
    fs::create_directories(base, error);
    if (error) throw WriteError(base, error.message());
  }
  if (!fs::is_directory(base, error)) throw WriteError(base, "exists and is not a directory");

  const fs::path relative = dir.lexically_normal().lexically_relative(base.lexically_normal());
  if (relative.empty() || *relative.begin() == "..") {
    throw WriteError(dir, "not inside the output directory '" + printable(base.string()) + "'");
  }
  fs::path at = base;
  for (const fs::path& part : relative) {
    if (part == "." || part.empty()) continue;
    at /= part;
    if (create && ::mkdir(at.c_str(), 0777) == 0) continue;
    if (create && errno != EEXIST) throw WriteError(at, systemReason(errno));
    struct stat info {};
    if (::lstat(at.c_str(), &info) != 0) {
      if (!create && errno == ENOENT) return;
      throw WriteError(at, systemReason(errno));
    }
    if (S_ISLNK(info.st_mode)) {
      throw WriteError(at, "is a symbolic link inside the output directory (not followed)");
    }
    if (!S_ISDIR(info.st_mode)) throw WriteError(at, "exists and is not a directory");
  }
}

}  // namespace

void makeOutputDirectories(const fs::path& dir, const fs::path& root) {
  walkOutputDirectories(dir, root, true);
}

void checkOutputDirectories(const fs::path& dir, const fs::path& root) {
  walkOutputDirectories(dir, root, false);
}

void removeOutputFile(const fs::path& path) {
  checkOutputFile(path);
  if (::unlink(path.c_str()) == 0 || errno == ENOENT) return;
  throw WriteError(path, "cannot remove the previous file: " + systemReason(errno));
}

std::string safeFileName(std::string_view name) {
  std::string safe(name.substr(0, kMaxSafeFileName));
  for (char& c : safe) {
    const auto u = static_cast<unsigned char>(c);
    const bool kept = (u >= 'a' && u <= 'z') || (u >= 'A' && u <= 'Z') || (u >= '0' && u <= '9') ||
                      u == '-' || u == '_' || u == '.';
    if (!kept) c = '_';
  }
  if (safe.empty()) return "_";
  if (safe.front() == '.') safe.front() = '_';
  return safe;
}

}  // namespace canopy
