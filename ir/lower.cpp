#include "frontend/color_literal.h"
#include "ir/lower.h"

#include "frontend/builtins.h"
#include "frontend/shape_operations.h"
#include "runtime/cga/comp_selector_name.h"

#include <algorithm>
#include <map>

namespace fgsg::ir {
namespace {

using namespace fgsg::frontend;

// Line(width, merge) without arguments: a thin line that merges into the lines it meets.
constexpr double kDefaultLineWidth = 0.05;
constexpr bool kDefaultLineMerge = true;

Type toType(ValueType t) {
  switch (t) {
    case ValueType::Bool: return Type::Bool;
    case ValueType::Str: return Type::Str;
    case ValueType::Vec3: return Type::Vec3;
    default: return Type::Num;
  }
}

Loc toLoc(const SourceRange& r) { return Loc{r.begin.line, r.begin.col}; }

class Lowerer {
 public:
  Lowerer(const Program& p, const SemaResult& s) : prog_(p), sema_(s) {}

  Module run() {
    m_.sourceName = prog_.fileName;
    for (const auto& s : sema_.symbols) {
      Symbol sym;
      sym.name = symbolDisplayName(s.name);  // `Roof$` from a .cga rule is `Roof`
      for (ValueType t : s.params) {
        sym.paramTypes.push_back(toType(t));
        sym.slotCount += slotWidth(toType(t));
      }
      for (size_t ri : s.rules)  // its first production's (lowerRule raises it to the highest)
        if (prog_.rules[ri].section == frontend::RuleSection::Production) {
          sym.priority = prog_.rules[ri].priority;
          break;
        }
      m_.symbols.push_back(sym);
    }
    for (const auto& a : sema_.attrs) {
      Attr attr;
      attr.name = a.name;
      attr.type = toType(a.value.type);
      attr.value = constant(a.value);
      m_.attrs.push_back(std::move(attr));
      if (a.importerValue) {  // reads only the attrs before it
        Expr v = expr(*a.importerValue);
        m_.attrs.back().fromImporter = true;
        m_.attrs.back().importerValue = std::move(v);
      }
      for (const auto& n : a.annotations) m_.attrs.back().annotations.push_back({n.name, n.args});
    }
    lowerEnvironment();  // first: queries refer to environment entries by index
    std::map<uint32_t, int> perSymbolCount;
    for (size_t i = 0; i < prog_.rules.size(); ++i) lowerRule(i, perSymbolCount);
    markFirstApplicable();
    lowerAxiom();
    m_.mode = sema_.mode == "parallel"    ? DeriveMode::Parallel
              : sema_.mode == "depthfirst" ? DeriveMode::DepthFirst
                                           : DeriveMode::BreadthFirst;
    m_.steps = sema_.steps;
    m_.depthBound = sema_.depthBound;
    m_.countAttr = sema_.countAttr.empty() ? -1 : m_.findAttr(sema_.countAttr);
    m_.decompositionDepth = prog_.decompositionDepth;
    m_.homomorphismDepth = prog_.homomorphismDepth;
    m_.cityEngineLots = prog_.cityEngineLots;
    m_.turtle = {sema_.turtleAngle, sema_.turtleStep, sema_.turtleWidth,
                 sema_.turtleSegments == "tubes"     ? TurtleSegments::Tubes
                 : sema_.turtleSegments == "ribbons" ? TurtleSegments::Ribbons
                 : sema_.turtleSegments == "lines"   ? TurtleSegments::Lines
                                                     : TurtleSegments::Cylinders,
                 sema_.turtleSides,
                 sema_.turtleColors.empty() ? defaultTurtleColors() : sema_.turtleColors};
    for (const std::string& name : sema_.contextIgnored) m_.contextIgnored.push_back(symbolIndex(name));
    lowerCollision();
    return std::move(m_);
  }

 private:
  uint32_t symbolIndex(const std::string& name) const {
    return static_cast<uint32_t>(sema_.findSymbol(name));
  }

  Expr constant(const ConstValue& v) {
    switch (v.type) {
      case ValueType::Bool: return Expr::boolean(v.num != 0);
      case ValueType::Str: return Expr::string(m_.internString(v.str));
      case ValueType::Vec3: {
        Expr e;
        e.type = Type::Vec3;
        for (int k = 0; k < 3; ++k) e.vec[k] = v.vec[k];
        return e;
      }
      default: return Expr::number(v.num);
    }
  }

  void lowerRule(size_t i, std::map<uint32_t, int>& perSymbolCount) {
    const frontend::Rule& r = prog_.rules[i];
    ir::Rule out;
    out.symbol = symbolIndex(r.predecessor.name);
    int n = perSymbolCount[out.symbol]++;
    out.label = r.label.empty() ? r.predecessor.name + "#" + std::to_string(n) : r.label;
    out.priority = r.priority;
    out.loc = toLoc(r.range);
    for (const auto& [name, type] : sema_.ruleParams[i]) {
      out.params.push_back({name, toType(type), out.slotCount});
      out.slotCount += slotWidth(toType(type));
    }
    // Context modules take their parameters' slots after the predecessor's, in order.
    size_t next = r.predecessor.params.size();
    auto context = [&](const std::vector<ModulePattern>& pats, std::vector<ContextModule>& dst) {
      for (const auto& pat : pats) {
        ContextModule cm;
        if (pat.name == "[" || pat.name == "]") {
          cm.bracket = pat.name == "[" ? 1 : -1;
        } else {
          cm.symbol = symbolIndex(pat.name);
          for (size_t k = 0; k < pat.params.size(); ++k) cm.paramSlots.push_back(out.params[next++].slot);
        }
        dst.push_back(cm);
      }
    };
    context(r.leftContext, out.left);
    context(r.rightContext, out.right);
    params_ = &out.params;
    if (r.guard) {
      out.hasGuard = true;
      out.guard = expr(*r.guard);
    }
    for (const auto& b : r.branches) {
      Alternative alt;
      alt.loc = toLoc(b.range);
      alt.probability = b.probability ? expr(*b.probability) : Expr::number(1.0);
      out.weighted = out.weighted || b.probability != nullptr;
      alt.ops = block(b.successor);
      out.alternatives.push_back(std::move(alt));
    }
    params_ = nullptr;
    Symbol& sym = m_.symbols[out.symbol];
    out.section = r.section == frontend::RuleSection::Decomposition ? RuleSection::Decomposition
                  : r.section == frontend::RuleSection::Homomorphism ? RuleSection::Homomorphism
                                                                     : RuleSection::Production;
    const uint32_t index = static_cast<uint32_t>(m_.rules.size());
    if (out.section == RuleSection::Decomposition) sym.decompositions.push_back(index);
    else if (out.section == RuleSection::Homomorphism) sym.homomorphisms.push_back(index);
    else sym.rules.push_back(index), sym.priority = std::max(sym.priority, out.priority);
    m_.rules.push_back(std::move(out));
  }

  // Symbol::firstApplicable: at least two specific rules (a guard or a context), none of
  // them weighted.
  void markFirstApplicable() {
    const auto firstApplicable = [&](const std::vector<uint32_t>& rules) {
      int specific = 0;
      bool weighted = false;
      for (uint32_t ri : rules) {
        const Rule& r = m_.rules[ri];
        if (!r.hasGuard && r.left.empty() && r.right.empty()) continue;
        ++specific;
        weighted = weighted || r.weighted;
      }
      return specific >= 2 && !weighted;
    };
    for (Symbol& sym : m_.symbols) {
      sym.firstApplicable = firstApplicable(sym.rules);
      sym.firstApplicableDecomposition = firstApplicable(sym.decompositions);
      sym.firstApplicableHomomorphism = firstApplicable(sym.homomorphisms);
    }
  }

  void lowerAxiom() {
    if (!prog_.axioms.empty()) {
      m_.axiom = block(prog_.axioms.front().successor);
      return;
    }
    Op emit;
    emit.kind = OpKind::Emit;
    emit.index = symbolIndex(sema_.startSymbol);
    emit.name = sema_.startSymbol;
    m_.axiom.push_back(std::move(emit));
  }

  void lowerCollision() {
    CollisionSettings& c = m_.collision;
    c.all = sema_.collisionAll;
    c.omit = sema_.collisionOmit;
    c.metric = sema_.collisionMetric == "centre"     ? CollisionMetric::Centre
               : sema_.collisionMetric == "geodesic" ? CollisionMetric::Geodesic
               : sema_.collisionMetric == "distance" ? CollisionMetric::Distance
                                                     : CollisionMetric::Mesh;
    c.radius = c.metric == CollisionMetric::Mesh ? 0.0 : sema_.collisionRadius;
    if (sema_.collisionDeclared) c.loc = toLoc(sema_.collisionRange);
  }

  void lowerEnvironment() {
    for (const auto& s : prog_.surfaces)
      m_.environment.push_back({"surface", s.path.empty() ? s.generator : s.path,
                                s.path.empty() ? "procedural" : "file", toLoc(s.range)});
    for (const auto& f : prog_.fields)
      m_.environment.push_back({"field", f.name, f.source, toLoc(f.range)});
    for (const auto& t : prog_.textures)
      m_.environment.push_back({"texture", t.name, t.path, toLoc(t.range)});
    lowerSurfaceAndFields();
    lowerTileSets();
  }

  // The surface and fields as sema evaluated them: constants only, names as written.
  void lowerSurfaceAndFields() {
    const SurfaceInfo& s = sema_.surface;
    if (s.present) {
      m_.surface.present = true;
      m_.surface.path = s.path;
      m_.surface.generator = s.generator;
      m_.surface.args = s.args;
      m_.surface.loc = toLoc(s.range);
    }
    for (const FieldInfo& f : sema_.fieldSpecs) {
      FieldSpec out;
      out.name = f.name;
      out.source = f.source;
      out.kind = f.kind;
      out.path = f.path;
      out.loc = toLoc(f.range);
      for (const FieldDesignInfo& d : f.design) out.design.push_back({d.kind, d.words, toLoc(d.range)});
      if (f.expression) {
        params_ = &surfacePointParams();
        out.expression.push_back(expr(*f.expression));
        params_ = nullptr;
      }
      m_.fields.push_back(std::move(out));
    }
  }

  void lowerTileSets() {
    auto curves = [&](const std::vector<TileCurveInfo>& in) {
      std::vector<TileCurveSpec> out;
      for (const TileCurveInfo& c : in) out.push_back({c.name, c.cubic, c.points, toLoc(c.range)});
      return out;
    };
    for (const TilesetInfo& t : sema_.tilesets)
      m_.tileSets.push_back(
          {t.name, curves(t.loci), curves(t.sections), t.orientations, t.symbols, t.settings, toLoc(t.range)});
  }

  // 1 + the tileset's index when `e` names a declared tileset, else 0.
  uint32_t tileSetReference(const frontend::Expr& e) const {
    if (e.kind != frontend::ExprKind::Ident) return 0;
    for (size_t i = 0; i < m_.tileSets.size(); ++i)
      if (m_.tileSets[i].name == e.text) return static_cast<uint32_t>(i + 1);
    return 0;
  }

  // ------------------------------------------------------------ successors

  Block block(const Successor& s) {
    Block out;
    for (const auto& item : s.items) lowerItem(item, out);
    return out;
  }

  void lowerItem(const Item& item, Block& out) {
    Op op;
    op.loc = toLoc(item.range);
    op.name = item.name;
    switch (item.kind) {
      case ItemKind::Bracket: {
        Op push;
        push.kind = OpKind::Push;
        push.loc = op.loc;
        out.push_back(push);
        for (const auto& c : item.children) lowerItem(c, out);
        Op pop;
        pop.kind = OpKind::Pop;
        pop.loc = toLoc(SourceRange{item.range.end, item.range.end});
        out.push_back(pop);
        return;
      }
      case ItemKind::Turtle:
        if (isShapeItem(item, sema_)) break;  // a turtle symbol with rules: a shape (below)
        op.kind = OpKind::Turtle;
        op.index = static_cast<uint32_t>(ir::turtleOpNamed(item.name));
        if (!item.surface.empty()) op.asset = m_.internAsset(item.surface);  // `~leaf`
        if (item.name == "@O") op.asset = m_.internAsset("sphere");
        if (item.name == "@o") op.asset = m_.internAsset("disc");
        for (const auto& a : item.args) op.args.push_back(expr(*a));
        out.push_back(std::move(op));
        return;
      case ItemKind::Call: break;
    }
    if (isShapeItem(item, sema_)) {
      op.kind = OpKind::Emit;
      op.index = symbolIndex(item.name);
      for (const auto& a : item.args) op.args.push_back(expr(*a));
      out.push_back(std::move(op));
      return;
    }
    const CommandInfo& cmd = *findCommand(item.name);
    for (const auto& b : item.body) op.bodies.push_back(block(b));
    auto allArgs = [&](size_t from) {
      for (size_t k = from; k < item.args.size(); ++k) op.args.push_back(expr(*item.args[k]));
    };
    switch (cmd.id) {
      case CommandId::Translate: op.kind = OpKind::Translate; allArgs(0); break;
      case CommandId::Rotate: op.kind = OpKind::Rotate; op.index = 3; allArgs(0); break;
      case CommandId::RotateX: op.kind = OpKind::Rotate; op.index = 0; allArgs(0); break;
      case CommandId::RotateY: op.kind = OpKind::Rotate; op.index = 1; allArgs(0); break;
      case CommandId::RotateZ: op.kind = OpKind::Rotate; op.index = 2; allArgs(0); break;
      case CommandId::RotateNormal: op.kind = OpKind::RotateNormal; allArgs(0); break;
      case CommandId::Scale:
        op.kind = OpKind::Scale;
        for (const auto& a : item.args) op.sizes.push_back(size(*a));
        break;
      case CommandId::Instance:
      case CommandId::InstanceCollide:
      case CommandId::InstanceMerge:
        op.kind = OpKind::Instance;
        op.mode = cmd.id == CommandId::Instance          ? InstanceMode::Plain
                  : cmd.id == CommandId::InstanceCollide ? InstanceMode::Collide
                                                         : InstanceMode::Merge;
        op.index = m_.internAsset(constString(*item.args[0]));
        if (!item.recordAs.empty()) op.recordAs = leafSymbol(symbolDisplayName(item.recordAs));
        if (cmd.id == CommandId::Instance) {  // I("asset"[, "yUp" | "zUp"[, insert mode]]), checked by sema
          if (item.args.size() > 1) op.zUp = constString(*item.args[1]) == "zUp";
          if (item.args.size() > 2) {
            const std::string fit = constString(*item.args[2]);
            op.insertFit = fit == "keepSizeAndPosition"     ? InsertFit::KeepSizeAndPosition
                           : fit == "keepSizeAlignPosition" ? InsertFit::KeepSizeAlignPosition
                                                            : InsertFit::AlignSizeAndPosition;
          }
          break;
        }
        allArgs(1);
        break;
      case CommandId::Subdiv:
        op.kind = OpKind::Subdiv;
        op.index = axisIndex(constString(*item.args[0]));
        op.repeat = item.repeatPattern;
        op.cityEngineSizing = item.cityEngineSizing;
        // Subdiv or SplitArea (sizes that are areas, laid out as a .cga split's): every
        // Subdiv names its command, so a plain split never reads as an area split.
        op.str = m_.internString(cmd.name);
        if (cmd.name == std::string("SplitArea")) op.cityEngineSizing = true;
        for (size_t k = 1; k < item.args.size(); ++k) op.sizes.push_back(size(*item.args[k]));
        break;
      case CommandId::Repeat: {
        op.kind = OpKind::Repeat;
        unsigned mask = 0;
        for (char c : constString(*item.args[0])) mask |= 1u << axisIndex(std::string(1, c));
        op.index = mask;
        // Sizes are listed per axis in the order written; store them low bit first.
        std::string axes = constString(*item.args[0]);
        std::vector<std::pair<uint32_t, Size>> bySlot;
        for (size_t k = 1; k < item.args.size(); ++k)
          bySlot.push_back({axisIndex(std::string(1, axes[k - 1])), size(*item.args[k])});
        std::sort(bySlot.begin(), bySlot.end(),
                  [](const auto& a, const auto& b) { return a.first < b.first; });
        for (auto& [axis, s] : bySlot) op.sizes.push_back(std::move(s));
        break;
      }
      case CommandId::Comp:
        op.kind = OpKind::Comp;
        op.str = m_.internString(constString(*item.args[0]));
        for (const auto& part : item.body)
          if (!part.selector.empty()) op.partLabels.push_back(m_.internString(part.selector));
        // comp.sel's names (ir::Module::compSelectors); an unlabelled comp's is `all`.
        for (uint32_t label : op.partLabels.empty() ? std::vector<uint32_t>{m_.internString("all")} : op.partLabels)
          if (std::find(m_.compSelectorLabels.begin(), m_.compSelectorLabels.end(), label) ==
              m_.compSelectorLabels.end()) {
            m_.compSelectorLabels.push_back(label);
            m_.compSelectors.push_back(m_.internString(rt::cga::compSelectorName(m_.strings[label])));
          }
        break;
      case CommandId::Extrude: op.kind = OpKind::Extrude; allArgs(0); break;
      case CommandId::Footprint:
        op.kind = OpKind::Footprint;
        for (const auto& a : item.args) {
          if (a->kind == frontend::ExprKind::String) op.ringStarts.push_back(static_cast<uint32_t>(op.args.size()));
          else op.args.push_back(expr(*a));
        }
        break;
      case CommandId::Offset:
        op.kind = OpKind::Offset;
        allArgs(0);
        for (const auto& part : item.body) op.partLabels.push_back(m_.internString(part.selector));
        break;
      case CommandId::Roof:
        op.kind = OpKind::Roof;
        op.str = m_.internString(constString(*item.args[0]));
        // Roof(kind, "byHeight" | "byAngle", value, ...): the word picks what value is.
        if (item.args.size() > 1 && sema_.exprTypes.count(item.args[1].get()) &&
            sema_.exprTypes.at(item.args[1].get()) == frontend::ValueType::Str) {
          op.index = constString(*item.args[1]) == "byHeight" ? kRoofByHeight : kRoofByAngle;
          allArgs(2);
        } else {
          allArgs(1);
        }
        break;
      case CommandId::Lock: op.kind = OpKind::Lock; break;
      case CommandId::Color:
        op.kind = OpKind::Color;
        if (item.args.size() == 1 && sema_.exprTypes.count(item.args[0].get()) &&
            sema_.exprTypes.at(item.args[0].get()) == frontend::ValueType::Vec3) {
          op.args = vectorComponents(expr(*item.args[0]));  // a vector (r, g, b)
        } else if (item.args.size() == 1 && item.args[0]->kind != ExprKind::String &&
                   !(sema_.names.count(item.args[0].get()) &&
                     sema_.names.at(item.args[0].get()).kind == frontend::NameRef::Const)) {
          op.args.push_back(expr(*item.args[0]));  // a string no constant: read as it runs
        } else if (item.args.size() == 1) {  // "#rrggbb": three constant numbers
          std::array<double, 3> rgb{};
          frontend::parseHexColor(constString(*item.args[0]), rgb);
          for (double c : rgb) {
            Expr e = Expr::number(c);
            e.loc = op.loc;
            op.args.push_back(std::move(e));
          }
        } else {
          allArgs(0);
        }
        break;
      case CommandId::Texture:
        op.kind = OpKind::Texture;
        op.str = m_.internString(constString(*item.args[0]));
        allArgs(1);
        break;
      case CommandId::Material: {
        op.kind = OpKind::Material;
        op.index = static_cast<uint32_t>(frontend::materialProperty(constString(*item.args[0])));
        if (materialPropertyIsImage(op.index))
          op.str = m_.internString(constString(*item.args[1]));
        else
          allArgs(1);
        break;
      }
      case CommandId::UvOperation: {
        op.kind = OpKind::Uv;
        op.index = static_cast<uint32_t>(frontend::uvOperation(item.name));
        const auto uv = static_cast<UvOp>(op.index);
        // The uv set, a number 0..9 (sema checks it): the optional argument after the
        // operation's own, CopyUV's second (its first, the source, stays an argument).
        static const size_t kOwnArgs[] = {3, 2, 2, 1, 2, 1, 0, 0, 1};
        const size_t own = std::min(item.args.size(), kOwnArgs[op.index]);
        if (item.args.size() > own) op.uvSet = static_cast<uint8_t>(item.args.back()->number);
        if (uv == UvOp::Setup || uv == UvOp::Normalize) op.str = m_.internString(constString(*item.args[0]));
        if (uv == UvOp::Setup || uv == UvOp::Tile)
          for (size_t k = uv == UvOp::Setup ? 1 : 0; k < own; ++k) op.sizes.push_back(size(*item.args[k]));
        else if (uv != UvOp::Normalize)
          for (size_t k = 0; k < own; ++k) op.args.push_back(expr(*item.args[k]));
        break;
      }
      case CommandId::Center:
        op.kind = OpKind::Center;
        for (char c : constString(*item.args[0])) op.index |= 1u << axisIndex(std::string(1, c));
        break;
      case CommandId::Line: {
        // Always two arguments: the defaults are filled in here, not by the runtime. A
        // third, the asset drawn along the line, is the op's asset.
        op.kind = OpKind::Line;
        for (size_t k = 0; k < std::min<size_t>(item.args.size(), 2); ++k) op.args.push_back(expr(*item.args[k]));
        op.asset = item.args.size() > 2 ? m_.internAsset(constString(*item.args[2])) : UINT32_MAX;
        Expr width = Expr::number(kDefaultLineWidth), merge = Expr::boolean(kDefaultLineMerge);
        width.loc = merge.loc = op.loc;
        if (op.args.size() < 1) op.args.push_back(std::move(width));
        if (op.args.size() < 2) op.args.push_back(std::move(merge));
        break;
      }
      case CommandId::LineSeg: op.kind = OpKind::LineSeg; allArgs(0); break;
      case CommandId::Marching: {
        // The condition is evaluated at each candidate destination, so it is a block of
        // its own (the last body) that the engine runs there, not an argument.
        op.kind = OpKind::Marching;
        op.args.push_back(expr(*item.args[0]));
        op.args.push_back(expr(*item.args[1]));
        if (item.args.size() > 3) {  // the terminals' smoothness, a word sema checked
          const std::string smoothness = constString(*item.args[3]);
          op.index = smoothness == "C0" ? kMarchC0 : smoothness == "none" ? kMarchDiscontinuous : kMarchC1;
        }
        if (op.bodies.size() < 2) op.bodies.emplace_back();  // no Extruded part written
        Op test;
        test.kind = OpKind::MarchCondition;
        test.loc = toLoc(item.args[2]->range);
        test.args.push_back(expr(*item.args[2]));
        op.bodies.emplace_back().push_back(std::move(test));
        break;
      }
      case CommandId::Branch: op.kind = OpKind::Branch; allArgs(0); break;
      case CommandId::Evolve:
        op.kind = OpKind::Evolve;
        op.index = tileSetReference(*item.args[0]);
        op.str = m_.internString(op.index ? item.args[0]->text : constString(*item.args[0]));
        allArgs(1);
        break;
      case CommandId::Cells: {
        op.kind = OpKind::Cells;
        const bool file = typeOf(*item.args[0]) == Type::Str;
        if (file) op.index = 1, op.str = m_.internString(constString(*item.args[0]));
        allArgs(file ? 1 : 0);
        break;
      }
      case CommandId::BrickBond:
      case CommandId::HeaderRow:
      case CommandId::ArchBricks:
      case CommandId::RandomStones:
      case CommandId::EnglishBond:
      case CommandId::FlemishBond:
      case CommandId::HeaderBond:
      case CommandId::Shingles: {
        static const std::pair<CommandId, CellGenerator> kGenerators[] = {
            {CommandId::BrickBond, CellGenerator::BrickBond},     {CommandId::HeaderRow, CellGenerator::HeaderRow},
            {CommandId::ArchBricks, CellGenerator::ArchBricks},   {CommandId::RandomStones, CellGenerator::RandomStones},
            {CommandId::EnglishBond, CellGenerator::EnglishBond}, {CommandId::FlemishBond, CellGenerator::FlemishBond},
            {CommandId::HeaderBond, CellGenerator::HeaderBond},   {CommandId::Shingles, CellGenerator::Shingles}};
        op.kind = OpKind::CellPattern;
        for (const auto& [id, generator] : kGenerators)
          if (id == cmd.id) op.index = static_cast<uint32_t>(generator);
        allArgs(0);
        break;
      }
      case CommandId::Synthesize:
        op.kind = OpKind::Synthesize;
        op.str = m_.internString(constString(*item.args[0]));
        for (size_t k = 1; k < 4; ++k) op.args.push_back(expr(*item.args[k]));
        // The parts' symbol of continuous synthesis, as a string id + 1 (0: none).
        op.index = item.args.size() > 4 ? m_.internString(constString(*item.args[4])) + 1 : 0;
        break;
      case CommandId::Report: op.kind = OpKind::Report; allArgs(0); break;
      case CommandId::Label: op.kind = OpKind::Label; allArgs(0); break;
      case CommandId::ShapeOperation:
        op.kind = OpKind::ShapeOperation;
        op.str = m_.internString(cmd.name);
        for (size_t k = 0; k < item.args.size(); ++k) {
          double code = 0;
          std::string allowed;
          if (item.args[k]->kind == ExprKind::String || !constString(*item.args[k]).empty()) {
            frontend::shapeOperationWord(cmd.name, k, constString(*item.args[k]), code, allowed);
            // InsertAlongUV's asset: the op's asset, found with the others before deriving.
            if (cmd.name == std::string("InsertAlongUV") && k == 1) op.asset = m_.internAsset(constString(*item.args[k]));
            Expr e = Expr::number(code);
            e.loc = op.loc;
            op.args.push_back(std::move(e));
          } else {
            op.args.push_back(expr(*item.args[k]));
          }
        }
        for (const auto& part : item.body) op.partLabels.push_back(m_.internString(part.selector));
        if (cmd.name == std::string("SetbackPerEdge")) {
          // CityEngine evaluates the distance once per edge, on the edge (comp.index set):
          // it moves into a first body, an EdgeDistance op the setback runs on each edge.
          Op distance;
          distance.kind = OpKind::ShapeOperation;
          distance.loc = op.loc;
          distance.str = m_.internString("EdgeDistance");
          distance.args = std::move(op.args);
          op.args.clear();
          op.bodies.insert(op.bodies.begin(), Block{});
          op.bodies.front().push_back(std::move(distance));
          op.partLabels.insert(op.partLabels.begin(), m_.internString("#distance"));
        }
        break;
      case CommandId::Print:
        op.kind = OpKind::Print;
        if (sema_.exprTypes.count(item.args[0].get()) &&
            sema_.exprTypes.at(item.args[0].get()) == frontend::ValueType::Vec3)
          op.args = vectorComponents(expr(*item.args[0]));  // printed "(x, y, z)"
        else
          allArgs(0);
        break;
      case CommandId::Forward:
      case CommandId::Move:
        op.kind = OpKind::Turtle;
        op.index = static_cast<uint32_t>(cmd.id == CommandId::Forward ? TurtleOp::Forward
                                                                      : TurtleOp::Move);
        allArgs(0);
        break;
      default:
        op.kind = OpKind::Unsupported;
        op.why = cmd.laterIssue ? cmd.laterIssue : "";
        allArgs(0);
        break;
    }
    out.push_back(std::move(op));
  }

  // A vector's three components: written out, each once; else read from it.
  static std::vector<Expr> vectorComponents(Expr v) {
    if (v.op == ExprOp::MakeVec) return std::move(v.args);
    std::vector<Expr> out;
    for (uint32_t k = 0; k < 3; ++k) {
      Expr c;
      c.op = ExprOp::VecElem;
      c.type = Type::Num;
      c.index = k;
      c.loc = v.loc;
      c.args.push_back(v);
      out.push_back(std::move(c));
    }
    return out;
  }

  static uint32_t axisIndex(const std::string& s) {
    char c = s.empty() ? 'X' : s[0];
    return (c == 'Y' || c == 'y') ? 1 : (c == 'Z' || c == 'z') ? 2 : 0;
  }

  std::string constString(const frontend::Expr& e) const {
    if (e.kind == ExprKind::String) return e.text;
    auto it = sema_.names.find(&e);
    if (it != sema_.names.end()) return it->second.value.str;
    return {};
  }

  // A constant number sema checked (Geometry.du's uv set): written, or a constant's value.
  double constNumber(const frontend::Expr& e) const {
    if (e.kind == ExprKind::Number) return e.number;
    auto it = sema_.names.find(&e);
    if (it != sema_.names.end()) return it->second.value.num;
    return 0;
  }

  Size size(const frontend::Expr& e) {
    Size s;
    if (e.kind == ExprKind::RelSize) {
      s.kind = Size::Relative;
      s.value = Expr::number(e.number);
    } else if (e.kind == ExprKind::FloatSize) {
      s.kind = Size::Floating;
      s.value = expr(*e.args[0]);
    } else {
      s.value = expr(e);
    }
    return s;
  }

  // ------------------------------------------------------------ expressions

  Type typeOf(const frontend::Expr& e) const {
    auto it = sema_.exprTypes.find(&e);
    return it == sema_.exprTypes.end() ? Type::Num : toType(it->second);
  }

  Expr node(ExprOp op, Type t, const frontend::Expr& src) {
    Expr e;
    e.op = op;
    e.type = t;
    e.loc = toLoc(src.range);
    return e;
  }

  Expr expr(const frontend::Expr& e) {
    Expr out;
    switch (e.kind) {
      case ExprKind::Number:
      case ExprKind::RelSize: out = Expr::number(e.number); break;
      case ExprKind::FloatSize: return expr(*e.args[0]);
      case ExprKind::Bool: out = Expr::boolean(e.boolean); break;
      case ExprKind::String: out = Expr::string(m_.internString(e.text)); break;
      case ExprKind::Ident: {
        const NameRef& ref = sema_.names.at(&e);
        switch (ref.kind) {
          case NameRef::Param:
            out = node(ExprOp::Param, (*params_)[ref.index].type, e);
            out.index = (*params_)[ref.index].slot;
            return out;
          case NameRef::Attr: return attrRead(ref.index, e);
          default: out = constant(ref.value); break;
        }
        break;
      }
      case ExprKind::Vector:
        out = node(ExprOp::MakeVec, Type::Vec3, e);
        for (const auto& a : e.args) out.args.push_back(expr(*a));
        return out;
      case ExprKind::Unary:
        out = node(e.text == "!" ? ExprOp::Not : ExprOp::Neg, typeOf(e), e);
        if (e.text == "+") return expr(*e.args[0]);
        out.args.push_back(expr(*e.args[0]));
        return out;
      case ExprKind::Binary: {
        static const std::map<std::string, ExprOp> kOps = {
            {"+", ExprOp::Add}, {"-", ExprOp::Sub}, {"*", ExprOp::Mul}, {"/", ExprOp::Div},
            {"%", ExprOp::Mod}, {"^", ExprOp::Pow}, {"==", ExprOp::Eq}, {"!=", ExprOp::Ne},
            {"<", ExprOp::Lt},  {"<=", ExprOp::Le}, {">", ExprOp::Gt},  {">=", ExprOp::Ge},
            {"&&", ExprOp::And}, {"||", ExprOp::Or}};
        // `+` with a string: CGA's string join ("floor" + 3), at run time.
        out = node(e.text == "+" && typeOf(e) == Type::Str ? ExprOp::Join : kOps.at(e.text), typeOf(e), e);
        out.args.push_back(expr(*e.args[0]));
        out.args.push_back(expr(*e.args[1]));
        return out;
      }
      case ExprKind::Ternary:
        out = node(ExprOp::Select, typeOf(e), e);
        for (const auto& a : e.args) out.args.push_back(expr(*a));
        return out;
      case ExprKind::Call: {
        if (e.text == "Rand" || e.text == "rand") {
          out = node(ExprOp::Rand, Type::Num, e);
        } else {
          static const std::map<std::string, Builtin> kFns = {
              {"sin", Builtin::Sin},     {"cos", Builtin::Cos},     {"tan", Builtin::Tan},
              {"asin", Builtin::Asin},   {"acos", Builtin::Acos},   {"atan", Builtin::Atan},
              {"atan2", Builtin::Atan2}, {"sqrt", Builtin::Sqrt},   {"abs", Builtin::Abs},
              {"min", Builtin::Min},     {"max", Builtin::Max},     {"floor", Builtin::Floor},
              {"ceil", Builtin::Ceil},   {"round", Builtin::Round}, {"clamp", Builtin::Clamp},
              {"lerp", Builtin::Lerp},   {"pow", Builtin::Pow},     {"exp", Builtin::Exp},
              {"log", Builtin::Log},     {"sign", Builtin::Sign},   {"length", Builtin::Length},
              {"dot", Builtin::Dot},     {"normalize", Builtin::Normalize}};
          out = node(ExprOp::Call, typeOf(e), e);
          out.index = static_cast<uint32_t>(kFns.at(e.text));
        }
        for (const auto& a : e.args) out.args.push_back(expr(*a));
        return out;
      }
      case ExprKind::Member: return member(e);
    }
    out.loc = toLoc(e.range);
    return out;
  }

  // The symbol of a leaf no successor creates (an insert's `Tree.`): found, or added
  // without rules or parameters.
  uint32_t leafSymbol(const std::string& name) {
    if (const int s = m_.findSymbol(name); s >= 0) return static_cast<uint32_t>(s);
    Symbol sym;
    sym.name = name;
    m_.symbols.push_back(std::move(sym));
    return static_cast<uint32_t>(m_.symbols.size() - 1);
  }

  Expr attrRead(size_t attr, const frontend::Expr& e) {
    Expr out = node(ExprOp::Attr, m_.attrs[attr].type, e);
    out.index = static_cast<uint32_t>(attr);
    return out;
  }

  Expr member(const frontend::Expr& e) {
    // Lot.area, Lot.prop(...): the attr the analyzer made for it.
    if (e.object == "Lot") return attrRead(sema_.names.at(&e).index, e);
    Expr out = node(ExprOp::Query, typeOf(e), e);
    static const std::map<std::string, Query> kScope = {
        {"sx", Query::ScopeSx}, {"sy", Query::ScopeSy}, {"sz", Query::ScopeSz},
        {"px", Query::ScopePx}, {"py", Query::ScopePy}, {"pz", Query::ScopePz}};
    if (e.object == "Scope" && e.text == "occ") {
      out.index = static_cast<uint32_t>(Query::ScopeOcc);
    } else if (e.object == "Scope") {
      out.index = static_cast<uint32_t>(kScope.at(e.text));
    } else if (e.object == "Shape" || e.object == "Geometry") {
      static const std::map<std::string, Query> kShape = {
          {"depth", Query::ShapeDepth},           {"index", Query::ShapeIndex},
          {"visible", Query::ShapeVisible},       {"splitIndex", Query::ShapeSplitIndex},
          {"splitTotal", Query::ShapeSplitTotal}, {"compIndex", Query::ShapeCompIndex},
          {"compTotal", Query::ShapeCompTotal},   {"compSel", Query::ShapeCompSel},
          {"inside", Query::ContextInside},
          {"overlaps", Query::ContextOverlaps},   {"touches", Query::ContextTouches},
          {"minimumDistance", Query::ContextMinimumDistance}, {"contextCount", Query::ContextCount},
          {"contextCompare", Query::ContextCompare}};
      static const std::map<std::string, Query> kGeometry = {
          {"area", Query::GeometryArea},         {"height", Query::GeometryHeight},
          {"nVertices", Query::GeometryVertices}, {"nFaces", Query::GeometryFaces},
          {"isPlanar", Query::GeometryIsPlanar}, {"isConcave", Query::GeometryIsConcave},
          {"boundaryLength", Query::GeometryBoundaryLength}, {"angle", Query::GeometryAngle},
          {"du", Query::GeometryDu}, {"dv", Query::GeometryDv}};
      out.index = static_cast<uint32_t>((e.object == "Shape" ? kShape : kGeometry).at(e.text));
      // comp.sel outside any comp: the string "" (its id in extra).
      if (static_cast<Query>(out.index) == Query::ShapeCompSel) out.extra = m_.internString("");
      if (static_cast<Query>(out.index) == Query::GeometryAngle) {
        // The selector is a constant word (sema checked it), fixed here as a number.
        const std::string selector = constString(*e.args[0]);
        out.extra = selector == "azimuth" ? 1u : selector == "zenith" ? 2u : 0u;
        return out;
      }
      // Geometry.du(k, "uvSpace"): the uv set k (a constant 0..9, sema checked it) in extra.
      if (static_cast<Query>(out.index) == Query::GeometryDu || static_cast<Query>(out.index) == Query::GeometryDv) {
        out.extra = static_cast<uint32_t>(constNumber(*e.args[0]));
        return out;
      }
      if (isContextQuery(static_cast<Query>(out.index))) {
        // The target is a constant word (sema checked it); the label any string, "" for none.
        const std::string target = e.args.empty() ? "all" : constString(*e.args[0]);
        out.extra = static_cast<uint32_t>(target == "intra" ? ContextTarget::Intra
                                          : target == "inter" ? ContextTarget::Inter
                                                              : ContextTarget::All);
        if (static_cast<Query>(out.index) == Query::ContextCompare) {
          // The comparison is a constant word too (sema checked it): its index in extra.
          static const char* const kComparisons[] = {"world.northernmost", "world.southernmost", "world.easternmost",
                                                     "world.westernmost",  "world.highest",      "world.lowest",
                                                     "area.largest",       "area.smallest"};
          const std::string comparison = constString(*e.args[2]);
          for (uint32_t c = 0; c < std::size(kComparisons); ++c)
            if (comparison == kComparisons[c]) out.extra |= c << 2;
        }
        if (e.args.size() > 1) {
          out.args.push_back(expr(*e.args[1]));
        } else {
          out.args.push_back(Expr::string(m_.internString("")));
          out.args.back().loc = out.loc;
        }
        return out;
      }
    } else if (e.object == "Feature") {
      out.index = static_cast<uint32_t>(Query::Feature);
      out.extra = m_.internString(e.text);
    } else if (e.object == "context") {
      out.index = static_cast<uint32_t>(Query::Texture);
      out.env = environmentIndex("texture", e.text);
      return out;  // its argument is always texCoord: the scope's own coordinate
    } else {
      out.index = static_cast<uint32_t>(Query::Field);
      out.extra = m_.internString(e.text);
      out.env = environmentIndex("field", e.object);
    }
    for (const auto& a : e.args) out.args.push_back(expr(*a));
    return out;
  }

  uint32_t environmentIndex(const std::string& kind, const std::string& name) const {
    for (size_t k = 0; k < m_.environment.size(); ++k)
      if (m_.environment[k].kind == kind && m_.environment[k].name == name)
        return static_cast<uint32_t>(k);
    return 0;
  }

  const Program& prog_;
  const SemaResult& sema_;
  Module m_;
  const std::vector<Param>* params_ = nullptr;
};

}  // namespace

Module lowerProgram(const frontend::Program& program, const frontend::SemaResult& sema) {
  return Lowerer(program, sema).run();
}

}  // namespace fgsg::ir
