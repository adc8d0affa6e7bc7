// All the files one command writes, replaced together or not at all. Each output's bytes
// go first to a fresh temporary file beside its target (a random name created with
// O_CREAT|O_EXCL|O_NOFOLLOW, so a planted file or link there is never written through),
// every write checked and the file fsync'ed; only when every output is staged does
// commit() rename them over their targets. Until then the targets are untouched; the
// temporaries are removed on any error, when the transaction is dropped, and on SIGINT,
// SIGTERM or SIGHUP (runtime/io/temp_cleanup.h). Each temporary stays open and locked
// until it is renamed or removed, and staging an output first removes the temporaries
// that dead processes left for the same target (runtime/io/stale_temps.h).
#pragma once

#include "runtime/io/byte_sink.h"

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace fgsg::rt::io {

class OutputTransaction {
 public:
  OutputTransaction() = default;
  OutputTransaction(const OutputTransaction&) = delete;
  OutputTransaction& operator=(const OutputTransaction&) = delete;
  ~OutputTransaction();  // removes whatever was staged and not committed

  // Writes `bytes` to a new temporary for `path`. False and a message naming `path` in
  // `error` when it cannot (no such folder, no permission, disk full, `ulimit -f`, ...).
  bool stage(const std::string& path, std::string_view bytes, std::string& error);

  // Streams the temporary's bytes: `produce` puts them into the sink (which writes the
  // file in large blocks as it goes). When `produce` fails, `error` is "cannot write
  // 'PATH': " and its message; when a write fails, the system's reason. Either way the
  // temporary is removed.
  using Producer = std::function<bool(ByteSink& out, std::string& error)>;
  bool stage(const std::string& path, const Producer& produce, std::string& error);

  // Renames every staged temporary over its target, in staging order. Each target was
  // checked when staged (its folder is writable, it is not a folder), so a rename fails
  // only if the file system changes meanwhile; then the outputs not yet renamed keep
  // their old contents and `error` names the first one.
  bool commit(std::string& error);

  // Removes the staged temporaries; the targets keep their old contents.
  void abandon();

 private:
  struct Staged {
    std::string target, temp;
    int cleanupSlot = -1;
    int fd = -1;  // open, holding the in-use lock, until renamed or removed
  };
  std::vector<Staged> staged_;

  // Creates the temporary, runs `fill` on its descriptor (false: `fillError` set, or
  // errno when that is empty), fsyncs and closes it, and records it for commit.
  bool stageWith(const std::string& path, const std::function<bool(int fd, std::string& fillError)>& fill,
                 std::string& error);
};

// Creates a new file named `prefix` + random characters (O_CREAT|O_EXCL|O_NOFOLLOW|
// O_CLOEXEC, mode 0666 less the umask): an open descriptor and its name in `name`, or -1
// with errno set.
int createUniqueFile(const std::string& prefix, std::string& name);

}  // namespace fgsg::rt::io
