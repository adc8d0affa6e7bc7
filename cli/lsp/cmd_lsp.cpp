// fgsg lsp: the language server, for editors (docs/editors.md).
#include "cli/commands.h"
#include "cli/lsp/lsp_server.h"

#include <unistd.h>

#include <csignal>
#include <iostream>

namespace fgsg::cli {

int lspCommand(const Args& args) {
  // Editors start servers with `--stdio` (vscode-languageclient does): the only transport.
  for (const std::string& a : args) {
    if (a != "--stdio") {
      std::cerr << "fgsg lsp: unknown argument '" << a << "' (the server speaks LSP on stdin and stdout)\n";
      return 2;
    }
  }
  // stdout carries the protocol only: anything else printed would break its framing.
  std::cout.rdbuf(std::cerr.rdbuf());
  std::signal(SIGPIPE, SIG_IGN);  // a client gone away ends the loop, not the process
  return lsp::serve(STDIN_FILENO, STDOUT_FILENO);
}

}  // namespace fgsg::cli
