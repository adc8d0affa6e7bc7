// The names and the header of a compiled grammar library (fgsg compile): libNAME.so
// exports `fgsg_program_NAME`; NAME.h declares it next to the C API (fgsg_api.h).
#pragma once

#include <string>

namespace fgsg::backend::aot {

// NAME for an output path `dir/libNAME.so`: the file name without its folder, its "lib"
// prefix and its ".so" extension, with '-' and '.' turned into '_'. Throws
// std::invalid_argument (the message says why) when the path does not end in ".so" or
// NAME cannot become a C identifier (empty, not starting with a letter, other
// characters than letters, digits, '_', '-' and '.').
std::string librarySymbolName(const std::string& outputPath);

// The text of NAME.h: an include guard, the whole C API (fgsg_api.h), the declaration of
// `fgsg_program_NAME` and `NAME_create()`, a generator for it. NAME must be an identifier
// (librarySymbolName's result).
std::string libraryHeader(const std::string& name);

}  // namespace fgsg::backend::aot
