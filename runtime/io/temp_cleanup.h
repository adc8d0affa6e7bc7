// Temporary output files that must not outlive an interrupted process: while a temp is
// registered here, SIGINT, SIGTERM and SIGHUP unlink it before the signal takes its
// usual effect. The handler touches only a fixed table (async-signal-safe); it is
// installed on first use, and only for signals still at their default action, so a host
// program's own handlers (the C API's callers) keep working.
#pragma once

namespace fgsg::rt::io {

// Registers `path` for removal on a terminating signal; returns a slot to release later,
// or -1 when the path is too long or the table is full (the file is still removed on any
// error, just not on a signal). Also makes SIGXFSZ ignored when it is at its default
// action, so exceeding `ulimit -f` is a write error (EFBIG) instead of a killed process.
int registerTempForCleanup(const char* path);

// Forgets a slot (after the temp was renamed or removed); -1 is ignored.
void releaseTempCleanup(int slot);

}  // namespace fgsg::rt::io
