// fgsg builtin-reference: docs/language.md's "Builtin reference" section, generated from
// the table `fgsg lsp` hovers with (frontend/builtin_docs.cpp). Not in --help: it is for
// regenerating the docs (docs/editors.md), which tests/docs/check_builtin_reference.py
// keeps equal to this output.
#include "cli/commands.h"
#include "frontend/builtin_docs.h"

#include <iostream>

namespace fgsg::cli {

int builtinReferenceCommand(const Args& args) {
  if (!args.empty()) {
    std::cerr << "fgsg builtin-reference: takes no arguments, got '" << args[0] << "'\n";
    return 2;
  }
  std::cout << frontend::builtinReferenceMarkdown();
  return 0;
}

}  // namespace fgsg::cli
