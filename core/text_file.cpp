#include "core/text_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/output_file.h"

namespace canopy {

std::optional<std::string> readRegularFile(const std::filesystem::path& path,
                                           std::size_t max_bytes, std::string& why) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) {
    why = std::strerror(errno);
    return std::nullopt;
  }
  struct stat info {};
  std::optional<std::string> text;
  if (::fstat(fd, &info) != 0) {
    why = std::strerror(errno);
  } else if (!S_ISREG(info.st_mode)) {
    why = "not a regular file";
  } else if (static_cast<unsigned long long>(info.st_size) > max_bytes) {
    why = "larger than " + std::to_string(max_bytes >> 20) + " MiB";
  } else {
    std::string bytes(static_cast<std::size_t>(info.st_size), '\0');
    std::size_t done = 0;
    while (done < bytes.size()) {
      const ssize_t n = ::read(fd, bytes.data() + done, bytes.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      done += static_cast<std::size_t>(n);
    }
    if (done == bytes.size()) {
      text = std::move(bytes);
    } else {
      why = "the file changed while it was read";
    }
  }
  ::close(fd);
  return text;
}

std::optional<std::string> readTextFile(const std::filesystem::path& path) {
  std::string why;
  return readRegularFile(path, std::size_t{1} << 30, why);
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
