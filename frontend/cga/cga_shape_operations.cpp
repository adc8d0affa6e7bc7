// The `.cga` dialect's footprint-shaping and scope operations (issue #44) as fgsg's
// commands of frontend/shape_operations.h:
//
//   alignScopeToAxes() / (x|y|z)              AlignScopeToAxes() / ("y")
//   alignScopeToGeometry(yUp|zUp, i|largest, j|longest)
//                                             AlignScopeToGeometry("y", i or "largest", j or "longest")
//   rotateScope(x, y, z)  mirrorScope(...)  mirror(...)
//                                             RotateScope  MirrorScope  Mirror (true/false as 1/0)
//   setback(d){ front : A | street.front = B | remainder : C }
//                                             Setback(d){ front: A | streetFront=: B | remainder: C }
//                                             (object.x as x, world.north as north; `=` merged;
//                                             an edge index `0 : A`, `-1 : B` as `0: A`, `-1: B`)
//   setbackToArea(area){ ... }  setbackPerEdge(distance){ ... }
//                                             SetbackToArea  SetbackPerEdge (distance evaluated per edge)
//   shapeL/U/O(...){ shape : A | remainder : B }, innerRectangle(scope|edge){ shape : A }
//   deleteHoles() reverseNormals() resetGeometry() cleanupGeometry(what, tolerance) convexify(maxLength)
//   trim()                                    ApplyTrimPlanes()  (set(trim.horizontal|vertical, b): SetTrim, cga_operations.cpp)
//   taper(height)
//   insertAlongUV(uvSet, asset, height[, scope.y|vertex.normal[, alignPosition|keepPosition]])
//                                             InsertAlongUV(uvSet, "asset", height, ...) (asset found as i() finds it)
//   envelope(normal|world.up, maxHeight, frontBase, frontAngle, ...)
//                                             Envelope("normal", maxHeight, frontBase, frontAngle, ...)
//   envelope(normal|world.up, maxHeight, [b0, b1, ...], [a0, a1, ...])
//                                             EnvelopePerEdge("normal", maxHeight, b0, a0, b1, a1, ...)
//   primitiveQuad/Cube/Cylinder/Sphere/Disk(...)
#include "frontend/builtins.h"
#include "frontend/cga/cga_translator.h"
#include "frontend/shape_operations.h"
#include "runtime/cga/edge_index_label.h"

#include <algorithm>
#include <map>
#include <optional>
#include <tuple>

namespace fgsg::frontend::cga {

namespace {

// CityEngine's name -> fgsg's command.
const std::map<std::string, std::string>& shapeOperationNames() {
  static const std::map<std::string, std::string> names = {
      {"alignScopeToAxes", "AlignScopeToAxes"}, {"alignScopeToGeometry", "AlignScopeToGeometry"},
      {"rotateScope", "RotateScope"},           {"mirrorScope", "MirrorScope"},
      {"mirror", "Mirror"},                     {"setback", "Setback"},
      {"setbackToArea", "SetbackToArea"},       {"setbackPerEdge", "SetbackPerEdge"},
      {"convexify", "Convexify"},               {"taper", "Taper"},
      {"envelope", "Envelope"},                 {"insertAlongUV", "InsertAlongUV"},
      {"shapeL", "ShapeL"},                     {"shapeU", "ShapeU"},
      {"shapeO", "ShapeO"},                     {"innerRectangle", "InnerRectangle"},
      {"innerRect", "InnerRectangle"},          {"deleteHoles", "DeleteHoles"},
      {"reverseNormals", "ReverseNormals"},     {"resetGeometry", "ResetGeometry"},
      {"cleanupGeometry", "CleanupGeometry"},   {"primitiveQuad", "PrimitiveQuad"},
      {"primitiveCube", "PrimitiveCube"},       {"primitiveCylinder", "PrimitiveCylinder"},
      {"primitiveSphere", "PrimitiveSphere"},   {"primitiveDisk", "PrimitiveDisk"},
      {"setPivot", "SetPivot"},                 {"trim", "ApplyTrimPlanes"}};
  return names;
}

// A setback selector as fgsg's label ("" when it has none).
std::string setbackLabel(const std::string& sel) {
  static const std::map<std::string, std::string> labels = {
      {"front", "front"},         {"back", "back"},           {"left", "left"},
      {"right", "right"},         {"side", "side"},           {"all", "all"},
      {"remainder", "remainder"}, {"object.front", "front"},  {"object.back", "back"},
      {"object.left", "left"},    {"object.right", "right"},  {"object.side", "side"},
      {"street.front", "streetFront"}, {"street.back", "streetBack"}, {"street.left", "streetLeft"},
      {"street.right", "streetRight"}, {"street.side", "streetSide"}, {"streetSide", "streetFront"},
      {"world.north", "north"},   {"world.south", "south"},   {"world.east", "east"},
      {"world.west", "west"}};
  const auto it = labels.find(sel);
  return it == labels.end() ? "" : it->second;
}

// An array written out, `[1, 2, 3]`: its elements; nullopt for anything else.
std::optional<std::vector<P::ExprContext*>> envelopeArrayLiteral(P::ExprContext* e) {
  auto* primary = dynamic_cast<P::PrimaryExprContext*>(e);
  auto* array = primary ? dynamic_cast<P::ArrayPrimaryContext*>(primary->primary()) : nullptr;
  if (!array) return std::nullopt;
  return array->expr();
}

}  // namespace

bool Translator::shapeOperation(P::CallOperationContext* op, const Env& env, std::optional<Item>& item) {
  const std::string name = op->name->getText();
  const auto found = shapeOperationNames().find(name);
  if (found == shapeOperationNames().end()) return false;
  const std::string& fgsgName = found->second;
  const CommandInfo& info = *findCommand(fgsgName);
  const SourceRange at = rangeOf(op);
  const auto argCtx = op->expr();
  if (int(argCtx.size()) < info.minArgs || int(argCtx.size()) > info.maxArgs) {
    error("E016", rangeOf(op->name), "'" + name + "' takes " + std::to_string(info.minArgs) +
                                         (info.minArgs == info.maxArgs ? "" : " to " + std::to_string(info.maxArgs)) +
                                         " arguments, got " + std::to_string(argCtx.size()));
    return true;
  }
  if (std::string forms; !shapeOperationArity(fgsgName, argCtx.size(), forms)) {
    error("E016", rangeOf(op->name), "'" + name + "' takes " + forms + ", got " + std::to_string(argCtx.size()));
    return true;
  }
  if (fgsgName == "Envelope") {  // op_envelope's direction is one of two selectors
    double code = 0;
    std::string allowed;
    if (!shapeOperationWord(fgsgName, 0, selectorWord(argCtx[0]), code, allowed)) {
      error("E028", rangeOf(argCtx[0]), "envelope's direction is normal or world.up, not '" + argCtx[0]->getText() + "'");
      return true;
    }
  }
  if (fgsgName == "SetPivot") {  // op_setPivot's axisMap is one of three selectors
    double code = 0;
    std::string allowed;
    if (!shapeOperationWord(fgsgName, 0, selectorWord(argCtx[0]), code, allowed)) {
      error("E028", rangeOf(argCtx[0]), "setPivot's axisMap is xyz, yzx or zxy, not '" + argCtx[0]->getText() + "'");
      return true;
    }
  }
  if (fgsgName == "Envelope" && argCtx.size() == 4 &&
      (envelopeArrayLiteral(argCtx[2]) || envelopeArrayLiteral(argCtx[3])))
    return envelopePerEdge(op, env, item);
  if (fgsgName == "InsertAlongUV")  // op_insertAlongUV's selectors (arguments 4 and 5)
    for (size_t k = 3; k < argCtx.size(); ++k) {
      double code = 0;
      std::string allowed;
      if (!shapeOperationWord(fgsgName, k, selectorWord(argCtx[k]), code, allowed)) {
        error("E028", rangeOf(argCtx[k]), std::string("insertAlongUV's ") +
                                              (k == 3 ? "heightDirection" : "heightAlignment") + " is " + allowed +
                                              ", not '" + argCtx[k]->getText() + "'");
        return true;
      }
    }
  Item made = command(fgsgName, at);
  for (size_t k = 0; k < argCtx.size(); ++k) {
    if (fgsgName == "InsertAlongUV" && k == 1) {
      // The asset, found as i() finds it (a built-in keeps its name); one not found stays
      // as written, and the derivation reports it at the operation (R003).
      ExprPtr asset = expr(argCtx[k], env);
      if (!asset) return true;
      if (asset->kind == ExprKind::String && asset->text.rfind("builtin:", 0) != 0)
        assetPath(asset->text, rangeOf(argCtx[k]), "asset", false);
      made.args.push_back(std::move(asset));
      continue;
    }
    // A selector word (`y`, `largest`, `scope`, `vertices`) is the command's string argument.
    std::string word = selectorWord(argCtx[k]);
    if (word == "yUp" || word == "zUp") word = word.substr(0, 1);
    if (word.rfind("world.", 0) == 0 && fgsgName == "AlignScopeToAxes") word = word.substr(6);
    double code = 0;
    std::string allowed;
    if (!word.empty() && shapeOperationWord(fgsgName, k, word, code, allowed)) {
      ExprPtr s = makeExpr(ExprKind::String, rangeOf(argCtx[k]));
      s->text = word;
      made.args.push_back(std::move(s));
      continue;
    }
    ExprPtr e = expr(argCtx[k], env);
    if (!e) return true;
    if (e->kind == ExprKind::Bool) {  // mirror(true, false, false): flips as 1 and 0
      e->kind = ExprKind::Number;
      e->number = e->boolean ? 1 : 0;
    }
    made.args.push_back(std::move(e));
  }
  const bool takesBody = info.body != BodyRule::None;
  if (!op->splitBody()) {
    if (takesBody && info.body != BodyRule::Optional) {
      error("E018", at, "'" + name + "' needs its parts: " + name + "(...){ " +
                            (fgsgName.rfind("Setback", 0) == 0 ? "front" : "shape") + " : A | remainder : B }");
      return true;
    }
    item = std::move(made);
    return true;
  }
  if (!takesBody || op->splitBody()->repeat) {
    error("E018", rangeOf(op->splitBody()), "'" + name + "' takes no { } body");
    return true;
  }
  made.hasBody = true;
  for (P::SplitPartContext* partCtx : op->splitBody()->splitPart()) {
    auto* sized = dynamic_cast<P::SizedPartContext*>(partCtx);
    if (!sized) {
      error("E018", rangeOf(partCtx), "'" + name + "''s parts are `selector : operations`");
      continue;
    }
    const std::string sel = selectorWord(sized->key);
    const bool edges = fgsgName.rfind("Setback", 0) == 0;
    std::string label = edges ? setbackLabel(sel) : (sel == "shape" || sel == "remainder") ? sel : "";
    // An index selector, `{ 0 : A | -1 : B }`: a whole number written out (op_setback's
    // index, wrapping around modulo the edge count at derivation).
    const std::string written = sized->key->getText();
    const size_t sign = !written.empty() && written[0] == '-' ? 1 : 0;
    if (edges && label.empty() && written.size() > sign && written.size() < 10 + sign &&
        written.find_first_not_of("0123456789", sign) == std::string::npos)
      label = rt::cga::edgeIndexLabel(std::stoll(written));
    if (label.empty() || (fgsgName == "InnerRectangle" && label == "remainder")) {
      notSupported(rangeOf(sized->key), "the selector '" + sized->key->getText() + "' of " + name);
      continue;
    }
    if (sized->sep->getText() == "=") label += "=";
    Successor part;
    part.range = rangeOf(partCtx);
    part.selector = label;
    part.selectorRange = rangeOf(sized->key);
    operations(sized->operation(), 0, part, env, true);
    made.body.push_back(std::move(part));
  }
  item = std::move(made);
  return true;
}

// envelope(direction, maxHeight, baseHeights, angles) with both arrays written out:
// EnvelopePerEdge(direction, maxHeight, b0, a0, b1, a1, ...), the shorter array filled with
// op_envelope's defaults (base height 0, angle 90) to the longer one's length.
bool Translator::envelopePerEdge(P::CallOperationContext* op, const Env& env, std::optional<Item>& item) {
  const auto argCtx = op->expr();
  const auto bases = envelopeArrayLiteral(argCtx[2]), angles = envelopeArrayLiteral(argCtx[3]);
  if (!bases || !angles) {
    notSupported(rangeOf(bases ? argCtx[3] : argCtx[2]),
                 "envelope's base heights and angles other than two arrays written out ([h0, h1], [a0, a1])");
    return true;
  }
  Item made = command("EnvelopePerEdge", rangeOf(op));
  const std::string word = selectorWord(argCtx[0]);
  double code = 0;
  std::string allowed;
  if (!word.empty() && shapeOperationWord("EnvelopePerEdge", 0, word, code, allowed)) {
    ExprPtr s = makeExpr(ExprKind::String, rangeOf(argCtx[0]));
    s->text = word;
    made.args.push_back(std::move(s));
  } else {
    ExprPtr e = expr(argCtx[0], env);
    if (!e) return true;
    made.args.push_back(std::move(e));
  }
  ExprPtr maxHeight = expr(argCtx[1], env);
  if (!maxHeight) return true;
  made.args.push_back(std::move(maxHeight));
  for (size_t i = 0; i < std::max(bases->size(), angles->size()); ++i)
    for (const auto& [array, fallback, whole] : {std::tuple{&*bases, 0.0, argCtx[2]}, std::tuple{&*angles, 90.0, argCtx[3]}}) {
      ExprPtr e;
      if (i < array->size()) {
        e = expr((*array)[i], env);
        if (!e) return true;
      } else {
        e = makeExpr(ExprKind::Number, rangeOf(whole));
        e->number = fallback;
      }
      made.args.push_back(std::move(e));
    }
  if (op->splitBody()) {
    error("E018", rangeOf(op->splitBody()), "'envelope' takes no { } body");
    return true;
  }
  item = std::move(made);
  return true;
}

}  // namespace fgsg::frontend::cga
