#include "ir/printer.h"

#include <charconv>
#include <cmath>
#include <iterator>

#include "frontend/builtins.h"
#include "ir/builtins.h"

namespace fgsg::ir {

namespace {

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default: out += c;
    }
  }
  return out + "\"";
}

// Binding strength used to decide parentheses; higher binds tighter.
enum Prec : int {
  PrecSelect = 1,
  PrecOr,
  PrecAnd,
  PrecEquality,
  PrecCompare,
  PrecAdd,
  PrecMul,
  PrecUnary,
  PrecPow,
  PrecAtom,
};

int precedence(const Expr& e) {
  switch (e.op) {
    case ExprOp::Select: return PrecSelect;
    case ExprOp::Or: return PrecOr;
    case ExprOp::And: return PrecAnd;
    case ExprOp::Eq:
    case ExprOp::Ne: return PrecEquality;
    case ExprOp::Lt:
    case ExprOp::Le:
    case ExprOp::Gt:
    case ExprOp::Ge: return PrecCompare;
    case ExprOp::Add:
    case ExprOp::Sub:
    case ExprOp::Join: return PrecAdd;
    case ExprOp::Mul:
    case ExprOp::Div:
    case ExprOp::Mod: return PrecMul;
    case ExprOp::Neg:
    case ExprOp::Not: return PrecUnary;
    case ExprOp::Pow: return PrecPow;
    case ExprOp::Const:
      // A negative number reads like a negation: `(-1) ^ 2`, `x - -1`.
      return e.type == Type::Num && std::signbit(e.num) ? PrecUnary : PrecAtom;
    default: return PrecAtom;
  }
}

class Printer {
 public:
  explicit Printer(const Module& m) : m_(m) {}

  std::string module() {
    line(0, "module " + quoted(m_.sourceName));
    std::string derive = "derive ";
    switch (m_.mode) {
      case DeriveMode::BreadthFirst: derive += "breadthfirst"; break;
      case DeriveMode::DepthFirst: derive += "depthfirst"; break;
      case DeriveMode::Parallel: derive += "parallel"; break;
    }
    if (m_.mode == DeriveMode::Parallel || m_.steps != 0) derive += " " + std::to_string(m_.steps);
    if (m_.mode != DeriveMode::Parallel && m_.depthBound >= 0) derive += " " + std::to_string(m_.depthBound);
    if (m_.countAttr >= 0 && size_t(m_.countAttr) < m_.attrs.size()) derive += " (attr " + m_.attrs[size_t(m_.countAttr)].name + ")";
    line(0, derive);
    const TurtleSettings defaults;
    if (m_.turtle.angle != defaults.angle || m_.turtle.step != defaults.step ||
        m_.turtle.width != defaults.width)
      line(0, "turtle angle " + printNumber(m_.turtle.angle) + " step " +
                  printNumber(m_.turtle.step) + " width " + printNumber(m_.turtle.width));
    if (m_.turtle.segments == TurtleSegments::Tubes)
      line(0, "turtle segments tubes sides " + std::to_string(m_.turtle.sides));
    if (m_.turtle.segments == TurtleSegments::Ribbons) line(0, "turtle segments ribbons");
    if (m_.turtle.segments == TurtleSegments::Lines) line(0, "turtle segments lines");
    if (m_.turtle.colors != defaultTurtleColors()) {
      std::string colors = "turtle colors";
      for (const auto& c : m_.turtle.colors) colors += " (" + printNumber(c[0]) + ", " + printNumber(c[1]) + ", " + printNumber(c[2]) + ")";
      line(0, colors);
    }
    if (!m_.contextIgnored.empty()) {
      std::string ignore = "#ignore:";
      for (uint32_t s : m_.contextIgnored) ignore += " " + m_.symbols[s].name;
      line(0, ignore);
    }
    if (m_.collision.all || m_.collision.omit || m_.collision.metric != CollisionMetric::Mesh) {
      std::string c = "collision";
      if (m_.collision.all) c += " all";
      if (m_.collision.omit) c += " omit";
      switch (m_.collision.metric) {
        case CollisionMetric::Mesh: break;
        case CollisionMetric::Centre: c += " centre " + printNumber(m_.collision.radius); break;
        case CollisionMetric::Geodesic: c += " geodesic " + printNumber(m_.collision.radius); break;
        case CollisionMetric::Distance: c += " distance " + printNumber(m_.collision.radius); break;
        default: c += " metric#" + std::to_string(static_cast<int>(m_.collision.metric));
      }
      line(0, c);
    }
    if (m_.surface.present) line(0, surfaceLine(m_.surface));
    for (const FieldSpec& f : m_.fields) line(0, fieldLine(f));
    for (const TileSetSpec& t : m_.tileSets) tileSet(t);
    for (const EnvDecl& d : m_.environment) {
      std::string s = "env " + d.kind;
      if (!d.name.empty()) s += " " + d.name;
      if (!d.detail.empty()) s += " " + quoted(d.detail);
      line(0, s);
    }
    for (const Attr& a : m_.attrs) {
      std::string notes;
      for (const AttrAnnotation& n : a.annotations) {
        notes += " @" + n.name;
        std::string args;
        for (const auto& [k, v] : n.args) args += (args.empty() ? "" : ", ") + (k.empty() ? v : k + "=" + v);
        if (!n.args.empty()) notes += "(" + args + ")";
      }
      line(0, "attr " + a.name + ": " + typeName(a.type) + " = " + expr(nullptr, a.value) +
                  (a.fromImporter ? " follows " + expr(nullptr, a.importerValue) : "") + notes);
    }
    for (const Symbol& s : m_.symbols) {
      std::string text = "symbol " + s.name + "(";
      for (size_t i = 0; i < s.paramTypes.size(); ++i)
        text += (i ? ", " : "") + std::string(typeName(s.paramTypes[i]));
      text += ")  priority " + std::to_string(s.priority) + "  rules [";
      for (size_t i = 0; i < s.rules.size(); ++i)
        text += (i ? " " : "") + std::to_string(s.rules[i]);
      text += "]";
      // lpfg's and L-Py's other sections, only where the symbol has rules there.
      const auto section = [&](const char* name, const std::vector<uint32_t>& rules) {
        if (rules.empty()) return;
        text += std::string("  ") + name + " [";
        for (size_t i = 0; i < rules.size(); ++i) text += (i ? " " : "") + std::to_string(rules[i]);
        text += "]";
      };
      section("decomposition", s.decompositions);
      section("homomorphism", s.homomorphisms);
      line(0, text);
    }
    line(0, "axiom");
    block(nullptr, m_.axiom, 1);
    for (const Rule& r : m_.rules) rule(r);
    return std::move(out_);
  }

  // tileset ornament
  //   locus arc cubic (0.5, 0) (0.5, 0.276) (0.724, 0.5) (1, 0.5)
  //   orientations 0 90 180 270
  void tileSet(const TileSetSpec& t) {
    line(0, "tileset " + t.name);
    auto curve = [&](const char* kind, const TileCurveSpec& c) {
      std::string s = std::string(kind) + (c.name.empty() ? "" : " " + c.name) + (c.cubic ? " cubic" : " polyline");
      for (const auto& p : c.points) s += " (" + printNumber(p[0]) + ", " + printNumber(p[1]) + ")";
      line(1, s);
    };
    for (const TileCurveSpec& c : t.loci) curve("locus", c);
    for (const TileCurveSpec& c : t.sections) curve("section", c);
    if (!t.orientations.empty()) {
      std::string s = "orientations";
      for (int o : t.orientations) s += " " + std::to_string(o);
      line(1, s);
    }
    if (!t.symbols.empty()) line(1, "symbols " + quoted(t.symbols));
    for (const auto& [name, values] : t.settings) {
      std::string s = name;
      for (double v : values) s += " " + printNumber(v);
      line(1, s);
    }
  }

  // `surface torus(2, 0.6)`, `surface "bunny.off"`
  static std::string surfaceLine(const SurfaceSpec& s) {
    if (s.generator.empty()) return "surface " + quoted(s.path);
    std::string text = "surface " + s.generator + "(";
    for (size_t i = 0; i < s.args.size(); ++i) text += (i ? ", " : "") + printNumber(s.args[i]);
    return text + ")";
  }

  // One value: `2`; three: `(0.2, 0.1, 0.9)`; none: nothing.
  static std::string designValues(const std::vector<double>& values) {
    if (values.size() == 1) return " " + printNumber(values[0]);
    if (values.empty()) return "";
    std::string text = " (";
    for (size_t i = 0; i < values.size(); ++i) text += (i ? ", " : "") + printNumber(values[i]);
    return text + ")";
  }

  // `field F1 = tensor("foot.tfield")`, `field K = curvature`,
  // `field F2 = design tensor { wedge vertex 120 decay 2; smooth iterations 300 }`
  std::string fieldLine(const FieldSpec& f) {
    std::string text = "field " + f.name + " = ";
    if (f.source == "curvature") return text + "curvature";
    if (f.source == "expression" && f.expression.size() == 1) {
      Rule vertex;  // names the expression's parameters x, y, z
      vertex.params = surfacePointParams();
      return text + "scalar(" + expr(&vertex, f.expression[0]) + ")";
    }
    if (f.source == "file") return text + f.kind + "(" + quoted(f.path) + ")";
    if (f.source == "image") return text + "image(" + quoted(f.path) + ")";
    if (f.source != "design") return text + "source#" + quoted(f.source);
    text += "design " + f.kind + " {";
    for (size_t i = 0; i < f.design.size(); ++i) {
      text += (i ? "; " : " ") + f.design[i].kind;
      for (const auto& [keyword, values] : f.design[i].words) text += " " + keyword + designValues(values);
    }
    return text + " }";
  }

  void rule(const Rule& r) {
    std::string head = "rule ";
    if (&r >= m_.rules.data() && &r < m_.rules.data() + m_.rules.size())
      head += std::to_string(&r - m_.rules.data()) + " ";
    head += quoted(r.label) + " ";
    size_t contextParams = 0;
    for (const ContextModule& c : r.left) contextParams += c.paramSlots.size();
    for (const ContextModule& c : r.right) contextParams += c.paramSlots.size();
    for (const ContextModule& c : r.left) head += contextModule(r, c) + " ";
    if (!r.left.empty()) head += "< ";
    head += symbolName(r.symbol) + "(";
    // Predecessor parameters come first in Rule::params; context parameters follow.
    const size_t own = r.params.size() > contextParams ? r.params.size() - contextParams : 0;
    for (size_t i = 0; i < own; ++i) head += (i ? ", " : "") + paramDecl(r.params[i]);
    head += ")";
    if (!r.right.empty()) head += " >";
    for (const ContextModule& c : r.right) head += " " + contextModule(r, c);
    head += "  priority " + std::to_string(r.priority);
    if (r.hasGuard) head += "  guard (" + expr(&r, r.guard) + ")";
    line(0, head);
    for (const Alternative& alt : r.alternatives) {
      line(1, "alt weight " + expr(&r, alt.probability));
      block(&r, alt.ops, 2);
    }
  }

  std::string expr(const Rule* rule, const Expr& e) {
    std::string s;
    writeExpr(rule, e, s);
    return s;
  }

  std::string take() { return std::move(out_); }

  void block(const Rule* r, const Block& ops, int depth) {
    if (ops.empty()) line(depth, "(empty)");
    for (const Op& op : ops) writeOp(r, op, depth);
  }

 private:
  void line(int depth, const std::string& text) {
    out_.append(static_cast<size_t>(depth) * 2, ' ');
    out_ += text;
    out_ += '\n';
  }

  std::string symbolName(uint32_t i) const {
    return i < m_.symbols.size() ? m_.symbols[i].name : "sym#" + std::to_string(i);
  }

  std::string stringLit(uint32_t i) const {
    return i < m_.strings.size() ? quoted(m_.strings[i]) : "str#" + std::to_string(i);
  }

  // A Str constant keeps its id in a double; a corrupt one must not be cast blindly.
  std::string stringLit(double id) const {
    if (id >= 0 && id < static_cast<double>(m_.strings.size()) && id == std::floor(id))
      return stringLit(static_cast<uint32_t>(id));
    return "str#" + printNumber(id);
  }

  static const Param* paramAt(const Rule* rule, uint32_t slot) {
    if (!rule) return nullptr;
    for (const Param& p : rule->params)
      if (p.slot == slot) return &p;
    return nullptr;
  }

  static std::string paramDecl(const Param& p) {
    return p.name + ": " + typeName(p.type) + " @" + std::to_string(p.slot);
  }

  std::string contextModule(const Rule& r, const ContextModule& c) const {
    if (c.symbol == ~0u) return c.bracket > 0 ? "[" : c.bracket < 0 ? "]" : "?";
    std::string s = symbolName(c.symbol) + "(";
    for (size_t i = 0; i < c.paramSlots.size(); ++i) {
      const Param* p = paramAt(&r, c.paramSlots[i]);
      s += (i ? ", " : "") + (p ? paramDecl(*p) : "@" + std::to_string(c.paramSlots[i]));
    }
    return s + ")";
  }

  // Environment entries are named by the module: F1.vector1, context.mask(uv).
  std::string envName(uint32_t i, const char* kind) const {
    if (i < m_.environment.size() && !m_.environment[i].name.empty())
      return m_.environment[i].name;
    return std::string(kind) + "#" + std::to_string(i);
  }

  std::string list(const Rule* r, const std::vector<Expr>& args) {
    std::string s;
    for (size_t i = 0; i < args.size(); ++i) s += (i ? ", " : "") + expr(r, args[i]);
    return s;
  }

  std::string sizeText(const Rule* r, const Size& sz) {
    if (sz.kind == Size::Absolute) return expr(r, sz.value);
    std::string s;
    writeOperand(r, sz.value, PrecAtom, s);
    return sz.kind == Size::Relative ? s + "r" : "~" + s;
  }

  std::string sizeList(const Rule* r, const std::vector<Size>& szs) {
    std::string s = "[";
    for (size_t i = 0; i < szs.size(); ++i) s += (i ? ", " : "") + sizeText(r, szs[i]);
    return s + "]";
  }

  static std::string axisName(uint32_t axis) {
    return axis < 3 ? std::string(1, "xyz"[axis]) : "axis#" + std::to_string(axis);
  }

  // An axes mask (1 X, 2 Y, 4 Z) as the letters it selects: "xz".
  static std::string axesName(uint32_t mask) {
    std::string axes;
    for (uint32_t a = 0; a < 3; ++a)
      if (mask & (1u << a)) axes += "xyz"[a];
    return mask > 7 || axes.empty() ? "mask#" + std::to_string(mask) : axes;
  }

  void writeOp(const Rule* r, const Op& op, int depth) {
    auto withArgs = [&](std::string s) {
      return op.args.empty() ? s : s + " " + list(r, op.args);
    };
    std::string text;
    switch (op.kind) {
      case OpKind::Translate: text = withArgs("translate"); break;
      case OpKind::Rotate:
        text = withArgs("rotate " + (op.index == 3 ? std::string("xyz") : axisName(op.index)));
        break;
      case OpKind::RotateNormal: text = withArgs("rotatenormal"); break;
      case OpKind::Scale: text = withArgs("scale " + sizeList(r, op.sizes)); break;
      case OpKind::Push: text = "push"; break;
      case OpKind::Pop: text = "pop"; break;
      case OpKind::Instance: {
        static const char* const kModes[] = {"plain", "collide", "merge"};
        const auto mode = static_cast<size_t>(op.mode);
        text = "instance " +
               (op.index < m_.assets.size() ? quoted(m_.assets[op.index])
                                            : "asset#" + std::to_string(op.index)) +
               " " + (mode < 3 ? kModes[mode] : "mode#" + std::to_string(mode));
        if (op.zUp) text += " zUp";
        if (op.insertFit == InsertFit::KeepSizeAndPosition) text += " keepSizeAndPosition";
        if (op.insertFit == InsertFit::KeepSizeAlignPosition) text += " keepSizeAlignPosition";
        if (op.recordAs != Op::kPlacingSymbol) text += " as " + symbolName(op.recordAs);
        text = withArgs(text);
        break;
      }
      case OpKind::Emit: text = "emit " + symbolName(op.index) + "(" + list(r, op.args) + ")"; break;
      case OpKind::Turtle: {
        static const char* const kTurtle[] = {"F", "f", "+", "-", "&", "^", "\\", "/", "|", "!", "$", "%", "{", ".",
                                              "}", "'", "~", "@Tp", "@Ts", "@O", "@M", "@R", ",", "@o", "@Gs", "@Gc",
                                              "@Ge"};
        text = std::string("turtle ") +
               (op.index < std::size(kTurtle) ? kTurtle[op.index]
                                              : "turtle#" + std::to_string(op.index));
        if (!op.args.empty()) text += "(" + list(r, op.args) + ")";
        break;
      }
      case OpKind::Subdiv:
        text = "subdiv " + axisName(op.index) + " " + sizeList(r, op.sizes) + (op.repeat ? " repeated" : "") +
               (op.cityEngineSizing ? " cityengine" : "") +
               (op.str < m_.strings.size() && m_.strings[op.str] == "SplitArea" ? " by area" : "");
        break;
      case OpKind::Repeat: text = "repeat " + axesName(op.index) + " " + sizeList(r, op.sizes); break;
      case OpKind::Center: text = "center " + axesName(op.index); break;
      case OpKind::Color: text = withArgs("color"); break;
      case OpKind::Texture: text = withArgs("texture " + stringLit(op.str)); break;
      case OpKind::Comp:
        text = "comp " + stringLit(op.str);
        for (uint32_t label : op.partLabels) text += " " + m_.strings[label] + ":";
        break;
      case OpKind::Extrude: text = withArgs("extrude"); break;
      case OpKind::Footprint:
        text = withArgs("footprint");
        for (uint32_t start : op.ringStarts) text += " hole@" + std::to_string(start);
        break;
      case OpKind::Offset:
        text = withArgs("offset");
        for (uint32_t label : op.partLabels) text += " " + m_.strings[label] + ":";
        break;
      case OpKind::Roof:
        text = withArgs("roof " + stringLit(op.str) + (op.index == kRoofByHeight ? " byHeight" : ""));
        break;
      case OpKind::Lock: text = "lock"; break;
      case OpKind::Line:
        text = withArgs("line");
        if (op.asset < m_.assets.size()) text += " along " + quoted(m_.assets[op.asset]);
        break;
      case OpKind::LineSeg: text = withArgs("lineseg"); break;
      case OpKind::Synthesize:
        text = withArgs("synthesize " + stringLit(op.str));
        if (op.index > 0) text += " parts " + stringLit(op.index - 1);
        break;
      case OpKind::Evolve:
        text = withArgs("evolve " + (op.index ? "tileset " + m_.strings[op.str] : stringLit(op.str)));
        break;
      case OpKind::Marching:
        text = withArgs(op.index == kMarchC0 ? "marching C0" : op.index == kMarchDiscontinuous ? "marching none" : "marching");
        break;
      case OpKind::MarchCondition: text = withArgs("march-condition"); break;
      case OpKind::Branch: text = withArgs("branch"); break;
      case OpKind::Cells: text = withArgs(op.index ? "cells " + stringLit(op.str) : std::string("cells")); break;
      case OpKind::CellPattern: {
        static const char* kNames[] = {"brick-bond",   "header-row",   "arch-bricks", "random-stones",
                                       "english-bond", "flemish-bond", "header-bond",   "shingles"};
        text = withArgs(op.index < 8 ? kNames[op.index] : "cell-pattern?");
        break;
      }
      case OpKind::Report: text = withArgs("report"); break;
      case OpKind::Print: text = withArgs("print"); break;
      case OpKind::Label: text = withArgs("label"); break;
      case OpKind::Material: {
        const char* word = frontend::materialPropertyName(int(op.index));
        const std::string property = word ? word : "property?";
        text = materialPropertyIsImage(op.index) ? "material " + property + " " + stringLit(op.str)
                                                 : withArgs("material " + property);
        break;
      }
      case OpKind::Uv: {
        static const char* const kUvOps[] = {"setup",     "scale",  "translate", "rotate", "tile",
                                             "normalize", "delete", "project",   "copy"};
        // The set only where it is not 0: the text of grammars on set 0 stays as it was.
        text = withArgs(std::string("uv ") + (op.index < std::size(kUvOps) ? kUvOps[op.index] : "op?") +
                        (op.uvSet ? " set " + std::to_string(op.uvSet) : std::string()));
        if (op.index == uint32_t(UvOp::Setup) || op.index == uint32_t(UvOp::Normalize)) text += " " + stringLit(op.str);
        if (!op.sizes.empty()) text += " " + sizeList(r, op.sizes);
        break;
      }
      case OpKind::ShapeOperation:
        text = withArgs("shape-operation " + stringLit(op.str));
        if (m_.strings[op.str] == "InsertAlongUV" && op.asset < m_.assets.size())
          text += " asset " + quoted(m_.assets[op.asset]);  // its argument 1 (a placeholder 0)
        for (uint32_t label : op.partLabels) text += " " + m_.strings[label] + ":";
        break;
      case OpKind::Unsupported: text = "unsupported " + quoted(op.name) + " " + quoted(op.why); break;
    }
    line(depth, text);
    for (size_t i = 0; i < op.bodies.size(); ++i) {
      line(depth + 1, "body " + std::to_string(i) + ":");
      block(r, op.bodies[i], depth + 2);
    }
  }

  void writeArgs(const Rule* rule, const std::vector<Expr>& args, std::string& s) {
    s += '(';
    for (size_t i = 0; i < args.size(); ++i) {
      if (i) s += ", ";
      writeExpr(rule, args[i], s);
    }
    s += ')';
  }

  // Writes `e`, parenthesised when it binds less tightly than `minPrec`.
  void writeOperand(const Rule* rule, const Expr& e, int minPrec, std::string& s) {
    const bool parens = precedence(e) < minPrec;
    if (parens) s += '(';
    writeExpr(rule, e, s);
    if (parens) s += ')';
  }

  void writeExpr(const Rule* rule, const Expr& e, std::string& s) {
    auto arg = [&](size_t i) -> const Expr* { return i < e.args.size() ? &e.args[i] : nullptr; };
    const int prec = precedence(e);
    switch (e.op) {
      case ExprOp::Const:
        switch (e.type) {
          case Type::Num: s += printNumber(e.num); break;
          case Type::Bool: s += e.num != 0 ? "true" : "false"; break;
          case Type::Str: s += stringLit(e.num); break;
          case Type::Vec3:
            s += "(" + printNumber(e.vec[0]) + ", " + printNumber(e.vec[1]) + ", " +
                 printNumber(e.vec[2]) + ")";
            break;
        }
        return;
      case ExprOp::Param: {
        const Param* p = paramAt(rule, e.index);
        s += p ? p->name : "@" + std::to_string(e.index);
        return;
      }
      case ExprOp::Attr:
        s += e.index < m_.attrs.size() ? m_.attrs[e.index].name : "attr#" + std::to_string(e.index);
        return;
      case ExprOp::Neg:
      case ExprOp::Not:
        s += operatorSpelling(e.op);
        if (arg(0)) writeOperand(rule, *arg(0), PrecAtom, s);  // -(-x), !(a && b)
        return;
      case ExprOp::Select:
        if (e.args.size() != 3) break;
        writeOperand(rule, e.args[0], PrecSelect + 1, s);
        s += " ? ";
        writeExpr(rule, e.args[1], s);
        s += " : ";
        writeOperand(rule, e.args[2], PrecSelect, s);  // right-associative
        return;
      case ExprOp::Call:
        s += e.index < static_cast<uint32_t>(kBuiltinCount)
                 ? builtinSignature(static_cast<Builtin>(e.index)).name
                 : "builtin#" + std::to_string(e.index);
        writeArgs(rule, e.args, s);
        return;
      case ExprOp::Rand:
        s += "rand";
        writeArgs(rule, e.args, s);
        return;
      case ExprOp::Query:
        writeQuery(rule, e, s);
        return;
      case ExprOp::MakeVec:
        writeArgs(rule, e.args, s);
        return;
      case ExprOp::VecElem:
        if (arg(0)) writeOperand(rule, *arg(0), PrecAtom, s);
        s += '.';
        s += e.index < 3 ? std::string(1, "xyz"[e.index]) : "lane#" + std::to_string(e.index);
        return;
      default:
        if (e.args.size() != 2) break;
        // Left-associative binary operators; `^` takes only atoms on either side so
        // that its reading never depends on how a parser ranks it against unary minus.
        writeOperand(rule, e.args[0], e.op == ExprOp::Pow ? PrecAtom : prec, s);
        s += ' ';
        s += operatorSpelling(e.op);
        s += ' ';
        writeOperand(rule, e.args[1], e.op == ExprOp::Pow ? PrecAtom : prec + 1, s);
        return;
    }
    // Malformed node: show its shape rather than guessing.
    s += "<op" + std::to_string(static_cast<int>(e.op)) + ">";
    writeArgs(rule, e.args, s);
  }

  void writeQuery(const Rule* rule, const Expr& e, std::string& s) {
    if (e.index > static_cast<uint32_t>(kLastQuery)) {
      s += "query#" + std::to_string(e.index);
      writeArgs(rule, e.args, s);
      return;
    }
    const Query q = static_cast<Query>(e.index);
    switch (q) {
      case Query::Field:
        s += envName(e.env, "field") + "." +
             (e.extra < m_.strings.size() ? m_.strings[e.extra] : "str#" + std::to_string(e.extra));
        if (!e.args.empty()) writeArgs(rule, e.args, s);
        return;
      case Query::Feature:
        s += "Feature." + (e.extra < m_.strings.size() ? m_.strings[e.extra] : "str#" + std::to_string(e.extra));
        if (!e.args.empty()) writeArgs(rule, e.args, s);
        return;
      case Query::Texture:
        s += "context." + envName(e.env, "texture");
        if (e.args.empty())
          s += "(texCoord)";  // sampled at the scope's texture coordinate, as written
        else
          writeArgs(rule, e.args, s);
        return;
      default: {
        const QuerySignature& sig = querySignature(q);
        s += std::string(sig.object) + "." + sig.member;
        if (q == Query::GeometryAngle) {  // Geometry.angle("maxSlope")
          static const char* const kAngles[] = {"(\"maxSlope\")", "(\"azimuth\")", "(\"zenith\")"};
          s += e.extra <= 2 ? kAngles[e.extra] : "(angle?)";
          return;
        }
        if ((q == Query::GeometryDu || q == Query::GeometryDv) && e.extra) {  // Geometry.du(3, "uvSpace")
          s += "(" + std::to_string(e.extra) + ", \"uvSpace\")";
          return;
        }
        if (isContextQuery(q)) {  // Shape.overlaps("intra", label)
          static const char* const kTargets[] = {"\"intra\"", "\"inter\"", "\"all\""};
          s += "(";
          s += (e.extra & 3) <= 2 ? kTargets[e.extra & 3] : "target?";
          for (const Expr& a : e.args) s += ", ", writeExpr(rule, a, s);
          if (q == Query::ContextCompare) s += ", comparison " + std::to_string(e.extra >> 2);
          s += ")";
          return;
        }
        if (sig.arity != 0) writeArgs(rule, e.args, s);
        return;
      }
    }
  }

  const Module& m_;
  std::string out_;
};

}  // namespace

std::string printNumber(double v) {
  char buf[64];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, end);
}

std::string printModule(const Module& m) { return Printer(m).module(); }

std::string printRule(const Module& m, const Rule& rule) {
  Printer p(m);
  p.rule(rule);
  return p.take();
}

std::string printExpr(const Module& m, const Rule* rule, const Expr& e) {
  return Printer(m).expr(rule, e);
}

}  // namespace fgsg::ir
