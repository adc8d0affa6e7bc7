#include "ir/verifier.h"

#include <algorithm>
#include <bit>
#include <iterator>
#include <cmath>

#include "ir/builtins.h"
#include "ir/printer.h"

namespace fgsg::ir {

namespace {

const char* opName(OpKind k) {
  switch (k) {
    case OpKind::Translate: return "translate";
    case OpKind::Rotate: return "rotate";
    case OpKind::RotateNormal: return "rotatenormal";
    case OpKind::Scale: return "scale";
    case OpKind::Push: return "push";
    case OpKind::Pop: return "pop";
    case OpKind::Instance: return "instance";
    case OpKind::Emit: return "emit";
    case OpKind::Turtle: return "turtle";
    case OpKind::Subdiv: return "subdiv";
    case OpKind::Repeat: return "repeat";
    case OpKind::Comp: return "comp";
    case OpKind::Extrude: return "extrude";
    case OpKind::Footprint: return "footprint";
    case OpKind::Offset: return "offset";
    case OpKind::Roof: return "roof";
    case OpKind::Lock: return "lock";
    case OpKind::Line: return "line";
    case OpKind::LineSeg: return "lineseg";
    case OpKind::Synthesize: return "synthesize";
    case OpKind::Evolve: return "evolve";
    case OpKind::Center: return "center";
    case OpKind::Color: return "color";
    case OpKind::Texture: return "texture";
    case OpKind::Marching: return "marching";
    case OpKind::MarchCondition: return "march-condition";
    case OpKind::Branch: return "branch";
    case OpKind::Cells: return "cells";
    case OpKind::CellPattern: return "cell-pattern";
    case OpKind::Report: return "report";
    case OpKind::Print: return "print";
    case OpKind::ShapeOperation: return "shape-operation";
    case OpKind::Label: return "label";
    case OpKind::Material: return "material";
    case OpKind::Uv: return "uv";
    case OpKind::Unsupported: return "unsupported";
  }
  return "op?";
}

std::string str(Type t) { return typeName(t); }

class Verifier {
 public:
  Verifier(const Module& m, std::vector<std::string>& problems) : m_(m), problems_(problems) {}

  bool run() {
    const size_t before = problems_.size();
    if (m_.steps < 0) problem("negative derivation steps " + std::to_string(m_.steps));
    if (m_.countAttr >= 0 && (size_t(m_.countAttr) >= m_.attrs.size() || m_.attrs[size_t(m_.countAttr)].type != Type::Num))
      problem("derivation count attr " + std::to_string(m_.countAttr) + " is not a number attr");
    collision();
    surface();
    fields();
    tileSets();
    for (size_t i = 0; i < m_.attrs.size(); ++i) {
      Scoped s(*this, "attr " + m_.attrs[i].name);
      const Attr& a = m_.attrs[i];
      if (!a.value.isConst()) problem("default value is not a constant");
      if (a.value.type != a.type)
        problem("default value is " + str(a.value.type) + ", attribute is " + str(a.type));
      expr(a.value, nullptr);
      if (a.fromImporter) {
        expr(a.importerValue, nullptr);
        if (a.importerValue.type != a.type)
          problem("importer's value is " + str(a.importerValue.type) + ", attribute is " + str(a.type));
      }
    }
    for (size_t i = 0; i < m_.symbols.size(); ++i) symbol(static_cast<uint32_t>(i));
    {
      Scoped s(*this, "axiom");
      block(m_.axiom, nullptr);
    }
    for (size_t i = 0; i < m_.rules.size(); ++i) rule(static_cast<uint32_t>(i));
    return problems_.size() == before;
  }

 private:
  // Names the part of the module under inspection in every problem found inside it.
  struct Scoped {
    Scoped(Verifier& v, const std::string& part) : v_(v), size_(v.where_.size()) {
      v.where_ += (v.where_.empty() ? "" : " ") + part;
    }
    ~Scoped() { v_.where_.resize(size_); }
    Verifier& v_;
    size_t size_;
  };

  void problem(const std::string& what) {
    problems_.push_back(where_.empty() ? what : where_ + ": " + what);
  }

  void expectType(const Expr& e, Type t, const char* role) {
    if (e.type != t) problem(std::string(role) + " is " + str(e.type) + ", expected " + str(t));
  }

  void collision() {
    const CollisionSettings& c = m_.collision;
    Scoped s(*this, "collision");
    if (c.metric > CollisionMetric::Distance) {
      problem("bad metric " + std::to_string(static_cast<int>(c.metric)));
      return;
    }
    if (c.metric != CollisionMetric::Mesh && !(c.radius > 0 && std::isfinite(c.radius)))
      problem("radius " + printNumber(c.radius) + " must be positive for the " +
              (c.metric == CollisionMetric::Centre     ? "centre"
               : c.metric == CollisionMetric::Geodesic ? "geodesic"
                                                       : "distance") +
              " metric");
  }

  // ------------------------------------------------------------ environment

  void finite(const std::vector<double>& values, const std::string& what) {
    for (double v : values)
      if (!std::isfinite(v)) problem(what + " " + printNumber(v) + " is not finite");
  }

  void surface() {
    const SurfaceSpec& s = m_.surface;
    Scoped sc(*this, "surface");
    if (!s.present) {
      if (!s.path.empty() || !s.generator.empty() || !s.args.empty())
        problem("not present, but has a path, generator or arguments");
      return;
    }
    if (s.path.empty() == s.generator.empty()) {
      problem("needs exactly one of a path and a generator");
      return;
    }
    if (!s.path.empty()) {
      if (!s.args.empty()) problem("a file surface has no arguments");
      return;
    }
    static const std::pair<const char*, size_t> kGenerators[] = {
        {"torus", 2}, {"sphere", 1}, {"plane", 2}, {"genus2", 0}, {"cylinder", 2}, {"tori3", 2}};
    const auto* g = std::find_if(std::begin(kGenerators), std::end(kGenerators),
                                 [&](const auto& k) { return s.generator == k.first; });
    if (g == std::end(kGenerators)) {
      problem("unknown generator '" + s.generator + "'");
      return;
    }
    // The generator's arguments, then optionally its resolution.
    if (s.args.size() != g->second && s.args.size() != g->second + 1)
      problem(s.generator + " takes " + std::to_string(g->second) + " arguments, has " +
              std::to_string(s.args.size()));
    finite(s.args, "argument");
  }

  void tileSets() {
    std::vector<std::string> names;
    for (const TileSetSpec& t : m_.tileSets) {
      Scoped sc(*this, "tileset " + t.name);
      if (t.name.empty()) problem("has no name");
      if (std::find(names.begin(), names.end(), t.name) != names.end()) problem("name is not unique");
      names.push_back(t.name);
      if (t.loci.empty() || t.sections.empty()) problem("needs a locus and a section");
      for (const auto* list : {&t.loci, &t.sections})
        for (const TileCurveSpec& c : *list) {
          if (c.cubic ? c.points.size() != 4 : c.points.size() < 2)
            problem(std::to_string(c.points.size()) + " points for a " + (c.cubic ? "cubic" : "polyline"));
          for (const auto& p : c.points) finite({p[0], p[1]}, "coordinate");
        }
      for (int o : t.orientations)
        if (o != 0 && o != 90 && o != 180 && o != 270) problem("orientation " + std::to_string(o));
      // The GA's settings, then Chan & Hui §6.4's variation (faces: up to 6 directions).
      static const char* kSettings[] = {"population", "max_generations", "threshold", "weights", "crossover",
                                        "mutation",   "parents",         "elite",     "faces",   "colours"};
      for (const auto& [name, values] : t.settings) {
        if (std::find_if(std::begin(kSettings), std::end(kSettings), [&](const char* k) { return name == k; }) ==
            std::end(kSettings))
          problem("unknown GA setting '" + name + "'");
        if (values.empty() || values.size() > (name == "faces" ? 6u : 4u)) problem("setting '" + name + "' with " + std::to_string(values.size()) + " values");
        finite(values, "setting value");
      }
    }
  }

  void fields() {
    if (!m_.fields.empty() && !m_.surface.present)
      problem("fields without a surface");
    std::vector<std::string> names;
    for (const FieldSpec& f : m_.fields) {
      Scoped sc(*this, "field " + f.name);
      if (f.name.empty()) problem("has no name");
      if (std::find(names.begin(), names.end(), f.name) != names.end()) problem("name is not unique");
      names.push_back(f.name);
      if (f.kind != "tensor" && f.kind != "vector" && f.kind != "scalar") problem("bad kind '" + f.kind + "'");
      if (f.source == "file" || f.source == "image") {
        if (f.path.empty()) problem(f.source + " source without a path");
        if (f.source == "image" && f.kind != "tensor") problem("an image field is a tensor field");
      } else if (f.source == "curvature") {
        if (f.kind != "tensor") problem("a curvature field is a tensor field");
      } else if (f.source == "design" && f.kind == "scalar") {
        problem("a design makes a tensor or a vector field");
      } else if (f.source == "expression") {
        if (f.kind != "scalar") problem("an expression field is a scalar field");
        if (f.expression.size() != 1) {
          problem("an expression field holds " + std::to_string(f.expression.size()) + " expressions");
        } else {
          Rule vertex;  // x, y, z
          vertex.params = surfacePointParams();
          vertex.slotCount = 3;
          expr(f.expression[0], &vertex);
          expectType(f.expression[0], Type::Num, "the expression");
        }
      } else if (f.source != "design") {
        problem("bad source '" + f.source + "'");
      }
      if (f.source != "design" && !f.design.empty()) problem("design items on a " + f.source + " field");
      if (f.source != "expression" && !f.expression.empty()) problem("an expression on a " + f.source + " field");
      if (f.source != "file" && f.source != "image" && !f.path.empty())
        problem("a path on a " + f.source + " field");
      for (const FieldDesignSpec& d : f.design) designItem(d);
    }
  }

  void designItem(const FieldDesignSpec& d) {
    static const char* kKinds[] = {"regular", "wedge", "trisector", "node", "centre", "saddle", "smooth"};
    Scoped sc(*this, "design " + d.kind);
    if (std::find_if(std::begin(kKinds), std::end(kKinds), [&](const char* k) { return d.kind == k; }) ==
        std::end(kKinds)) {
      problem("unknown kind");
      return;
    }
    // keyword -> number of values
    static const std::pair<const char*, size_t> kWords[] = {
        {"vertex", 1}, {"at", 3},       {"decay", 1},     {"direction", 3},
        {"angle", 1},  {"strength", 1}, {"iterations", 1}};
    bool positioned = false;
    for (const auto& [keyword, values] : d.words) {
      const auto* w = std::find_if(std::begin(kWords), std::end(kWords),
                                   [&](const auto& k) { return keyword == k.first; });
      if (w == std::end(kWords)) {
        problem("unknown keyword '" + keyword + "'");
        continue;
      }
      if ((keyword == "iterations") != (d.kind == "smooth"))
        problem("keyword '" + keyword + "' does not belong to a " + d.kind);
      if ((keyword == "direction" || keyword == "angle") && d.kind != "regular")
        problem("keyword '" + keyword + "' is for regular elements only");
      if (values.size() != w->second)
        problem("'" + keyword + "' has " + std::to_string(values.size()) + " values, expected " +
                std::to_string(w->second));
      finite(values, "'" + keyword + "' value");
      if ((keyword == "vertex" || keyword == "iterations") && !values.empty() &&
          !(values[0] >= 0 && values[0] == std::floor(values[0])))
        problem("'" + keyword + "' " + printNumber(values[0]) + " is not a whole number >= 0");
      if (keyword == "decay" && !values.empty() && !(values[0] > 0))
        problem("decay " + printNumber(values[0]) + " is not positive");
      if (keyword == "vertex" || keyword == "at") positioned = true;
    }
    if (d.kind != "smooth" && !positioned) problem("has no position (vertex or at)");
  }

  // ------------------------------------------------------------ symbols and rules

  void symbol(uint32_t index) {
    const Symbol& s = m_.symbols[index];
    Scoped sc(*this, "symbol " + s.name);
    if (m_.findSymbol(s.name) != static_cast<int>(index)) problem("name is not unique");
    uint32_t slots = 0;
    for (Type t : s.paramTypes) slots += slotWidth(t);
    if (slots != s.slotCount)
      problem("slotCount " + std::to_string(s.slotCount) + ", parameters take " +
              std::to_string(slots));
    int highest = 0;
    bool any = false;
    for (uint32_t r : s.rules) {
      if (r >= m_.rules.size()) {
        problem("rule " + std::to_string(r) + " out of range");
        continue;
      }
      if (m_.rules[r].symbol != index) problem("lists rule " + std::to_string(r) + " of another symbol");
      highest = any ? std::max(highest, m_.rules[r].priority) : m_.rules[r].priority;
      any = true;
    }
    if (any && highest != s.priority)
      problem("priority " + std::to_string(s.priority) + ", its rules' highest is " +
              std::to_string(highest));
  }

  void rule(uint32_t index) {
    const Rule& r = m_.rules[index];
    Scoped sc(*this, "rule " + std::to_string(index) + " \"" + r.label + "\"");
    if (r.symbol >= m_.symbols.size()) {
      problem("symbol " + std::to_string(r.symbol) + " out of range");
    } else {
      const Symbol& s = m_.symbols[r.symbol];
      const std::vector<uint32_t>& listed = r.section == RuleSection::Decomposition ? s.decompositions
                                            : r.section == RuleSection::Homomorphism  ? s.homomorphisms
                                                                                      : s.rules;
      if (std::find(listed.begin(), listed.end(), index) == listed.end())
        problem("not listed in the rules of symbol " + s.name);
      predecessorParams(r, s);
    }
    paramLayout(r);
    for (const ContextModule& c : r.left) context(r, c, "left context");
    for (const ContextModule& c : r.right) context(r, c, "right context");
    if (r.hasGuard) {
      Scoped s(*this, "guard");
      expectType(r.guard, Type::Bool, "guard");
      expr(r.guard, &r);
    }
    if (r.alternatives.empty()) problem("no alternative");
    for (size_t i = 0; i < r.alternatives.size(); ++i) {
      Scoped s(*this, "alt " + std::to_string(i));
      expectType(r.alternatives[i].probability, Type::Num, "probability");
      expr(r.alternatives[i].probability, &r);
      block(r.alternatives[i].ops, &r);
    }
  }

  // Emit writes arguments in the symbol's order from slot 0, so the rule must read its
  // predecessor parameters from exactly those slots.
  void predecessorParams(const Rule& r, const Symbol& s) {
    if (r.params.size() < s.paramTypes.size()) {
      problem(std::to_string(r.params.size()) + " parameters, symbol " + s.name + " has " +
              std::to_string(s.paramTypes.size()));
      return;
    }
    uint32_t slot = 0;
    for (size_t i = 0; i < s.paramTypes.size(); ++i) {
      const Param& p = r.params[i];
      if (p.type != s.paramTypes[i])
        problem("parameter " + p.name + " is " + str(p.type) + ", symbol " + s.name + " has " +
                str(s.paramTypes[i]));
      if (p.slot != slot)
        problem("parameter " + p.name + " in slot " + std::to_string(p.slot) + ", expected " +
                std::to_string(slot));
      slot += slotWidth(s.paramTypes[i]);
    }
  }

  void paramLayout(const Rule& r) {
    std::vector<bool> used(std::min<uint32_t>(r.slotCount, 1u << 16), false);
    for (const Param& p : r.params) {
      const uint32_t width = slotWidth(p.type);
      if (p.slot >= used.size() || p.slot + width > r.slotCount) {
        problem("parameter " + p.name + " (slot " + std::to_string(p.slot) +
                ") outside slotCount " + std::to_string(r.slotCount));
        continue;
      }
      for (uint32_t k = p.slot; k < p.slot + width && k < used.size(); ++k) {
        if (used[k]) problem("parameter " + p.name + " overlaps slot " + std::to_string(k));
        used[k] = true;
      }
    }
  }

  void context(const Rule& r, const ContextModule& c, const char* side) {
    Scoped sc(*this, side);
    if (c.symbol == ~0u) {
      if (c.bracket != 1 && c.bracket != -1) problem("bracket must be 1 or -1");
      if (!c.paramSlots.empty()) problem("a bracket takes no parameters");
      return;
    }
    if (c.bracket != 0) problem("a symbol module with bracket set");
    if (c.symbol >= m_.symbols.size()) {
      problem("symbol " + std::to_string(c.symbol) + " out of range");
      return;
    }
    const Symbol& s = m_.symbols[c.symbol];
    if (c.paramSlots.size() != s.paramTypes.size()) {
      problem(std::to_string(c.paramSlots.size()) + " parameters for " + s.name + ", which has " +
              std::to_string(s.paramTypes.size()));
      return;
    }
    for (size_t i = 0; i < c.paramSlots.size(); ++i) {
      const Param* p = paramAt(&r, c.paramSlots[i]);
      if (!p)
        problem("slot " + std::to_string(c.paramSlots[i]) + " holds no parameter");
      else if (p->type != s.paramTypes[i])
        problem("parameter " + p->name + " is " + str(p->type) + ", " + s.name + " has " +
                str(s.paramTypes[i]));
    }
  }

  static const Param* paramAt(const Rule* r, uint32_t slot) {
    if (!r) return nullptr;
    for (const Param& p : r->params)
      if (p.slot == slot) return &p;
    return nullptr;
  }

  // ------------------------------------------------------------ ops

  void block(const Block& ops, const Rule* r) {
    int depth = 0;
    for (size_t i = 0; i < ops.size(); ++i) {
      Scoped s(*this, "op " + std::to_string(i) + " (" + opName(ops[i].kind) + ")");
      if (ops[i].kind == OpKind::Push) ++depth;
      if (ops[i].kind == OpKind::Pop && --depth < 0) {
        problem("pop without push");
        depth = 0;
      }
      op(ops[i], r);
    }
    if (depth > 0) problem(std::to_string(depth) + " push without pop");
  }

  void numArgs(const Op& op, const Rule* r, size_t count) {
    if (op.args.size() != count)
      problem(std::to_string(op.args.size()) + " arguments, expected " + std::to_string(count));
    for (size_t i = 0; i < op.args.size(); ++i) {
      expectType(op.args[i], Type::Num, "argument");
      expr(op.args[i], r);
    }
  }

  void sizes(const Op& op, const Rule* r) {
    for (const Size& s : op.sizes) {
      if (s.kind > Size::Floating) problem("bad size kind");
      expectType(s.value, Type::Num, "size");
      expr(s.value, r);
    }
  }

  void bodies(const Op& op, const Rule* r) {
    for (size_t i = 0; i < op.bodies.size(); ++i) {
      Scoped s(*this, "body " + std::to_string(i));
      block(op.bodies[i], r);
    }
  }

  void expectBodies(const Op& op, size_t count) {
    if (op.bodies.size() != count)
      problem(std::to_string(op.bodies.size()) + " bodies, expected " + std::to_string(count));
  }

  void stringId(uint32_t id) {
    if (id >= m_.strings.size()) problem("string " + std::to_string(id) + " out of range");
  }

  void op(const Op& op, const Rule* r) {
    switch (op.kind) {
      case OpKind::Translate: numArgs(op, r, 3); break;
      case OpKind::Rotate:
        if (op.index > 3) problem("axis " + std::to_string(op.index) + " out of range");
        numArgs(op, r, op.index == 3 ? 3 : 1);
        break;
      case OpKind::RotateNormal: numArgs(op, r, 1); break;
      case OpKind::Scale:
        if (op.sizes.size() != 3) problem(std::to_string(op.sizes.size()) + " sizes, expected 3");
        numArgs(op, r, 0);
        break;
      case OpKind::Push:
      case OpKind::Pop: numArgs(op, r, 0); break;
      case OpKind::Instance:
        if (op.index >= m_.assets.size()) problem("asset " + std::to_string(op.index) + " out of range");
        if (op.mode > InstanceMode::Merge) problem("bad instance mode");
        if (op.recordAs != Op::kPlacingSymbol && op.recordAs >= m_.symbols.size())
          problem("instance recorded as symbol " + std::to_string(op.recordAs) + ", out of range");
        numArgs(op, r, op.mode == InstanceMode::Merge ? 2 : 0);  // IM: maxDist, maxAngle
        break;
      case OpKind::Emit: emit(op, r); break;
      case OpKind::Turtle:
        if (op.index > static_cast<uint32_t>(TurtleOp::CylinderEnd))
          problem("turtle op " + std::to_string(op.index) + " out of range");
        if (op.index == static_cast<uint32_t>(TurtleOp::Tropism) || op.index == static_cast<uint32_t>(TurtleOp::MoveTo))
          numArgs(op, r, 3);  // @Tp(x, y, z), @M(x, y, z)
        else if (op.index == static_cast<uint32_t>(TurtleOp::SetHeading))
          numArgs(op, r, 6);  // @R(hx, hy, hz, ux, uy, uz)
        else if (op.index == static_cast<uint32_t>(TurtleOp::SurfaceBox))
          numArgs(op, r, op.args.size() == 3 ? 3 : std::min<size_t>(op.args.size(), 1));  // ~, ~(s), ~(x, y, z)
        else
          numArgs(op, r, std::min<size_t>(op.args.size(), 1));  // argument optional
        break;
      case OpKind::Subdiv:
        if (op.index > 2) problem("axis " + std::to_string(op.index) + " out of range");
        if (op.sizes.empty()) problem("no sizes");
        expectBodies(op, op.sizes.size());
        numArgs(op, r, 0);
        break;
      case OpKind::Repeat:
        if (op.index == 0 || op.index > 7) problem("axes mask " + std::to_string(op.index));
        if (op.sizes.size() != static_cast<size_t>(std::popcount(op.index)))
          problem(std::to_string(op.sizes.size()) + " sizes for axes mask " + std::to_string(op.index));
        expectBodies(op, 1);
        numArgs(op, r, 0);
        break;
      case OpKind::Comp:
        stringId(op.str);
        if (op.partLabels.empty()) expectBodies(op, 1);
        else if (op.partLabels.size() != op.bodies.size())
          problem(std::to_string(op.partLabels.size()) + " part labels for " + std::to_string(op.bodies.size()) +
                  " bodies");
        for (uint32_t label : op.partLabels) stringId(label);
        numArgs(op, r, 0);
        break;
      case OpKind::Extrude: numArgs(op, r, op.args.size() == 2 ? 2 : 1); break;  // height[, world-up flag]
      case OpKind::Offset:
        numArgs(op, r, 1);
        if (op.partLabels.size() != op.bodies.size() || op.bodies.empty())
          problem(std::to_string(op.partLabels.size()) + " part labels for " + std::to_string(op.bodies.size()) +
                  " bodies");
        for (uint32_t label : op.partLabels) stringId(label);
        break;
      case OpKind::Footprint: {
        expectBodies(op, 0);
        uint32_t start = 0;
        for (size_t ring = 0; ring <= op.ringStarts.size(); ++ring) {
          const uint32_t end = ring < op.ringStarts.size() ? op.ringStarts[ring] : uint32_t(op.args.size());
          if (end < start || end - start < 6 || (end - start) % 2 != 0)
            problem("footprint ring " + std::to_string(ring) + " of " + std::to_string(end - start) +
                    " coordinates (pairs x, z, three at least)");
          start = end;
        }
        break;
      }
      case OpKind::Color:
        expectBodies(op, 0);
        // r, g, b; or a string "#rrggbb" read as the command runs
        if (op.args.size() != 1 || op.args[0].type != Type::Str) numArgs(op, r, 3);
        break;
      case OpKind::Texture:
        expectBodies(op, 0);
        stringId(op.str);
        if (!op.args.empty()) numArgs(op, r, 2);
        break;
      case OpKind::Material:
        expectBodies(op, 0);
        if (op.index >= kMaterialProperties) problem("material property " + std::to_string(op.index));
        if (materialPropertyIsImage(op.index)) stringId(op.str), numArgs(op, r, 0);
        else numArgs(op, r, 1);
        break;
      case OpKind::Uv:
        expectBodies(op, 0);
        if (op.index > uint32_t(UvOp::Copy)) problem("uv operation " + std::to_string(op.index));
        if (op.uvSet >= kUvSets) problem("uv set " + std::to_string(op.uvSet));
        if (op.index == uint32_t(UvOp::Copy)) numArgs(op, r, 1);
        if (op.index == uint32_t(UvOp::Setup) || op.index == uint32_t(UvOp::Normalize)) stringId(op.str);
        if ((op.index == uint32_t(UvOp::Setup) || op.index == uint32_t(UvOp::Tile)) && op.sizes.size() != 2)
          problem("uv sizes " + std::to_string(op.sizes.size()));
        break;
      case OpKind::Center:
        if (op.index == 0 || op.index > 7) problem("axes mask " + std::to_string(op.index));
        numArgs(op, r, 0);
        break;
      case OpKind::Roof:
        stringId(op.str);
        if (op.bodies.size() > 1) expectBodies(op, 1);  // the body is optional
        // The angle, then optionally the overhangs and the edge index.
        if (op.args.empty() || op.args.size() > 4) problem(std::to_string(op.args.size()) + " arguments, expected 1 to 4");
        for (const auto& arg : op.args) {
          expectType(arg, Type::Num, "argument");
          expr(arg, r);
        }
        break;
      case OpKind::Lock:
        if (op.bodies.empty()) problem("no bodies");
        numArgs(op, r, 0);
        break;
      case OpKind::Line:
        expectBodies(op, 0);
        if (op.args.size() != 2) {
          problem(std::to_string(op.args.size()) + " arguments, expected 2 (width, merge)");
        } else {
          expectType(op.args[0], Type::Num, "width");
          expectType(op.args[1], Type::Bool, "merge");
        }
        if (op.asset != UINT32_MAX && op.asset >= m_.assets.size()) problem("asset " + std::to_string(op.asset) + " out of range");
        for (const Expr& a : op.args) expr(a, r);
        break;
      case OpKind::LineSeg:
        expectBodies(op, 0);
        if (op.args.size() > 1)
          problem(std::to_string(op.args.size()) + " arguments, expected 0 or 1 (length)");
        numArgs(op, r, op.args.size());
        break;
      case OpKind::Cells:
        if (op.index) stringId(op.str);
        expectBodies(op, op.bodies.size() == 2 && !op.index ? 2 : 1);  // { Base | Feature } without a file
        if (op.args.empty() || op.args.size() > 2)
          problem(std::to_string(op.args.size()) + " arguments, expected 1 or 2 (joint, mortar)");
        numArgs(op, r, op.args.size());
        break;
      case OpKind::CellPattern:
        if (op.index > static_cast<uint32_t>(CellGenerator::Shingles))
          problem("cell generator " + std::to_string(op.index) + " out of range");
        if (op.bodies.size() > 1) problem(std::to_string(op.bodies.size()) + " bodies, expected 0 or 1");
        if (op.args.size() < 3 || op.args.size() > 4) problem(std::to_string(op.args.size()) + " arguments, expected 3 or 4");
        break;
      case OpKind::ShapeOperation:
        stringId(op.str);
        if (op.partLabels.size() != op.bodies.size())
          problem(std::to_string(op.partLabels.size()) + " part labels for " + std::to_string(op.bodies.size()) +
                  " bodies");
        for (uint32_t label : op.partLabels) stringId(label);
        numArgs(op, r, op.args.size());
        break;
      case OpKind::Label:
        expectBodies(op, 0);
        if (op.args.size() != 1) problem(std::to_string(op.args.size()) + " arguments, expected 1");
        else expectType(op.args[0], Type::Str, "label");
        for (const Expr& a : op.args) expr(a, r);
        break;
      case OpKind::Report:
      case OpKind::Print: {
        expectBodies(op, 0);
        const size_t values = op.kind == OpKind::Report ? 2 : op.args.size() == 3 ? 3 : 1;
        if (op.args.size() != values) problem(std::to_string(op.args.size()) + " arguments, expected " + std::to_string(values));
        if (op.kind == OpKind::Report && !op.args.empty()) expectType(op.args[0], Type::Str, "key");
        for (size_t k = op.kind == OpKind::Report ? 1 : 0; k < op.args.size(); ++k)
          if (op.args[k].type == Type::Vec3 || (op.args.size() == 3 && op.args[k].type != Type::Num))
            problem(std::string("value is ") + str(op.args[k].type) + ", expected num, bool or str");
        for (const Expr& a : op.args) expr(a, r);
        break;
      }
      case OpKind::Synthesize:
        stringId(op.str);
        if (op.index > 0) stringId(op.index - 1);
        expectBodies(op, 0);
        numArgs(op, r, 3);
        break;
      case OpKind::Evolve:
        stringId(op.str);
        if (op.index > m_.tileSets.size())
          problem("tileset " + std::to_string(op.index) + " of " + std::to_string(m_.tileSets.size()));
        expectBodies(op, 0);
        if (op.args.empty() || op.args.size() > 4) {
          problem(std::to_string(op.args.size()) + " arguments, expected 1 to 4 (generation, k, p4, resolution)");
        } else {
          for (size_t k = 0; k < op.args.size(); ++k) {
            expectType(op.args[k], k == 2 ? Type::Bool : Type::Num, k == 2 ? "p4 flag" : "number");
            expr(op.args[k], r);
          }
        }
        break;
      case OpKind::Marching:
        // Top, Extruded, and the condition block: one MarchCondition op.
        expectBodies(op, 3);
        numArgs(op, r, 2);
        if (op.index > kMarchDiscontinuous) problem("smoothness " + std::to_string(op.index) + " out of range");
        if (op.bodies.size() == 3 &&
            (op.bodies[2].size() != 1 || op.bodies[2][0].kind != OpKind::MarchCondition))
          problem("the condition body is not one march-condition op");
        break;
      case OpKind::MarchCondition:
        expectBodies(op, 0);
        if (op.args.size() != 1) {
          problem(std::to_string(op.args.size()) + " arguments, expected 1 (the condition)");
        } else {
          expectType(op.args[0], Type::Bool, "condition");
          expr(op.args[0], r);
        }
        break;
      case OpKind::Branch:
        if (op.bodies.empty()) problem("no bodies");
        numArgs(op, r, 1);
        break;
      case OpKind::Unsupported:
        if (op.name.empty()) problem("no construct name");
        break;
      default: problem("bad op kind " + std::to_string(static_cast<int>(op.kind)));
    }
    if (op.kind != OpKind::Scale && op.kind != OpKind::Subdiv && op.kind != OpKind::Repeat && op.kind != OpKind::Uv &&
        !op.sizes.empty())
      problem("sizes on an op that takes none");
    sizes(op, r);
    bodies(op, r);
  }

  void emit(const Op& op, const Rule* r) {
    if (op.index >= m_.symbols.size()) {
      problem("symbol " + std::to_string(op.index) + " out of range");
      return;
    }
    const Symbol& s = m_.symbols[op.index];
    if (op.args.size() != s.paramTypes.size())
      problem(std::to_string(op.args.size()) + " arguments for " + s.name + ", which has " +
              std::to_string(s.paramTypes.size()));
    for (size_t i = 0; i < op.args.size(); ++i) {
      if (i < s.paramTypes.size() && op.args[i].type != s.paramTypes[i])
        problem("argument " + std::to_string(i) + " is " + str(op.args[i].type) + ", " + s.name +
                " takes " + str(s.paramTypes[i]));
      expr(op.args[i], r);
    }
  }

  // ------------------------------------------------------------ expressions

  bool arity(const Expr& e, size_t n, const char* what) {
    if (e.args.size() == n) return true;
    problem(std::string(what) + " with " + std::to_string(e.args.size()) + " operands, expected " +
            std::to_string(n));
    return false;
  }

  void expr(const Expr& e, const Rule* r) {
    for (const Expr& a : e.args) expr(a, r);
    switch (e.op) {
      case ExprOp::Const: constant(e); return;
      case ExprOp::Param: {
        if (!r) {
          problem("parameter outside a rule");
          return;
        }
        const Param* p = paramAt(r, e.index);
        if (!p)
          problem("slot " + std::to_string(e.index) + " holds no parameter (slotCount " +
                  std::to_string(r->slotCount) + ")");
        else if (p->type != e.type)
          problem("parameter " + p->name + " is " + str(p->type) + ", read as " + str(e.type));
        return;
      }
      case ExprOp::Attr:
        if (e.index >= m_.attrs.size())
          problem("attr " + std::to_string(e.index) + " out of range");
        else if (m_.attrs[e.index].type != e.type)
          problem("attr " + m_.attrs[e.index].name + " is " + str(m_.attrs[e.index].type) +
                  ", read as " + str(e.type));
        return;
      case ExprOp::Neg:
      case ExprOp::Not:
        if (!arity(e, 1, operatorSpelling(e.op))) return;
        if (unaryResultType(e.op, e.args[0].type) != e.type)
          problem(std::string(operatorSpelling(e.op)) + str(e.args[0].type) + " typed " + str(e.type));
        return;
      case ExprOp::Select:
        if (!arity(e, 3, "?:")) return;
        expectType(e.args[0], Type::Bool, "condition");
        if (e.args[1].type != e.type || e.args[2].type != e.type)
          problem("branches " + str(e.args[1].type) + " and " + str(e.args[2].type) + " typed " +
                  str(e.type));
        return;
      case ExprOp::Call: call(e); return;
      case ExprOp::Rand:
        if (!arity(e, 2, "rand")) return;
        for (const Expr& a : e.args) expectType(a, Type::Num, "rand bound");
        expectType(e, Type::Num, "rand");
        return;
      case ExprOp::Query: query(e); return;
      case ExprOp::Join:
        if (!arity(e, 2, "string +")) return;
        for (const Expr& a : e.args)
          if (a.type == Type::Vec3) problem("string + of a vector");
        expectType(e, Type::Str, "string +");
        return;
      case ExprOp::MakeVec:
        if (!arity(e, 3, "vector")) return;
        for (const Expr& a : e.args) expectType(a, Type::Num, "vector component");
        expectType(e, Type::Vec3, "vector");
        return;
      case ExprOp::VecElem:
        if (!arity(e, 1, "component")) return;
        expectType(e.args[0], Type::Vec3, "component operand");
        if (e.index > 2) problem("lane " + std::to_string(e.index));
        expectType(e, Type::Num, "component");
        return;
      default:
        break;
    }
    if (*operatorSpelling(e.op) == '\0') {
      problem("bad expression op " + std::to_string(static_cast<int>(e.op)));
      return;
    }
    if (!arity(e, 2, operatorSpelling(e.op))) return;
    if (binaryResultType(e.op, e.args[0].type, e.args[1].type) != e.type)
      problem(str(e.args[0].type) + " " + operatorSpelling(e.op) + " " + str(e.args[1].type) +
              " typed " + str(e.type));
  }

  void constant(const Expr& e) {
    if (!e.args.empty()) problem("constant with operands");
    if (e.type == Type::Bool && e.num != 0 && e.num != 1) problem("boolean constant not 0/1");
    if (e.type == Type::Str) {
      if (e.num != std::floor(e.num) || e.num < 0 || e.num >= static_cast<double>(m_.strings.size()))
        problem("string constant " + std::to_string(e.num) + " out of range");
    }
  }

  void call(const Expr& e) {
    if (e.index >= static_cast<uint32_t>(kBuiltinCount)) {
      problem("builtin " + std::to_string(e.index) + " out of range");
      return;
    }
    const BuiltinSignature& sig = builtinSignature(static_cast<Builtin>(e.index));
    if (!arity(e, static_cast<size_t>(sig.arity), sig.name)) return;
    for (int i = 0; i < sig.arity; ++i)
      if (e.args[i].type != sig.args[i])
        problem(std::string(sig.name) + " argument " + std::to_string(i) + " is " +
                str(e.args[i].type) + ", expected " + str(sig.args[i]));
    if (e.type != sig.result)
      problem(std::string(sig.name) + " typed " + str(e.type) + ", returns " + str(sig.result));
  }

  void query(const Expr& e) {
    if (e.index > static_cast<uint32_t>(kLastQuery)) {
      problem("query " + std::to_string(e.index) + " out of range");
      return;
    }
    const Query q = static_cast<Query>(e.index);
    const QuerySignature& sig = querySignature(q);
    if (sig.arity >= 0 && !arity(e, static_cast<size_t>(sig.arity), "query")) return;
    if (sig.typed) {
      for (const Expr& a : e.args) expectType(a, sig.arg, "query argument");
      expectType(e, sig.result, "query");
    }
    if (q == Query::Field || q == Query::Texture) {
      const char* kind = q == Query::Field ? "field" : "texture";
      if (e.env >= m_.environment.size() || m_.environment[e.env].kind != kind)
        problem("environment entry " + std::to_string(e.env) + " is not a " + kind);
    }
    if (q == Query::Field || q == Query::Feature) stringId(e.extra);
    if (isContextQuery(q) && ((e.extra & 3) > static_cast<uint32_t>(ContextTarget::All) ||
                              (q != Query::ContextCompare && e.extra > 3) ||
                              (e.extra >> 2) > static_cast<uint32_t>(ContextComparison::SmallestArea)))
      problem("context target " + std::to_string(e.extra) + " out of range");
    if (q == Query::GeometryAngle && e.extra > 2)
      problem("geometry angle selector " + std::to_string(e.extra) + " out of range");
    if ((q == Query::GeometryDu || q == Query::GeometryDv) && e.extra >= kUvSets)
      problem("geometry du/dv uv set " + std::to_string(e.extra) + " out of range");
  }

  const Module& m_;
  std::vector<std::string>& problems_;
  std::string where_;
};

}  // namespace

bool verifyModule(const Module& m, std::vector<std::string>& problems) {
  return Verifier(m, problems).run();
}

}  // namespace fgsg::ir
