// `fgsg lsp`: the Language Server Protocol server, JSON-RPC over a pair of file
// descriptors (stdin and stdout). Reads a message, answers it; publishes a changed
// document's diagnostics once the input waiting is read.
#pragma once

namespace fgsg::cli::lsp {

// Serves until `exit` or the end of input: 0 after a `shutdown`, 1 otherwise (as LSP says).
int serve(int in, int out);

}  // namespace fgsg::cli::lsp
