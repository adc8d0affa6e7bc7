// Checking a command item (S, Subdiv, Repeat, Comp, Center, I, ...): its argument count, the
// type of each argument, the constant strings some take (axes, selectors, roof kinds,
// assets), and its { } body against the command's BodyRule (frontend/builtins.h).

#include "frontend/color_literal.h"
#include "frontend/sema_analyzer.h"

#include "frontend/builtins.h"
#include "frontend/shape_operations.h"
#include "runtime/cga/edge_index_label.h"
#include "runtime/synthesis/continuous/example_file.h"

#include <cmath>
#include <set>
#include <string>

namespace fgsg::frontend::sema_detail {

namespace {

int axisMask(const std::string& axes) {
  int mask = 0;
  for (char c : axes) {
    int bit = (c == 'X' || c == 'x') ? 1 : (c == 'Y' || c == 'y') ? 2 : (c == 'Z' || c == 'z') ? 4 : -1;
    if (bit < 0 || (mask & bit)) return -1;
    mask |= bit;
  }
  return mask;
}

bool drawsRandom(const Expr& e) {
  if (e.kind == ExprKind::Call && (e.text == "Rand" || e.text == "rand")) return true;
  for (const auto& a : e.args)
    if (a && drawsRandom(*a)) return true;
  return false;
}

}  // namespace

void Analyzer::checkCommand(const Item& item, const CommandInfo& cmd, const Where& w) {
  if (!checkSplitSyntax(item, cmd)) return;
  const int n = static_cast<int>(item.args.size());
  if (n < cmd.minArgs || (cmd.maxArgs >= 0 && n > cmd.maxArgs)) {
    diags_.error("E016", item.range,
                 "'" + item.name + "' takes " +
                     (cmd.minArgs == cmd.maxArgs ? std::to_string(cmd.minArgs)
                      : cmd.maxArgs < 0 ? "at least " + std::to_string(cmd.minArgs)
                                        : std::to_string(cmd.minArgs) + " to " +
                                              std::to_string(cmd.maxArgs)) +
                     " argument" + (cmd.maxArgs == 1 ? "" : "s") + ", got " +
                     std::to_string(n) + ": " + cmd.signature);
    return;
  }
  checkBody(item, cmd);
  bool stringOk = false;  // the last stringArg was a constant string (possibly empty)
  auto stringArg = [&](size_t k, const char* what) -> std::string {
    ConstValue v;
    stringOk = evalConst(*item.args[k], v) && v.type == ValueType::Str;
    if (!stringOk) {
      diags_.error("E017", item.args[k]->range,
                   std::string("the ") + what + " of '" + item.name + "' must be a constant string: " +
                       cmd.signature);
      return {};
    }
    res_.exprTypes[item.args[k].get()] = ValueType::Str;
    return v.str;
  };
  auto numArgs = [&](size_t from, bool sizes) {
    for (size_t k = from; k < item.args.size(); ++k)
      expect(*item.args[k], w.operand(sizes), ValueType::Num, "this argument");
  };
  switch (cmd.id) {
    case CommandId::Scale: numArgs(0, true); break;
    case CommandId::Instance:
      stringArg(0, "asset");
      // CityEngine's i(asset, upAxisOfGeometry, insertMode), as words.
      for (size_t k = 1; k < item.args.size(); ++k) {
        const std::string word = stringArg(k, k == 1 ? "up axis" : "insert mode");
        const bool known = k == 1 ? word == "yUp" || word == "zUp"
                                  : word == "alignSizeAndPosition" || word == "keepSizeAndPosition" ||
                                        word == "keepSizeAlignPosition";
        if (stringOk && !known)
          diags_.error("E028", item.args[k]->range, "'" + word + "' is not " +
                                                        (k == 1 ? "an up axis" : "an insert mode") + ": " + cmd.signature);
      }
      break;
    case CommandId::InstanceCollide: stringArg(0, "asset"); break;
    case CommandId::InstanceMerge:
      stringArg(0, "asset");
      numArgs(1, false);
      break;
    case CommandId::Subdiv: {
      std::string axis = stringArg(0, "axis");
      int mask = axisMask(axis);
      if (stringOk && (mask != 1 && mask != 2 && mask != 4))
        diags_.error("E028", item.args[0]->range,
                     item.name + " splits along one axis: \"X\", \"Y\" or \"Z\", not \"" + axis + "\"");
      numArgs(1, true);
      break;
    }
    case CommandId::Repeat: {
      std::string axes = stringArg(0, "axes");
      int mask = axisMask(axes);
      if (stringOk && mask <= 0)
        diags_.error("E028", item.args[0]->range,
                     "Repeat axes must be letters X, Y, Z each at most once, not \"" + axes + "\"");
      else if (stringOk && static_cast<int>(axes.size()) != n - 1)
        diags_.error("E016", item.range,
                     "Repeat(\"" + axes + "\", ...) needs one size per axis: " +
                         std::to_string(axes.size()) + " expected, got " + std::to_string(n - 1));
      numArgs(1, false);
      break;
    }
    case CommandId::Center: {
      const std::string axes = stringArg(0, "axes");
      if (stringOk && axisMask(axes) <= 0)
        diags_.error("E028", item.args[0]->range,
                     "Center axes must be letters X, Y, Z each at most once, as in \"xz\", not \"" + axes + "\"");
      break;
    }
    case CommandId::Color: {
      if (n == 3) {
        numArgs(0, false);
        break;
      }
      if (n != 1) {
        diags_.error("E016", item.range, "'Color' takes three numbers r, g, b from 0 to 1, or one \"#rrggbb\": " +
                                             std::string(cmd.signature));
        break;
      }
      // A vector (r, g, b), as a picture's colour `P.rgb`: read three times, so it may not
      // draw random numbers unless written out as (r, g, b).
      if (typeOf(*item.args[0], w, false) == ValueType::Vec3) {
        expect(*item.args[0], w.operand(), ValueType::Vec3, "the colour");
        if (item.args[0]->kind != ExprKind::Vector && drawsRandom(*item.args[0]))
          diags_.error("E016", item.args[0]->range,
                       "a colour vector that draws random numbers must be written (r, g, b): each "
                       "component is read from it");
        break;
      }
      // A string that is no constant (an attr, lot properties and --set may change it): read
      // as "#rrggbb" when the command runs (R027 if it is no colour).
      if (ConstValue cv; !evalConst(*item.args[0], cv) && typeOf(*item.args[0], w, false) == ValueType::Str) {
        expect(*item.args[0], w.operand(), ValueType::Str, "the colour");
        break;
      }
      const std::string text = stringArg(0, "colour");
      std::array<double, 3> rgb;
      if (stringOk && !parseHexColor(text, rgb))
        diags_.error("E042", item.args[0]->range,
                     "a colour is written \"#rrggbb\" (six hex digits, as \"#8c3b2e\"), not \"" + text + "\"");
      break;
    }
    case CommandId::Texture: {
      const std::string file = stringArg(0, "image file");
      if (stringOk && file.empty()) diags_.error("E017", item.args[0]->range, "'Texture' needs an image file name");
      if (n == 2)
        diags_.error("E016", item.range,
                     "'Texture' takes the image alone (one image over the scope) or with both tile sizes: " +
                         std::string(cmd.signature));
      numArgs(1, false);
      break;
    }
    case CommandId::Material: {
      const std::string property = stringArg(0, "property");
      if (!stringOk) break;
      if (materialProperty(property) < 0) {
        diags_.error("E028", item.args[0]->range,
                     "a material property is " + std::string(materialPropertyList()) + ", not \"" + property + "\"");
        break;
      }
      if (materialPropertyIsImage(materialProperty(property))) {
        // The image is found and checked before deriving, as Texture's.
        const std::string file = stringArg(1, "image");
        if (stringOk && file.empty())
          diags_.error("E017", item.args[1]->range,
                       "'Material(\"" + property + "\", ...)' needs an image file name (\"none\": none)");
        break;
      }
      numArgs(1, false);
      break;
    }
    case CommandId::UvOperation: {
      const int uv = uvOperation(item.name);
      // The arguments past the operation's own name uv sets: CopyUV's two, the others' optional last.
      static const int kOwnArgs[] = {3, 2, 2, 1, 2, 1, 0, 0, 0};
      const int own = kOwnArgs[uv];
      for (int k = own; k < n; ++k) {
        // Written as a number: the set is known when the grammar is compiled (ir::Op::uvSet).
        const Expr& set = *item.args[k];
        const bool number = set.kind == ExprKind::Number;
        if (!number || !(set.number >= 0 && set.number <= 9) || set.number != std::floor(set.number)) {
          diags_.error("E028", set.range,
                       "a uv set is a whole number from 0 to 9 (CityEngine's texture layers), written as one" +
                           (number ? ", not " + formatNumber(set.number) : std::string()) + ": " + cmd.signature);
          return;
        }
        res_.exprTypes[item.args[k].get()] = ValueType::Num;
      }
      const auto ownNumArgs = [&](int from, bool sizes) {
        for (int k = from; k < std::min(n, own); ++k) expect(*item.args[k], w.operand(sizes), ValueType::Num, "this argument");
      };
      if (uv == 0) {  // SetupProjection("xz", w, h)
        const std::string axes = stringArg(0, "axes");
        static const std::set<std::string> kAxes = {"xy", "xz", "yz", "yx", "zx", "zy"};
        const bool world = axes.rfind("world.", 0) == 0;
        if (stringOk && !kAxes.count(world ? axes.substr(6) : axes))
          diags_.error("E028", item.args[0]->range,
                       "SetupProjection's axes are two of the scope's: \"xy\", \"xz\", \"yz\", \"yx\", \"zx\" or "
                       "\"zy\" (or the world's: \"world.xz\" ...), not \"" + axes + "\"");
        ownNumArgs(1, true);
      } else if (uv == 5) {  // NormalizeUV("uv")
        const std::string mode = stringArg(0, "mode");
        if (stringOk && mode != "uv" && mode != "uvUniform" && mode != "u" && mode != "v")
          diags_.error("E028", item.args[0]->range,
                       "NormalizeUV's mode is \"uv\", \"uvUniform\", \"u\" or \"v\", not \"" + mode + "\"");
      } else {
        ownNumArgs(0, uv == 4);  // TileUV's sizes may be relative (1r) or floating (~2)
      }
      break;
    }
    case CommandId::Comp: {
      static const std::set<std::string> kSelectors = {
          "faces", "f", "sidefaces", "vertical", "aslant", "horizontal", "nutant", "top", "bottom", "front", "back",
          "left", "right", "edges", "e", "sideedges", "topedges", "bottomedges", "eaves", "ridges", "rakes", "hips",
          "valleys", "v", "vertices"};
      std::string sel = stringArg(0, "selector");
      if (stringOk && !kSelectors.count(sel))
        diags_.error("E028", item.args[0]->range,
                     "unknown component selector \"" + sel +
                         "\" (faces or f, sidefaces, vertical, aslant, horizontal, nutant, top, bottom, front, back, left, "
                         "right, edges or e, "
                         "sideedges, topedges, bottomedges; on roofs eaves, ridges, rakes, hips, valleys; "
                         "vertices or v)");
      break;
    }
    case CommandId::Offset: numArgs(0, false); break;
    case CommandId::ShapeOperation:
      if (std::string forms; !shapeOperationArity(item.name, item.args.size(), forms))
        diags_.error("E016", item.range,
                     "'" + item.name + "' takes " + forms + ", got " + std::to_string(item.args.size()) + ": " +
                         cmd.signature);
      if (item.name == "InsertAlongUV" && item.args.size() >= 2) {
        // The uv set is known when the grammar is compiled, as the uv operations' is; the
        // asset is a file found before deriving, so its name is a constant string.
        const Expr& set = *item.args[0];
        const bool number = set.kind == ExprKind::Number;
        if (!number || !(set.number >= 0 && set.number <= 9) || set.number != std::floor(set.number))
          diags_.error("E028", set.range,
                       "a uv set is a whole number from 0 to 9 (CityEngine's texture layers), written as one" +
                           (number ? ", not " + formatNumber(set.number) : std::string()) + ": " + cmd.signature);
        if (ConstValue asset; !(evalConst(*item.args[1], asset) && asset.type == ValueType::Str))
          diags_.error("E028", item.args[1]->range,
                       "InsertAlongUV's asset is a file name written as a string: " + std::string(cmd.signature));
      }
      // A word where the operation takes one ("largest", "y"), else a number.
      for (size_t k = 0; k < item.args.size(); ++k) {
        ConstValue v;
        double code = 0;
        std::string allowed;
        if (!(evalConst(*item.args[k], v) && v.type == ValueType::Str)) {
          expect(*item.args[k], w.operand(), ValueType::Num, "this argument");
        } else if (res_.exprTypes[item.args[k].get()] = ValueType::Str;
                   !shapeOperationWord(item.name, k, v.str, code, allowed)) {
          diags_.error("E028", item.args[k]->range,
                       "'" + item.name + "' takes " + (allowed.empty() ? "a number" : allowed) + " here, not \"" +
                           v.str + "\": " + cmd.signature);
        }
      }
      break;
    case CommandId::Footprint: {
      // Rings of corner pairs, each hole after the word "hole": Footprint(outline..., "hole", ...).
      size_t ringStart = 0;
      auto endRing = [&](size_t end, const SourceRange& at) {
        const size_t count = end - ringStart;
        if (count % 2 != 0 || count < 6)
          diags_.error("E016", at,
                       std::string(ringStart == 0 ? "the outline" : "a hole") +
                           " of 'Footprint' takes pairs of coordinates x, z, three corners at least, got " +
                           std::to_string(count) + " numbers: " + cmd.signature);
      };
      for (size_t k = 0; k < item.args.size(); ++k) {
        ConstValue v;
        if (!(evalConst(*item.args[k], v) && v.type == ValueType::Str)) {
          expect(*item.args[k], w, ValueType::Num, "this argument");
          continue;
        }
        res_.exprTypes[item.args[k].get()] = ValueType::Str;
        if (v.str != "hole")
          diags_.error("E028", item.args[k]->range,
                       "between a Footprint's rings write \"hole\" (then the hole's corners), not \"" + v.str + "\"");
        endRing(k, item.args[k]->range);
        ringStart = k + 1;
      }
      endRing(item.args.size(), item.range);
      break;
    }
    case CommandId::Roof: {
      std::string kind = stringArg(0, "roof kind");
      if (stringOk && kind != "hipped" && kind != "gable" && kind != "pyramid" && kind != "shed" && kind != "ridge")
        diags_.error("E028", item.args[0]->range,
                     "unknown roof kind \"" + kind + "\" (hipped, gable, pyramid, shed or ridge)");
      // Roof(kind, "byHeight" | "byAngle", value, ...): CityEngine's valueType as a word
      // before the value; without it the value is the angle (at most 5 arguments).
      ConstValue word;
      if (n > 1 && evalConst(*item.args[1], word) && word.type == ValueType::Str) {
        res_.exprTypes[item.args[1].get()] = ValueType::Str;
        if (word.str != "byHeight" && word.str != "byAngle")
          diags_.error("E028", item.args[1]->range,
                       "Roof's value type is \"byAngle\" or \"byHeight\", not \"" + word.str + "\"");
        else if (n < 3)
          diags_.error("E016", item.range, "'Roof' with \"" + word.str + "\" takes the value after it: " + cmd.signature);
        numArgs(2, false);
      } else {
        if (n > 5)
          diags_.error("E016", item.range,
                       "'Roof' takes 2 to 5 arguments, got " + std::to_string(n) + ": " + cmd.signature);
        numArgs(1, false);
      }
      break;
    }
    case CommandId::Marching:
      expect(*item.args[0], w, ValueType::Num, "the marching length");
      expect(*item.args[1], w, ValueType::Num, "the marching angle");
      expect(*item.args[2], w, ValueType::Bool, "the marching condition");
      if (n > 3) {  // the terminals' smoothness (Buron et al. §6)
        const std::string smoothness = stringArg(3, "smoothness");
        if (stringOk && smoothness != "C1" && smoothness != "C0" && smoothness != "none")
          diags_.error("E028", item.args[3]->range,
                       "the smoothness of 'Marching' is \"C1\", \"C0\" or \"none\", not \"" + smoothness + "\"");
      }
      break;
    case CommandId::Synthesize: {
      // A mesh example is continuous synthesis; its fifth argument names the symbol of
      // the solid's parts.
      const std::string file = stringArg(0, "example file");
      const bool fileOk = stringOk;
      for (size_t k = 1; k < 4; ++k) expect(*item.args[k], w, ValueType::Num, "this argument");
      if (n == 5) {
        const std::string part = stringArg(4, "symbol of the synthesized parts");
        if (fileOk && !rt::synthesis::continuous::isPolygonalExampleFile(file))
          diags_.error("E064", item.args[4]->range,
                       "a symbol for the synthesized parts needs a polygonal example (continuous synthesis: "
                       ".obj, .ply, .off, .stl, .glb or .gltf), not \"" + file + "\"");
        else if (stringOk && res_.findSymbol(part) < 0)
          diags_.error("E064", item.args[4]->range, "'" + part + "' is no symbol of this grammar: " + cmd.signature);
      }
      break;
    }
    case CommandId::Line:
      if (n > 0) expect(*item.args[0], w, ValueType::Num, "the width of 'Line'");
      if (n > 1) expect(*item.args[1], w, ValueType::Bool, "the merge flag of 'Line'");
      if (n > 2) stringArg(2, "asset drawn along the line");
      break;
    case CommandId::LineSeg:
      if (n > 0) expect(*item.args[0], w, ValueType::Num, "the length of 'LineSeg'");
      break;
    case CommandId::Evolve:
      // A declared tileset by name, or a tile file.
      if (item.args[0]->kind == ExprKind::Ident && tilesetDeclared(item.args[0]->text))
        res_.exprTypes[item.args[0].get()] = ValueType::Str;
      else if (item.args[0]->kind == ExprKind::Ident && res_.constants.count(item.args[0]->text) == 0)
        diags_.error("E017", item.args[0]->range,
                     "'" + item.args[0]->text + "' is no tileset declared in this grammar (`tileset " +
                         item.args[0]->text + " { ... }`) and no constant: " + cmd.signature);
      else
        stringArg(0, "tile file");
      expect(*item.args[1], w, ValueType::Num, "the generation of 'Evolve'");
      if (n > 2) expect(*item.args[2], w, ValueType::Num, "the rule size k of 'Evolve'");
      if (n > 3) expect(*item.args[3], w, ValueType::Bool, "the p4 flag of 'Evolve'");
      if (n > 4) expect(*item.args[4], w, ValueType::Num, "the polycube resolution of 'Evolve'");
      break;
    case CommandId::Cells: {
      // An optional base-mesh file first, then the joint and the mortar offset.
      ConstValue v;
      const size_t first = evalConst(*item.args[0], v) && v.type == ValueType::Str ? 1 : 0;
      if (first) stringArg(0, "base mesh file");
      if (n - int(first) < 1 || n - int(first) > 2)
        diags_.error("E016", item.range,
                     std::string("'Cells' takes an optional base mesh file, the mortar joint and an optional mortar "
                                 "offset: ") + cmd.signature);
      numArgs(first, false);
      if (first && item.body.size() == 2)
        diags_.error("E018", item.range,
                     "'Cells' takes its base mesh from a file or from a base part { Base | Feature }, not both: " +
                         std::string(cmd.signature));
      break;
    }
    case CommandId::BrickBond:
    case CommandId::HeaderRow:
    case CommandId::ArchBricks:
    case CommandId::RandomStones:
    case CommandId::EnglishBond:
    case CommandId::FlemishBond:
    case CommandId::HeaderBond:
    case CommandId::Shingles:
      for (size_t k = 0; k < item.args.size(); ++k)
        expect(*item.args[k], w, k == 3 && cmd.id != CommandId::RandomStones ? ValueType::Bool : ValueType::Num,
               "this argument");
      break;
    case CommandId::Label:
      expect(*item.args[0], w.operand(), ValueType::Str, "the label of 'Label'");
      break;
    case CommandId::Report:
    case CommandId::Print: {
      // Report's key is a string; the value (Report's and Print's) a number, a truth value,
      // a string or (Print) a vector.
      if (cmd.id == CommandId::Report) expect(*item.args[0], w.operand(), ValueType::Str, "the key of 'Report'");
      const Expr& value = *item.args.back();
      const ValueType t = typeOf(value, w.operand(), true);
      if (t == ValueType::Vec3 && cmd.id == CommandId::Report)
        diags_.error("E013", value.range, "'Report' takes a number, a boolean or a string, not a vector: report its components");
      else if (t == ValueType::Vec3 && value.kind != ExprKind::Vector && drawsRandom(value))
        diags_.error("E016", value.range,
                     "a vector that draws random numbers must be written (x, y, z) to be printed: each component is read from it");
      break;
    }
    default: numArgs(0, false); break;
  }
  for (const auto& b : item.body) checkSuccessor(b, w);
}

// CGA's split syntax: size labels `4:` on Subdiv's parts (the AST builder made them its
// sizes when every part has one) and `{ ... }*` repeats. False when it reported an error.
bool Analyzer::checkSplitSyntax(const Item& item, const CommandInfo& cmd) {
  bool ok = true;
  for (const auto& part : item.body) {
    if (!part.size) continue;
    ok = false;
    if (cmd.id == CommandId::Subdiv)
      diags_.error("E018", part.size->range,
                   "give every part of the split a size, and Subdiv only its axis: "
                   "`Subdiv(\"Y\"){ 4: Ground | ~3: Floor }` (or all sizes as arguments)");
    else
      diags_.error("E018", part.size->range,
                   "a size label `4:` belongs to a part of Subdiv (CGA's split), not of '" + item.name + "'");
    break;
  }
  if (!item.repeatPattern) return ok;
  if (cmd.id != CommandId::Subdiv) {
    diags_.error("E018", item.range,
                 "`{ ... }*` repeats the parts of a Subdiv (`Subdiv(\"X\"){ ~1: Wall | 1.4: Window }*`), not of '" +
                     item.name + "'");
    return false;
  }
  for (size_t k = 1; k < item.args.size(); ++k)
    if (item.args[k]->kind == ExprKind::RelSize) {
      diags_.error("E018", item.args[k]->range,
                   "a repeated pattern's parts need sizes in metres, absolute or floating (`~1`): a relative size "
                   "has no length to repeat by");
      ok = false;
    }
  return ok;
}

void Analyzer::checkBody(const Item& item, const CommandInfo& cmd) {
  // The faces a labelled part of Comp may name (rt::cga::componentSelectorMask), and with
  // them the edges and vertices of CityEngine's Comp("e") / Comp("v"); an index `2:` too.
  static const std::set<std::string> kPartFaces = {
      "front",       "back",       "left",       "right",       "top",        "bottom",      "vertical",
      "aslant",      "horizontal", "nutant",     "side",        "all",        "border",      "inside",
      "worldUp",     "worldDown",  "worldNorth", "worldSouth",  "worldEast",  "worldWest",   "worldSide",
      "objectTop",   "objectBottom", "objectFront", "objectBack", "objectLeft", "objectRight", "objectSide",
      "streetFront", "streetBack", "streetLeft", "streetRight", "streetSide"};
  // Those of fgsg's Comp of edges: roof edges by their class (Comp("e") takes them too).
  static const std::set<std::string> kEdgeComponents = {"edges",  "sideedges", "topedges", "bottomedges",
                                                        "eaves", "ridges", "rakes",     "hips",     "valleys"};
  static const std::set<std::string> kPartEdges = {"all",   "eave",   "eaves",   "ridge", "ridges", "hip",
                                                   "hips",  "valley", "valleys", "gable", "rake",   "rakes"};
  const std::string component =
      cmd.id == CommandId::Comp && !item.args.empty() && item.args[0]->kind == ExprKind::String ? item.args[0]->text
                                                                                                : "";
  const bool edgeComp = kEdgeComponents.count(component) > 0;
  const size_t parts = item.body.size();
  size_t labelled = 0;
  for (const auto& part : item.body) {
    if (part.selector.empty()) continue;
    ++labelled;
    // A merged part (`all=: A`): Comp("f"), Comp("e") and Comp("v") make one shape of what it takes.
    if (cmd.id == CommandId::Comp && part.selector.size() > 1 && part.selector.back() == '=') {
      if (edgeComp)
        diags_.error("E028", part.selectorRange,
                     "a merged part '" + part.selector + ":' (one shape of all it takes) belongs to Comp(\"f\"), "
                     "Comp(\"e\") or Comp(\"v\"); Comp(\"" + component + "\") gives each component a shape: '" +
                         part.selector.substr(0, part.selector.size() - 1) + ":'");
      const std::string bare = part.selector.substr(0, part.selector.size() - 1);
      long long index = 0;
      if (!kPartFaces.count(bare) && !(component == "e" && kPartEdges.count(bare)) &&
          !rt::cga::edgeIndexOfLabel(bare, index))
        diags_.error("E028", part.selectorRange, "unknown part '" + part.selector + ":' of Comp(\"" + component + "\")");
      continue;
    }
    if (cmd.id == CommandId::ShapeOperation) {
      std::string allowed;
      if (!shapeOperationLabel(item.name, part.selector, allowed))
        diags_.error("E028", part.selectorRange,
                     "unknown part '" + part.selector + ":' of " + item.name +
                         (allowed.empty() ? " (it takes no labelled parts)" : " (" + allowed + ")"));
    } else if (cmd.id == CommandId::Offset) {
      if (part.selector != "inside" && part.selector != "border")
        diags_.error("E028", part.selectorRange, "unknown part '" + part.selector + ":' of Offset (inside, border)");
    } else if (cmd.id != CommandId::Comp) {
      diags_.error("E018", part.selectorRange,
                   "a labelled part '" + part.selector + ":' belongs to Comp (`Comp(\"f\"){ front: A | side: B }`) "
                   "or Offset, not to '" + item.name + "'");
    } else if (edgeComp) {
      if (!kPartEdges.count(part.selector))
        diags_.error("E028", part.selectorRange,
                     "unknown edge '" + part.selector + ":' (eave, ridge, hip, valley, gable, all)");
    } else if (long long index = 0; rt::cga::edgeIndexOfLabel(part.selector, index)) {
      // an index selector: the component at that place (wrapping around), any component
    } else if (!kPartFaces.count(part.selector) && !(component == "e" && kPartEdges.count(part.selector))) {
      const char* what = component == "e" ? "edge" : component == "v" || component == "vertices" ? "vertex" : "face";
      diags_.error("E028", part.selectorRange,
                   std::string("unknown ") + what + " '" + part.selector +
                       ":' (front, back, left, right, top, bottom, vertical, aslant, horizontal, nutant, side, all, "
                       "border, inside, worldUp ... worldSide, objectTop ... objectSide, streetFront ... streetSide, an index" +
                       (component == "e" ? ", eave, ridge, hip, valley, gable)" : ")"));
    }
  }
  if (cmd.id == CommandId::ShapeOperation && labelled != parts && !shapeOperationPlainBody(item.name))
    diags_.error("E018", item.range, "label every part of '" + item.name + "': " + std::string(cmd.signature));
  if (cmd.id == CommandId::Offset && labelled != parts)
    diags_.error("E018", item.range, "label every part of 'Offset': " + std::string(cmd.signature));
  if (cmd.id == CommandId::Comp && labelled > 0) {
    if (labelled != parts)
      diags_.error("E018", item.range, "label every part of 'Comp' or none: `Comp(\"f\"){ front: A | side: B }`");
    return;
  }
  switch (cmd.body) {
    case BodyRule::None:
      if (item.hasBody)
        diags_.error("E018", item.range, "'" + item.name + "' takes no { } body: " + cmd.signature);
      break;
    case BodyRule::PerSize:
      if (!item.hasBody)
        diags_.error("E018", item.range, "'" + item.name + "' needs a { } body: " + cmd.signature);
      else if (parts != item.args.size() - 1)
        diags_.error("E018", item.range,
                     "'" + item.name + "' has " + std::to_string(item.args.size() - 1) +
                         " size" + (item.args.size() == 2 ? "" : "s") + " but " +
                         std::to_string(parts) + " body part" + (parts == 1 ? "" : "s") +
                         "; write one part per size, separated by '|'");
      break;
    case BodyRule::One:
      if (!item.hasBody || parts != 1)
        diags_.error("E018", item.range,
                     "'" + item.name + "' needs exactly one { } body part: " + cmd.signature);
      break;
    case BodyRule::AtLeastOne:
      if (!item.hasBody || parts == 0)
        diags_.error("E018", item.range, "'" + item.name + "' needs a { } body: " + cmd.signature);
      else if (cmd.id == CommandId::Marching && parts > 2)
        diags_.error("E018", item.range,
                     "'Marching' has " + std::to_string(parts) +
                         " body parts; it takes the Top part and optionally the Extruded part: " +
                         cmd.signature);
      else if (cmd.id == CommandId::Cells && parts > 2)
        diags_.error("E018", item.range,
                     "'Cells' has " + std::to_string(parts) +
                         " body parts; it takes the feature tree, after an optional base part: " + cmd.signature);
      break;
    case BodyRule::Optional:
      if (parts > 1)
        diags_.error("E018", item.range,
                     "'" + item.name + "' takes at most one { } body part, the symbol of its cells: " + cmd.signature);
      break;
  }
}

}  // namespace fgsg::frontend::sema_detail
