// LSP's base protocol on a pair of file descriptors: `Content-Length: N\r\n\r\n` then N
// bytes of JSON. Every message is bounded (headers and body), and a malformed one is
// reported, skipped and followed by a resynchronisation on the next `Content-Length:`, so
// bad input costs an error response, never a crash, a hang or unbounded memory.
#pragma once

#include <cstddef>
#include <string>

namespace fgsg::cli::lsp {

constexpr size_t kMaxHeaderBytes = 8 * 1024;
constexpr size_t kMaxBodyBytes = 32 * 1024 * 1024;

class MessageReader {
 public:
  explicit MessageReader(int fd) : fd_(fd) {}

  enum class Status { Message, Malformed, End };
  // Message: `body` holds one message's JSON text. Malformed: `error` says why; the reader
  // skips to the next message on the following call. End: the input closed.
  Status next(std::string& body, std::string& error);
  // Whether more input is already here (read or waiting): diagnostics wait until the
  // client's burst of changes is read (a debounce that costs no timer).
  bool inputPending() const;

 private:
  bool readMore();  // false at the end of input
  void resynchronise();

  int fd_;
  std::string buffer_;
  bool ended_ = false;
  bool skipping_ = false;
};

// Writes one framed message; false when the output is gone.
bool writeMessage(int fd, const std::string& body);

}  // namespace fgsg::cli::lsp
