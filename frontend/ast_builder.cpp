#include "frontend/ast_builder.h"

#include "frontend/builtins.h"
#include "frontend/context_lists.h"
#include "frontend/lex.h"
#include "runtime/cga/edge_index_label.h"

#include <charconv>
#include <cmath>
#include <cstdlib>

namespace fgsg::frontend {

using antlr4::Token;

namespace {

// Far beyond any real grammar; keeps this recursion (and every later pass over the AST)
// away from the end of the stack on generated or malicious input.
constexpr int kMaxExprDepth = 1000;

std::string text(const Token* t) { return t ? t->getText() : std::string(); }

SourceRange rangeOf(const antlr4::ParserRuleContext* ctx) {
  if (!ctx || !ctx->start) return {};
  SourceRange r = tokenRange(ctx->start);
  const Token* stop = ctx->stop;
  if (stop && stop->getTokenIndex() != INVALID_INDEX &&
      stop->getTokenIndex() >= ctx->start->getTokenIndex()) {
    r.end = tokenRange(stop).end;
  }
  return r;
}

SourceRange rangeOf(const Token* t) { return t ? tokenRange(t) : SourceRange{}; }


// "a \"b\"" -> a "b"; also \\ \n \t. An unknown escape keeps the character.
std::string unquote(const std::string& literal) {
  if (literal.size() < 2) return "";
  std::string out;
  for (size_t i = 1; i + 1 < literal.size(); ++i) {
    char c = literal[i];
    if (c == '\\' && i + 2 < literal.size()) {
      c = literal[++i];
      if (c == 'n') c = '\n';
      else if (c == 't') c = '\t';
    }
    out += c;
  }
  return out;
}

ExprPtr makeExpr(ExprKind kind, const SourceRange& range) {
  auto e = std::make_unique<Expr>();
  e->kind = kind;
  e->range = range;
  return e;
}

}  // namespace

// ================================================================ statements

void AstBuilder::addStatement(P::StatementContext* ctx) {
  if (!ctx) return;
  depthReported_ = false;
  if (auto* c = ctx->importDecl()) program_.imports.push_back(buildImportDecl(c));
  else if (auto* c = ctx->valueDecl()) program_.values.push_back(buildValueDecl(c));
  else if (auto* c = ctx->surfaceDecl()) program_.surfaces.push_back(buildSurfaceDecl(c));
  else if (auto* c = ctx->fieldDecl()) program_.fields.push_back(buildFieldDecl(c));
  else if (auto* c = ctx->textureDecl()) program_.textures.push_back(buildTextureDecl(c));
  else if (auto* c = ctx->tilesetDecl()) program_.tilesets.push_back(buildTilesetDecl(c));
  else if (auto* c = ctx->deriveDecl()) program_.derives.push_back(buildDeriveDecl(c));
  else if (auto* c = ctx->turtleDecl()) program_.turtles.push_back(buildTurtleDecl(c));
  else if (auto* c = ctx->ignoreDecl()) program_.ignores.push_back(buildIgnoreDecl(c));
  else if (auto* c = ctx->collisionDecl()) program_.collisions.push_back(buildCollisionDecl(c));
  else if (auto* c = ctx->axiomDecl()) program_.axioms.push_back(buildAxiomDecl(c));
  else if (auto* c = ctx->priorityDecl()) applyPriorityDecl(c);
  else if (auto* c = ctx->grammarRule()) program_.rules.push_back(buildRule(c));
}

// ============================================================== declarations

ImportDecl AstBuilder::buildImportDecl(P::ImportDeclContext* ctx) {
  ImportDecl d;
  d.range = rangeOf(ctx);
  d.path = unquote(text(ctx->path));
  d.pathRange = rangeOf(ctx->path);
  if (ctx->asWord && text(ctx->asWord) != "as")
    diags_.error("E002", rangeOf(ctx->asWord), "expected `as` after the module's path, found '" + text(ctx->asWord) + "'");
  if (ctx->alias) d.alias = text(ctx->alias);
  for (auto* s : ctx->importSetting()) {
    d.settings.emplace_back(text(s->name), buildExpr(s->expr()));
    d.settingRanges.push_back(rangeOf(s));
  }
  return d;
}

ValueDecl AstBuilder::buildValueDecl(P::ValueDeclContext* ctx) {
  ValueDecl d;
  d.range = rangeOf(ctx);
  d.isAttr = ctx->kind && ctx->kind->getType() == P::ATTR;
  d.name = text(ctx->name);
  d.value = buildExpr(ctx->expr());
  return d;
}

SurfaceDecl AstBuilder::buildSurfaceDecl(P::SurfaceDeclContext* ctx) {
  SurfaceDecl d;
  d.range = rangeOf(ctx);
  if (ctx->path) {
    d.path = unquote(text(ctx->path));
    d.target = d.nameRange = rangeOf(ctx->path);
  } else {
    d.generator = text(ctx->generator);
    d.target = d.nameRange = rangeOf(ctx->generator);
    if (ctx->callArgs()) d.target.end = rangeOf(ctx->callArgs()).end;
    d.args = buildCallArgs(ctx->callArgs());
  }
  return d;
}

// tensor("foot.tfield") is a file; `design tensor { ... }` a design; `curvature` the
// surface's curvature tensor; any other name or call is kept as a call for later passes.
FieldDecl AstBuilder::buildFieldDecl(P::FieldDeclContext* ctx) {
  FieldDecl d;
  d.range = rangeOf(ctx);
  d.name = text(ctx->name);
  d.nameRange = rangeOf(ctx->name);
  P::FieldSourceContext* src = ctx->fieldSource();
  if (!src) return d;
  d.sourceRange = rangeOf(src);
  d.functionRange = rangeOf(src->function);
  d.function = text(src->function);
  if (src->designWord) {
    if (text(src->designWord) != "design") {
      diags_.error("E002", rangeOf(src->designWord),
                   "expected 'design' before '" + d.function + " { ... }', found '" + text(src->designWord) + "'");
    }
    d.source = "design";
    for (auto* item : src->fieldDesignItem()) d.design.push_back(buildFieldDesignItem(item));
    return d;
  }
  d.args = buildCallArgs(src->callArgs());
  const bool fileFunction = d.function == "tensor" || d.function == "vector" || d.function == "scalar";
  if (fileFunction && d.args.size() == 1 && d.args[0] && d.args[0]->kind == ExprKind::String) {
    d.source = "file";
    d.path = d.args[0]->text;
    d.args.clear();
  } else if (d.function == "curvature" && !src->callArgs()) {
    d.source = "curvature";
    d.function.clear();
  } else {
    d.source = "call";
  }
  return d;
}

FieldDesignItem AstBuilder::buildFieldDesignItem(P::FieldDesignItemContext* ctx) {
  FieldDesignItem item;
  item.range = rangeOf(ctx);
  item.kindRange = rangeOf(ctx->kind);
  item.kind = text(ctx->kind);
  for (auto* word : ctx->fieldDesignWord()) {
    FieldDesignWord w;
    w.range = rangeOf(word);
    w.keyword = text(word->keyword);
    w.value = buildDesignValue(word->designValue());
    item.words.push_back(std::move(w));
  }
  return item;
}

ExprPtr AstBuilder::buildDesignValue(P::DesignValueContext* ctx) {
  if (!ctx) return nullptr;
  ExprPtr value;
  const auto exprs = ctx->expr();
  if (auto* n = ctx->number()) {
    value = buildNumber(n);
  } else if (auto* s = ctx->STRING()) {
    value = makeExpr(ExprKind::String, rangeOf(s->getSymbol()));
    value->text = unquote(s->getText());
  } else if (ctx->TRUE() || ctx->FALSE()) {
    value = makeExpr(ExprKind::Bool, rangeOf(ctx));
    value->boolean = ctx->TRUE() != nullptr;
  } else if (exprs.size() == 1) {
    value = buildExpr(exprs[0]);
    if (value) value->range = rangeOf(ctx);  // point at the parentheses too
  } else {
    value = makeExpr(ExprKind::Vector, rangeOf(ctx));
    for (auto* e : exprs) value->args.push_back(buildExpr(e));
  }
  if (ctx->sign) {
    auto unary = makeExpr(ExprKind::Unary, rangeOf(ctx));
    unary->text = text(ctx->sign);
    unary->args.push_back(std::move(value));
    value = std::move(unary);
  }
  return value;
}

TextureDecl AstBuilder::buildTextureDecl(P::TextureDeclContext* ctx) {
  TextureDecl d;
  d.range = rangeOf(ctx);
  d.name = text(ctx->name);
  d.path = unquote(text(ctx->path));
  return d;
}

TilesetDecl AstBuilder::buildTilesetDecl(P::TilesetDeclContext* ctx) {
  TilesetDecl d;
  d.range = rangeOf(ctx);
  d.name = text(ctx->name);
  d.nameRange = rangeOf(ctx->name);
  for (auto* i : ctx->tilesetItem()) {
    TilesetItem item;
    item.range = rangeOf(i);
    item.kind = text(i->kind);
    item.kindRange = rangeOf(i->kind);
    if (i->itemName) {
      item.name = text(i->itemName);
      item.nameRange = rangeOf(i->itemName);
    }
    for (auto* e : i->expr()) item.values.push_back(buildExpr(e));
    d.items.push_back(std::move(item));
  }
  return d;
}

DeriveDecl AstBuilder::buildDeriveDecl(P::DeriveDeclContext* ctx) {
  DeriveDecl d;
  d.range = rangeOf(ctx);
  d.mode = text(ctx->order);
  d.steps = buildExpr(ctx->steps);
  return d;
}

IgnoreDecl AstBuilder::buildIgnoreDecl(P::IgnoreDeclContext* ctx) {
  IgnoreDecl d;
  d.range = rangeOf(ctx);
  d.consider = listsConsideredModules(ctx->IGNORE()->getText());
  for (auto* s : ctx->ignoredSymbol()) d.symbols.emplace_back(s->getText(), rangeOf(s));
  return d;
}

TurtleDecl AstBuilder::buildTurtleDecl(P::TurtleDeclContext* ctx) {
  TurtleDecl d;
  d.range = rangeOf(ctx);
  for (auto* setting : ctx->turtleSetting()) {
    d.settings.emplace_back(text(setting->name), buildExpr(setting->value));
  }
  return d;
}

CollisionDecl AstBuilder::buildCollisionDecl(P::CollisionDeclContext* ctx) {
  CollisionDecl d;
  d.range = rangeOf(ctx);
  for (auto* word : ctx->collisionWord()) {
    CollisionWord w;
    w.range = rangeOf(word);
    if (word->word) {
      w.word = text(word->word);
    } else if (auto* n = word->number()) {
      w.number = literalNumber(n->getText(), rangeOf(n));
      if (word->sign) w.number = -w.number;
    }
    d.words.push_back(std::move(w));
  }
  return d;
}

AxiomDecl AstBuilder::buildAxiomDecl(P::AxiomDeclContext* ctx) {
  AxiomDecl d;
  d.range = rangeOf(ctx);
  d.successor = buildSuccessor(ctx->successor());
  return d;
}

void AstBuilder::applyPriorityDecl(P::PriorityDeclContext* ctx) {
  int level = 0;
  const std::string digits = text(ctx->level);
  auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), level);
  if (ec != std::errc()) {
    diags_.error("E002", rangeOf(ctx->level), "priority '" + digits + "' is not a small integer");
    return;
  }
  priority_ = ctx->sign ? -level : level;
}

// ===================================================================== rules

Rule AstBuilder::buildRule(P::GrammarRuleContext* ctx) {
  Rule rule;
  rule.range = rangeOf(ctx);
  rule.priority = priority_;
  rule.section = section_;
  if (ctx->label) rule.label = ctx->label->getText();
  if (auto* head = ctx->ruleHead()) {
    if (auto* left = head->leftContext()) {
      for (auto* m : left->modulePattern()) rule.leftContext.push_back(buildModulePattern(m));
    }
    rule.predecessor = buildModulePattern(head->predecessor);
    if (auto* right = head->rightContext()) {
      for (auto* m : right->contextModule()) rule.rightContext.push_back(buildContextModule(m));
    }
  }
  rule.guard = buildExpr(ctx->guard);
  P::RuleBodyContext* body = ctx->ruleBody();
  if (!body) return rule;
  if (body->mullerGuard) {
    ExprPtr second = buildExpr(body->mullerGuard);
    if (!rule.guard) {
      rule.guard = std::move(second);
    } else {  // `A : c1 ~> c2 ~> ...`: both must hold
      auto both = makeExpr(ExprKind::Binary, rule.guard->range);
      both->range.end = second ? second->range.end : both->range.end;
      both->text = "&&";
      both->args.push_back(std::move(rule.guard));
      both->args.push_back(std::move(second));
      rule.guard = std::move(both);
    }
  }
  for (auto* branch : body->branch()) rule.branches.push_back(buildBranch(branch));
  return rule;
}

ModulePattern AstBuilder::buildModulePattern(P::ModulePatternContext* ctx) {
  ModulePattern m;
  if (!ctx) return m;
  m.range = rangeOf(ctx);
  m.name = ctx->turtle ? ctx->turtle->getText() : text(ctx->name);
  for (auto* param : ctx->paramDecl()) {
    m.params.push_back({param->getText(), rangeOf(param)});
  }
  return m;
}

ModulePattern AstBuilder::buildContextModule(P::ContextModuleContext* ctx) {
  if (auto* m = ctx->modulePattern()) return buildModulePattern(m);
  ModulePattern bracket;
  bracket.range = rangeOf(ctx);
  bracket.name = ctx->open ? "[" : "]";
  return bracket;
}

Branch AstBuilder::buildBranch(P::BranchContext* ctx) {
  Branch b;
  b.range = rangeOf(ctx);
  b.successor = buildSuccessor(ctx->successor());
  b.probability = buildExpr(ctx->probability);
  return b;
}

// ================================================================ successors

Successor AstBuilder::buildSuccessor(P::SuccessorContext* ctx) {
  Successor s;
  if (!ctx) return s;
  s.range = rangeOf(ctx);
  s.epsilon = ctx->EPSILON() != nullptr;
  for (auto* item : ctx->sequenceItem()) appendSequenceItem(item, s.items);
  return s;
}

Successor AstBuilder::buildBodyPart(P::BodyPartContext* ctx) {
  Successor s;
  s.range = rangeOf(ctx);
  s.epsilon = ctx->EPSILON() != nullptr;
  if (ctx->selector) {
    s.selector = text(ctx->selector);
    if (ctx->merged) s.selector += "=";  // `all=: A`: the label of a merged part, as a .cga `=`
    s.selectorRange = rangeOf(ctx->selector);
  }
  if (ctx->size) s.size = buildExpr(ctx->size);
  for (auto* item : ctx->item()) appendItem(item, s.items);
  return s;
}

// Corners written as pairs, `Footprint((0, 0), (20, 0), (20, 9))`, are the coordinates
// written flat, `Footprint(0, 0, 20, 0, 20, 9)`.
void AstBuilder::cornersAsPairs(Item& item) {
  std::vector<ExprPtr> flat;
  for (ExprPtr& a : item.args) {
    if (a && a->kind == ExprKind::Vector && a->args.size() == 2) {
      for (ExprPtr& c : a->args) flat.push_back(std::move(c));
    } else {
      flat.push_back(std::move(a));
    }
  }
  item.args = std::move(flat);
}

// CGA's split syntax, `Subdiv("Y"){ 4: Ground | ~3: Floor }` (and SplitArea's), is Subdiv("Y", 4, ~3){
// Ground | Floor }: when every part is labelled and only the axis is given, the labels
// become the sizes (a bare name, `floor_h: Floor`, is read as the value it names).
// Anything else stays as written for the analyzer to judge.
void AstBuilder::sizesFromParts(Item& item) {
  if ((item.name != "Subdiv" && item.name != "SplitArea") || item.args.size() != 1 || item.body.empty()) return;
  for (const Successor& part : item.body)
    if (!part.size && part.selector.empty()) return;
  for (Successor& part : item.body) {
    if (!part.size) {
      part.size = makeExpr(ExprKind::Ident, part.selectorRange);
      part.size->text = part.selector;
      part.selector.clear();
    }
    item.args.push_back(std::move(part.size));
  }
}

// CGA's index selectors of a setback, `Setback(2){ 0: Front | -1: West | remainder: R }`,
// and of a comp, `Comp("e"){ 2: Edge }`: a part whose label is a whole number (the parser
// reads it as a size) selects that edge (component), labelled as
// runtime/cga/edge_index_label.h's edgeIndexLabel. Other sizes stay for the analyzer to judge.
void AstBuilder::edgeIndexesFromParts(Item& item) {
  if (item.name != "Setback" && item.name != "SetbackPerEdge" && item.name != "SetbackToArea" && item.name != "Comp")
    return;
  for (Successor& part : item.body) {
    if (!part.size || !part.selector.empty()) continue;
    const Expr* number = part.size.get();
    double sign = 1;
    if (number->kind == ExprKind::Unary && number->text == "-" && number->args.size() == 1)
      sign = -1, number = number->args[0].get();
    if (number->kind != ExprKind::Number || number->number != std::floor(number->number) ||
        !(std::abs(number->number) < 1e9))
      continue;
    part.selector = rt::cga::edgeIndexLabel(static_cast<long long>(sign * number->number));
    part.selectorRange = part.size->range;
    part.size.reset();
  }
}

void AstBuilder::appendSequenceItem(P::SequenceItemContext* ctx, std::vector<Item>& out) {
  if (auto* item = ctx->item()) {
    appendItem(item, out);
  } else if (ctx->polygon) {
    Item brace;
    brace.kind = ItemKind::Turtle;  // { }: turtle symbols of ABOP's polygons
    brace.name = text(ctx->polygon);
    brace.range = rangeOf(ctx);
    out.push_back(std::move(brace));
  } else {
    appendTurtleSymbols(ctx, ctx->symbol, ctx->callArgs(), out);
  }
}

void AstBuilder::appendItem(P::ItemContext* ctx, std::vector<Item>& out) {
  if (auto* call = dynamic_cast<P::CallItemContext*>(ctx)) {
    if (appendNameThenPolygon(call, out)) return;
    out.push_back(buildCallItem(call));
  } else if (auto* polygon = dynamic_cast<P::PolygonItemContext*>(ctx)) {
    Item item;
    item.kind = ItemKind::Turtle;  // `.`: a vertex of ABOP's polygons
    item.name = text(polygon->polygon);
    item.range = rangeOf(ctx);
    out.push_back(std::move(item));
  } else if (auto* turtle = dynamic_cast<P::TurtleItemContext*>(ctx)) {
    appendTurtleSymbols(turtle, turtle->symbol, turtle->callArgs(), out);
  } else if (auto* bracket = dynamic_cast<P::BracketItemContext*>(ctx)) {
    out.push_back(buildBracketItem(bracket));
  } else if (auto* surface = dynamic_cast<P::SurfaceItemContext*>(ctx)) {
    out.push_back(buildSurfaceItem(surface));
  }
}

// ABOP's predefined surface `~leaf(s)` is `[ ~(s) I("leaf") ]`: the turtle symbol `~`
// makes the scope the surface's box at the turtle (sizes evaluated once), I() places the
// asset there like any instance, and the brackets give the turtle back.
Item AstBuilder::buildSurfaceItem(P::SurfaceItemContext* ctx) {
  Item frame;
  frame.kind = ItemKind::Turtle;
  frame.name = "~";
  frame.range = rangeOf(ctx);
  frame.args = buildCallArgs(ctx->callArgs());
  frame.surface = ctx->surface ? text(ctx->surface) : unquote(text(ctx->surfaceFile));
  Item place;
  place.kind = ItemKind::Call;
  place.name = "I";
  place.range = ctx->surface ? rangeOf(ctx->surface) : rangeOf(ctx->surfaceFile);
  auto asset = makeExpr(ExprKind::String, place.range);
  asset->text = frame.surface;
  place.args.push_back(std::move(asset));
  Item item;
  item.kind = ItemKind::Bracket;
  item.range = frame.range;
  item.children.push_back(std::move(frame));
  item.children.push_back(std::move(place));
  return item;
}

namespace {

// Whether the tree holds a polygon vertex `.`.
bool hasVertex(antlr4::tree::ParseTree* t) {
  if (auto* p = dynamic_cast<fgsg_grammar::FgsgParser::PolygonItemContext*>(t)) return p->getText() == ".";
  for (auto* child : t->children)
    if (hasVertex(child)) return true;
  return false;
}

}  // namespace

// `A{.-f.+f.}`: a name that takes no body (a shape symbol, F, f ...) followed by a
// polygon parses as a body; it is the name, then `{`, the parts' items with the `|`
// between them (turtle symbols inside a polygon), then `}`. Only a body with a vertex
// `.` is read so, and nothing a polygon cannot be (labelled or sized parts, `,`, `}*`):
// anything else stays a body, for the usual messages (E018 on a shape symbol's body).
bool AstBuilder::appendNameThenPolygon(P::CallItemContext* ctx, std::vector<Item>& out) {
  auto* body = ctx->body();
  if (!body || body->repeat || !hasVertex(body)) return false;
  const CommandInfo* command = findCommand(text(ctx->name));
  if (command && command->body != BodyRule::None) return false;
  for (auto* part : body->bodyPart())
    if (part->selector || part->size || part->EPSILON()) return false;
  for (auto* child : body->children)
    if (child->getText() == ",") return false;
  Item name;
  name.kind = ItemKind::Call;
  name.range = rangeOf(ctx->name);
  name.name = text(ctx->name);
  name.args = buildCallArgs(ctx->callArgs());
  if (auto* args = ctx->callArgs()) name.range.end = rangeOf(args).end;
  out.push_back(std::move(name));
  const auto symbol = [&](const std::string& s, antlr4::tree::TerminalNode* at) {
    Item item;
    item.kind = ItemKind::Turtle;
    item.name = s;
    item.range = rangeOf(at->getSymbol());
    out.push_back(std::move(item));
  };
  for (auto* child : body->children) {
    if (auto* part = dynamic_cast<P::BodyPartContext*>(child)) {
      for (auto* item : part->item()) appendItem(item, out);
    } else if (auto* token = dynamic_cast<antlr4::tree::TerminalNode*>(child)) {
      symbol(token->getText(), token);  // {, | and }
    }
  }
  return true;
}

Item AstBuilder::buildCallItem(P::CallItemContext* ctx) {
  Item item;
  item.kind = ItemKind::Call;
  item.range = rangeOf(ctx);
  item.name = text(ctx->name);
  item.args = buildCallArgs(ctx->callArgs());
  if (item.name == "Footprint") cornersAsPairs(item);
  if (auto* body = ctx->body()) {
    item.hasBody = true;
    item.repeatPattern = body->repeat != nullptr;
    for (auto* part : body->bodyPart()) item.body.push_back(buildBodyPart(part));
    sizesFromParts(item);
    edgeIndexesFromParts(item);
  }
  return item;
}

// The lexer reads `&&` and `||` as one token; between items they are two turtle
// symbols (`F&&F` pitches down twice). Arguments belong to the last one.
void AstBuilder::appendTurtleSymbols(antlr4::ParserRuleContext* ctx, Token* symbol,
                                     P::CallArgsContext* args, std::vector<Item>& out) {
  std::string name = text(symbol);
  if (name == ";") name = "'";  // lpfg's colour step is ABOP's '; its `,` (the previous colour) stays `,`
  if (name == "&&" || name == "||") {
    Item first;
    first.kind = ItemKind::Turtle;
    first.name = name.substr(0, 1);
    first.range = rangeOf(symbol);
    first.range.end = first.range.begin;
    out.push_back(std::move(first));
    name = name.substr(1);
  }
  Item item;
  item.kind = ItemKind::Turtle;
  item.name = name;
  item.range = rangeOf(ctx);
  item.args = buildCallArgs(args);
  out.push_back(std::move(item));
}

Item AstBuilder::buildBracketItem(P::BracketItemContext* ctx) {
  Item item;
  item.kind = ItemKind::Bracket;
  item.range = rangeOf(ctx);
  for (auto* child : ctx->sequenceItem()) appendSequenceItem(child, item.children);
  return item;
}

std::vector<ExprPtr> AstBuilder::buildCallArgs(P::CallArgsContext* ctx) {
  std::vector<ExprPtr> args;
  if (!ctx) return args;
  for (auto* e : ctx->expr()) args.push_back(buildExpr(e));
  return args;
}

// =============================================================== expressions

// Counts the recursion depth of buildExpr/buildPrimary; past the limit the expression is
// replaced by 0 and reported once per statement.
class AstBuilder::DepthGuard {
 public:
  explicit DepthGuard(AstBuilder& b) : b_(b) { ++b_.exprDepth_; }
  ~DepthGuard() { --b_.exprDepth_; }
  bool tooDeep(const antlr4::ParserRuleContext* ctx) {
    if (b_.exprDepth_ <= kMaxExprDepth) return false;
    if (!b_.depthReported_) {
      b_.diags_.error("E002", rangeOf(ctx),
                      "expression nested too deeply (more than " + std::to_string(kMaxExprDepth) + " levels)");
      b_.depthReported_ = true;
    }
    return true;
  }

 private:
  AstBuilder& b_;
};

ExprPtr AstBuilder::buildExpr(P::ExprContext* ctx) {
  if (!ctx) return nullptr;
  DepthGuard depth(*this);
  if (depth.tooDeep(ctx)) return makeExpr(ExprKind::Number, rangeOf(ctx));
  if (auto* c = dynamic_cast<P::PrimaryExprContext*>(ctx)) return buildPrimary(c->primary());
  if (auto* c = dynamic_cast<P::UnaryExprContext*>(ctx)) return buildUnary(c);
  if (auto* c = dynamic_cast<P::BinaryExprContext*>(ctx)) return buildBinary(c);
  if (auto* c = dynamic_cast<P::TernaryExprContext*>(ctx)) return buildTernary(c);
  return nullptr;
}

ExprPtr AstBuilder::buildUnary(P::UnaryExprContext* ctx) {
  auto e = makeExpr(ExprKind::Unary, rangeOf(ctx));
  e->text = text(ctx->op);
  e->args.push_back(buildExpr(ctx->expr()));
  return e;
}

ExprPtr AstBuilder::buildBinary(P::BinaryExprContext* ctx) {
  auto e = makeExpr(ExprKind::Binary, rangeOf(ctx));
  e->text = text(ctx->op);
  for (auto* operand : ctx->expr()) e->args.push_back(buildExpr(operand));
  return e;
}

ExprPtr AstBuilder::buildTernary(P::TernaryExprContext* ctx) {
  auto e = makeExpr(ExprKind::Ternary, rangeOf(ctx));
  for (auto* operand : ctx->expr()) e->args.push_back(buildExpr(operand));
  return e;
}

ExprPtr AstBuilder::buildPrimary(P::PrimaryContext* ctx) {
  if (!ctx) return nullptr;
  DepthGuard depth(*this);
  if (depth.tooDeep(ctx)) return makeExpr(ExprKind::Number, rangeOf(ctx));
  if (auto* c = dynamic_cast<P::NumberPrimaryContext*>(ctx)) return buildNumber(c->number());
  if (auto* c = dynamic_cast<P::RelSizePrimaryContext*>(ctx)) {
    auto e = makeExpr(ExprKind::RelSize, rangeOf(ctx));
    e->number = literalNumber(c->getText(), rangeOf(ctx));
    return e;
  }
  if (auto* c = dynamic_cast<P::StringPrimaryContext*>(ctx)) {
    auto e = makeExpr(ExprKind::String, rangeOf(ctx));
    e->text = unquote(c->getText());
    return e;
  }
  if (auto* c = dynamic_cast<P::BoolPrimaryContext*>(ctx)) {
    auto e = makeExpr(ExprKind::Bool, rangeOf(ctx));
    e->boolean = c->value && c->value->getType() == P::TRUE;
    return e;
  }
  if (auto* c = dynamic_cast<P::MemberPrimaryContext*>(ctx)) return buildMember(c);
  if (auto* c = dynamic_cast<P::CallPrimaryContext*>(ctx)) {
    auto e = makeExpr(ExprKind::Call, rangeOf(ctx));
    e->text = text(c->name);
    e->args = buildCallArgs(c->callArgs());
    return e;
  }
  if (auto* c = dynamic_cast<P::IdentPrimaryContext*>(ctx)) {
    auto e = makeExpr(ExprKind::Ident, rangeOf(ctx));
    e->text = text(c->name);
    if (e->text == "\u03C0") e->text = "pi";  // the papers' π
    return e;
  }
  if (auto* c = dynamic_cast<P::ParenPrimaryContext*>(ctx)) {
    ExprPtr inner = buildExpr(c->expr());
    if (inner) inner->range = rangeOf(ctx);  // point at the parentheses too
    return inner;
  }
  if (auto* c = dynamic_cast<P::VectorPrimaryContext*>(ctx)) return buildVector(c);
  if (auto* c = dynamic_cast<P::FloatSizePrimaryContext*>(ctx)) {
    auto e = makeExpr(ExprKind::FloatSize, rangeOf(ctx));
    e->args.push_back(buildPrimary(c->primary()));
    return e;
  }
  return nullptr;
}

ExprPtr AstBuilder::buildNumber(P::NumberContext* ctx) {
  if (!ctx) return nullptr;
  auto e = makeExpr(ExprKind::Number, rangeOf(ctx));
  e->number = literalNumber(ctx->getText(), rangeOf(ctx));
  return e;
}

double AstBuilder::literalNumber(const std::string& text, const SourceRange& at) {
  std::string s = text;
  if (!s.empty() && s.back() == 'r') s.pop_back();  // relative size 0.5r
  double value = 0.0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec == std::errc::result_out_of_range) {
    // Too small for a double is (about) 0; too large has no value at all. (The program
    // keeps the C locale, so strtod reads the '.' as from_chars does.)
    const double nearest = std::strtod(s.c_str(), nullptr);
    if (!std::isinf(nearest)) return nearest;
    diags_.error("E002", at, "the number " + text + " is too large (numbers are at most about 1.8e308)");
    return 0.0;
  }
  return value;
}

ExprPtr AstBuilder::buildMember(P::MemberPrimaryContext* ctx) {
  auto e = makeExpr(ExprKind::Member, rangeOf(ctx));
  e->object = text(ctx->object);
  e->text = text(ctx->member);
  e->hasCall = ctx->callArgs() != nullptr;
  e->args = buildCallArgs(ctx->callArgs());
  if (!ctx->sub) return e;
  // CGA's `Lot.props.height` is Lot.prop("height", 0): a number property, 0 without lots.
  if (e->object == "Lot" && e->text == "props" && !e->hasCall) {
    e->text = "prop";
    e->hasCall = true;
    auto key = makeExpr(ExprKind::String, rangeOf(ctx->sub));
    key->text = text(ctx->sub);
    e->args.push_back(std::move(key));
    auto none = makeExpr(ExprKind::Number, rangeOf(ctx->sub));
    none->number = 0;
    e->args.push_back(std::move(none));
    return e;
  }
  e->text += "." + text(ctx->sub);  // no other query has a third part: sema names it unknown
  return e;
}

ExprPtr AstBuilder::buildVector(P::VectorPrimaryContext* ctx) {
  auto e = makeExpr(ExprKind::Vector, rangeOf(ctx));
  for (auto* component : ctx->expr()) e->args.push_back(buildExpr(component));
  return e;
}

}  // namespace fgsg::frontend
