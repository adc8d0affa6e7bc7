// The grammar an `fgsg repl` session builds up, one input at a time.
//
// The session is a list of statements (their source text, as typed) keyed by what they
// define: `rule:P` for every rule of predecessor P, `value:x` for `const x`/`attr x`,
// `axiom`, `surface`, `field:F` ... An input's statements replace the session's
// statements with the same keys (a rule for P replaces every earlier rule for P; the
// rules for P in one input add up), in the place of the first replaced one, otherwise
// they are appended. After every input the whole session is reassembled into one text
// and compiled from scratch with ir::compileSource; a rejected input leaves the session
// as it was. Diagnostics are mapped back to the input (`<repl:N>`) or file they came from.
#pragma once

#include "backend/engine.h"
#include "backend/native/code_loader.h"
#include "frontend/diagnostics.h"
#include "ir/ir.h"
#include "runtime/derivation.h"

#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace fgsg::cli::repl {

struct Statement {
  std::string key;   // what it defines: "rule:P", "value:x", "axiom", ...
  std::string text;  // the source text, without its ';'
  int priority = 0;  // rules: the `priority N:` in force where it was written
  std::shared_ptr<const frontend::SourceFile> origin;  // the input or file it came from
  int line = 1, col = 1;  // where the text starts in `origin`
};

// Where one statement sits in the assembled text, to map diagnostics back.
struct Segment {
  int firstLine = 0, lineCount = 0;  // in the assembled text
  int colShift = 0;                  // subtracted from columns on the first line
  std::shared_ptr<const frontend::SourceFile> origin;
  int originLine = 1;
};

struct Assembled {
  frontend::SourceFile source;
  std::vector<Segment> segments;
};

class Session {
 public:
  // Adds the statements of `input` (named like `<repl:3>` or a file path). Prints the
  // diagnostics to `err`; false (session unchanged) when the input is rejected.
  bool addStatements(std::shared_ptr<const frontend::SourceFile> input, std::ostream& err);
  // Evaluates a bare expression with the session's constants and attributes and
  // writes its value ("3", "true", "\"a\"", "(1, 2, 3)") into `value`.
  bool evaluate(std::shared_ptr<const frontend::SourceFile> input, std::string& value,
                std::ostream& err);
  // Derives the current grammar; false after printing errors. `maxDepth` 0: no limit.
  bool derive(uint32_t maxDepth, rt::DeriveResult& result, size_t& triangles,
              std::ostream& err, const std::string& exportPath = "");

  bool setAttribute(const std::string& name, const std::string& value, std::string& error);
  void setSeed(uint64_t seed) { seed_ = seed; }
  // :step N: later derivations of an L-system stop after step N (fgsg run --step); -1
  // (:step off): its whole length.
  void setStep(int32_t step) { step_ = step; }
  int32_t step() const { return step_; }
  // :lots FILE: the axiom derives once per lot of a GeoJSON file (as fgsg run --lots);
  // an empty path goes back to one derivation. False with the file's problem in `error`.
  bool setLots(const std::string& path, std::string& error);
  size_t lotCount() const { return lots_.size(); }
  // The JIT (default) compiles the session's current text for every :derive (from the
  // object cache when it is unchanged), so a redefined rule never runs stale code.
  void setEngine(backend::Engine engine) { engine_ = engine; }
  void reset();

  // The session grammar as one .fgsg text that `fgsg run` reads.
  std::string grammarText() const;
  const std::vector<Statement>& statements() const { return statements_; }
  const ir::Module* module() const { return module_.get(); }
  const std::vector<std::pair<std::string, std::string>>& overrides() const { return overrides_; }

  // True when `text` is a statement input (declaration or rule), false when it would be
  // read as an expression.
  static bool looksLikeStatements(const std::string& text);

 private:
  Assembled assemble(const std::vector<Statement>& list, bool valuesOnly) const;
  bool compile(const Assembled& a, ir::Module& out, std::ostream& err,
               const frontend::SourceFile* warningsFor) const;
  void printMapped(const Assembled& a, const frontend::Diagnostic& d, std::ostream& err) const;

  std::vector<Statement> statements_;
  std::unique_ptr<ir::Module> module_;  // the last good compile of statements_
  Assembled assembled_;                 // and the text it was compiled from
  int priority_ = 0;                    // the `priority N:` in force for the next rule
  uint64_t seed_ = 1;
  int32_t step_ = -1;  // rt::DeriveOptions::parallelStep
  backend::Engine engine_ = backend::Engine::Jit;
  // One code loader (and JIT) for the session, made at the first :derive: its optimising
  // compiles for the cache run while the user types.
  std::shared_ptr<backend::native::CodeLoader> code_;
  std::vector<std::pair<std::string, std::string>> overrides_;
  std::vector<rt::Lot> lots_;
  std::string lotsName_;
};

}  // namespace fgsg::cli::repl
