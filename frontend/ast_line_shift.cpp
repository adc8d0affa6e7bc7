#include "frontend/ast_line_shift.h"

namespace fgsg::frontend {

namespace {

// A place with line 0 is "none written" (a selector's when there is none): it stays so.
void shiftRangeLines(SourceRange& r, int lines) {
  if (r.begin.line > 0) r.begin.line += lines;
  if (r.end.line > 0) r.end.line += lines;
}

void shiftExprLines(Expr* e, int lines) {
  if (!e) return;
  shiftRangeLines(e->range, lines);
  for (auto& a : e->args) shiftExprLines(a.get(), lines);
}

void shiftSuccessorLines(Successor& s, int lines);

void shiftItemLines(Item& item, int lines) {
  shiftRangeLines(item.range, lines);
  for (auto& a : item.args) shiftExprLines(a.get(), lines);
  for (Successor& part : item.body) shiftSuccessorLines(part, lines);
  for (Item& child : item.children) shiftItemLines(child, lines);
}

void shiftSuccessorLines(Successor& s, int lines) {
  shiftRangeLines(s.range, lines);
  shiftRangeLines(s.selectorRange, lines);
  shiftExprLines(s.size.get(), lines);
  for (Item& item : s.items) shiftItemLines(item, lines);
}

void shiftPatternLines(ModulePattern& m, int lines) {
  shiftRangeLines(m.range, lines);
  for (ParamDecl& p : m.params) shiftRangeLines(p.range, lines);
}

}  // namespace

void shiftLines(Rule& rule, int lines) {
  if (lines == 0) return;
  shiftRangeLines(rule.range, lines);
  for (ModulePattern& m : rule.leftContext) shiftPatternLines(m, lines);
  shiftPatternLines(rule.predecessor, lines);
  for (ModulePattern& m : rule.rightContext) shiftPatternLines(m, lines);
  shiftExprLines(rule.guard.get(), lines);
  for (Branch& b : rule.branches) {
    shiftRangeLines(b.range, lines);
    shiftSuccessorLines(b.successor, lines);
    shiftExprLines(b.probability.get(), lines);
  }
}

void shiftLines(ValueDecl& value, int lines) {
  if (lines == 0) return;
  shiftRangeLines(value.range, lines);
  shiftExprLines(value.value.get(), lines);
}

}  // namespace fgsg::frontend
