// Compiling a test grammar's text to IR and keeping its diagnostics as printed: shared by
// the `.cga` dialect's front-end tests (dialect, envelope, imported functions, styles).
#pragma once

#include "ir/ir.h"
#include "ir/pipeline.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

namespace fgsg::frontend::test {

struct CgaCompiled {
  bool ok = false;
  ir::Module module;
  std::string messages;  // file:line:col, the line and a caret, as `fgsg check` prints them
  bool says(const std::string& text) const { return messages.find(text) != std::string::npos; }
};

// `text` read as the file `name` (its dialect from the extension), started by `startRule`
// (--start-rule's `Style$Rule`; empty: the file's own).
inline CgaCompiled compileGrammarText(const std::string& text, const std::string& name = "test.cga",
                                      const std::string& startRule = "") {
  CgaCompiled c;
  SourceFile file = SourceFile::make(name, text);
  file.startRule = startRule;
  Diagnostics diags(&file);
  c.ok = ir::compileSource(file, c.module, diags);
  std::ostringstream out;
  diags.print(out);
  c.messages = out.str();
  return c;
}

// A file a test grammar imports, written into `dir` (made if missing).
// Written to a temporary file and renamed: ctest runs each test case as its own process,
// two at a time, and a case reading the file while another truncates it saw it empty.
inline void writeImportedFile(const std::string& dir, const std::string& name, const std::string& text) {
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/" + name;
  const std::string temporary = path + ".tmp" + std::to_string(::getpid());
  std::ofstream(temporary) << text;
  std::filesystem::rename(temporary, path);
}

}  // namespace fgsg::frontend::test
