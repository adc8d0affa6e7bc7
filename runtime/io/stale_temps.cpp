#include "runtime/io/stale_temps.h"

#include <cctype>
#include <cerrno>
#include <cstring>
#include <ctime>
#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace fgsg::rt::io {

namespace {

// A temporary's writer creates it and locks it right after: an empty file this young may
// be in that gap, so it is not taken for stale.
constexpr time_t kCreationGraceSeconds = 60;

bool isTempName(const char* name, const std::string& prefix) {
  if (std::strncmp(name, prefix.c_str(), prefix.size()) != 0) return false;
  const char* rest = name + prefix.size();
  if (std::strlen(rest) != kTempRandomChars) return false;
  for (const char* c = rest; *c; ++c)
    if (!std::isalnum(static_cast<unsigned char>(*c))) return false;
  return true;
}

// Removes `name` (in the folder `dirFd`) when it is a stale temporary of ours.
bool removeIfStale(int dirFd, const char* name) {
  const int fd = ::openat(dirFd, name, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) return false;  // a link, gone meanwhile, or not ours to read
  bool removed = false;
  struct stat st {};
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_uid == ::geteuid() &&
      !(st.st_size == 0 && std::time(nullptr) - st.st_mtime < kCreationGraceSeconds) &&
      ::flock(fd, LOCK_EX | LOCK_NB) == 0) {
    // No one holds it. Unlink it only if the name still refers to the file checked.
    struct stat now {};
    if (::fstatat(dirFd, name, &now, AT_SYMLINK_NOFOLLOW) == 0 && now.st_dev == st.st_dev &&
        now.st_ino == st.st_ino)
      removed = ::unlinkat(dirFd, name, 0) == 0;
  }
  ::close(fd);  // drops the lock taken
  return removed;
}

}  // namespace

bool isOutputTemporary(const std::string& fileName) {
  const size_t infix = std::strlen(kTempInfix);
  if (fileName.size() <= infix + kTempRandomChars) return false;  // the target's name is not empty
  const size_t at = fileName.size() - kTempRandomChars - infix;
  return isTempName(fileName.c_str() + at, kTempInfix);
}

bool lockTempInUse(int fd) {
  while (::flock(fd, LOCK_EX | LOCK_NB) != 0)
    if (errno != EINTR) return false;
  return true;
}

int removeStaleTemps(const std::string& target) {
  const size_t slash = target.rfind('/');
  const std::string folder = slash == std::string::npos ? "." : slash == 0 ? "/" : target.substr(0, slash);
  const std::string prefix = target.substr(slash == std::string::npos ? 0 : slash + 1) + kTempInfix;
  const int dirFd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dirFd < 0) return 0;
  DIR* dir = ::fdopendir(dirFd);
  if (!dir) {
    ::close(dirFd);
    return 0;
  }
  int removed = 0;
  while (const dirent* entry = ::readdir(dir))
    if (isTempName(entry->d_name, prefix) && removeIfStale(dirFd, entry->d_name)) ++removed;
  ::closedir(dir);  // closes dirFd too
  return removed;
}

}  // namespace fgsg::rt::io
