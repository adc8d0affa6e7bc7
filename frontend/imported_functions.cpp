#include "frontend/imported_functions.h"

#include "frontend/ast_copy.h"
#include "frontend/did_you_mean.h"

#include <map>
#include <set>

namespace fgsg::frontend {

namespace {

class ImportedFunctionInliner {
 public:
  ImportedFunctionInliner(const std::string& alias, const Program& module, const std::string& modulePath,
                          Diagnostics& diags)
      : prefix_(alias + "."), path_(modulePath), diags_(diags) {
    for (const FunctionDecl& f : module.functions) functions_[f.name] = &f;
    for (const ValueDecl& v : module.values) values_.insert(v.name);  // `alias.x` already
  }

  void run(Program& p) {
    for (ValueDecl& v : p.values) expr(v.value);
    for (Rule& r : p.rules) {
      expr(r.guard);
      for (Branch& b : r.branches) {
        expr(b.probability);
        successor(b.successor);
      }
    }
    for (AxiomDecl& a : p.axioms) successor(a.successor);
    for (FunctionDecl& f : p.functions) expr(f.body);
  }

 private:
  void successor(Successor& s) {
    expr(s.size);
    for (Item& it : s.items) item(it);
  }

  void item(Item& it) {
    for (ExprPtr& a : it.args) expr(a);
    for (Successor& b : it.body) successor(b);
    for (Item& c : it.children) item(c);
  }

  void expr(ExprPtr& e) {
    if (!e) return;
    for (ExprPtr& a : e->args) expr(a);  // arguments first: F.f(F.g(1))
    const bool call = e->kind == ExprKind::Call;
    if ((!call && e->kind != ExprKind::Ident) || e->text.compare(0, prefix_.size(), prefix_) != 0) return;
    const std::string name = e->text.substr(prefix_.size());
    if (!call && values_.count(e->text)) return;  // the module's attr
    const auto found = functions_.find(name);
    if (found == functions_.end()) {
      if (!call) return;  // not the module's: sema says what it is not
      std::vector<std::string> names;
      for (const auto& [n, f] : functions_) names.push_back(n);
      const std::string near = closestName(name, names);
      diags_.error("E062", e->range,
                   "the module '" + path_ + "' has no function '" + name + "'" +
                       (near.empty() ? std::string() : "; did you mean '" + prefix_ + near + "'?"));
      return;
    }
    const FunctionDecl& f = *found->second;
    if (e->args.size() != f.params) {
      const std::string takes = std::to_string(f.params) + " argument" + (f.params == 1 ? "" : "s");
      diags_.error("E016", e->range,
                   "'" + e->text + "' takes " + takes + ", got " + std::to_string(e->args.size()) +
                       (call ? std::string() : " (write " + e->text + "(...))"));
      return;
    }
    if (!f.body) {
      if (reported_.insert(f.name).second) {
        diags_.error(f.errorCode, f.errorAt, f.error);
        diags_.note(e->range, "'" + e->text + "' is called here");
      }
      return;
    }
    if (copied_ > kMaxInlinedNodes) return;  // said once, at the call that went past it
    ExprPtr body = copyWithArguments(*f.body, e->args);
    if (copied_ > kMaxInlinedNodes) {
      diags_.error("E002", e->range,
                   "'" + e->text + "' expands to more than " + std::to_string(kMaxInlinedNodes) +
                       " expression nodes (a call's arguments are copied into the function's body at each use, "
                       "so nested calls multiply); compute the inner value once, in a const or attr");
      return;
    }
    body->range = e->range;
    e = std::move(body);
  }

  // Inlining copies each argument once per use of its parameter: calls nested n deep in a
  // body that uses its parameter twice are 2^n nodes. Past this many the file is refused.
  static constexpr size_t kMaxInlinedNodes = 1'000'000;

  // The body with each parameter "#k" replaced by a copy of argument k (counted in copied_;
  // past the limit the copy stops short and the caller refuses it).
  ExprPtr copyWithArguments(const Expr& from, const std::vector<ExprPtr>& args) {
    if (from.kind == ExprKind::Ident && from.text.size() > 1 && from.text[0] == '#') {
      const size_t k = std::stoul(from.text.substr(1));
      if (k < args.size()) return copyWithArguments(*args[k], {});
    }
    ++copied_;
    ExprPtr c = copyExprNode(from);
    for (const ExprPtr& a : from.args)
      c->args.push_back(a && copied_ <= kMaxInlinedNodes ? copyWithArguments(*a, args) : nullptr);
    return c;
  }

  std::string prefix_, path_;
  Diagnostics& diags_;
  std::map<std::string, const FunctionDecl*> functions_;
  std::set<std::string> values_;
  std::set<std::string> reported_;  // bodies whose error is said once
  size_t copied_ = 0;                // expression nodes inlined so far, in the whole importer
};

}  // namespace

void inlineImportedFunctions(Program& importer, const std::string& alias, const Program& module,
                             const std::string& modulePath, Diagnostics& diags) {
  if (alias.empty()) return;  // unqualified names: the importer's translator saw none of them
  ImportedFunctionInliner(alias, module, modulePath, diags).run(importer);
}

}  // namespace fgsg::frontend
