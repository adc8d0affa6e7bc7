#include "runtime/io/output_transaction.h"

#include "runtime/io/stale_temps.h"
#include "runtime/io/temp_cleanup.h"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <memory>
#include <new>
#include <csignal>
#include <fcntl.h>
#include <pthread.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

namespace fgsg::rt::io {

namespace {

std::string describe(const std::string& what, const std::string& path, int err) {
  return "cannot " + what + " '" + path + "': " + std::strerror(err);
}

}  // namespace

int createUniqueFile(const std::string& prefix, std::string& name) {
  static const char kAlphabet[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
  for (int attempt = 0; attempt < 100; ++attempt) {
    unsigned char random[8];
    if (::getrandom(random, sizeof random, 0) != ssize_t(sizeof random)) {
      // No entropy source (a very old kernel or a sandbox): still unique enough with the
      // address of a local and the attempt, since O_EXCL catches any collision.
      uint64_t fallback = uint64_t(reinterpret_cast<uintptr_t>(&random)) ^ (uint64_t(::getpid()) << 20) ^ attempt;
      std::memcpy(random, &fallback, sizeof random);
    }
    name = prefix;
    for (unsigned char r : random) name += kAlphabet[r % (sizeof kAlphabet - 1)];
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  errno = EEXIST;
  return -1;
}

OutputTransaction::~OutputTransaction() { abandon(); }

bool OutputTransaction::stage(const std::string& path, std::string_view bytes, std::string& error) {
  return stageWith(
      path, [&](int fd, std::string&) { return writeAllToFd(fd, bytes.data(), bytes.size()); }, error);
}

bool OutputTransaction::stage(const std::string& path, const Producer& produce, std::string& error) {
  return stageWith(
      path,
      [&](int fd, std::string& fillError) {
        std::unique_ptr<FdSink> sink;
        try {
          sink = std::make_unique<FdSink>(fd);
        } catch (const std::bad_alloc&) {  // its buffer
          fillError = "out of memory";
          return false;
        }
        if (!produce(*sink, fillError)) {
          if (fillError.empty()) fillError = "the encoder failed";
          return false;
        }
        if (sink->flush()) return true;
        errno = sink->error();
        return false;
      },
      error);
}

bool OutputTransaction::stageWith(const std::string& path,
                                  const std::function<bool(int fd, std::string& fillError)>& fill,
                                  std::string& error) {
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) {
    error = describe("replace", path, EISDIR);
    return false;
  }
  // What killed runs left for this target goes first (a 1 GiB temporary each).
  removeStaleTemps(path);
  // Beside the target: rename is atomic only within one file system.
  std::string temp;
  // Terminating signals wait until the new temporary is registered for removal.
  sigset_t terminating, previous;
  sigemptyset(&terminating);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&terminating, sig);
  ::pthread_sigmask(SIG_BLOCK, &terminating, &previous);
  const int fd = createUniqueFile(path + kTempInfix, temp);
  const int createErrno = errno;
  // In use while this process lives (a file system without locks: never taken for stale).
  if (fd >= 0) lockTempInUse(fd);
  const int slot = fd >= 0 ? registerTempForCleanup(temp.c_str()) : -1;
  ::pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  if (fd < 0) {
    error = describe("write", path, createErrno);
    const std::string folder = std::filesystem::path(path).parent_path().string();
    if (createErrno == ENOENT && ::stat(folder.empty() ? "." : folder.c_str(), &st) != 0)
      error += " (the folder " + folder + " does not exist)";
    return false;
  }
  const auto fail = [&](const std::string& what, int err) {
    ::unlink(temp.c_str());
    releaseTempCleanup(slot);
    error = describe(what, path, err);
    return false;
  };
  std::string fillError;
  bool filled = false;
  try {
    filled = fill(fd, fillError);
  } catch (...) {  // e.g. out of memory while encoding: no temporary stays behind
    ::close(fd);
    fail("write", 0);
    throw;
  }
  if (!filled) {
    const int err = errno;
    ::close(fd);
    if (fillError.empty()) return fail("write", err);
    fail("write", 0);
    error = "cannot write '" + path + "': " + fillError;
    return false;
  }
  if (::fsync(fd) != 0) {
    const int err = errno;
    ::close(fd);
    return fail("write", err);
  }
  try {
    staged_.push_back({path, temp, slot, fd});
  } catch (...) {
    ::close(fd);
    fail("write", ENOMEM);
    throw;
  }
  return true;
}

bool OutputTransaction::commit(std::string& error) {
  for (size_t i = 0; i < staged_.size(); ++i) {
    Staged& s = staged_[i];
    if (::rename(s.temp.c_str(), s.target.c_str()) != 0) {
      error = describe("replace", s.target, errno);
      staged_.erase(staged_.begin(), staged_.begin() + long(i));
      abandon();
      return false;
    }
    releaseTempCleanup(s.cleanupSlot);
    ::close(s.fd);  // the lock goes with it; the name is the target's now
    s.fd = -1;
  }
  staged_.clear();
  return true;
}

void OutputTransaction::abandon() {
  for (const Staged& s : staged_) {
    ::unlink(s.temp.c_str());
    releaseTempCleanup(s.cleanupSlot);
    if (s.fd >= 0) ::close(s.fd);
  }
  staged_.clear();
}

}  // namespace fgsg::rt::io
