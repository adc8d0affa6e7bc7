// `fgsg check` beyond the grammar text: the data files it names with a constant path
// that the run would load before deriving anything (synthesis examples), and the grammar's
// declared tilesets, loaded as
// `fgsg run` loads them, so that a bad file is found by `check` and not first by `run`.
#pragma once

#include "frontend/diagnostics.h"
#include "ir/ir.h"

#include <string>

namespace fgsg::cli {

// Reports each named file that cannot be used as an error at the call that names it,
// with the message `fgsg run` gives (R013). `grammarPath` locates the files as run does
// (the grammar's folder, then its assets/ folder).
void checkDataFiles(const ir::Module& module, const std::string& grammarPath, frontend::Diagnostics& diags);

}  // namespace fgsg::cli
