#include "cli/repl_session.h"

#include "backend/interp/eval.h"
#include "backend/interp/interpreter.h"
#include "backend/jit/jit.h"
#include "frontend/lex.h"
#include "frontend/parse.h"
#include "ir/pipeline.h"
#include "ir/printer.h"
#include "runtime/assemble.h"
#include "runtime/io/write_mesh.h"
#include "runtime/random.h"

#include <algorithm>
#include <charconv>
#include <iostream>
#include <sstream>

namespace fgsg::cli::repl {

using fgsg_grammar::FgsgLexer;
using frontend::SourceFile;
using frontend::SourceLoc;

namespace {

// The rule a bare expression is compiled into; its value is read from the IR.
const char* kEvalPrefix = "ReplEval__ ~> ReplValue__(";

// Byte offset of 1-based character column `col` in a UTF-8 line.
size_t byteOffset(const std::string& line, int col) {
  size_t i = 0;
  for (int c = 1; c < col && i < line.size(); ++c) {
    ++i;
    while (i < line.size() && (static_cast<unsigned char>(line[i]) & 0xC0) == 0x80) ++i;
  }
  return i;
}

// The text from `begin` to `end` (inclusive, character columns).
std::string slice(const SourceFile& f, SourceLoc begin, SourceLoc end) {
  std::string out;
  for (int l = begin.line; l <= end.line && l <= static_cast<int>(f.lines.size()); ++l) {
    const std::string& line = f.lines[l - 1];
    const size_t from = l == begin.line ? byteOffset(line, begin.col) : 0;
    size_t to = line.size();
    if (l == end.line) {
      to = byteOffset(line, end.col + 1);
    }
    if (l != begin.line) out += '\n';
    if (from < to) out += line.substr(from, to - from);
  }
  return out;
}

struct Lexed {
  frontend::LexedSource lexed;
  std::vector<const antlr4::Token*> tokens;  // without EOF
};

Lexed lexQuietly(const SourceFile& f) {
  Lexed out;
  frontend::Diagnostics ignored(&f);
  out.lexed = frontend::lexSource(f, ignored);
  for (const auto& t : out.lexed.tokens)
    if (t->getType() != antlr4::Token::EOF) out.tokens.push_back(t.get());
  return out;
}

bool isDeclKeyword(size_t type) {
  switch (type) {
    case FgsgLexer::CONST: case FgsgLexer::ATTR: case FgsgLexer::SURFACE: case FgsgLexer::FIELD:
    case FgsgLexer::TEXTURE: case FgsgLexer::DERIVE: case FgsgLexer::TURTLE:
    case FgsgLexer::COLLISION: case FgsgLexer::AXIOM: case FgsgLexer::PRIORITY:
      return true;
    default:
      return false;
  }
}

bool hasQuery(const ir::Expr& e) {
  if (e.op == ir::ExprOp::Query || e.op == ir::ExprOp::Param) return true;
  for (const auto& a : e.args)
    if (hasQuery(a)) return true;
  return false;
}

// Whether the statements contain a rule or an axiom, something to derive from.
bool hasStart(const std::vector<Statement>& list) {
  for (const Statement& s : list)
    if (s.key == "axiom" || s.key.rfind("rule:", 0) == 0) return true;
  return false;
}

}  // namespace

bool Session::looksLikeStatements(const std::string& text) {
  const SourceFile f = SourceFile::make("<repl>", text);
  Lexed l = lexQuietly(f);
  if (l.tokens.empty()) return true;  // only comments: nothing to add
  if (isDeclKeyword(l.tokens[0]->getType())) return true;
  if (l.tokens.size() > 1 && l.tokens[0]->getType() == FgsgLexer::INT &&
      l.tokens[1]->getType() == FgsgLexer::COLON)
    return true;
  for (const auto* t : l.tokens)
    if (t->getType() == FgsgLexer::ARROW || t->getType() == FgsgLexer::ASSIGN) return true;
  return false;
}

Assembled Session::assemble(const std::vector<Statement>& list, bool valuesOnly) const {
  std::string text;
  Assembled a;
  int line = 1;
  int priority = 0;
  for (const Statement& s : list) {
    const bool isRule = s.key.rfind("rule:", 0) == 0;
    if (valuesOnly && s.key.rfind("value:", 0) != 0) continue;
    if (isRule && s.priority != priority) {
      text += "priority " + std::to_string(s.priority) + ":\n";
      ++line;
      priority = s.priority;
    }
    Segment seg;
    seg.firstLine = line;
    seg.lineCount = 1 + static_cast<int>(std::count(s.text.begin(), s.text.end(), '\n'));
    seg.origin = s.origin;
    seg.originLine = s.line;
    seg.colShift = 0;
    a.segments.push_back(seg);
    text += std::string(static_cast<size_t>(std::max(0, s.col - 1)), ' ') + s.text + ";\n";
    line += seg.lineCount;
  }
  // Declarations alone are not a grammar yet (E024): a placeholder start keeps them
  // compilable, outside every segment, so it never shows in a diagnostic.
  if (!valuesOnly && !hasStart(list)) text += "ReplEmpty__ ~> epsilon;\n";
  a.source = SourceFile::make("<session>", text);
  return a;
}

std::string Session::grammarText() const {
  std::string text = "// written by fgsg repl\n";
  int priority = 0;
  for (const Statement& s : statements_) {
    if (s.key.rfind("rule:", 0) == 0 && s.priority != priority) {
      text += "priority " + std::to_string(s.priority) + ":\n";
      priority = s.priority;
    }
    text += s.text + ";\n";
  }
  return text;
}

void Session::printMapped(const Assembled& a, const frontend::Diagnostic& d,
                          std::ostream& err) const {
  frontend::Diagnostic mapped = d;
  const SourceFile* file = &a.source;
  for (const Segment& s : a.segments) {
    const int l = d.range.begin.line;
    if (l >= s.firstLine && l < s.firstLine + s.lineCount) {
      auto shift = [&](SourceLoc& loc) {
        if (loc.line == s.firstLine) loc.col = std::max(1, loc.col - s.colShift);
        loc.line = loc.line - s.firstLine + s.originLine;
      };
      shift(mapped.range.begin);
      if (d.range.end.line >= s.firstLine && d.range.end.line < s.firstLine + s.lineCount)
        shift(mapped.range.end);
      else
        mapped.range.end = mapped.range.begin;
      file = s.origin.get();
      break;
    }
  }
  frontend::Diagnostics one(file);
  err << one.format(mapped) << "\n";
}

bool Session::compile(const Assembled& a, ir::Module& out, std::ostream& err,
                      const SourceFile* warningsFor) const {
  frontend::Diagnostics diags(&a.source);
  const bool ok = ir::compileSource(a.source, out, diags);
  for (const auto& d : diags.all()) {
    if (d.severity != frontend::Severity::Error) {
      // Warnings of earlier inputs were shown when they were typed.
      bool mine = false;
      for (const Segment& s : a.segments)
        if (d.range.begin.line >= s.firstLine && d.range.begin.line < s.firstLine + s.lineCount)
          mine = s.origin.get() == warningsFor;
      if (!mine || !warningsFor) continue;
    }
    printMapped(a, d, err);
  }
  return ok;
}

bool Session::addStatements(std::shared_ptr<const SourceFile> input, std::ostream& err) {
  // Syntax first, against the input alone, so positions are the input's own.
  {
    frontend::Program program;
    frontend::Diagnostics diags(input.get());
    if (!frontend::parseProgram(*input, program, diags)) {
      for (const auto& d : diags.all()) err << diags.format(d) << "\n";
      return false;
    }
  }
  // Split into statements at each top-level ';' (explicit or implicit).
  Lexed l = lexQuietly(*input);
  std::vector<Statement> added;
  int priority = priority_;
  size_t i = 0;
  while (i < l.tokens.size()) {
    const size_t start = i;
    const size_t type = l.tokens[start]->getType();
    if (type == FgsgLexer::SEMI) {
      ++i;
      continue;
    }
    if (type == FgsgLexer::PRIORITY) {  // priority [-] INT :
      size_t j = i + 1;
      bool negative = false;
      if (j < l.tokens.size() && l.tokens[j]->getType() == FgsgLexer::MINUS) negative = true, ++j;
      // A level that is not a small integer keeps the current one: compiling the
      // statement reports it (E002), so no exception may escape here.
      int level = 0;
      if (j < l.tokens.size()) {
        const std::string digits = l.tokens[j]->getText();
        auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), level);
        if (ec == std::errc() && end == digits.data() + digits.size()) priority = negative ? -level : level;
      }
      i = j + 2;
      continue;
    }
    int braces = 0;
    size_t end = i;
    for (; end < l.tokens.size(); ++end) {
      const size_t t = l.tokens[end]->getType();
      if (type == FgsgLexer::FIELD && t == FgsgLexer::LBRACE) ++braces;
      if (type == FgsgLexer::FIELD && t == FgsgLexer::RBRACE) braces = std::max(0, braces - 1);
      if (t == FgsgLexer::SEMI && braces == 0) break;
    }
    const size_t last = end - 1;  // the last token of the statement
    i = end + 1;
    Statement s;
    s.origin = input;
    const frontend::SourceRange first = frontend::tokenRange(l.tokens[start]);
    const frontend::SourceRange lastRange = frontend::tokenRange(l.tokens[last]);
    s.line = first.begin.line;
    s.col = first.begin.col;
    s.text = slice(*input, first.begin, lastRange.end);
    s.priority = priority;
    auto nameAfter = [&](const char* kind) {
      return std::string(kind) + (start + 1 < end ? l.tokens[start + 1]->getText() : "");
    };
    switch (type) {
      case FgsgLexer::CONST: case FgsgLexer::ATTR: s.key = nameAfter("value:"); break;
      case FgsgLexer::FIELD: s.key = nameAfter("field:"); break;
      case FgsgLexer::TEXTURE: s.key = nameAfter("texture:"); break;
      case FgsgLexer::SURFACE: s.key = "surface"; break;
      case FgsgLexer::DERIVE: s.key = "derive"; break;
      case FgsgLexer::TURTLE: s.key = "turtle"; break;
      case FgsgLexer::COLLISION: s.key = "collision"; break;
      case FgsgLexer::AXIOM: s.key = "axiom"; break;
      default: {
        // A rule: parse it alone to learn its predecessor (labels and contexts included).
        const SourceFile one = SourceFile::make(input->name, s.text);
        frontend::Program p;
        frontend::Diagnostics d(&one);
        frontend::parseProgram(one, p, d);
        s.key = "rule:" + (p.rules.empty() ? s.text : p.rules[0].predecessor.name);
      }
    }
    added.push_back(std::move(s));
  }

  // Replace what the input redefines, in place of the first replaced statement.
  std::vector<Statement> next;
  std::vector<bool> placed(added.size(), false);
  for (const Statement& old : statements_) {
    bool replaced = false;
    for (size_t k = 0; k < added.size(); ++k) {
      if (added[k].key != old.key) continue;
      replaced = true;
      if (!placed[k]) {
        for (size_t m = k; m < added.size(); ++m)
          if (added[m].key == old.key && !placed[m]) next.push_back(added[m]), placed[m] = true;
      }
    }
    if (!replaced) next.push_back(old);
  }
  for (size_t k = 0; k < added.size(); ++k)
    if (!placed[k]) next.push_back(added[k]);

  Assembled a = assemble(next, false);
  auto module = std::make_unique<ir::Module>();
  if (!compile(a, *module, err, input.get())) return false;
  statements_ = std::move(next);
  module_ = std::move(module);
  assembled_ = std::move(a);
  priority_ = priority;
  // Overrides of attributes that no longer exist are dropped.
  overrides_.erase(std::remove_if(overrides_.begin(), overrides_.end(),
                                  [&](const auto& o) { return module_->findAttr(o.first) < 0; }),
                   overrides_.end());
  return true;
}

bool Session::evaluate(std::shared_ptr<const SourceFile> input, std::string& value,
                       std::ostream& err) {
  Assembled a = assemble(statements_, true);
  std::string text = a.source.text;
  Segment seg;
  seg.firstLine = 1 + static_cast<int>(std::count(text.begin(), text.end(), '\n'));
  seg.lineCount = static_cast<int>(input->lines.size());
  seg.colShift = static_cast<int>(std::string(kEvalPrefix).size());
  seg.origin = input;
  text += kEvalPrefix + input->text + "\n);\n";
  a.source = SourceFile::make("<session>", text);
  a.segments.push_back(seg);
  ir::Module m;
  if (!compile(a, m, err, nullptr)) return false;
  const int sym = m.findSymbol("ReplEval__");
  const ir::Expr* e = nullptr;
  if (sym >= 0 && !m.symbols[sym].rules.empty()) {
    for (const auto& op : m.rules[m.symbols[sym].rules[0]].alternatives.at(0).ops)
      if (op.kind == ir::OpKind::Emit && !op.args.empty()) e = &op.args[0];
  }
  if (!e) {
    err << input->name << ": error: not an expression\n";
    return false;
  }
  if (hasQuery(*e)) {
    err << input->name << ": error: this expression asks about a shape (Scope, Shape, fields): "
        << "it can only be evaluated in a rule\n";
    return false;
  }
  try {
    backend::Evaluator ev(m, backend::attributeSlots(m, overrides_));
    rt::RandomStream rng{rt::rootKey(seed_), 0};
    backend::Frame f;
    f.rng = &rng;
    switch (e->type) {
      case ir::Type::Num: value = ir::printNumber(ev.num(*e, f)); break;
      case ir::Type::Bool: value = ev.truth(*e, f) ? "true" : "false"; break;
      case ir::Type::Str: value = "\"" + ev.string(ev.num(*e, f)) + "\""; break;
      case ir::Type::Vec3: {
        const rt::Vec3 v = ev.vec(*e, f);
        value = "(" + ir::printNumber(v.x()) + ", " + ir::printNumber(v.y()) + ", " +
                ir::printNumber(v.z()) + ")";
        break;
      }
    }
  } catch (const backend::DeriveError& ex) {
    err << input->name << ": error[" << ex.code << "]: " << ex.message << "\n";
    return false;
  }
  return true;
}

bool Session::derive(uint32_t maxDepth, rt::DeriveResult& result, size_t& triangles,
                     std::ostream& err, const std::string& exportPath) {
  if (!module_ || !hasStart(statements_)) {
    err << "error: the session has no rules or axiom to derive yet\n";
    return false;
  }
  rt::DeriveOptions opt;
  opt.seed = seed_;
  opt.attrOverrides = overrides_;
  if (maxDepth > 0) opt.maxDepth = maxDepth;
  rt::AssetLibrary assets;
  for (const char* dir : {".", "assets"}) {
    assets.addSearchDir(dir);
    opt.assetDirs.push_back(dir);
  }
  if (engine_ == backend::Engine::Jit && !jit_) {
    try {
      jit_ = std::make_shared<backend::jit::Jit>();
    } catch (const std::exception& e) {
      err << "error: the JIT cannot start: " << e.what() << " (fgsg repl --engine=interp runs without it)\n";
      return false;
    }
  }
  result = backend::derive(engine_, *module_, assembled_.source.text, opt, assets, nullptr, jit_.get());
  bool ok = true;
  for (const auto& m : result.messages) {
    frontend::Diagnostic d;
    d.severity = m.isError ? frontend::Severity::Error : frontend::Severity::Warning;
    d.code = m.code;
    d.message = m.message;
    d.range = {{m.line, m.col}, {m.line, m.col}};
    printMapped(assembled_, d, err);
    if (m.isError) ok = false;
  }
  if (!ok) return false;
  std::vector<int> meshOf;
  std::string error;
  if (!rt::resolveAssets(result.instances, assets, meshOf, error)) {
    err << "error: " << error << "\n";
    return false;
  }
  if (exportPath.empty()) {
    triangles = rt::countTriangles(result.instances, assets, meshOf);
    return true;
  }
  rt::Mesh mesh = rt::assembleInstances(result.instances, assets, meshOf);
  triangles = mesh.triangleCount();
  if (!rt::io::writeMesh(mesh, exportPath, error)) {
    err << "error: " << error << "\n";
    return false;
  }
  return true;
}

bool Session::setAttribute(const std::string& name, const std::string& value, std::string& error) {
  if (!module_ || module_->findAttr(name) < 0) {
    error = "no attribute '" + name + "' in the session (declare it with `attr " + name + " = ...;`)";
    return false;
  }
  auto next = overrides_;
  next.erase(std::remove_if(next.begin(), next.end(), [&](const auto& o) { return o.first == name; }),
             next.end());
  next.push_back({name, value});
  try {
    ir::Module copy = *module_;
    backend::attributeSlots(copy, next);
  } catch (const backend::DeriveError& ex) {
    error = ex.message;
    return false;
  }
  overrides_ = std::move(next);
  return true;
}

void Session::reset() {
  statements_.clear();
  module_.reset();
  assembled_ = Assembled{};
  priority_ = 0;
  seed_ = 1;
  overrides_.clear();
}

}  // namespace fgsg::cli::repl
