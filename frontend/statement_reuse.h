// Statement reuse for re-parsing an edited grammar (fgsg lsp, #50): a parse records, for
// each rule and attr/const statement it parsed cleanly, a key made of the statement's
// tokens (type, text, line from the statement's first, column, offsets), its lpfg section
// and the `priority` in force, and where its AST went in the Program and on which line. The next parse, given that Program, moves the AST
// of a statement whose key comes again instead of parsing it: the same tokens in the same
// places and context give the same AST, moved by as many lines as the statement moved
// (frontend/ast_line_shift.h), so the result is the one a fresh parse would give.
// A statement that had a syntax error or any diagnostic is never recorded, so its errors are
// always reported anew.
#pragma once

#include "frontend/ast.h"
#include "frontend/ast_line_shift.h"
#include "frontend/diagnostics.h"

#include <memory>
#include <string>
#include <unordered_map>

namespace fgsg::frontend {

class IncrementalLexCache;  // frontend/incremental_lex.h

// Where one recorded statement's AST is in the Program it was parsed into.
struct ReusableStatementSlot {
  bool isRule = false;  // in `rules`, else in `values`
  size_t index = 0;
  int firstLine = 0;  // the line of the statement's first token
};
using ReusableStatementIndex = std::unordered_map<std::string, ReusableStatementSlot>;

class StatementReuse {
 public:
  // The statements of `previous` (parsed with `recorded` as its index) may be moved out of
  // it by the next parse: `previous` must not be used afterwards except to destroy it.
  void offer(Program& previous, ReusableStatementIndex recorded) {
    previous_ = &previous;
    offered_ = std::move(recorded);
  }
  // The index of the statements the last parse put in its Program.
  ReusableStatementIndex takeRecorded() { return std::move(recorded_); }

  // The raw tokens of the previous text (incremental lexing, frontend/incremental_lex.h):
  // offered with the statements, taken back after the parse for the next one.
  void offerTokens(std::shared_ptr<IncrementalLexCache> tokens) { tokens_ = std::move(tokens); }
  std::shared_ptr<IncrementalLexCache> takeTokens() { return std::move(tokens_); }
  IncrementalLexCache& tokens();  // for the parser; an empty cache when none was offered

  // How many statements the last parse took over instead of parsing (tests, the bench).
  size_t reusedCount() const { return reused_; }

  // For the parser (frontend/parse.cpp): moves the AST recorded under `key` into `out`,
  // to the statement's `firstLine` now, and records it there; false when there is none.
  bool reuse(const std::string& key, Program& out, int firstLine) {
    if (!previous_) return false;
    const auto it = offered_.find(key);
    if (it == offered_.end()) return false;
    const ReusableStatementSlot slot = it->second;
    offered_.erase(it);  // moved once: the slot is empty after
    if (slot.isRule) {
      if (slot.index >= previous_->rules.size()) return false;
      out.rules.push_back(std::move(previous_->rules[slot.index]));
      shiftLines(out.rules.back(), firstLine - slot.firstLine);
    } else {
      if (slot.index >= previous_->values.size()) return false;
      out.values.push_back(std::move(previous_->values[slot.index]));
      shiftLines(out.values.back(), firstLine - slot.firstLine);
    }
    record(key, slot.isRule, out, firstLine);
    ++reused_;
    return true;
  }
  // For the parser: the statement just parsed into `out` (its last rule or value), whose
  // first token is on `firstLine`, has `key`.
  void record(const std::string& key, bool isRule, const Program& out, int firstLine) {
    recorded_[key] = ReusableStatementSlot{isRule, (isRule ? out.rules.size() : out.values.size()) - 1, firstLine};
  }

 private:
  Program* previous_ = nullptr;
  ReusableStatementIndex offered_;
  ReusableStatementIndex recorded_;
  size_t reused_ = 0;
  std::shared_ptr<IncrementalLexCache> tokens_;
};

// parseProgram (frontend/parse.h) with statements taken over from `reuse`'s previous parse
// where their tokens did not change; records this parse's statements in `reuse`.
bool parseProgramReusing(const SourceFile& file, Program& out, Diagnostics& diags, StatementReuse& reuse);

}  // namespace fgsg::frontend
