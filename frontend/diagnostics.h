// Diagnostics for user errors in grammar text: `file:line:col: error[E012]: message`,
// then the source line and a caret under the column. Collected, never thrown, so one
// run reports every mistake it can find.
#pragma once

#include "frontend/ast.h"

#include <iosfwd>
#include <string>
#include <vector>

namespace fgsg::frontend {

// A grammar's text and, once its imports are read (frontend/imports.cpp), the modules' texts
// after it: one numbering of lines for the whole (each module's lines follow the ones
// before), so locations stay (line, column) and a diagnostic names the file they are in.
struct SourceFile {
  std::string name;  // as given by the user, printed in diagnostics
  // The grammar's text, then each module's behind a marker line: what a JIT cache key
  // hashes and a compiled library embeds, so the modules travel with the grammar.
  std::string text;
  std::vector<std::string> lines;  // the grammar's lines, then each module's

  struct Module {
    std::string key;       // where it was read (a path): one import of it is one module
    std::string name;      // as diagnostics name it
    std::string importer;  // the key of the file whose import read it ("": the grammar)
    std::string written;   // that import's path, as written
    std::string text;
    int firstLine = 0;     // its line 1 is lines[firstLine - 1]
  };
  std::vector<Module> modules;
  // Import aliases declared outside this text (the REPL's earlier inputs): `alias.X` is one
  // name here too.
  std::vector<std::string> importAliases;
  // A `.cga` grammar: the rule each start shape (lot) gets instead of its @StartRule
  // (`fgsg run --start-rule NAME`); empty: the @StartRule.
  std::string startRule;

  // `text` may be a grammar with its modules (as `text` above): they are split off again.
  static SourceFile make(std::string name, std::string text);
  // The grammar's own text, without its modules.
  std::string mainText() const { return text.substr(0, mainLength_); }
  void addModule(Module m);
  // The file a line of the whole is in, and the line there.
  std::pair<std::string, int> locate(int line) const;

 private:
  size_t mainLength_ = std::string::npos;
};

enum class Severity { Error, Warning, Note };

struct Diagnostic {
  Severity severity = Severity::Error;
  std::string code;  // "E012"
  std::string message;
  SourceRange range;
};

class Diagnostics {
 public:
  explicit Diagnostics(const SourceFile* file) : file_(file) {}

  void error(const std::string& code, const SourceRange& at, std::string message);
  void warning(const std::string& code, const SourceRange& at, std::string message);
  void note(const SourceRange& at, std::string message);

  bool hasErrors() const { return errorCount_ > 0; }
  int errorCount() const { return errorCount_; }
  const std::vector<Diagnostic>& all() const { return list_; }

  // Prints every diagnostic in the order reported, each with its source line and caret.
  void print(std::ostream& out) const;
  std::string format(const Diagnostic& d) const;

 private:
  const SourceFile* file_;
  std::vector<Diagnostic> list_;
  int errorCount_ = 0;
};

}  // namespace fgsg::frontend
