// Where the mesh encoders put their bytes: a staging buffer of a few MiB that is handed
// to a destination (a file descriptor, a string) whenever it fills, so that formatting
// writes straight into the buffer and a file gets few, large write() calls. Arrays that
// go out verbatim (GLB and PLY data) bypass the buffer.
//
// A failed destination write is remembered and later output is dropped; the encoder
// checks ok() at the end (and may check it earlier to stop early).
#pragma once

#include <cassert>
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

namespace fgsg::rt::io {

class ByteSink {
 public:
  static constexpr size_t kDefaultBuffer = size_t(4) << 20;
  static constexpr size_t kDirectRun = size_t(64) << 10;  // append() passes runs this long on

  explicit ByteSink(size_t bufferSize = kDefaultBuffer);
  virtual ~ByteSink();
  ByteSink(const ByteSink&) = delete;
  ByteSink& operator=(const ByteSink&) = delete;

  // At least `n` writable bytes (n at most the buffer size); write them, then advance()
  // with the end of what was written.
  char* room(size_t n) {
    if (size_t(end_ - cur_) < n) flushBuffer();
    return cur_;
  }
  void advance(char* newEnd) {
    assert(newEnd >= cur_ && newEnd <= end_);  // more than room() gave overran the buffer
    cur_ = newEnd;
  }
  size_t bufferSize() const { return size_t(end_ - buf_.get()); }

  // Appends bytes: small runs are copied into the buffer, large ones go to the
  // destination directly (after what is buffered).
  void append(const void* data, size_t n);
  void append(std::string_view s) { append(s.data(), s.size()); }

  // Hands everything buffered to the destination; false once any write failed.
  bool flush();
  bool ok() const { return ok_; }

 protected:
  // Writes all `n` bytes to the destination; false (with the reason saved by the
  // subclass) when it cannot.
  virtual bool drain(const char* data, size_t n) = 0;

 private:
  void flushBuffer();

  std::unique_ptr<char[]> buf_;
  char* cur_;
  char* end_;
  bool ok_ = true;
};

// Appends to a string (encodeMesh, tests).
class StringSink final : public ByteSink {
 public:
  explicit StringSink(std::string& out, size_t bufferSize = size_t(256) << 10)
      : ByteSink(bufferSize), out_(out) {}

 protected:
  bool drain(const char* data, size_t n) override {
    out_.append(data, n);
    return true;
  }

 private:
  std::string& out_;
};

// Writes to an open file descriptor, every write checked and retried on EINTR and short
// writes; error() is the errno of the first failure. Every few MiB it asks the kernel to
// start writing the new part to disk (sync_file_range), so that the caller's fsync has
// only the tail left to wait for.
class FdSink final : public ByteSink {
 public:
  explicit FdSink(int fd, size_t bufferSize = kDefaultBuffer) : ByteSink(bufferSize), fd_(fd) {}
  int error() const { return errno_; }

 protected:
  bool drain(const char* data, size_t n) override;

 private:
  static constexpr size_t kWritebackStep = size_t(16) << 20;
  int fd_;
  int errno_ = 0;
  size_t written_ = 0, writebackFrom_ = 0;
};

// Writes all of `bytes` to `fd` (EINTR and short writes retried); false with errno set.
bool writeAllToFd(int fd, const char* data, size_t n);

}  // namespace fgsg::rt::io
