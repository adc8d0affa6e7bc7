// Links a compiled grammar (a relocatable object, backend/codegen/program_codegen.h)
// into a shared library with the system's C compiler driver: against libfgsg.so for
// `fgsg compile`, or against nothing for the JIT's cache (native/object_cache.h: the
// runtime's entry points then come from the fgsg process that loads it).
#pragma once

#include "runtime/plugins/plugin_library.h"

#include <string>

namespace fgsg::backend::aot {

// The folder that holds libfgsg.so (runtime/plugins/plugin_library.h); empty, with a
// message in `error`, when it is not there.
inline std::string findRuntimeLibraryDir(std::string& error) { return rt::findLibraryDir("libfgsg.so", error); }

// Writes `object` to a temporary file and runs `cc -shared -o TMP OBJ -LLIBDIR -lfgsg
// -lm -Xlinker -rpath -Xlinker LIBDIR` ($FGSG_CC instead of cc when set; split at
// spaces), then renames TMP over `outputPath`, so the library appears whole or not at
// all. An empty `libDir` links neither libfgsg nor an rpath. False with a message
// holding the linker's output when linking fails.
bool linkSharedLibrary(const std::string& object, const std::string& outputPath,
                       const std::string& libDir, std::string& error);

}  // namespace fgsg::backend::aot
