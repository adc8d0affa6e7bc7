// The session's operations: adding an input's statements (replacing what it redefines,
// then recompiling the whole session), evaluating a bare expression, deriving and
// exporting, attribute overrides. Reading statements: repl_statements.cpp; the
// assembled text and its diagnostics: repl_assemble.cpp.
#include "cli/repl_session.h"

#include "backend/interp/eval.h"
#include "backend/interp/interpreter.h"
#include "backend/native/code_loader.h"
#include "cli/derive_flags.h"
#include "cli/repl_statements.h"
#include "frontend/parse.h"
#include "ir/printer.h"
#include "runtime/assemble.h"
#include "runtime/io/read_lots.h"
#include "runtime/io/write_mesh.h"
#include "runtime/random.h"

#include <algorithm>
#include <iostream>

namespace fgsg::cli::repl {

using frontend::SourceFile;

namespace {

// The rule a bare expression is compiled into; its value is read from the IR.
const char* kEvalPrefix = "ReplEval__ ~> ReplValue__(";

bool hasQuery(const ir::Expr& e) {
  if (e.op == ir::ExprOp::Query || e.op == ir::ExprOp::Param) return true;
  for (const auto& a : e.args)
    if (hasQuery(a)) return true;
  return false;
}

}  // namespace

bool Session::addStatements(std::shared_ptr<const SourceFile> input, std::ostream& err) {
  // Syntax first, against the input alone, so positions are the input's own; `p.X` is one
  // name where an earlier input imported `as p`.
  {
    SourceFile alone = *input;
    for (const Statement& s : statements_)
      if (s.key.rfind("import:", 0) == 0) {
        const frontend::SourceFile one = SourceFile::make(s.origin->name, s.text + ";");
        frontend::Program p;
        frontend::Diagnostics quiet(&one);
        frontend::parseProgram(one, p, quiet);
        for (const auto& d : p.imports)
          if (!d.alias.empty()) alone.importAliases.push_back(d.alias);
      }
    frontend::Program program;
    frontend::Diagnostics diags(&alone);
    if (!frontend::parseProgram(alone, program, diags)) {
      for (const auto& d : diags.all()) err << diags.format(d) << "\n";
      return false;
    }
  }
  // Split into statements at each top-level ';' (explicit or implicit).
  int priority = priority_;
  std::vector<Statement> added = splitStatements(input, priority);

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
  opt.lots = lots_;
  opt.lotsName = lotsName_;
  if (maxDepth > 0) opt.maxDepth = maxDepth;
  opt.parallelStep = step_;
  {
    std::string error, warning;
    if (!checkStepFlag(*module_, "the session grammar", opt, error, warning, ":step")) {
      err << "error: " << error << " (:step off to derive it)\n";
      return false;
    }
    if (!warning.empty()) err << "warning: " << warning << "\n";
  }
  rt::AssetLibrary assets;
  for (const char* dir : {".", "assets"}) {
    assets.addSearchDir(dir);
    opt.assetDirs.push_back(dir);
  }
  if (engine_ == backend::Engine::Jit && !code_) code_ = std::make_shared<backend::native::CodeLoader>();
  result = backend::derive(engine_, *module_, assembled_.source.text, opt, assets, nullptr, code_.get());
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

bool Session::setLots(const std::string& path, std::string& error) {
  std::vector<rt::Lot> lots;
  size_t skipped = 0;
  if (!path.empty() && !rt::readLots(path, lots, skipped, error)) return false;
  lots_ = std::move(lots);
  lotsName_ = path;
  return true;
}

void Session::reset() {
  statements_.clear();
  module_.reset();
  assembled_ = Assembled{};
  priority_ = 0;
  seed_ = 1;
  step_ = -1;
  overrides_.clear();
  lots_.clear();
  lotsName_.clear();
}

}  // namespace fgsg::cli::repl
