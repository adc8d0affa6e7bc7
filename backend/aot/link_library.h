// Links a compiled grammar (a relocatable object, backend/codegen/program_codegen.h)
// into a shared library against libfgsg.so, with the system's C compiler driver.
#pragma once

#include <string>

namespace fgsg::backend::aot {

// The folder that holds libfgsg.so: $FGSG_LIBDIR when set, else ../lib beside the
// running executable (/proc/self/exe; the build tree's bin/ and lib/, or an install's).
// Empty, with a message in `error`, when libfgsg.so is not there.
std::string findRuntimeLibraryDir(std::string& error);

// Writes `object` to a temporary file and runs `cc -shared -o TMP OBJ -LLIBDIR -lfgsg
// -lm -Xlinker -rpath -Xlinker LIBDIR` ($FGSG_CC instead of cc when set; split at
// spaces), then renames TMP over `outputPath`, so the library appears whole or not at
// all. False with a message holding the linker's output when linking fails.
bool linkSharedLibrary(const std::string& object, const std::string& outputPath,
                       const std::string& libDir, std::string& error);

}  // namespace fgsg::backend::aot
