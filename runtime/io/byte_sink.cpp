#include "runtime/io/byte_sink.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

namespace fgsg::rt::io {

// for_overwrite: the buffer's pages are touched only as far as output reaches.
ByteSink::ByteSink(size_t bufferSize)
    : buf_(std::make_unique_for_overwrite<char[]>(std::max<size_t>(bufferSize, 4096))),
      cur_(buf_.get()),
      end_(buf_.get() + std::max<size_t>(bufferSize, 4096)) {}

ByteSink::~ByteSink() = default;

void ByteSink::flushBuffer() {
  const size_t n = size_t(cur_ - buf_.get());
  cur_ = buf_.get();
  if (n > 0 && ok_ && !drain(buf_.get(), n)) ok_ = false;
}

void ByteSink::append(const void* data, size_t n) {
  // Callers append empty spans with a null pointer (an empty vector's data()); memcpy
  // may not be given one, even for zero bytes.
  if (n == 0) return;
  const char* p = static_cast<const char*>(data);
  if (n <= size_t(end_ - cur_)) {
    std::memcpy(cur_, p, n);
    cur_ += n;
    return;
  }
  // A small run fills up the buffer's rest; a larger one goes out in one piece after
  // what is buffered, without being copied.
  if (n < std::min(kDirectRun, bufferSize() / 2)) {
    const size_t first = size_t(end_ - cur_);
    std::memcpy(cur_, p, first);
    cur_ = end_;
    flushBuffer();
    std::memcpy(cur_, p + first, n - first);
    cur_ += n - first;
    return;
  }
  flushBuffer();
  if (ok_ && !drain(p, n)) ok_ = false;
}

bool ByteSink::flush() {
  flushBuffer();
  return ok_;
}

bool writeAllToFd(int fd, const char* data, size_t n) {
  size_t done = 0;
  while (done < n) {
    // At most 1 GiB a call: Linux writes no more than about 2 GiB at once anyway.
    const ssize_t w = ::write(fd, data + done, std::min<size_t>(n - done, size_t(1) << 30));
    if (w < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    if (w == 0) {  // no progress and no error: say so rather than loop
      errno = EIO;
      return false;
    }
    done += size_t(w);
  }
  return true;
}

bool FdSink::drain(const char* data, size_t n) {
  if (!writeAllToFd(fd_, data, n)) {
    errno_ = errno;
    return false;
  }
  written_ += n;
  // The file is fsync'ed when whole: starting the disk on what is written so far lets it
  // work while the rest is encoded, instead of all of it waiting for the final fsync. A
  // hint only (its failure changes nothing: fsync reports any write error).
  if (written_ - writebackFrom_ >= kWritebackStep) {
    ::sync_file_range(fd_, off64_t(writebackFrom_), off64_t(written_ - writebackFrom_), SYNC_FILE_RANGE_WRITE);
    writebackFrom_ = written_;
  }
  return true;
}

}  // namespace fgsg::rt::io
