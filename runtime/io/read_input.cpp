#include "runtime/io/read_input.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace fgsg::rt::io {

namespace {

// "a directory", "a FIFO (named pipe)", ...: what a non-regular file is.
std::string kindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

std::string symlinkTarget(const std::string& path) {
  char buf[4096];
  const ssize_t n = readlink(path.c_str(), buf, sizeof buf - 1);
  return n > 0 ? std::string(buf, size_t(n)) : std::string("?");
}

std::string capText(uint64_t cap) {
  if (cap >= (uint64_t(1) << 20) && cap % (uint64_t(1) << 20) == 0)
    return std::to_string(cap >> 20) + " MiB";
  return std::to_string(cap) + " bytes";
}

// The message for a file that stat() describes but that cannot be read as input, or ""
// when it is a regular file within the cap.
std::string refusal(const std::string& path, const struct stat& st, bool viaLink,
                    const std::string& what, uint64_t cap) {
  if (!S_ISREG(st.st_mode)) {
    const std::string kind = kindOf(st.st_mode);
    if (viaLink)
      return path + ": is a symbolic link to '" + symlinkTarget(path) + "', " + kind + ", not " +
             what;
    return path + ": is " + kind + ", not " + what;
  }
  if (uint64_t(st.st_size) > cap)
    return path + ": is larger than " + capText(cap) + " (" + std::to_string(st.st_size) +
           " bytes; the limit for input files), not read";
  return "";
}

std::string openFailure(const std::string& path, int err) {
  if (err == ENOENT || err == ENOTDIR) return path + ": no such file";
  if (err == EACCES || err == EPERM) return path + ": cannot be read (permission denied)";
  return path + ": cannot be read (" + std::strerror(err) + ")";
}

}  // namespace

bool checkInputFile(const std::string& path, const std::string& what, std::string& error,
                    uint64_t cap) {
  struct stat link{}, st{};
  if (lstat(path.c_str(), &link) != 0) {
    error = openFailure(path, errno);
    return false;
  }
  const bool viaLink = S_ISLNK(link.st_mode);
  if (stat(path.c_str(), &st) != 0) {
    const int err = errno;
    error = viaLink && err == ENOENT
                ? path + ": is a symbolic link to '" + symlinkTarget(path) +
                      "', which does not exist"
                : openFailure(path, err);
    return false;
  }
  error = refusal(path, st, viaLink, what, cap);
  if (!error.empty()) return false;
  if (access(path.c_str(), R_OK) != 0) {
    error = openFailure(path, errno);
    return false;
  }
  return true;
}

bool readInputFile(const std::string& path, const std::string& what, std::string& out,
                   std::string& error, uint64_t cap) {
  out.clear();
  if (!checkInputFile(path, what, error, cap)) return false;
  // Non-blocking: opening a FIFO put here since the check must not wait for a writer.
  const int fd = open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) {
    error = openFailure(path, errno);
    return false;
  }
  struct stat st{};
  if (fstat(fd, &st) != 0 || !(error = refusal(path, st, false, what, cap)).empty()) {
    if (error.empty()) error = openFailure(path, errno);
    close(fd);
    return false;
  }
  // One spare byte: the end of a file that kept its size is found without growing the
  // buffer. Reads up to one byte past the cap, so a file that grows meanwhile is bounded.
  out.resize(size_t(st.st_size) + 1);
  size_t have = 0;
  for (;;) {
    if (have == out.size()) {
      if (have > cap) break;
      out.resize(std::min<uint64_t>(cap + 1, std::max<uint64_t>(2 * have, 4096)));
    }
    const ssize_t n = read(fd, &out[have], out.size() - have);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      error = openFailure(path, errno);
      close(fd);
      out.clear();
      return false;
    }
    if (n == 0) break;
    have += size_t(n);
  }
  close(fd);
  out.resize(have);
  if (have > cap) {
    error = path + ": is larger than " + capText(cap) + " (the limit for input files), not read";
    out.clear();
    return false;
  }
  return true;
}

}  // namespace fgsg::rt::io
