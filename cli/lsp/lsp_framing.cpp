#include "cli/lsp/lsp_framing.h"

#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <cctype>

namespace fgsg::cli::lsp {
namespace {

const std::string kLengthHeader = "content-length:";

std::string lowered(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Where the header block ends (the index after its blank line), or npos. A bare "\n\n" is
// accepted as well as "\r\n\r\n": hand-written clients send it.
size_t headerEnd(const std::string& buffer, size_t& blankLength) {
  const size_t crlf = buffer.find("\r\n\r\n");
  const size_t lf = buffer.find("\n\n");
  if (crlf == std::string::npos && lf == std::string::npos) return std::string::npos;
  if (lf == std::string::npos || (crlf != std::string::npos && crlf < lf)) {
    blankLength = 4;
    return crlf;
  }
  blankLength = 2;
  return lf;
}

}  // namespace

bool MessageReader::readMore() {
  if (ended_) return false;
  char chunk[64 * 1024];
  for (;;) {
    const ssize_t n = ::read(fd_, chunk, sizeof chunk);
    if (n > 0) {
      buffer_.append(chunk, static_cast<size_t>(n));
      return true;
    }
    if (n < 0 && errno == EINTR) continue;
    ended_ = true;
    return false;
  }
}

bool MessageReader::inputPending() const {
  if (!buffer_.empty()) return true;
  if (ended_) return false;
  pollfd p{fd_, POLLIN, 0};
  return ::poll(&p, 1, 0) > 0;
}

// Drops input up to the next `Content-Length:` (the skipped message's body may run straight
// into it, without a newline). Keeps only a header name's length of tail while searching:
// bounded memory whatever arrives.
void MessageReader::resynchronise() {
  for (;;) {
    const size_t at = lowered(buffer_).find(kLengthHeader);
    if (at != std::string::npos) {
      buffer_.erase(0, at);
      break;
    }
    if (buffer_.size() > kLengthHeader.size()) buffer_.erase(0, buffer_.size() - kLengthHeader.size());
    if (!readMore()) {
      buffer_.clear();
      break;
    }
  }
  skipping_ = false;
}

MessageReader::Status MessageReader::next(std::string& body, std::string& error) {
  if (skipping_) resynchronise();
  size_t blank = 0, end;
  while ((end = headerEnd(buffer_, blank)) == std::string::npos) {
    if (buffer_.size() > kMaxHeaderBytes) {
      error = "header block longer than " + std::to_string(kMaxHeaderBytes) + " bytes";
      buffer_.clear();
      skipping_ = true;
      return Status::Malformed;
    }
    if (!readMore()) {
      const bool onlySpace = buffer_.find_first_not_of(" \t\r\n") == std::string::npos;
      buffer_.clear();
      if (onlySpace) return Status::End;
      error = "input ended inside a header block";
      return Status::Malformed;
    }
  }
  if (end > kMaxHeaderBytes) {
    error = "header block longer than " + std::to_string(kMaxHeaderBytes) + " bytes";
    buffer_.erase(0, end + blank);
    skipping_ = true;
    return Status::Malformed;
  }
  const std::string headers = buffer_.substr(0, end);
  buffer_.erase(0, end + blank);

  // Content-Length is required; Content-Type and any other header are ignored.
  long long length = -1;
  size_t from = 0;
  while (from <= headers.size()) {
    size_t eol = headers.find('\n', from);
    if (eol == std::string::npos) eol = headers.size();
    std::string line = headers.substr(from, eol - from);
    from = eol + 1;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const size_t colon = line.find(':');
    if (colon == std::string::npos) {
      error = "malformed header line (no ':')";
      skipping_ = true;
      return Status::Malformed;
    }
    if (lowered(line.substr(0, colon + 1)) != kLengthHeader) continue;
    std::string value = line.substr(colon + 1);
    value.erase(0, value.find_first_not_of(" \t"));
    value.erase(value.find_last_not_of(" \t") + 1);
    if (value.empty() || value.size() > 12 || value.find_first_not_of("0123456789") != std::string::npos) {
      error = "Content-Length is not a number";
      skipping_ = true;
      return Status::Malformed;
    }
    length = std::stoll(value);
  }
  if (length < 0) {
    error = "no Content-Length header";
    skipping_ = true;
    return Status::Malformed;
  }
  if (static_cast<unsigned long long>(length) > kMaxBodyBytes) {
    error = "Content-Length " + std::to_string(length) + " is over the limit of " + std::to_string(kMaxBodyBytes) +
            " bytes";
    skipping_ = true;
    return Status::Malformed;
  }
  while (buffer_.size() < static_cast<size_t>(length)) {
    if (!readMore()) {
      buffer_.clear();
      error = "input ended inside a message body";
      return Status::Malformed;
    }
  }
  body = buffer_.substr(0, static_cast<size_t>(length));
  buffer_.erase(0, static_cast<size_t>(length));
  return Status::Message;
}

bool writeMessage(int fd, const std::string& body) {
  const std::string framed = "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body;
  size_t done = 0;
  while (done < framed.size()) {
    const ssize_t n = ::write(fd, framed.data() + done, framed.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

}  // namespace fgsg::cli::lsp
