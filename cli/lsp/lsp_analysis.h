// One document's analysis: what `fgsg check` reports for its current text (the same
// compile, read from the editor's buffer rather than the disk), and its parsed program
// with its modules, which completion, hover, definition and symbols read.
#pragma once

#include "frontend/ast.h"
#include "frontend/diagnostics.h"
#include "frontend/statement_reuse.h"

#include <nlohmann/json.hpp>

#include <memory>
#include <string>
#include <vector>

namespace fgsg::cli::lsp {

using Json = nlohmann::json;

// A name the grammar declares, where it is declared.
struct Definition {
  enum class Kind { Rule, Attr, Const, Field };
  Kind kind;
  std::string name;         // as written and shown (a .cga rule's '$' mark dropped)
  frontend::SourceRange range;      // the whole declaration (a rule: its first line)
  frontend::SourceRange nameRange;  // the name, where the declaration writes it
  bool inDocument = true;   // false: in an imported module
};

struct Analysis {
  std::string path;
  frontend::SourceFile source;  // the document's lines, then its modules'
  std::vector<frontend::Diagnostic> diagnostics;
  frontend::Program program;    // its modules' declarations merged in
  std::vector<Definition> definitions;  // the document's first, in order, then the modules'
  // Where each statement of `program` that the next analysis may take over is (statement
  // reuse: frontend/statement_reuse.h).
  frontend::ReusableStatementIndex statements;
  // Its raw tokens, which the next analysis lexes again only around the edit.
  std::shared_ptr<frontend::IncrementalLexCache> tokens;

  // The last line of the document itself in `source`.
  int documentLines() const;
  // A line of `source` (1-based, whole numbering) as the file it is in and its 0-based line there.
  struct Place {
    std::string path;
    int line = 0;
    bool inDocument = true;
  };
  Place placeOf(int wholeLine) const;
  // An LSP Range (0-based, UTF-16, end exclusive) of a front-end range of `source`.
  Json rangeOf(const frontend::SourceRange& range) const;
  // An LSP Location: the file's URI and the range there.
  Json locationOf(const frontend::SourceRange& range) const;
  // The definitions named `name` (a rule defined by several rules gives each).
  std::vector<const Definition*> find(const std::string& name) const;
};

// Compiles `text` as the grammar at `path` (imports are looked for beside it). `previous`,
// the analysis of the document's text before an edit, gives the statements that did not
// change (their parsed AST is moved out of it: it is spent); ignored when anyone else
// still holds it.
std::shared_ptr<Analysis> analyze(const std::string& path, const std::string& text,
                                  std::shared_ptr<Analysis> previous = nullptr);

// The name under (or, with `prefixOnly`, ending at) byte `at` of `line`: letters, digits,
// '_' and the '.' of a qualified name (facade.Window).
std::string nameAt(const std::string& line, size_t at, bool prefixOnly);

}  // namespace fgsg::cli::lsp
