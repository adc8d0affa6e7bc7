// Every file fgsg reads as input (grammar, surface mesh, field, synthesis example, image)
// goes through here first: a name that is not a regular file (a directory, a FIFO, a device,
// also behind a symbolic link) or that is larger than the cap is refused with a message
// saying so, before anything blocks on it or reads without end (`field "/dev/zero"`).
#pragma once

#include <cstdint>
#include <string>

namespace fgsg::rt::io {

// The largest input file read: far above any sound grammar, field, example or mesh (a
// 2 M-triangle OFF is about 80 MiB), and small enough to read into memory at once.
constexpr uint64_t kMaxInputBytes = uint64_t(256) << 20;

// Checks that `path` names a readable regular file of at most `cap` bytes. On failure
// `error` reads "PATH: is a FIFO (named pipe), not a grammar file" and the like, with
// `what` naming the kind of file expected ("a grammar file", "a mesh file", ...).
bool checkInputFile(const std::string& path, const std::string& what, std::string& error,
                    uint64_t cap = kMaxInputBytes);

// checkInputFile, then the whole content into `out`. The file is opened without blocking
// and checked again once open, so a name swapped for a FIFO meanwhile cannot hang the read.
bool readInputFile(const std::string& path, const std::string& what, std::string& out,
                   std::string& error, uint64_t cap = kMaxInputBytes);

// The message of checkInputFile or readInputFile without its leading "PATH: ", for callers
// whose diagnostics name the file already.
inline std::string withoutPath(const std::string& error, const std::string& path) {
  const std::string prefix = path + ": ";
  return error.compare(0, prefix.size(), prefix) == 0 ? error.substr(prefix.size()) : error;
}

}  // namespace fgsg::rt::io
