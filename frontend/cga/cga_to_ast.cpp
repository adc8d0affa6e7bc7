// The `.cga` dialect's declarations and rules: attrs, consts and functions, imports, the
// start rule, and rule bodies — `case` chains (the first condition that holds wins, as in
// CityEngine: each branch is guarded by its condition and the negation of every condition
// before it) and stochastic choices (`30% : A 20% : B else : C`: weights 0.3, 0.2, 0.5).
// A choice nested inside another's branch becomes a rule of a helper symbol `Name$n`
// with the same parameters, created in its place.
#include "frontend/cga/cga_translator.h"
#include "frontend/did_you_mean.h"
#include "ir/pinned_attr.h"

#include <cmath>

namespace fgsg::frontend::cga {

SourceRange rangeOf(const antlr4::Token* t) {
  SourceRange r;
  r.begin = {int(t->getLine()), int(t->getCharPositionInLine()) + 1};
  const std::string text = t->getText();
  size_t chars = 0;
  for (unsigned char c : text) chars += (c & 0xC0) != 0x80;
  r.end = {r.begin.line, r.begin.col + int(chars > 0 ? chars - 1 : 0)};
  return r;
}

SourceRange rangeOf(const antlr4::ParserRuleContext* constCtx) {
  auto* ctx = const_cast<antlr4::ParserRuleContext*>(constCtx);  // ANTLR's getters are not const
  SourceRange r = rangeOf(ctx->getStart());
  const antlr4::Token* stop = ctx->getStop();
  if (stop && stop->getTokenIndex() >= ctx->getStart()->getTokenIndex()) r.end = rangeOf(stop).end;
  return r;
}

ExprPtr makeExpr(ExprKind kind, const SourceRange& at) {
  auto e = std::make_unique<Expr>();
  e->kind = kind;
  e->range = at;
  return e;
}

ExprPtr number(double v, const SourceRange& at) {
  ExprPtr e = makeExpr(ExprKind::Number, at);
  e->number = v;
  return e;
}

ExprPtr binary(const std::string& op, ExprPtr a, ExprPtr b) {
  ExprPtr e = makeExpr(ExprKind::Binary, SourceRange{a->range.begin, b->range.end});
  e->text = op;
  e->args.push_back(std::move(a));
  e->args.push_back(std::move(b));
  return e;
}

ExprPtr unaryNot(ExprPtr a) {
  ExprPtr e = makeExpr(ExprKind::Unary, a->range);
  e->text = "!";
  e->args.push_back(std::move(a));
  return e;
}

ExprPtr conjunction(ExprPtr a, ExprPtr b) {
  if (!a) return b;
  if (!b) return a;
  return binary("&&", std::move(a), std::move(b));
}

std::string stringValue(const std::string& token) {
  std::string out;
  for (size_t i = 1; i + 1 < token.size(); ++i) {
    if (token[i] == '\\' && i + 2 < token.size()) {
      const char c = token[++i];
      out += c == 'n' ? '\n' : c == 't' ? '\t' : c;
    } else {
      out += token[i];
    }
  }
  return out;
}

namespace {

ExprPtr clone(const ExprPtr& e) { return e ? cloneExpr(*e) : nullptr; }

// The side length of the square lot a `.cga` grammar starts on without --lots (metres).
constexpr double kDefaultLotSide = 20.0;

}  // namespace

void Translator::run(P::CgaFileContext* file) {
  program_.cityEngineLots = true;
  // `--start-rule Winter$Lot`: the rule Lot in the style Winter (cga_styles.cpp).
  if (const size_t mark = startRuleOverride_.find('$'); mark != std::string::npos && mark > 0) {
    chosenStyle_ = startRuleOverride_.substr(0, mark);
    startRuleOverride_ = startRuleOverride_.substr(mark + 1);
  }
  readStyles(file);
  collect(file);
  for (P::DeclarationContext* d : file->declaration()) {
    if (auto* v = d->versionDecl()) {
      (void)v;  // any version: the dialect is CityEngine's current CGA
    } else if (auto* dialect = d->dialectDecl()) {
      if (dialect->ID()->getText() != "cga")
        error("E002", rangeOf(dialect), "this file is read as CityEngine CGA: `dialect cga;` is the only dialect here");
    } else if (auto* imp = d->importDecl()) {
      importDecl(imp);
    } else if (auto* a = d->annotated(); a && keeps(a)) {  // the chosen style's (cga_styles.cpp)
      declaration(a);
    }
  }
  startRule();
  exportFunctions();
  annotatePinnedAttrs();
}

ExprPtr Translator::pinnedAttrString(const Expr& value, const SourceRange& at) {
  if (value.kind != ExprKind::Ident) return nullptr;
  const auto decl = attrDecls_.find(value.text);
  if (decl == attrDecls_.end()) return nullptr;
  Diagnostics* const loud = diags_;
  Diagnostics quiet(nullptr);  // the attr's own declaration reports its errors
  diags_ = &quiet;
  ExprPtr text = this->value(styledAttrValue(decl->second), Env{});
  diags_ = loud;
  if (!text || text->kind != ExprKind::String) return nullptr;
  text->range = value.range;
  pinnedAttrs_.emplace(value.text, at);
  return text;
}

// The attr keeps its default's file: a value from --set or a lot that differs is an error
// at run time (backend attributeSlots), where the derivation would otherwise ignore it.
void Translator::annotatePinnedAttrs() {
  for (ValueDecl& v : program_.values) {
    const auto pin = pinnedAttrs_.find(v.name);
    if (!v.isAttr || pin == pinnedAttrs_.end()) continue;
    v.annotations.push_back({ir::kPinnedAttrAnnotation,
                             {{"line", std::to_string(pin->second.begin.line)},
                              {"col", std::to_string(pin->second.begin.col)}}});
  }
}

// Each function and const with its parameters as the Idents "#0", "#1" ... (ast.h:
// FunctionDecl), for an importer's `alias.f(x)`. Translated quietly: a function no one
// calls may hold an error, which an importer's call of it reports (frontend/imports.cpp).
void Translator::exportFunctions() {
  Diagnostics* const loud = diags_;
  for (const auto& [fnName, def] : functions_) {
    Diagnostics quiet(nullptr);
    diags_ = &quiet;
    std::vector<ExprPtr> params;
    Env env;
    for (size_t k = 0; k < def.params.size(); ++k) {
      params.push_back(makeExpr(ExprKind::Ident, def.range));
      params.back()->text = "#" + std::to_string(k);
      env.bound[def.params[k]] = params.back().get();
    }
    FunctionDecl f;
    f.range = def.range;
    f.name = fnName;
    f.params = def.params.size();
    currentParams_ = nullptr;
    inlining_ = {fnName};
    f.body = value(def.body, env);
    inlining_.clear();
    if (quiet.hasErrors()) {
      f.body.reset();
      for (const Diagnostic& d : quiet.all())
        if (d.severity == Severity::Error) {
          f.errorCode = d.code;
          f.error = d.message;
          f.errorAt = d.range;
          break;
        }
    }
    program_.functions.push_back(std::move(f));
  }
  diags_ = loud;
}

// Names first, so that a rule may use a function, attr or rule declared after it.
void Translator::collect(P::CgaFileContext* file) {
  for (P::DeclarationContext* d : file->declaration()) {
    if (auto* imp = d->importDecl(); imp && imp->alias) importAliases_.insert(imp->alias->getText());
    auto* a = d->annotated();
    // A rule a style redefines stays the @StartRule when the redefinition has no annotation.
    if (auto* r = a ? a->ruleDecl() : nullptr; r && !keeps(a) && declaredStartRule_.empty())
      for (auto* note : a->annotation())
        if (note->name->getText() == "StartRule" && owner_[a] == "Default") {
          declaredStartRule_ = r->name->getText();
          startRange_ = rangeOf(r->name);
        }
    if (!a || !keeps(a)) continue;  // another style's, or redefined in the chosen one (cga_styles.cpp)
    if (auto* f = a->functionDecl()) {
      if (f->name->getText().find('.') != std::string::npos) continue;  // an import's attr, set (declaration)
      Function fn{f->name->getText(), {}, f->value(), rangeOf(f->name)};
      if (f->params())
        for (auto* p : f->params()->ID()) fn.params.push_back(p->getText());
      if (functions_.count(fn.name)) error("E803", fn.range, "the function '" + fn.name + "' is declared twice");
      functions_[fn.name] = fn;
    } else if (auto* c = a->constDecl()) {
      Function fn{c->name->getText(), {}, c->value(), rangeOf(c->name)};
      if (c->params())
        for (auto* p : c->params()->ID()) fn.params.push_back(p->getText());
      if (functions_.count(fn.name)) error("E803", fn.range, "the const '" + fn.name + "' is declared twice");
      functions_[fn.name] = fn;
    } else if (auto* at = a->attrDecl()) {
      attrs_.insert(at->name->getText());
      attrDecls_[at->name->getText()] = at;
    } else if (auto* r = a->ruleDecl()) {
      const size_t n = r->params() ? r->params()->ID().size() : 0;
      const std::string name = r->name->getText();
      // Rules of one name with different numbers of parameters are different rules (a call
      // picks one by its argument count); two with the same number are an error, as in CityEngine.
      const auto [first, fresh] = ruleDecls_.emplace(std::make_pair(name, n), rangeOf(r->name));
      if (!fresh)
        error("E019", rangeOf(r->name),
              "'" + name + "' has a second rule with " + std::to_string(n) + " parameters (the first is at line " +
                  std::to_string(first->second.begin.line) + ":" + std::to_string(first->second.begin.col) +
                  "): rules of one name differ in their number of parameters");
      rules_[name].insert(n);
      for (auto* note : a->annotation())  // initialShape.startRule may be read before it
        if (note->name->getText() == "StartRule" && declaredStartRule_.empty()) declaredStartRule_ = name;
    }
  }
}

// CityEngine's import: this file's attrs reach the imported file's attrs of the same
// names, but for those its list names: `(a, b)` keeps a and b the imported file's own,
// `(a = expr)` sets a from here (expr read in this file), `()` keeps all of them.
void Translator::importDecl(P::ImportDeclContext* ctx) {
  ImportDecl d;
  d.range = rangeOf(ctx);
  d.pathRange = rangeOf(ctx->path);
  d.path = stringValue(ctx->path->getText());
  if (ctx->alias) d.alias = ctx->alias->getText();
  d.propagateAttrs = true;
  bool attrList = false;  // `(...)` after the path (the styles list comes before the `:`)
  for (auto* paren : ctx->LPAREN()) attrList = attrList || paren->getSymbol()->getTokenIndex() > ctx->path->getTokenIndex();
  d.protectAll = attrList && ctx->importArg().empty();
  for (antlr4::Token* style : ctx->styles) {  // checked against the file's styles (frontend/imports.cpp)
    d.styles.push_back(style->getText());
    d.styleRanges.push_back(rangeOf(style));
  }
  for (P::ImportArgContext* arg : ctx->importArg()) {
    if (arg->key) {
      currentParams_ = nullptr;
      ExprPtr v = expr(arg->expr(), Env{});
      if (!v) continue;
      d.settings.emplace_back(arg->key->getText(), std::move(v));
      d.settingRanges.push_back(rangeOf(arg->key));
      continue;
    }
    auto* prim = dynamic_cast<P::PrimaryExprContext*>(arg->expr());
    auto* name = prim ? dynamic_cast<P::NamePrimaryContext*>(prim->primary()) : nullptr;
    if (!name || name->name->getType() != P::ID) {
      error("E002", rangeOf(arg),
            "an import's list names the imported file's attrs to keep (`(height, width)`) or sets them "
            "(`(height = 10)`), not '" + arg->getText() + "'");
      continue;
    }
    d.protectedAttrs.push_back(name->name->getText());
    d.protectedRanges.push_back(rangeOf(arg));
  }
  program_.imports.push_back(std::move(d));
}

// `f.tileWidth = 5` after `import f : "lib.cga"`: the library's attr takes this value, as
// fgsg's `import "lib" as f (tileWidth = 5)` sets it.
void Translator::importSetting(P::FunctionDeclContext* ctx) {
  const std::string name = ctx->name->getText();
  const SourceRange at = rangeOf(ctx->name);
  const size_t dot = name.find('.');
  const std::string alias = name.substr(0, dot), attr = name.substr(dot + 1);
  ImportDecl* target = nullptr;
  for (ImportDecl& d : program_.imports)
    if (d.alias == alias) target = &d;
  if (!target) {
    error("E010", at, "'" + name + "' sets an attr of an import, but no import before it is called '" + alias + "'");
    return;
  }
  if (ctx->params() || ctx->LPAREN() || attr.find('.') != std::string::npos) {
    error("E002", at, "'" + name + " = value' sets the imported attr '" + attr + "': it takes no parameters");
    return;
  }
  currentParams_ = nullptr;
  ExprPtr v = value(ctx->value(), Env{});
  if (!v) return;
  target->settings.emplace_back(attr, std::move(v));
  target->settingRanges.push_back(at);
}

void Translator::declaration(P::AnnotatedContext* ctx) {
  bool start = false;
  std::string name = ctx->attrDecl()    ? ctx->attrDecl()->name->getText()
                     : ctx->ruleDecl()  ? ctx->ruleDecl()->name->getText()
                     : ctx->constDecl() ? ctx->constDecl()->name->getText()
                                        : ctx->functionDecl()->name->getText();
  std::vector<AttrAnnotation> notes = annotations(ctx->annotation(), start, name);
  if (start) {
    if (!ctx->ruleDecl()) {
      error("E803", rangeOf(ctx->annotation(0)), "@StartRule belongs to a rule, not to '" + name + "'");
    } else if (!startRule_.empty() && startRule_ != name) {
      error("E803", rangeOf(ctx->ruleDecl()->name),
            "a second @StartRule ('" + startRule_ + "' has one): a file has one start rule");
    } else {
      startRule_ = name;
      startRange_ = rangeOf(ctx->ruleDecl()->name);
    }
  }
  if (auto* a = ctx->attrDecl()) {
    ValueDecl v;
    v.range = rangeOf(a);
    v.isAttr = true;
    v.name = name;
    currentParams_ = nullptr;
    v.value = value(styledAttrValue(a), Env{});  // a style may redefine it (cga_styles.cpp)
    v.annotations = std::move(notes);
    if (v.value) program_.values.push_back(std::move(v));
  } else if (auto* r = ctx->ruleDecl()) {
    rule(r);
  } else if (auto* f = ctx->functionDecl(); f && name.find('.') != std::string::npos) {
    importSetting(f);
  }
  // consts and functions are inlined where they are used (cga_functions.cpp).
}

void Translator::rule(P::RuleDeclContext* ctx) {
  RuleHead head;
  head.name = overloadSymbol(ctx->name->getText(), ctx->params() ? ctx->params()->ID().size() : 0);
  head.range = rangeOf(ctx->name);
  if (ctx->params())
    for (auto* p : ctx->params()->ID()) {
      head.params.push_back({p->getText(), rangeOf(p->getSymbol())});
      head.paramNames.insert(p->getText());
    }
  currentRule_ = symbolName(ctx->name->getText());  // all overloads' leaves: the written name's
  ruleBody(ctx->ruleBody(), head, nullptr);
}

std::string Translator::overloadSymbol(const std::string& name, size_t arity) const {
  const auto rules = rules_.find(name);
  if (rules == rules_.end() || rules->second.empty() || arity <= *rules->second.begin()) return symbolName(name);
  return symbolName(name) + "$/" + std::to_string(arity);
}

std::string Translator::arityList(const std::string& name) const {
  std::string out;
  const auto rules = rules_.find(name);
  if (rules == rules_.end()) return out;
  const std::vector<size_t> counts(rules->second.begin(), rules->second.end());
  for (size_t k = 0; k < counts.size(); ++k) {
    if (k > 0) out += k + 1 == counts.size() ? " or " : ", ";
    out += std::to_string(counts[k]);
  }
  return out;
}

Rule Translator::newRule(const RuleHead& head, ExprPtr guard) {
  Rule r;
  r.range = head.range;
  r.predecessor.name = head.name;
  r.predecessor.range = head.range;
  r.predecessor.params = head.params;
  r.guard = std::move(guard);
  return r;
}

Translator::RuleHead Translator::auxHead(const RuleHead& head) {
  RuleHead aux = head;
  aux.name = head.name + "$" + std::to_string(++auxCount_);
  return aux;
}

Successor Translator::emitOf(const RuleHead& head, const SourceRange& at) {
  Successor s;
  s.range = at;
  Item item;
  item.kind = ItemKind::Call;
  item.range = at;
  item.name = head.name;
  for (const ParamDecl& p : head.params) {
    ExprPtr e = makeExpr(ExprKind::Ident, at);
    e->text = p.name;
    item.args.push_back(std::move(e));
  }
  s.items.push_back(std::move(item));
  return s;
}

void Translator::ruleBody(P::RuleBodyContext* body, const RuleHead& head, ExprPtr guard) {
  if (auto* c = dynamic_cast<P::CaseBodyContext*>(body)) {
    caseChain(c, 0, head, std::move(guard));
    return;
  }
  Rule r = newRule(head, std::move(guard));
  if (auto* s = dynamic_cast<P::StochasticBodyContext*>(body)) {
    const auto percents = s->PERCENT_LIT();
    const auto bodies = s->ruleBody();
    double sum = 0.0;
    for (size_t i = 0; i < percents.size(); ++i) {
      std::string text = percents[i]->getText();
      const double p = std::stod(text.substr(0, text.size() - 1));
      sum += p;
      Branch b;
      b.range = rangeOf(bodies[i]);
      b.successor = successorFor(bodies[i], head);
      b.probability = number(p / 100.0, rangeOf(percents[i]->getSymbol()));
      r.branches.push_back(std::move(b));
    }
    if (sum > 100.0 + 1e-9)
      error("E803", rangeOf(percents.back()->getSymbol()),
            "the percentages of this choice add up to " + std::to_string(sum) + "%, more than 100%");
    const double rest = std::max(0.0, 1.0 - sum / 100.0);
    if (s->ELSE() || rest > 1e-12) {
      Branch b;
      b.range = s->ELSE() ? rangeOf(bodies.back()) : rangeOf(s);
      if (s->ELSE()) {
        b.successor = successorFor(bodies.back(), head);
      } else {
        b.successor.epsilon = true;  // no `else`: the rest of the time the shape is removed
        b.successor.range = b.range;
      }
      b.probability = number(rest, b.range);
      r.branches.push_back(std::move(b));
    }
  } else {
    auto* ops = static_cast<P::OperationBodyContext*>(body);
    Branch b;
    b.range = rangeOf(ops);
    b.successor.range = b.range;
    Env env;
    env.ruleParams = &head.paramNames;
    currentParams_ = &head.paramNames;
    operations(ops->operation(), 0, b.successor, env, true);
    r.branches.push_back(std::move(b));
  }
  program_.rules.push_back(std::move(r));
}

Successor Translator::successorFor(P::RuleBodyContext* body, const RuleHead& head) {
  if (auto* ops = dynamic_cast<P::OperationBodyContext*>(body)) {
    Successor s;
    s.range = rangeOf(ops);
    Env env;
    env.ruleParams = &head.paramNames;
    currentParams_ = &head.paramNames;
    operations(ops->operation(), 0, s, env, true);
    return s;
  }
  RuleHead aux = auxHead(head);
  ruleBody(body, aux, nullptr);
  return emitOf(aux, rangeOf(body));
}

// `case c1 : A case c2 : B else : C` from branch `from` on. A condition `p(x)` is a random
// choice: the branch with weight x, the rest of the chain (a helper symbol) with 1 - x;
// other random conditions would be drawn once per guard and are refused.
void Translator::caseChain(P::CaseBodyContext* body, size_t from, const RuleHead& head, ExprPtr guard) {
  const auto conds = body->expr();
  const auto bodies = body->ruleBody();
  Env env;
  env.ruleParams = &head.paramNames;
  currentParams_ = &head.paramNames;
  ExprPtr notPrev;
  // `p(x)` as written (not a function of the file named p).
  auto chance = [&](P::ExprContext* c) -> P::CallPrimaryContext* {
    auto* prim = dynamic_cast<P::PrimaryExprContext*>(c);
    auto* call = prim ? dynamic_cast<P::CallPrimaryContext*>(prim->primary()) : nullptr;
    return call && call->name->getText() == "p" && call->expr().size() == 1 && !functions_.count("p") ? call
                                                                                                     : nullptr;
  };
  for (size_t i = from; i < conds.size(); ++i) {
    P::CallPrimaryContext* call = chance(conds[i]);
    // `case det && p(x)` (or `p(x) && det`): where det holds, the random choice of `p(x)`;
    // where it does not, the chain goes on as after any condition that fails.
    ExprPtr det;
    if (auto* both = dynamic_cast<P::BinaryExprContext*>(conds[i]); !call && both && both->op->getText() == "&&") {
      const bool right = chance(both->expr(1)) != nullptr;
      if (right || chance(both->expr(0))) {
        det = expr(both->expr(right ? 0 : 1), env);
        if (!det) return;
        if (isRandom(*det)) {
          notSupported(rangeOf(conds[i]), "a random `case` condition other than p(x) (write the choice as `30% : ...`)");
          return;
        }
        call = chance(both->expr(right ? 1 : 0));
      }
    }
    if (call) {
      ExprPtr x = expr(call->expr(0), env);
      if (!x) return;
      Rule r = newRule(head, conjunction(clone(guard), conjunction(clone(notPrev), clone(det))));
      Branch taken;
      taken.range = rangeOf(bodies[i]);
      taken.successor = successorFor(bodies[i], head);
      taken.probability = clone(x);
      RuleHead aux = auxHead(head);
      caseChain(body, i + 1, aux, nullptr);
      Branch rest;
      rest.range = rangeOf(conds[i]);
      rest.successor = emitOf(aux, rest.range);
      const SourceRange xAt = x->range;  // before `x` is moved into the call
      rest.probability = binary("-", number(1.0, xAt), std::move(x));
      r.branches.push_back(std::move(taken));
      r.branches.push_back(std::move(rest));
      program_.rules.push_back(std::move(r));
      if (!det) return;
      // Where det fails the chain goes on in the same helper rule as where the chance
      // fails: the rest is translated once (twice per such case would be 2^n rules).
      Rule failed = newRule(head, conjunction(std::move(guard), conjunction(std::move(notPrev), unaryNot(std::move(det)))));
      Branch onward;
      onward.range = rangeOf(conds[i]);
      onward.successor = emitOf(aux, onward.range);
      failed.branches.push_back(std::move(onward));
      program_.rules.push_back(std::move(failed));
      return;
    }
    ExprPtr cond = expr(conds[i], env);
    if (!cond) return;
    if (isRandom(*cond)) {
      notSupported(rangeOf(conds[i]), "a random `case` condition other than p(x) (write the choice as `30% : ...`)");
      return;
    }
    ruleBody(bodies[i], head, conjunction(clone(guard), conjunction(clone(notPrev), clone(cond))));
    notPrev = conjunction(std::move(notPrev), unaryNot(std::move(cond)));
  }
  currentParams_ = &head.paramNames;
  ruleBody(bodies.back(), head, conjunction(std::move(guard), std::move(notPrev)));
}

// The start: each lot (--lots), or without lots a square lot kDefaultLotSide metres a
// side at the origin, derived by the @StartRule (or --start-rule's rule). A rule `Axiom`
// chooses between the two by Lot.area (0 without lots); an importer drops it.
void Translator::startRule() {
  // A rule redefined in the chosen style without the annotation is still the @StartRule.
  if (startRule_.empty() && rules_.count(declaredStartRule_)) startRule_ = declaredStartRule_;
  std::string start = startRuleOverride_.empty() ? startRule_ : startRuleOverride_;
  SourceRange at = startRange_;
  if (start.empty()) {
    if (rules_.count("Lot")) start = "Lot";
    else return;  // a module of rules: nothing starts here
  }
  // --start-rule's name has no place in the file: its errors are at line 1 and say so.
  const bool given = !startRuleOverride_.empty();
  const std::string named = given ? "--start-rule " + start + ": " : "";
  if (!rules_.count(start)) {
    // The rules a start shape can derive: those without parameters, the @StartRule first.
    std::string candidates;
    std::vector<std::string> startable;
    if (!startRule_.empty()) candidates = startRule_ + " (@StartRule)";
    for (const auto& [name, arities] : rules_) {
      if (arities.count(0)) startable.push_back(name);
      if (!arities.count(0) || name == startRule_) continue;
      candidates += (candidates.empty() ? "" : ", ") + name;
    }
    const std::string meant = closestName(start, startable);
    error("E803", given ? SourceRange{{1, 1}, {1, 1}} : at,
          named + "the start rule '" + start + "' is not a rule of this file" +
              (meant.empty() ? std::string() : "; did you mean '" + meant + "'?") +
              (candidates.empty() ? std::string(" (it has no rule without parameters)")
                                  : "; rules that can start: " + candidates));
    return;
  }
  if (!rules_[start].count(0)) {
    error("E803", given ? SourceRange{{1, 1}, {1, 1}} : at,
          named + "the start rule '" + start + "' takes parameters: a start shape has none to give");
    return;
  }
  if (given && !startRule_.empty() && startRule_ != start && rules_.count(startRule_))
    program_.otherStartRules.push_back(overloadSymbol(startRule_, 0));
  auto lotArea = [&] {
    ExprPtr e = makeExpr(ExprKind::Member, at);
    e->object = "Lot";
    e->text = "area";
    return binary(">", std::move(e), number(0, at));
  };
  RuleHead axiom;
  axiom.name = "Axiom";
  axiom.range = at;
  RuleHead target;
  target.name = overloadSymbol(start, 0);
  Rule onLot = newRule(axiom, lotArea());
  Branch b;
  b.range = at;
  b.successor = emitOf(target, at);
  onLot.branches.push_back(std::move(b));
  program_.rules.push_back(std::move(onLot));

  Rule alone = newRule(axiom, unaryNot(lotArea()));
  Branch d;
  d.range = at;
  d.successor = emitOf(target, at);
  Item lot = command("Footprint", at);
  for (double v : {0.0, 0.0, kDefaultLotSide, 0.0, kDefaultLotSide, kDefaultLotSide, 0.0, kDefaultLotSide})
    lot.args.push_back(number(v, at));
  d.successor.items.insert(d.successor.items.begin(), std::move(lot));
  alone.branches.push_back(std::move(d));
  program_.rules.push_back(std::move(alone));
}

}  // namespace fgsg::frontend::cga
