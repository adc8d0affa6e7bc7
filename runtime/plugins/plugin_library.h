// fgsg's own shared libraries beside the executable: libfgsg.so (the C API) and the
// plugins that keep heavy dependencies out of every process's start-up (issue #18):
// lib/libfgsg_llvm.so (the code generator and JIT, backend/native/llvm_plugin.h) and
// lib/libfgsg_fcl.so (collision tests, runtime/collision/collision_backend.h). A plugin
// resolves what it uses of fgsg from the executable that opens it, which exports it
// (CMake: fgsg_export_for_plugins); executables that link a plugin's code in (tests,
// benchmarks, libfgsg.so) never open it.
#pragma once

#include <stdexcept>
#include <string>

namespace fgsg::rt {

// The folder that holds fgsg's library `fileName`: $FGSG_LIBDIR when set, else ../lib
// beside the running executable (/proc/self/exe; the build tree's bin/ and lib/, or an
// install's). Empty, with a message in `error`, when the library is not there.
std::string findLibraryDir(const std::string& fileName, std::string& error);

// A plugin that cannot be used: fgsg is not installed whole (or FGSG_LIBDIR is wrong),
// or — outOfMemory — the loader could not map it for lack of address space.
struct PluginError : std::runtime_error {
  explicit PluginError(const std::string& what, bool noMemory = false) : std::runtime_error(what), outOfMemory(noMemory) {}
  bool outOfMemory = false;
};

// Opens lib/`fileName` (never closed) and returns its extern "C" function `entry`, or
// throws PluginError naming the library and why it cannot be used.
void* openPlugin(const std::string& fileName, const char* entry);

}  // namespace fgsg::rt
