// compileSource (ir/pipeline.h) for a grammar compiled again after an edit (fgsg lsp): the
// same passes and diagnostics, with the statements whose tokens did not change taken over
// from the previous compile's parsed program instead of parsed again
// (frontend/statement_reuse.h).
#pragma once

#include "frontend/statement_reuse.h"
#include "ir/pipeline.h"

namespace fgsg::ir {

// `keep` receives the parsed program (as compileSource's `keep`); `reuse` offers the
// previous one's statements and records this one's.
bool compileSourceReusing(frontend::SourceFile& file, Module& out, frontend::Diagnostics& diags,
                          frontend::Program& keep, frontend::StatementReuse& reuse);

}  // namespace fgsg::ir
