#include "slipwave/io/whole_write.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>

namespace slipwave::io {

bool WriteWhole(int fd, const std::string &text) {
  size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue; // a handled signal (SIGTERM's flag) before any byte
    if (n <= 0) return false;
    done += (size_t)n;
  }
  return true;
}

bool AppendWhole(const std::string &path, const std::string &text, bool truncate) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | (truncate ? O_TRUNC : 0), 0644);
  if (fd < 0) return false;
  const bool written = WriteWhole(fd, text);
  const int  saved   = errno;
  if (::close(fd) != 0 || !written) {
    if (!written) errno = saved;
    return false;
  }
  return true;
}

} // namespace slipwave::io
