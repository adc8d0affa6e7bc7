// Writes a whole file or nothing: the bytes go to a temporary file next to the target,
// are flushed to disk, and only then renamed over it, so a reader (or a crash) never sees
// a partially written output. A one-file OutputTransaction (output_transaction.h): the
// temporary has a random name created exclusively, never following a link.
#pragma once

#include <string>
#include <string_view>

namespace fgsg::rt::io {

// Replaces `path` with `bytes`. On failure the target is untouched, no temporary file is
// left behind, and `error` says why (e.g. the directory does not exist).
bool writeFileAtomically(const std::string& path, std::string_view bytes, std::string& error);

}  // namespace fgsg::rt::io
