// Is an exception the system running out of memory or threads, rather than a bug? The
// boundaries that turn exceptions into diagnostics ask this so that a process short of
// memory gets "out of memory", never "internal error".
#pragma once

#include <exception>
#include <string>

namespace fgsg::rt {

// The system's own words for what ran out, or "" when `e` is something else: std::bad_alloc;
// a std::system_error for ENOMEM or EAGAIN (std::thread); TBB's std::runtime_error
// "pthread_create has failed: ..." when it cannot start a worker (each thread reserves its
// stack, so a tight `ulimit -v` fails here first); a PluginError the loader could not map.
std::string outOfResources(const std::exception& e);

// Which limit a process that ran out of memory met, for its message: "the address-space
// limit (ulimit -v) of 781M", "the cgroup's memory limit of 2G" or "the machine's 16G
// of memory", whichever is lowest; with the memory in use ("; 612M in use").
std::string memoryLimitInForce();

}  // namespace fgsg::rt
