// The `.cga` dialect's operations: CityEngine's names and argument forms as fgsg commands.
//
//   extrude(h), extrude(world.y, h)     Extrude(h)
//   split(x|y|z [, adjust|noAdjust]){ sizes : ops | { ... }* }[*]
//                                       Subdiv with CityEngine's sizing (rest empty, overflow
//                                       cut; a nested repeat takes what the others leave)
//   splitArea(x|y|z [, adjust|noAdjust]){ areas : ops }[*]   SplitArea: the same, in areas
//   comp(f){ top : A | side = B }       Comp("f"){ top: A | side=: B }  (`=`: the faces one shape)
//   comp(e|v){ vertical : A | world.up : B | border : C | 2 : D | street.front = E }
//                                       Comp("e"){ vertical: A | worldUp: B | border: C | #2: D | streetFront=: E }
//   offset(-d, inside|border)           Offset(d){ inside: rest of the successor }
//   offset(-d) comp(f){ inside : A | border : B }   Offset(d){ inside: A | border: B }
//   roofGable/Hip/Pyramid/Shed(angle)   Roof(kind, angle){ rest of the successor }
//   roofRidge(byAngle, angle)           Roof("ridge", angle){ rest of the successor }
//   roofHip(byHeight, h, ...) ...       Roof(kind, "byHeight", h, ...){ rest of the successor }
//   translate(rel, scope, x, y, z)      T(x, y, z)
//   translate(rel|abs, world, x, y, z)  Translate("rel" or "abs", "world", x, y, z)
//   rotate(rel, scope, x, y, z)         R(x, y, z)
//   rotate(rel|abs, world, x, y, z)     Rotate("rel" or "abs", "world", x, y, z)
//   i("asset"[, upAxis[, insertMode]])  I(...) (also builtin:cube/unitQuad), moved after the scope operations that follow
//                                       it (CityEngine transforms the inserted geometry with
//                                       the scope); a missing file is W801, the insert skipped
//   s t r center color set(material.color.rgb, ...)
//   set(material.roughness|metallic|opacity|color.r|g|b|emissive.r|g|b|colormap|...|metallicmap, v), texture(x)
//   set(trim.horizontal|vertical, b)  SetTrim("horizontal"|"vertical", b)   trim()  ApplyTrimPlanes()
//                                       Material("roughness", v) ... (texture: "colormap")
//   setupProjection(0, scope.xz, w, h) tileUV scaleUV translateUV rotateUV normalizeUV
//                                       SetupProjection("xz", w, h), TileUV(w, h) ...;
//                                       projectUV(0) nothing (the projection applies at output)
//   report(k, v), print(x)              Report(k, v), Print(x) (where fgsg has them)
//   scatter(domain, n, distribution...) { operations }   Scatter(...){ operations } (cga_scatter.cpp)
//   [ ... ]  NIL  X.  .
// A successor that creates no shape ends with its shape as a leaf (CityEngine keeps it):
// the leaf symbol is the rule's name followed by '.'. Any other CityEngine operation is
// E800 at its name; an unknown lowercase call too.
#include "frontend/cga/cga_translator.h"

#include "frontend/builtins.h"
#include "frontend/did_you_mean.h"
#include "runtime/cga/edge_index_label.h"

#include <cctype>
#include <cmath>
#include <filesystem>
#include <set>

namespace fgsg::frontend::cga {

namespace fs = std::filesystem;

namespace {

// Every shape operation of CityEngine's CGA reference (2023): the dialect knows these
// names, and those it does not translate are E800 "not supported yet".
const char* const kCityEngineOperations[] = {
    "alignScopeToAxes", "alignScopeToGeometry", "alignScopeToGeometryBBox", "center", "cleanupGeometry", "color",
    "comp", "convexify", "copyUV", "deleteHoles", "deleteUV", "envelope", "extrude", "footprint", "i", "innerRect",
    "innerRectangle", "insertAlongUV", "label", "mirror", "mirrorScope", "modify", "normalizeUV", "offset", "print",
    "primitiveCube", "primitiveCylinder", "primitiveDisk", "primitiveQuad", "primitiveSphere", "projectUV", "r",
    "rectify", "reduceGeometry", "report", "resetGeometry", "resetMaterial", "reverseNormals", "roofGable",
    "roofHip", "roofPyramid", "roofRidge", "roofShed", "rotate", "rotateScope", "rotateUV", "s", "scaleUV",
    "scatter", "set", "setback", "setbackPerEdge", "setbackToArea", "setNormals", "setPivot", "setupProjection",
    "shapeL", "shapeO", "shapeU", "simplifyGeometry", "softenNormals", "split", "splitArea", "splitAndSetbackPerimeter",
    "t", "taper", "texture", "tileUV", "translate", "translateUV", "trim", "deleteHoles", "fuse", "insert",
    "scaleUV", "setElevation", "generateTexture", "text", "alignScopeToGeometry"};

}  // namespace

std::string symbolName(const std::string& name) {
  const size_t dot = name.rfind('.');
  if (dot != std::string::npos && dot + 1 < name.size())
    return name.substr(0, dot + 1) + symbolName(name.substr(dot + 1));
  return findCommand(name) ? name + "$" : name;
}

bool isCityEngineOperation(const std::string& name) {
  for (const char* op : kCityEngineOperations)
    if (name == op) return true;
  return false;
}

std::vector<std::string> cityEngineOperations() {
  std::set<std::string> names(std::begin(kCityEngineOperations), std::end(kCityEngineOperations));
  return {names.begin(), names.end()};
}

struct Translator::Sequence {
  Successor& out;
  bool createsShapes = false;
  bool nil = false;
  bool done = false;  // an operation took the rest of the successor as its body
  std::unique_ptr<Item> pendingInsert{};
  const std::vector<P::OperationContext*>* ops = nullptr;
  size_t index = 0;
  bool topLevel = true;
};

Item Translator::command(const std::string& fgsgName, const SourceRange& at) {
  Item item;
  item.kind = ItemKind::Call;
  item.name = fgsgName;
  item.range = at;
  return item;
}

namespace {

ExprPtr stringExpr(const std::string& s, const SourceRange& at) {
  ExprPtr e = makeExpr(ExprKind::String, at);
  e->text = s;
  return e;
}

ExprPtr scopeSize(int axis, const SourceRange& at) {
  ExprPtr e = makeExpr(ExprKind::Member, at);
  e->object = "Scope";
  e->text = std::string("s") + "xyz"[axis];
  return e;
}

// "#f00" -> "#ff0000"; anything else as written (sema checks it).
std::string fullColor(const std::string& c) {
  if (c.size() == 4 && c[0] == '#') return std::string("#") + c[1] + c[1] + c[2] + c[2] + c[3] + c[3];
  return c;
}

// A `.cga` comp selector as the label of fgsg's Comp part (runtime/cga/components.cpp's
// componentSelectorMask): the sides, slopes, `side`, `all`, `border` and `inside` as
// written, world.up as worldUp, object.front as objectFront, street.side as streetSide,
// comp(e)'s roof edges, an index selector `2` / `-1` (a whole number written out) as "#2" /
// "#-1"; "" where comp(kind) has no such selector (a computed or fractional index ...).
std::string cgaCompSelectorLabel(const std::string& kind, const std::string& word, const std::string& written) {
  static const char* const kAnyComponent[] = {"all",      "front",  "back",       "left",   "right",  "top",   "bottom",
                                              "side",     "vertical", "aslant",   "horizontal", "nutant", "border",
                                              "inside"};
  static const char* const kRoofEdges[] = {"eave", "ridge", "hip", "valley", "gable"};
  static const char* const kFrameSides[] = {"world.up",      "world.down",   "world.north",  "world.south",
                                            "world.east",    "world.west",   "world.side",   "object.top",
                                            "object.bottom", "object.front", "object.back",  "object.left",
                                            "object.right",  "object.side",  "street.front", "street.back",
                                            "street.left",   "street.right", "street.side"};
  for (const char* k : kAnyComponent)
    if (word == k) return word;
  if (kind == "e")
    for (const char* k : kRoofEdges)
      if (word == k) return word;
  for (const char* k : kFrameSides)
    if (word == k) {
      const size_t dot = word.find('.');
      std::string label = word.substr(0, dot) + word.substr(dot + 1);
      label[dot] = static_cast<char>(std::toupper(static_cast<unsigned char>(label[dot])));
      return label;
    }
  const size_t sign = !written.empty() && written[0] == '-' ? 1 : 0;
  if (word.empty() && written.size() > sign && written.size() < 10 + sign &&
      written.find_first_not_of("0123456789", sign) == std::string::npos)
    return rt::cga::edgeIndexLabel(std::stoll(written));
  return "";
}

}  // namespace

// The word a selector argument is written as (`x`, `world.y`, `inside`, `noAdjust`), or "".
std::string Translator::selectorWord(P::ExprContext* e) const {
  auto* p = dynamic_cast<P::PrimaryExprContext*>(e);
  if (!p) return "";
  if (auto* n = dynamic_cast<P::NamePrimaryContext*>(p->primary())) return n->name->getText();
  return "";
}

bool Translator::operations(const std::vector<P::OperationContext*>& ops, size_t from, Successor& out, const Env& env,
                            bool topLevel) {
  Sequence seq{out};
  seq.ops = &ops;
  seq.topLevel = topLevel;
  for (size_t k = from; k < ops.size() && !seq.done; ++k) {
    seq.index = k;
    operation(ops[k], seq, env);
  }
  if (seq.pendingInsert && !seq.nil) {
    out.items.push_back(std::move(*seq.pendingInsert));
    seq.createsShapes = true;
  }
  if (topLevel && !seq.createsShapes && !seq.nil) {
    Item leaf = command(currentRule_ + ".", out.range);
    out.items.push_back(std::move(leaf));
  }
  if (out.items.empty()) out.epsilon = true;
  return seq.createsShapes;
}

void Translator::operation(P::OperationContext* op, Sequence& seq, const Env& env) {
  const SourceRange at = rangeOf(op);
  auto flushInsert = [&] {
    if (seq.pendingInsert) {
      seq.out.items.push_back(std::move(*seq.pendingInsert));
      seq.pendingInsert.reset();
      seq.createsShapes = true;
    }
  };
  auto emit = [&](const std::string& name, bool leaf, std::vector<ExprPtr> args) {
    // After an insert a leaf is the inserted asset itself: nothing more to output, and the
    // instance is the leaf's (`i("tree.obj") Tree.` places a Tree).
    if (seq.pendingInsert && leaf) {
      seq.pendingInsert->recordAs = symbolName(name);
      flushInsert();
      return;
    }
    flushInsert();
    Item item = command(symbolName(name), at);
    item.args = std::move(args);
    seq.out.items.push_back(std::move(item));
    seq.createsShapes = true;
  };
  if (dynamic_cast<P::NilOperationContext*>(op)) {
    seq.nil = true;
    seq.pendingInsert.reset();
    return;
  }
  if (auto* l = dynamic_cast<P::LeafOperationContext*>(op)) {
    std::string name = l->leaf->getText();
    name.pop_back();
    // `X.`: X without its rules; a name without rules keeps its name.
    emit(rules_.count(name) ? symbolName(name) + "." : name, true, {});
    return;
  }
  if (dynamic_cast<P::DotOperationContext*>(op)) {
    emit(currentRule_ + ".", true, {});
    return;
  }
  if (auto* b = dynamic_cast<P::PushPopOperationContext*>(op)) {
    flushInsert();
    Successor inner;
    inner.range = at;
    // A bracket's shapes replace the shape too.
    if (operations(b->operation(), 0, inner, env, false)) seq.createsShapes = true;
    Item bracket;
    bracket.kind = ItemKind::Bracket;
    bracket.range = at;
    bracket.children = std::move(inner.items);
    seq.out.items.push_back(std::move(bracket));
    return;
  }
  if (auto* s = dynamic_cast<P::ShapeOperationContext*>(op)) {
    const std::string name = s->name->getText();
    const size_t dot = name.find('.');
    const bool imported = dot != std::string::npos && importAliases_.count(name.substr(0, dot));
    if (!rules_.count(name) && !imported && isCityEngineOperation(name)) {
      error("E800", at, "unknown operation '" + name + "' (CityEngine CGA; not supported yet)");
      return;
    }
    if (!imported && dot != std::string::npos) {
      error("E010", at, "unknown name '" + name + "' (no import is called '" + name.substr(0, dot) + "')");
      return;
    }
    if (rules_.count(name) && !rules_[name].count(0)) {
      error("E019", at, "'" + name + "' takes " + arityList(name) + " parameters");
      return;
    }
    emit(name, !rules_.count(name) && !imported, {});
    return;
  }
  callOperation(static_cast<P::CallOperationContext*>(op), seq, env);
}

void Translator::callOperation(P::CallOperationContext* op, Sequence& seq, const Env& env) {
  const std::string name = op->name->getText();
  const SourceRange at = rangeOf(op);
  const SourceRange nameAt = rangeOf(op->name);
  const auto argCtx = op->expr();
  const size_t dot = name.find('.');
  const bool imported = dot != std::string::npos && importAliases_.count(name.substr(0, dot));
  auto flushInsert = [&] {
    if (seq.pendingInsert) {
      seq.out.items.push_back(std::move(*seq.pendingInsert));
      seq.pendingInsert.reset();
      seq.createsShapes = true;
    }
  };
  auto args = [&](Env e) {
    std::vector<ExprPtr> out;
    for (auto* a : argCtx) out.push_back(expr(a, e));
    return out;
  };
  auto allOk = [](const std::vector<ExprPtr>& v) {
    for (const auto& e : v)
      if (!e) return false;
    return true;
  };
  auto count = [&](size_t lo, size_t hi, const std::string& forms) {
    if (argCtx.size() >= lo && argCtx.size() <= hi) return true;
    error("E016", nameAt, "'" + name + "' takes " + forms + ", got " + std::to_string(argCtx.size()));
    return false;
  };
  auto noBody = [&] {
    if (!op->splitBody()) return true;
    error("E018", rangeOf(op->splitBody()), "'" + name + "' takes no { } body");
    return false;
  };
  auto push = [&](Item item) { seq.out.items.push_back(std::move(item)); };
  // A shape of `name` with the call's arguments, after the insert waiting for its scope.
  auto pushShape = [&] {
    std::vector<ExprPtr> a = args(env);
    if (!allOk(a)) return;
    flushInsert();
    Item item = command(overloadSymbol(name, argCtx.size()), at);
    item.args = std::move(a);
    push(std::move(item));
    seq.createsShapes = true;
  };
  // The operations after this one, as the body of a command that replaces the shape.
  auto restAsBody = [&](Item& item, const std::string& label) {
    Successor part;
    part.range = at;
    part.selector = label;
    operations(*seq.ops, seq.index + 1, part, env, true);
    item.hasBody = true;
    item.body.push_back(std::move(part));
  };

  // `{ operations }` without selectors belongs to scatter (cga_scatter.cpp) alone.
  if (name == "scatter" && !rules_.count(name) && !imported) {
    std::optional<Item> scattered = scatter(op, env);
    if (!scattered) return;
    flushInsert();
    push(std::move(*scattered));
    seq.createsShapes = true;
    return;
  }
  if (op->operationBlock()) {
    error("E018", rangeOf(op->operationBlock()),
          "'" + name + "' takes no { operations } body (scatter does; a split or comp's parts are `selector : operations`)");
    return;
  }

  // A parametric rule (or an imported one): a shape with these arguments.
  if (rules_.count(name) || imported) {
    if (!noBody()) return;
    if (rules_.count(name) && !rules_[name].count(argCtx.size())) {  // an overload with this many (overloadSymbol)
      error("E019", nameAt, "'" + name + "' takes " + arityList(name) + " parameters, got " +
                                std::to_string(argCtx.size()));
      return;
    }
    pushShape();
    return;
  }

  if (name == "extrude") {
    if (!noBody() || !count(1, 2, "1 or 2 arguments (height, or axis and height)")) return;
    if (argCtx.size() == 2) {
      const std::string axis = selectorWord(argCtx[0]);
      // face.normal is extrude(h)'s own direction; world.up is world.y (the reference:
      // "in the direction of the world coordinate system's y-axis").
      if (axis != "world.y" && axis != "world.up" && axis != "face.normal") {
        notSupported(rangeOf(argCtx[0]), "extrude along '" + argCtx[0]->getText() + "'");
        return;
      }
    }
    ExprPtr h = expr(argCtx.back(), env);
    if (!h) return;
    flushInsert();
    Item item = command("Extrude", at);
    item.args.push_back(std::move(h));
    // world.up: Extrude's second argument 1 has the engine check that the face faces up.
    if (argCtx.size() == 2 && selectorWord(argCtx[0]) != "face.normal") item.args.push_back(number(1.0, at));
    push(std::move(item));
    return;
  }
  if (name == "split" || name == "splitArea") {
    if (!count(1, 2, "1 or 2 arguments (axis, and adjust or noAdjust)")) return;
    split(op, selectorWord(argCtx[0]), seq, env);
    return;
  }
  if (name == "comp") {
    comp(op, seq, env);
    return;
  }
  if (name == "offset") {
    if (!noBody() || !count(1, 2, "1 or 2 arguments (distance, and inside or border)")) return;
    const std::string part = argCtx.size() == 2 ? selectorWord(argCtx[1]) : "";
    if (argCtx.size() == 2 && part != "inside" && part != "border") {
      notSupported(rangeOf(argCtx[1]), "offset's selector '" + argCtx[1]->getText() + "'");
      return;
    }
    ExprPtr d = expr(argCtx[0], env);
    if (!d) return;
    if (d->kind == ExprKind::Number && d->number >= 0) {
      // Outward (issue #44): Setback(-d){ remainder: the grown polygon | all=: the band around it }.
      flushInsert();
      Item item = command("Setback", at);
      d->number = -d->number;
      item.args.push_back(std::move(d));
      if (part == "border") {
        restAsBody(item, "all=");
      } else {
        Successor band;  // every edge moves out; the band itself makes nothing
        band.range = at;
        band.selector = "all=";
        band.epsilon = true;
        item.hasBody = true;
        item.body.push_back(std::move(band));
        restAsBody(item, "remainder");
      }
      push(std::move(item));
      seq.createsShapes = true;
      seq.done = true;
      return;
    }
    flushInsert();
    Item item = command("Offset", at);
    ExprPtr inward = makeExpr(ExprKind::Unary, d->range);
    inward->text = "-";
    inward->args.push_back(std::move(d));
    item.args.push_back(std::move(inward));
    if (part.empty() && offsetComp(*seq.ops, seq.index + 1, item, env)) {
      push(std::move(item));
      seq.createsShapes = true;
      seq.done = true;
      return;
    }
    // Without a selector CityEngine keeps both as one shape; here they are two shapes.
    if (part.empty() || part == "inside") restAsBody(item, "inside");
    if (part.empty() || part == "border") restAsBody(item, "border");
    push(std::move(item));
    seq.createsShapes = true;
    seq.done = true;
    return;
  }
  if (name == "roofRidge") {
    // roofRidge(byAngle, angle), roofRidge(byHeight, height) (op_roofRidge's two forms):
    // fgsg's Roof("ridge", angle), Roof("ridge", "byHeight", height), the ridge along the
    // scope's x.
    if (!noBody() || !count(2, 2, "byAngle or byHeight and a value")) return;
    const std::string valueType = selectorWord(argCtx[0]);
    if (valueType != "byAngle" && valueType != "byHeight") {
      error("E028", rangeOf(argCtx[0]),
            "roofRidge's value type is byAngle or byHeight, not '" + argCtx[0]->getText() + "'");
      return;
    }
    ExprPtr angle = expr(argCtx[1], env);
    if (!angle) return;
    flushInsert();
    Item item = command("Roof", at);
    item.args.push_back(stringExpr("ridge", nameAt));
    if (valueType == "byHeight") item.args.push_back(stringExpr("byHeight", rangeOf(argCtx[0])));
    item.args.push_back(std::move(angle));
    restAsBody(item, "");
    push(std::move(item));
    seq.createsShapes = true;
    seq.done = true;
    return;
  }
  if (name == "roofGable" || name == "roofHip" || name == "roofPyramid" || name == "roofShed") {
    // roofGable(angle, overhangX, overhangY, even, index), roofHip(angle, overhang, even),
    // roofShed(angle, index), roofPyramid(angle), each also as (byAngle, angle, ...) and
    // (byHeight, height, ...): fgsg's Roof(kind[, "byHeight"], value, overhang, gable
    // overhang, edge index). roofGable's overhangY defaults to its overhangX (Roof's gable
    // overhang does).
    const bool gable = name == "roofGable", hip = name == "roofHip", shed = name == "roofShed";
    const std::string valueType = argCtx.empty() ? "" : selectorWord(argCtx[0]);
    const bool byHeight = valueType == "byHeight";
    const size_t first = valueType == "byAngle" || byHeight ? 1 : 0;
    const size_t most = first + (gable ? 5 : hip ? 3 : shed ? 2 : 1);
    const std::string forms = std::string(first ? valueType + ", " : "") + (byHeight ? "a height" : "an angle") +
                              (gable ? ", overhangX, overhangY, even and index"
                               : hip ? ", overhang and even"
                               : shed ? " and an edge index"
                                      : "");
    if (!noBody()) return;
    if (!count(first + 1, most, forms)) return;
    const size_t even = first + (gable ? 3 : 2);
    if ((gable || hip) && argCtx.size() > even && argCtx[even]->getText() != "false") {
      notSupported(rangeOf(argCtx[even]), name + "'s even roof (non-planar faces)");
      return;
    }
    std::vector<ExprPtr> args;
    for (size_t k = first; k < argCtx.size() && k < (gable ? first + 3 : hip ? first + 2 : argCtx.size()); ++k)
      args.push_back(expr(argCtx[k], env));
    if (gable && argCtx.size() > first + 4) args.push_back(expr(argCtx[first + 4], env));  // the ridge index
    if (!allOk(args)) return;
    if (shed && args.size() == 2) {
      // Roof("shed", angle, 0, 0, index): no overhangs before the edge index.
      ExprPtr index = std::move(args[1]);
      args.resize(1);
      args.push_back(number(0, index->range));
      args.push_back(number(0, index->range));
      args.push_back(std::move(index));
    }
    flushInsert();
    const char* kind = gable ? "gable" : hip ? "hipped" : name == "roofPyramid" ? "pyramid" : "shed";
    Item item = command("Roof", at);
    item.args.push_back(stringExpr(kind, nameAt));
    if (byHeight) item.args.push_back(stringExpr("byHeight", rangeOf(argCtx[0])));
    for (ExprPtr& a : args) item.args.push_back(std::move(a));
    restAsBody(item, "");
    push(std::move(item));
    seq.createsShapes = true;
    seq.done = true;
    return;
  }
  if (name == "i") {
    if (!noBody()) return;
    insert(op, seq, env);
    return;
  }
  // The insert waits for the scope operations after it, which for an asset that keeps its
  // size would act before the asset sets the scope (CityEngine's order): only moves commute.
  if (seq.pendingInsert && seq.pendingInsert->args.size() > 2 &&
      seq.pendingInsert->args[2]->text != "alignSizeAndPosition" &&
      (name == "s" || name == "r" || name == "rotate" || name == "center")) {
    notSupported(nameAt, name + "() after an i() that keeps the asset's size");
    return;
  }
  if (name == "s" || name == "t") {
    if (!noBody() || !count(3, 3, "3 arguments")) return;
    Item item = command(name == "s" ? "S" : "T", at);
    for (size_t k = 0; k < 3; ++k) {
      Env e = env;
      e.relativeAxis = name == "s" ? 3 : int(k);
      e.relativeIndex = int(k);
      item.args.push_back(expr(argCtx[k], e));
    }
    if (!allOk(item.args)) return;
    push(std::move(item));
    return;
  }
  if (name == "translate" || name == "rotate") {
    // translate|rotate(rel|abs, scope|pivot|object|world, x, y, z) (op_translate,
    // op_rotate: about the scope's origin): fgsg's Translate / Rotate, which take every
    // mode and system (backend/commands/shape_operations.cpp; docs/cga.md), or T / R.
    const bool moves = name == "translate";
    if (!noBody() || !count(5, 5, moves ? "5 arguments (rel or abs, scope, pivot, object or world, x, y, z)"
                                        : "5 arguments (rel or abs, scope, pivot, object or world, x, y, z angles)"))
      return;
    const std::string mode = selectorWord(argCtx[0]), system = selectorWord(argCtx[1]);
    if (mode != "rel" && mode != "abs") {
      error("E028", rangeOf(argCtx[0]), name + "'s mode is rel or abs, not '" + argCtx[0]->getText() + "'");
      return;
    }
    if (system != "scope" && system != "world" && system != "pivot" && system != "object") {
      error("E028", rangeOf(argCtx[1]),
            name + "'s coordinate system is scope, pivot, object or world, not '" + argCtx[1]->getText() + "'");
      return;
    }
    // In the scope's own system abs is rel (the scope stands at its origin, unturned):
    // both are t() / r().
    Item item = command(system == "scope" ? (moves ? "T" : "R") : (moves ? "Translate" : "Rotate"), at);
    if (system != "scope") {
      item.args.push_back(stringExpr(mode, rangeOf(argCtx[0])));
      item.args.push_back(stringExpr(system, rangeOf(argCtx[1])));
    }
    for (size_t k = 2; k < 5; ++k) item.args.push_back(expr(argCtx[k], env));
    if (!allOk(item.args)) return;
    push(std::move(item));
    return;
  }
  if (name == "r") {
    if (!noBody() || !count(3, 4, "3 angles, or scopeCenter / scopeOrigin and 3 angles")) return;
    std::string pivot = argCtx.size() == 4 ? selectorWord(argCtx[0]) : "scopeOrigin";
    if (pivot != "scopeOrigin" && pivot != "scopeCenter") {
      notSupported(rangeOf(argCtx[0]), "rotating about '" + argCtx[0]->getText() + "'");
      return;
    }
    Item rot = command("R", at);
    for (size_t k = argCtx.size() - 3; k < argCtx.size(); ++k) rot.args.push_back(expr(argCtx[k], env));
    if (!allOk(rot.args)) return;
    auto half = [&](bool back) {
      Item t = command("T", at);
      for (int axis = 0; axis < 3; ++axis) {
        ExprPtr h = binary("/", scopeSize(axis, at), number(back ? -2.0 : 2.0, at));
        t.args.push_back(std::move(h));
      }
      return t;
    };
    if (pivot == "scopeCenter") push(half(false));
    push(std::move(rot));
    if (pivot == "scopeCenter") push(half(true));
    return;
  }
  if (name == "center") {
    if (!noBody() || !count(1, 1, "1 argument (x, y, z, xy, xz, yz or xyz)")) return;
    std::string axes = selectorWord(argCtx[0]);
    for (char& c : axes) c = char(std::toupper(static_cast<unsigned char>(c)));
    if (axes.empty() || axes.find_first_not_of("XYZ") != std::string::npos) {
      error("E028", rangeOf(argCtx[0]), "center takes the axes to centre on: x, y, z, xy, xz, yz or xyz");
      return;
    }
    Item item = command("Center", at);
    item.args.push_back(stringExpr(axes, rangeOf(argCtx[0])));
    push(std::move(item));
    return;
  }
  auto colorItem = [&](std::vector<P::ExprContext*> values) {
    Item item = command("Color", at);
    for (auto* v : values) item.args.push_back(expr(v, env));
    if (!allOk(item.args)) return;
    if (item.args.size() == 1 && item.args[0]->kind == ExprKind::String)
      item.args[0]->text = fullColor(item.args[0]->text);
    push(std::move(item));
  };
  if (name == "color") {
    if (!noBody() || !count(1, 4, "a \"#rrggbb\" string or r, g, b, and the opacity after either")) return;
    if (argCtx.size() == 4 || argCtx.size() == 2) {
      // color(r, g, b, a) and color("#rrggbb", a): the colour, and a as material.opacity.
      colorItem({argCtx.begin(), argCtx.end() - 1});
      materialItem(op, "opacity", env, seq);
      return;
    }
    colorItem(argCtx);
    return;
  }
  if (name == "set") {
    if (!noBody() || !count(2, 2, "2 arguments (attribute, value)")) return;
    const std::string what = selectorWord(argCtx[0]);
    if (what == "material.color.rgb" || what == "material.color") {
      colorItem({argCtx[1]});
      return;
    }
    // material.roughness / metallic / opacity / color.r|g|b / emissive.r|g|b and the maps
    // (colormap ... metallicmap): fgsg's Material(property, value) (texture() is
    // set(material.colormap, ...)).
    if (what.rfind("material.", 0) == 0 && materialProperty(what.substr(9)) >= 0) {
      materialItem(op, what.substr(9), env, seq);
      return;
    }
    // The trim attribute (attr_trim): fgsg's SetTrim("horizontal" | "vertical", on).
    if (what == "trim.horizontal" || what == "trim.vertical") {
      ExprPtr on = expr(argCtx[1], env);
      if (!on) return;
      if (on->kind == ExprKind::Bool) on->kind = ExprKind::Number, on->number = on->boolean ? 1 : 0;
      Item item = command("SetTrim", rangeOf(op));
      item.args.push_back(stringExpr(what.substr(5), rangeOf(argCtx[0])));
      item.args.push_back(std::move(on));
      seq.out.items.push_back(std::move(item));
      return;
    }
    notSupported(rangeOf(argCtx[0]), "set(" + argCtx[0]->getText() + ", ...)");
    return;
  }
  if (name == "texture") {
    if (!noBody() || !count(1, 1, "1 argument (the image)")) return;
    materialItem(op, "colormap", env, seq);
    return;
  }
  if (name == "setupProjection" || name == "projectUV" || name == "tileUV" || name == "scaleUV" ||
      name == "translateUV" || name == "rotateUV" || name == "normalizeUV" || name == "deleteUV" ||
      name == "copyUV") {
    if (!noBody()) return;
    uvOperation(op, env, seq);
    return;
  }
  if (name == "print" && !findCommand("Print")) return;  // CityEngine's console: nothing to generate
  if (name == "report" || name == "label" || name == "print") {
    const std::string fgsgName = name == "report" ? "Report" : name == "print" ? "Print" : "Label";
    if (!findCommand(fgsgName)) {
      notSupported(nameAt, "the operation '" + name + "'");
      return;
    }
    if (!noBody()) return;
    Item item = command(fgsgName, at);
    item.args = args(env);
    if (!allOk(item.args)) return;
    push(std::move(item));
    return;
  }
  if (std::optional<Item> shaped; shapeOperation(op, env, shaped)) {
    if (!shaped) return;
    flushInsert();
    if (shaped->hasBody) seq.createsShapes = true;
    push(std::move(*shaped));
    return;
  }
  if (isCityEngineOperation(name)) {
    error("E800", nameAt, "unknown operation '" + name + "' (CityEngine CGA; not supported yet)");
    return;
  }
  if (dot != std::string::npos) {
    error("E010", nameAt, "unknown name '" + name + "' (no import is called '" + name.substr(0, dot) + "')");
    return;
  }
  if (std::islower(static_cast<unsigned char>(name[0]))) {
    std::vector<std::string> known(std::begin(kCityEngineOperations), std::end(kCityEngineOperations));
    for (const auto& [rule, params] : rules_) known.push_back(rule);
    const std::string near = closestName(name, known);  // "extrud": extrude, or a rule's slip
    error("E800", nameAt, "unknown operation '" + name + "'" + (near.empty() ? "" : "; did you mean '" + near + "'?") +
                              " (no rule of this file has that name)");
    return;
  }
  // CityEngine derives a shape of a rule it does not have as a leaf (and warns).
  if (!noBody()) return;
  pushShape();
}

void Translator::split(P::CallOperationContext* op, const std::string& axisWord, Sequence& seq, const Env& env) {
  const SourceRange at = rangeOf(op);
  const auto argCtx = op->expr();
  const std::string name = op->name->getText();  // split or splitArea (sizes that are areas)
  if ((axisWord == "u" || axisWord == "v") && name == "split") {
    notSupported(rangeOf(argCtx[0]), "a split in texture space (u, v)");
    return;
  }
  if (axisWord != "x" && axisWord != "y" && axisWord != "z") {
    error("E028", rangeOf(argCtx[0]), name + " splits along x, y or z, not '" + argCtx[0]->getText() + "'");
    return;
  }
  if (argCtx.size() == 2) {
    const std::string adjust = selectorWord(argCtx[1]);
    if (adjust != "adjust" && adjust != "noAdjust") {
      error("E028", rangeOf(argCtx[1]), name + "'s second argument is adjust or noAdjust");
      return;
    }
  }
  if (!op->splitBody()) {
    error("E018", at, name + " needs its parts: " + name + "(" + axisWord + "){ 2 : A | ~1 : B }");
    return;
  }
  if (seq.pendingInsert) {
    seq.out.items.push_back(std::move(*seq.pendingInsert));
    seq.pendingInsert.reset();
  }
  Item item = command(name == "splitArea" ? "SplitArea" : "Subdiv", at);
  item.args.push_back(stringExpr(std::string(1, char(std::toupper(axisWord[0]))), rangeOf(argCtx[0])));
  splitBody(op->splitBody(), axisWord, item, env);
  seq.out.items.push_back(std::move(item));
  seq.createsShapes = true;
}

void Translator::splitBody(P::SplitBodyContext* body, const std::string& axisWord, Item& item, const Env& env) {
  item.cityEngineSizing = true;
  item.hasBody = true;
  item.repeatPattern = body->repeat != nullptr;
  const int axis = axisWord[0] - 'x';
  const bool byArea = item.name == "SplitArea";
  for (P::SplitPartContext* partCtx : body->splitPart()) {
    Successor part;
    part.range = rangeOf(partCtx);
    if (auto* nested = dynamic_cast<P::NestedPartContext*>(partCtx); nested && byArea) {
      notSupported(part.range, "a group of parts `{ ... }*` inside splitArea");
      continue;
    }
    if (auto* nested = dynamic_cast<P::NestedPartContext*>(partCtx)) {
      // `{ ... }*` among the parts: a repeat that takes what the other parts leave.
      if (item.repeatPattern || !nested->splitBody()->repeat) {
        notSupported(part.range, item.repeatPattern ? "a repeat inside a repeated split"
                                                    : "a group of parts `{ ... }` without `*`");
        continue;
      }
      Item inner = command("Subdiv", part.range);
      inner.args.push_back(cloneExpr(*item.args[0]));
      splitBody(nested->splitBody(), axisWord, inner, env);
      part.items.push_back(std::move(inner));
      ExprPtr share = makeExpr(ExprKind::RelSize, part.range);
      share->number = 1;
      item.args.push_back(std::move(share));
      item.body.push_back(std::move(part));
      continue;
    }
    auto* sized = static_cast<P::SizedPartContext*>(partCtx);
    if (sized->sep->getText() != ":")
      error("E002", rangeOf(sized->sep), "a split's part is `size : operations` (`=` belongs to comp)");
    Env e = env;
    e.relativeAxis = byArea ? 4 : axis;  // splitArea: 'x is that share of the shape's area
    ExprPtr size = expr(sized->key, e);
    if (!size) continue;
    operations(sized->operation(), 0, part, env, true);
    item.args.push_back(std::move(size));
    item.body.push_back(std::move(part));
  }
}

void Translator::comp(P::CallOperationContext* op, Sequence& seq, const Env& env) {
  const SourceRange at = rangeOf(op);
  const auto argCtx = op->expr();
  if (argCtx.size() != 1) {
    error("E016", rangeOf(op->name), "comp takes 1 argument (f), got " + std::to_string(argCtx.size()));
    return;
  }
  const std::string kind = selectorWord(argCtx[0]);
  if (kind != "f" && kind != "e" && kind != "v") {
    notSupported(rangeOf(argCtx[0]), "comp(" + argCtx[0]->getText() + ")");
    return;
  }
  if (!op->splitBody() || op->splitBody()->repeat) {
    error("E018", at, "comp(" + kind + ") needs its parts: comp(" + kind + "){ " +
                          (kind == "f" ? "top : Roof | side : Facade" : "all : Post") + " }");
    return;
  }
  if (kind != "f") {
    compEdgesOrVertices(op, kind, seq, env);
    return;
  }
  if (seq.pendingInsert) {
    seq.out.items.push_back(std::move(*seq.pendingInsert));
    seq.pendingInsert.reset();
  }
  Item item = command("Comp", at);
  item.args.push_back(stringExpr("f", rangeOf(argCtx[0])));
  item.hasBody = true;
  for (P::SplitPartContext* partCtx : op->splitBody()->splitPart()) {
    auto* sized = dynamic_cast<P::SizedPartContext*>(partCtx);
    if (!sized) {
      error("E018", rangeOf(partCtx), "comp's parts are `selector : operations`");
      continue;
    }
    const std::string sel = cgaCompSelectorLabel(kind, selectorWord(sized->key), sized->key->getText());
    if (sel.empty()) {
      notSupported(rangeOf(sized->key), "the comp selector '" + sized->key->getText() + "'");
      continue;
    }
    Successor part;
    part.range = rangeOf(partCtx);
    // `=`: the faces it takes merged into one shape (fgsg's label "side=").
    part.selector = sized->sep->getText() == "=" ? sel + "=" : sel;
    part.selectorRange = rangeOf(sized->key);
    operations(sized->operation(), 0, part, env, true);
    item.body.push_back(std::move(part));
  }
  seq.out.items.push_back(std::move(item));
  seq.createsShapes = true;
}

// comp(e){ ... } and comp(v){ ... }: fgsg's Comp("e") / Comp("v"), each edge or vertex a
// shape of its own going to the first part whose selector takes it (cgaCompSelectorLabel:
// the sides and slopes of its normal, border / inside, world.* / object.*, its index;
// comp(e) also CityEngine's roof edges `eave ridge hip valley gable`; street.*); with `=`
// all it takes are one shape. One `all :` alone is an unlabelled body.
void Translator::compEdgesOrVertices(P::CallOperationContext* op, const std::string& kind, Sequence& seq,
                                     const Env& env) {
  std::vector<P::SizedPartContext*> parts;
  std::vector<std::string> labels;
  for (P::SplitPartContext* partCtx : op->splitBody()->splitPart()) {
    auto* sized = dynamic_cast<P::SizedPartContext*>(partCtx);
    if (!sized) {
      error("E018", rangeOf(partCtx), "comp's parts are `selector : operations`");
      return;
    }
    const std::string label = cgaCompSelectorLabel(kind, selectorWord(sized->key), sized->key->getText());
    if (label.empty()) {
      notSupported(rangeOf(sized->key), "the comp(" + kind + ") selector '" + sized->key->getText() + "'");
      return;
    }
    parts.push_back(sized);
    // `=`: the components it takes merged into one shape (fgsg's label "all=").
    labels.push_back(sized->sep->getText() == "=" ? label + "=" : label);
  }
  if (parts.empty()) {
    error("E018", rangeOf(op->splitBody()), "comp(" + kind + ") needs its parts: comp(" + kind + "){ all : A }");
    return;
  }
  if (seq.pendingInsert) {
    seq.out.items.push_back(std::move(*seq.pendingInsert));
    seq.pendingInsert.reset();
  }
  Item item = command("Comp", rangeOf(op));
  item.args.push_back(stringExpr(kind, rangeOf(op->expr()[0])));
  item.hasBody = true;
  // One `all` alone stays an unlabelled body (every edge or vertex).
  const bool labelled = parts.size() > 1 || labels[0] != "all";
  for (size_t k = 0; k < parts.size(); ++k) {
    P::SizedPartContext* sized = parts[k];
    Successor part;
    part.range = rangeOf(sized);
    if (labelled) {
      part.selector = labels[k];
      part.selectorRange = rangeOf(sized->key);
    }
    operations(sized->operation(), 0, part, env, true);
    item.body.push_back(std::move(part));
  }
  seq.out.items.push_back(std::move(item));
  seq.createsShapes = true;
}

// `offset(-d) comp(f) { inside : A | border : B }`: the comp's parts become the Offset's
// inside and border bodies (`=` too: each piece is one shape either way). False (nothing
// done) when the operation after the offset is not such a comp.
bool Translator::offsetComp(const std::vector<P::OperationContext*>& ops, size_t next, Item& offset, const Env& env) {
  if (next >= ops.size()) return false;
  auto* c = dynamic_cast<P::CallOperationContext*>(ops[next]);
  if (!c || c->name->getText() != "comp" || c->expr().size() != 1 || selectorWord(c->expr()[0]) != "f" ||
      !c->splitBody() || c->splitBody()->repeat)
    return false;
  std::vector<P::SizedPartContext*> parts;
  for (P::SplitPartContext* partCtx : c->splitBody()->splitPart()) {
    auto* sized = dynamic_cast<P::SizedPartContext*>(partCtx);
    const std::string sel = sized ? selectorWord(sized->key) : "";
    if (sel != "inside" && sel != "border") return false;
    parts.push_back(sized);
  }
  for (P::SizedPartContext* sized : parts) {
    Successor part;
    part.range = rangeOf(sized);
    part.selector = selectorWord(sized->key);
    part.selectorRange = rangeOf(sized->key);
    operations(sized->operation(), 0, part, env, true);
    offset.body.push_back(std::move(part));
  }
  offset.hasBody = true;
  if (next + 1 < ops.size())
    warning("W800", rangeOf(ops[next + 1]), "operations after comp(f) { ... } are never applied (comp replaces the shape)");
  return true;
}

// An asset or image named by a .cga file, found as CityEngine finds it: beside the rule
// file, in its assets/ folder, or in the project (the folders above it, whose assets/
// holds CityEngine's). Found: the path becomes absolute. Missing: W801 once per path.
bool Translator::assetPath(std::string& path, const SourceRange& at, const char* what, bool warnMissing) {
  std::error_code ec;
  if (fs::path(path).is_absolute()) {
    if (fs::is_regular_file(path, ec)) return true;
  } else {
    fs::path dir = fs::absolute(fs::path(fileName_), ec).parent_path();
    for (int up = 0; up < 4 && !dir.empty(); ++up, dir = dir.parent_path()) {
      for (const fs::path& c : {dir / path, dir / "assets" / path})
        if (fs::is_regular_file(c, ec)) {
          path = c.lexically_normal().string();
          return true;
        }
      if (dir == dir.parent_path()) break;
    }
  }
  if (warnMissing && warnedAssets_.insert(path).second)
    warning("W801", at, std::string("the ") + what + " '" + path +
                            "' is not found (beside the rule file, in its assets/ folder or the project's): "
                            "skipped, as CityEngine does");
  return false;
}

// i(asset[, yUp|zUp[, alignSizeAndPosition|keepSizeAndPosition|keepSizeAlignPosition]]):
// I("asset", "zUp", "keepSizeAndPosition") (runtime/insert_fit.h fits it).
void Translator::insert(P::CallOperationContext* op, Sequence& seq, const Env& env) {
  const auto argCtx = op->expr();
  const SourceRange at = rangeOf(op);
  if (argCtx.empty() || argCtx.size() > 3) {
    if (argCtx.size() > 3) notSupported(rangeOf(argCtx[3]), "i()'s cleanup mode");
    else error("E016", rangeOf(op->name), "i takes the asset to insert");
    return;
  }
  std::vector<ExprPtr> words;
  for (size_t k = 1; k < argCtx.size(); ++k) {
    const std::string word = selectorWord(argCtx[k]);
    const bool known = k == 1 ? word == "yUp" || word == "zUp"
                              : word == "alignSizeAndPosition" || word == "keepSizeAndPosition" ||
                                    word == "keepSizeAlignPosition";
    if (!known) {
      error("E028", rangeOf(argCtx[k]),
            "i()'s " + std::string(k == 1 ? "up axis is yUp or zUp" :
                                            "insert mode is alignSizeAndPosition, keepSizeAndPosition or "
                                            "keepSizeAlignPosition") +
                ", not '" + argCtx[k]->getText() + "'");
      return;
    }
    words.push_back(stringExpr(word, rangeOf(argCtx[k])));
  }
  ExprPtr asset = expr(argCtx[0], env);
  if (!asset) return;
  if (ExprPtr pinned = pinnedAttrString(*asset, rangeOf(argCtx[0]))) asset = std::move(pinned);
  if (asset->kind == ExprKind::String) {
    std::string& p = asset->text;
    if (p.rfind("builtin:", 0) == 0) {
      // CityEngine's built-in assets keep their names (runtime/assets.cpp builds them).
      const std::string b = p.substr(8);
      if (b != "cube" && b != "unitQuad") {
        notSupported(rangeOf(argCtx[0]), "the built-in asset '" + p + "'");
        return;
      }
    } else if (!assetPath(p, at, "asset")) {
      return;
    }
  }
  Item item = command("I", at);
  item.args.push_back(std::move(asset));
  for (ExprPtr& w : words) item.args.push_back(std::move(w));
  if (seq.pendingInsert) seq.out.items.push_back(std::move(*seq.pendingInsert));
  seq.pendingInsert = std::make_unique<Item>(std::move(item));
}

// set(material.X, v) and texture(x) (= set(material.colormap, x)): Material("X", v). An
// image is found as CityEngine finds it (assetPath); "" is "none" (no image).
void Translator::materialItem(P::CallOperationContext* op, const std::string& property, const Env& env, Sequence& seq) {
  const auto argCtx = op->expr();
  const SourceRange at = rangeOf(op);
  ExprPtr value = expr(argCtx.back(), env);
  if (!value) return;
  if (materialPropertyIsImage(materialProperty(property))) {
    if (ExprPtr pinned = pinnedAttrString(*value, rangeOf(argCtx.back()))) value = std::move(pinned);
    if (value->kind != ExprKind::String) {
      notSupported(rangeOf(argCtx.back()), "an image name that is not a constant string");
      return;
    }
    if (value->text.empty()) value->text = "none";
    else if (value->text != "none" && !assetPath(value->text, at, "texture")) return;
  }
  Item item = command("Material", at);
  item.args.push_back(stringExpr(property, rangeOf(argCtx[0])));
  item.args.push_back(std::move(value));
  seq.out.items.push_back(std::move(item));
}

// CGA's uv operations on uv sets 0..9: setupProjection(0, scope.xz, w, h)
// SetupProjection("xz", w, h), tileUV TileUV, scaleUV ScaleUV, translateUV TranslateUV,
// rotateUV RotateUV, normalizeUV(0, mode, collectiveAllFaces) NormalizeUV(mode);
// projectUV(0) ProjectUV (which only matters after deleteUV: the projection applies to the
// leaves below it when they are output), deleteUV(0) DeleteUV; copyUV(s, d) CopyUV(s, d)
// (nothing where s = d). A set other than 0 is the fgsg command's last argument. A relative size `'x` is x times the scope's size along the axis (setupProjection)
// or the shape's extent in the projection (tileUV); `~w` a floating size.
void Translator::uvOperation(P::CallOperationContext* op, const Env& env, Sequence& seq) {
  const std::string name = op->name->getText();
  const auto argCtx = op->expr();
  const SourceRange at = rangeOf(op);
  struct Form {
    const char* cga;
    const char* fgsg;
    size_t args;
    const char* forms;
  };
  static const Form kForms[] = {
      {"setupProjection", "SetupProjection", 4, "4 arguments (uvSet, scope.xy, textureWidth, textureHeight)"},
      {"projectUV", "ProjectUV", 1, "1 argument (the uv set)"},
      {"deleteUV", "DeleteUV", 1, "1 argument (the uv set)"},
      {"copyUV", "CopyUV", 2, "2 arguments (uvSetSource, uvSetDest)"},
      {"tileUV", "TileUV", 3, "3 arguments (uvSet, textureWidth, textureHeight)"},
      {"scaleUV", "ScaleUV", 3, "3 arguments (uvSet, uFactor, vFactor)"},
      {"translateUV", "TranslateUV", 3, "3 arguments (uvSet, uOffset, vOffset)"},
      {"rotateUV", "RotateUV", 2, "2 arguments (uvSet, angle)"},
      {"normalizeUV", "NormalizeUV", 3, "3 arguments (uvSet, uv|uvUniform|u|v, separatePerFace|collectiveAllFaces)"}};
  const Form* form = nullptr;
  for (const Form& f : kForms)
    if (name == f.cga) form = &f;
  if (name == "setupProjection" && (argCtx.size() == 6 || argCtx.size() == 7)) {
    notSupported(rangeOf(argCtx[4]), "setupProjection's offsets and uwFactor");
    return;
  }
  if (argCtx.size() != form->args) {
    error("E016", rangeOf(op->name), "'" + name + "' takes " + form->forms + ", got " + std::to_string(argCtx.size()));
    return;
  }
  ExprPtr sets[2];
  for (size_t k = 0; k < (name == "copyUV" ? 2u : 1u); ++k) {
    sets[k] = expr(argCtx[k], env);
    if (!sets[k]) return;
    const double n = sets[k]->number;
    if (sets[k]->kind != ExprKind::Number || !(n >= 0 && n <= 9) || n != std::floor(n)) {
      error("E028", rangeOf(argCtx[k]), "a uv set is a whole number from 0 to 9 (CityEngine's texture layers), not '" +
                                            argCtx[k]->getText() + "'");
      return;
    }
  }
  if (name == "copyUV") {
    if (sets[0]->number == sets[1]->number) return;  // the set onto itself
    Item item = command("CopyUV", at);
    item.args.push_back(std::move(sets[0]));
    item.args.push_back(std::move(sets[1]));
    seq.out.items.push_back(std::move(item));
    return;
  }
  // Set 0 as the command's default: a grammar on set 0 lowers as it did before sets.
  ExprPtr set = sets[0]->number != 0 ? std::move(sets[0]) : nullptr;
  Item item = command(form->fgsg, at);
  size_t first = 1;
  if (name == "setupProjection") {
    const std::string axes = selectorWord(argCtx[1]);
    static const char* const kAxes[] = {"xy", "xz", "yz", "yx", "zx", "zy"};
    const bool world = axes.rfind("world.", 0) == 0;
    bool known = axes.rfind("scope.", 0) == 0 || world;
    bool pair = false;
    for (const char* k : kAxes) pair |= known && axes.substr(6) == k;
    if (!pair) {
      error("E028", rangeOf(argCtx[1]), "setupProjection's axes are scope.xy, scope.xz, scope.yz, scope.yx, scope.zx, scope.zy "
                                        "or world.xy ... world.zy, not '" + argCtx[1]->getText() + "'");
      return;
    }
    item.args.push_back(stringExpr(world ? axes : axes.substr(6), rangeOf(argCtx[1])));
    first = 2;
  }
  if (name == "normalizeUV") {
    const std::string mode = selectorWord(argCtx[1]), type = selectorWord(argCtx[2]);
    if (mode != "uv" && mode != "uvUniform" && mode != "u" && mode != "v") {
      error("E028", rangeOf(argCtx[1]), "normalizeUV's mode is uv, uvUniform, u or v, not '" + argCtx[1]->getText() + "'");
      return;
    }
    if (type == "separatePerFace") {
      notSupported(rangeOf(argCtx[2]), "normalizeUV per face (separatePerFace)");
      return;
    }
    if (type != "collectiveAllFaces") {
      error("E028", rangeOf(argCtx[2]), "normalizeUV's type is separatePerFace or collectiveAllFaces, not '" + argCtx[2]->getText() + "'");
      return;
    }
    item.args.push_back(stringExpr(mode, rangeOf(argCtx[1])));
    if (set) item.args.push_back(std::move(set));
    seq.out.items.push_back(std::move(item));
    return;
  }
  const bool sized = name == "setupProjection" || name == "tileUV";
  for (size_t k = first; k < argCtx.size(); ++k) {
    Env e = env;
    if (sized) {
      // 'x: fgsg's relative size (the runtime knows what it is relative to).
      e.relativeAxis = 3;
      e.relativeIndex = name == "setupProjection" ? item.args[0]->text[item.args[0]->text.size() - 2 + (k - first)] - 'x' : 0;
    }
    ExprPtr v = expr(argCtx[k], e);
    if (!v) return;
    item.args.push_back(std::move(v));
  }
  if (set) item.args.push_back(std::move(set));
  seq.out.items.push_back(std::move(item));
}

}  // namespace fgsg::frontend::cga
