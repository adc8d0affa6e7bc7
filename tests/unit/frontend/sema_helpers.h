// Parsing and analysing a grammar in a test, and finding its diagnostics: shared by the
// declaration tests (test_environment.cpp, test_tilesets.cpp).
#pragma once

#include "frontend/parse.h"
#include "frontend/sema.h"

#include <catch2/catch.hpp>

#include <sstream>
#include <string>
#include <vector>

namespace fgsg::frontend::test {

struct Analysed {
  SourceFile file;
  Program program;
  SemaResult sema;
  std::vector<Diagnostic> diags;
  std::string printed;
  bool ok = false;
};

inline Analysed analyse(const std::string& text) {
  Analysed a;
  a.file = SourceFile::make("t.fgsg", text);
  Diagnostics diags(&a.file);
  REQUIRE(parseProgram(a.file, a.program, diags));
  a.ok = analyze(a.program, a.sema, diags);
  a.diags = diags.all();
  std::ostringstream out;
  diags.print(out);
  a.printed = out.str();
  return a;
}

// A grammar with a rule, so that only the declarations can be wrong.
inline Analysed declarations(const std::string& decls) { return analyse(decls + "\nA ~> I(\"cube\");"); }

// Exactly one error, with this code at line:col, whose message contains `words`.
inline void onlyError(const Analysed& a, const std::string& code, int line, int col,
               const std::string& words = "") {
  INFO(a.printed);
  CHECK_FALSE(a.ok);
  int errors = 0;
  for (const auto& d : a.diags) errors += d.severity == Severity::Error;
  CHECK(errors == 1);
  bool found = false;
  for (const auto& d : a.diags)
    if (d.code == code && d.range.begin.line == line && d.range.begin.col == col &&
        d.message.find(words) != std::string::npos)
      found = true;
  CHECK(found);
}

inline bool has(const Analysed& a, const std::string& code, int line, int col) {
  for (const auto& d : a.diags)
    if (d.code == code && d.range.begin.line == line && d.range.begin.col == col) return true;
  return false;
}

}  // namespace fgsg::frontend::test
