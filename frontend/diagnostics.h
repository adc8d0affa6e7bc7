// Diagnostics for user errors in grammar text: `file:line:col: error[E012]: message`,
// then the source line and a caret under the column. Collected, never thrown, so one
// run reports every mistake it can find.
#pragma once

#include "frontend/ast.h"

#include <iosfwd>
#include <string>
#include <vector>

namespace fgsg::frontend {

struct SourceFile {
  std::string name;  // as given by the user, printed in diagnostics
  std::string text;
  std::vector<std::string> lines;  // filled by SourceFile::make

  static SourceFile make(std::string name, std::string text);
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
