// Temporaries that killed runs left beside an output (SIGKILL, the OOM killer, a power
// cut: nothing of the process runs to remove them). Each temporary is locked (flock) by
// the process writing it for as long as it exists under its temporary name; the kernel
// drops the lock when the process dies, however it dies. So a file with our temporary
// name pattern that no one holds locked is a dead process's, and the next write to the
// same output removes it: a killed 1 GiB export does not stay on disk forever.
#pragma once

#include <string>

namespace fgsg::rt::io {

// The temporary name pattern for `target`: target + kTempInfix + kTempRandomChars
// letters and digits (output_transaction.h's createUniqueFile draws them).
inline constexpr const char* kTempInfix = ".tmp.";
inline constexpr size_t kTempRandomChars = 8;

// Whether a file name (no folder) has the temporary pattern of some output: a name,
// kTempInfix and kTempRandomChars letters and digits ("city.glb.tmp.a1B2c3D4"). For
// watchers (fgsg view) that should not take a write in progress for an edit.
bool isOutputTemporary(const std::string& fileName);

// Takes the lock that marks a temporary as in use (`fd` open on it). False when the file
// system has no locks; the temporary is then never taken for stale, as no one could
// tell it from a live one.
bool lockTempInUse(int fd);

// Removes the stale temporaries of `target`: regular files (never links) in its folder
// named by the pattern above, owned by this user, that no process holds locked. A
// temporary that is empty and was touched within the last minute is left alone: its
// writer may be between creating it and locking it. Returns how many were removed;
// failures are ignored (the write goes on, the stale file stays).
int removeStaleTemps(const std::string& target);

}  // namespace fgsg::rt::io
