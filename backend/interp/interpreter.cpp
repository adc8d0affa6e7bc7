#include "backend/interp/interpreter.h"

#include "backend/interp/collision_placement.h"
#include "backend/interp/eval.h"
#include "backend/interp/shape_store.h"
#include "backend/interp/surface_world.h"
#include "backend/jit/query_bridge.h"
#include "backend/synthesis_examples.h"
#include "ir/program_layout.h"
#include "runtime/abi.h"
#include "runtime/cga/cga.h"
#include "runtime/deadline.h"
#include "runtime/float_range.h"
#include "runtime/fresh_stack.h"
#include "runtime/memory_budget.h"
#include "runtime/occlusion.h"
#include "runtime/random.h"
#include "runtime/stack_budget.h"
#include "runtime/synthesis/synthesis.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <exception>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <new>
#include <optional>

namespace fgsg::backend {
namespace {

using Clock = std::chrono::steady_clock;

// Shapes derived where they are written (Lock sets) nest native calls: beyond this depth
// the set is refused rather than the stack overflowing.
constexpr uint32_t kMaxOnTheSpotDepth = 2000;

// Without a surface, patterns grow on the XY plane: RS() turns about its normal.
const rt::Vec3 kPlaneNormal = rt::Vec3::UnitZ();

// Thrown to end a derivation early when a limit is reached; what was derived is kept.
struct LimitReached {
  std::string message;
  ir::Loc loc;
};

// One module of a parallel (L-system) string: a shape symbol or a command, with its
// evaluated arguments in the string's argument pool.
struct Module {
  const ir::Op* op = nullptr;  // the op that produced it (Emit for a symbol)
  uint32_t firstArg = 0;
  uint32_t argCount = 0;
  uint64_t key = 0;
  uint32_t index = 0;           // position among the symbols of its successor (Shape.index)
  uint32_t owner = UINT32_MAX;  // symbol whose rule produced it; UINT32_MAX: the axiom
};

// The scope a successor works on. Its [ ] stack lives in one shared vector above
// `stackBase`, so pushing allocates nothing once the vector has grown.
struct Saved {
  rt::Scope scope;
  rt::GeomRef geom;
  double width;
  rt::LineCursor line;
};
struct State {
  rt::Scope scope;
  rt::GeomRef geom;
  double width = 0.1;
  size_t stackBase = 0;
  rt::LineCursor line;  // the line LineSeg extends (a ']' returns to the '[' point)
};

// What one running successor knows: its random stream, key and parameters, the
// children it has written so far, and whether a collision culled its rest.
struct Exec {
  rt::RandomStream* rng;
  uint64_t key;
  uint32_t depth;   // depth of the shapes this successor creates
  uint32_t symbol;  // the shape being rewritten (UINT32_MAX for the axiom)
  const double* params;
  uint32_t childCount;
  bool culled = false;    // the rest of this production is dropped (FGSG §4.4)
  bool collided = false;  // ... because something in it collided
};

// Room for one op's evaluated arguments: on the stack unless a split has many sizes.
struct ArgBuffer {
  double small[16];
  std::vector<double> big;
  double* reserve(uint32_t n) {
    if (n <= 16) return small;
    big.resize(n);
    return big.data();
  }
};

// A parallel derivation's next string, which a successor's modules are appended to.
struct StringTarget {
  std::vector<Module>* out;
  std::vector<double>* args;
  uint64_t key;     // the rewritten module's key (its children's keys derive from it)
  uint32_t owner;   // the symbol rewritten (UINT32_MAX: the axiom)
  uint32_t child = 0;
};

class Interpreter;

// The context of one compiled block while it runs: the runtime entry points at the
// bottom of this file find the engine and the successor's state through it. What the
// engine throws is caught there and kept here until the block has returned, so no
// exception unwinds through generated frames.
// Thrown when direct derivation gives up; run() ends and deriveCompiled starts again.
struct InexactDirect {};

struct NativeCall : FgsgContext {
  Interpreter* engine = nullptr;
  State* st = nullptr;  // sequential: the successor's scope and stack
  Exec* ex = nullptr;
  Frame* f = nullptr;
  StringTarget* string = nullptr;  // parallel: where modules are appended
  std::exception_ptr thrown;

  template <class Fn>
  void guard(Fn&& fn) noexcept;
};

class Interpreter final : public QueryHost {
 public:
  Interpreter(const ir::Module& m, const rt::DeriveOptions& o, rt::AssetLibrary& assets,
              std::vector<double> attrs, const FgsgProgram* program = nullptr, bool direct = false)
      : m_(m), opt_(o), assets_(assets), eval_(m, std::move(attrs)), paramStride_(maxSlotCount(m)),
        ruleUses_(m.rules.size(), 0), maxSlots_(maxRuleSlots(m)), program_(program), direct_(direct) {
    if (program_) layout_ = ir::layoutProgram(m_);
  }

  static uint32_t maxSlotCount(const ir::Module& m) {
    uint32_t n = 0;
    for (const auto& s : m.symbols) n = std::max(n, s.slotCount);
    return n;
  }
  static uint32_t maxRuleSlots(const ir::Module& m) {
    uint32_t n = maxSlotCount(m);
    for (const auto& r : m.rules) n = std::max(n, r.slotCount);
    return n;
  }

  rt::DeriveResult run() {
    rt::DeriveResult result;
    const auto start = Clock::now();
    deadline_ = rt::Deadline(opt_.startedAt == Clock::time_point{} ? start : opt_.startedAt, opt_.maxSeconds);
    memoryBudget_ = opt_.maxMemoryBytes ? opt_.maxMemoryBytes : rt::defaultMemoryBudget();
    stackFloor_ = rt::stackFloor();
    try {
      checkProgram();
      checkEnvironment();
      // Direct code applies scope commands on the plane (on a surface T traces).
      direct_ = direct_ && program_ && program_->direct && !surface_ && m_.mode != ir::DeriveMode::Parallel;
      resolveAssets();
      initOutput();
      orderedDirect_ = direct_ && canOrderDirectInstances();
      if (m_.mode == ir::DeriveMode::Parallel)
        runParallel();
      else
        runSequential();
      result.ok = true;
      if (depthLimitHit_) result.messages.push_back(depthWarning_);
      orderDirectInstances();
      appendLineTubes(lines_, assets_, out_, symbolColor_);
      appendSurface();
    } catch (const LimitReached& limit) {
      keepAfter(limit, result);
    } catch (const rt::TimeLimitReached&) {  // from a trace, deep in the runtime
      keepAfter(timeLimit(), result);
    } catch (const std::bad_alloc&) {
      outOfMemory(result);
    } catch (const DeriveError& e) {
      result.messages.push_back({true, e.code, e.loc.line, e.loc.col, e.message});
    } catch (const InexactDirect&) {
      inexactDirect_ = true;
    }
    stats_.deriveSeconds = std::chrono::duration<double>(Clock::now() - start).count();
    stats_.instances = out_.instances.size();
    result.stats = stats_;
    result.instances = std::move(out_);
    return result;
  }

 private:
  // A branch of a rule that applies, with its weight.
  struct Candidate {
    const ir::Alternative* alt;
    uint32_t rule;
    double weight;
  };

  // A limit ends the derivation: what was derived is kept, with the R004 warning.
  void keepAfter(const LimitReached& limit, rt::DeriveResult& result) {
    if (depthLimitHit_) result.messages.push_back(depthWarning_);
    result.ok = true;
    result.messages.push_back({false, "R004", limit.loc.line, limit.loc.col, limit.message});
    try {
      orderDirectInstances();
      appendLineTubes(lines_, assets_, out_, symbolColor_);
      appendSurface();
    } catch (const std::bad_alloc&) {
      result.messages.clear();
      outOfMemory(result);
    }
  }

  // Memory ran out before the budget noticed (a single huge allocation, or a budget over
  // what the system gives): nothing is kept, and the error names the rule that ran away.
  void outOfMemory(rt::DeriveResult& result) {
    out_ = rt::InstanceList{};
    buckets_.clear();
    result.ok = false;
    const auto [who, loc] = runaway(ir::Loc{});
    result.messages.push_back({true, "R020", loc.line, loc.col,
                               "out of memory while deriving (" + rt::formatMemorySize(rt::residentMemoryBytes()) +
                                   " in use): " + who +
                                   " ran away; nothing is written (--max-memory stops a derivation "
                                   "earlier and keeps its shapes)"});
  }

  // The surface the pattern grew on is part of the output, in a neutral grey.
  void appendSurface() {
    if (!surface_) return;
    out_.symbols.push_back("surface");
    rt::placeGenerated(assets_, out_, "<surface>", surface_->surfaceMesh(),
                       static_cast<uint32_t>(out_.symbols.size() - 1), {0.72f, 0.72f, 0.7f});
  }

  // ------------------------------------------------------------ set-up

  // Compiled code must come from this very grammar: its tables are numbered by its IR.
  void checkProgram() const {
    if (!program_) return;
    const FgsgProgram& p = *program_;
    if (p.abiVersion != FGSG_ABI_VERSION)
      throw DeriveError{{}, "R900", "compiled code for runtime ABI " + std::to_string(p.abiVersion) +
                                        ", but this runtime is ABI " + std::to_string(FGSG_ABI_VERSION) +
                                        ": compile the grammar again"};
    if ((p.direct && !p.directPlaces) || p.blockCount != layout_.blocks.size() || p.ruleCount != m_.rules.size() ||
        p.alternativeCount != layout_.alternativeCount || p.symbolCount != m_.symbols.size() ||
        p.scopeSize != sizeof(rt::Scope))
      throw DeriveError{{}, "R900", "the compiled code does not match this grammar (" +
                                        std::to_string(p.blockCount) + " blocks and " +
                                        std::to_string(p.ruleCount) + " rules compiled, " +
                                        std::to_string(layout_.blocks.size()) + " and " +
                                        std::to_string(m_.rules.size()) + " in the grammar)"};
  }

  void checkEnvironment() {
    if (m_.mode == ir::DeriveMode::Parallel && (m_.collision.all || opt_.collideAll))
      throw DeriveError{m_.collision.loc, "R009",
                        "collision tests need a sequential derivation: a collision culls the rest "
                        "of one production, and an L-system rewrites every module at once"};
    if (m_.surface.present || !opt_.surfaceOverride.empty()) {
      if (m_.mode == ir::DeriveMode::Parallel)
        throw DeriveError{m_.surface.loc, "R009",
                          "a surface needs a sequential derivation: L-system turtles draw on the "
                          "plane"};
      surface_ = std::make_unique<SurfaceWorld>(m_, opt_, opt_.assetDirs, &deadline_);
    }
    for (const auto& env : m_.environment)
      if (env.kind == "texture")
        throw DeriveError{env.loc, "R001",
                          "texture declarations are not yet supported when running: textures "
                          "arrive with on-mesh marching (this grammar parses and type-checks; "
                          "`fgsg check` accepts it)"};
  }

  // Every asset is loaded before deriving, so a missing file is reported at its I().
  void resolveAssets() {
    std::vector<ir::Loc> firstUse(m_.assets.size());
    std::function<void(const ir::Block&)> visit = [&](const ir::Block& b) {
      for (const auto& op : b) {
        if (op.kind == ir::OpKind::Instance && firstUse[op.index].line == 0) firstUse[op.index] = op.loc;
        for (const auto& body : op.bodies) visit(body);
      }
    };
    visit(m_.axiom);
    for (const auto& r : m_.rules)
      for (const auto& a : r.alternatives) visit(a.ops);
    for (size_t i = 0; i < m_.assets.size(); ++i) {
      std::string error;
      if (assets_.resolve(m_.assets[i], error) < 0) throw DeriveError{firstUse[i], "R003", error};
    }
  }

  void initOutput() {
    out_.assets = m_.assets;
    out_.strings = m_.strings;
    for (const auto& s : m_.symbols) {
      out_.symbols.push_back(s.name);
      std::vector<rt::ParamKind> kinds;
      for (ir::Type t : s.paramTypes)
        kinds.push_back(t == ir::Type::Bool  ? rt::ParamKind::Boolean
                        : t == ir::Type::Str ? rt::ParamKind::String
                        : t == ir::Type::Vec3 ? rt::ParamKind::Vector
                                              : rt::ParamKind::Number);
      out_.paramKinds.push_back(std::move(kinds));
    }
    segmentAsset_ = static_cast<uint32_t>(out_.assets.size());
    out_.assets.push_back("cylinder");
    segmentSymbol_ = static_cast<uint32_t>(out_.symbols.size());
    out_.symbols.push_back("F");
    for (const auto& s : m_.symbols) symbolColor_.push_back(colorFor(s.name));
    symbolColor_.push_back({0.45f, 0.33f, 0.2f});  // turtle segments: bark brown
    axiomSymbol_ = static_cast<uint32_t>(out_.symbols.size());
    out_.symbols.push_back("axiom");
    symbolColor_.push_back(colorFor("axiom"));
    usesOcclusion_ = moduleUsesQuery(ir::Query::ScopeOcc);
    testAll_ = m_.collision.all || opt_.collideAll;
    if (testAll_ || moduleUses([](const ir::Op& op) {
          return op.kind == ir::OpKind::Lock ||
                 (op.kind == ir::OpKind::Instance && op.mode != ir::InstanceMode::Plain);
        }))
      collisions_ = std::make_unique<CollisionPlacement>(assets_, out_, m_.collision);
    if (collisions_ && surface_ && m_.collision.metric == ir::CollisionMetric::Geodesic)
      collisions_->measureAlongSurface([this](const rt::Scope& a, const rt::Scope& b, double limit) {
        return surface_->geodesicDistance(a, b, limit);
      });
    findEagerSymbols();
    noneId_ = stringId("none");
    partId_ = stringId("part");
    fullId_ = stringId("full");
  }

  // Whether any op of the grammar satisfies `pred`.
  template <class Pred>
  bool moduleUses(Pred pred) const {
    std::function<bool(const ir::Block&)> inBlock = [&](const ir::Block& b) {
      for (const auto& op : b) {
        if (pred(op)) return true;
        for (const auto& body : op.bodies)
          if (inBlock(body)) return true;
      }
      return false;
    };
    for (const auto& r : m_.rules)
      for (const auto& alt : r.alternatives)
        if (inBlock(alt.ops)) return true;
    return inBlock(m_.axiom);
  }

  // FGSG §4.4: "we derive simple rules that only place one shape in a depth-first manner
  // to detect collisions". A symbol is simple when each of its successors writes at most
  // one shape that has rules, itself simple (a chain C ~> F, F ~> IC(...)), without
  // recursion, and something in the chain can collide (IC, I under `collision all`, or
  // a line segment). A simple symbol is derived on the spot, where its successor writes
  // it; a collision inside counts as its own and culls the rest of that production.
  void findEagerSymbols() {
    const size_t n = m_.symbols.size();
    enum Mark : uint8_t { Unseen, Visiting, Done };
    std::vector<Mark> mark(n, Unseen);
    std::vector<uint8_t> simple(n, 0), collides(n, 0);
    std::function<void(uint32_t)> visit = [&](uint32_t s) {
      mark[s] = Visiting;
      bool ok = true, hit = false;
      int growing = 0;  // shapes with rules written by the successor being scanned
      std::function<void(const ir::Block&)> scan = [&](const ir::Block& b) {
        for (const auto& op : b) {
          if (op.kind == ir::OpKind::Instance)
            hit |= op.mode == ir::InstanceMode::Collide || (op.mode == ir::InstanceMode::Plain && testAll_);
          if (op.kind == ir::OpKind::LineSeg) hit = true;
          if (op.kind == ir::OpKind::Emit && !m_.symbols[op.index].rules.empty()) {
            if (++growing > 1) ok = false;
            if (mark[op.index] == Unseen) visit(op.index);
            if (mark[op.index] == Visiting || !simple[op.index]) ok = false;  // recursion
            hit |= collides[op.index] != 0;
          }
          for (const auto& body : op.bodies) scan(body);
        }
      };
      for (uint32_t ri : m_.symbols[s].rules)
        for (const auto& alt : m_.rules[ri].alternatives) {
          growing = 0;
          scan(alt.ops);
        }
      simple[s] = ok;
      collides[s] = hit;
      mark[s] = Done;
    };
    eager_.assign(n, 0);
    for (uint32_t s = 0; s < n; ++s) {
      if (m_.symbols[s].rules.empty()) continue;
      if (mark[s] == Unseen) visit(s);
      eager_[s] = simple[s] && collides[s];
    }
  }

  bool moduleUsesQuery(ir::Query q) const {
    std::function<bool(const ir::Expr&)> inExpr = [&](const ir::Expr& e) {
      if (e.op == ir::ExprOp::Query && e.index == static_cast<uint32_t>(q)) return true;
      for (const auto& a : e.args)
        if (inExpr(a)) return true;
      return false;
    };
    std::function<bool(const ir::Block&)> inBlock = [&](const ir::Block& b) {
      for (const auto& op : b) {
        for (const auto& a : op.args)
          if (inExpr(a)) return true;
        for (const auto& sz : op.sizes)
          if (inExpr(sz.value)) return true;
        for (const auto& body : op.bodies)
          if (inBlock(body)) return true;
      }
      return false;
    };
    for (const auto& r : m_.rules) {
      if (r.hasGuard && inExpr(r.guard)) return true;
      for (const auto& alt : r.alternatives)
        if (inExpr(alt.probability) || inBlock(alt.ops)) return true;
    }
    return inBlock(m_.axiom);
  }

  double stringId(const std::string& s) const {
    for (size_t i = 0; i < m_.strings.size(); ++i)
      if (m_.strings[i] == s) return static_cast<double>(i);
    return -1.0 - s.size();  // never equal to a grammar string: nothing compares with it
  }

  static std::array<float, 3> colorFor(const std::string& name) {
    // A stable pastel hue per symbol, so parts of a pattern are told apart in previews.
    const double h = (rt::mix64(std::hash<std::string>{}(name)) % 360) / 60.0;
    const double x = 1 - std::abs(std::fmod(h, 2.0) - 1);
    double r = 0, g = 0, b = 0;
    switch (static_cast<int>(h)) {
      case 0: r = 1, g = x; break;
      case 1: r = x, g = 1; break;
      case 2: g = 1, b = x; break;
      case 3: g = x, b = 1; break;
      case 4: r = x, b = 1; break;
      default: r = 1, b = x; break;
    }
    auto pastel = [](double c) { return static_cast<float>(0.35 + 0.55 * c); };
    return {pastel(r), pastel(g), pastel(b)};
  }

  // ------------------------------------------------------------ queries

  double visible(const rt::Scope& scope, const std::string& target, ir::Loc at) override {
    if (target != "street")
      throw DeriveError{at, "R011",
                        "Shape.visible(\"" + target + "\"): the only target is \"street\""};
    // The street lies in front of the lot: the axiom's +Z side. A face sees it when its
    // outward normal points within 60 degrees of that direction.
    return scope.Z().dot(streetDirection_) > 0.5 ? 1.0 : 0.0;
  }

  double occlusion(const rt::Scope& scope, ir::Loc) override {
    switch (occluders_.test(scope)) {
      case rt::Occlusion::None: return noneId_;
      case rt::Occlusion::Partial: return partId_;
      case rt::Occlusion::Full: return fullId_;
    }
    return noneId_;
  }

  // Fields live on surfaces: the compiler refuses a field without one.
  double fieldNumber(const rt::Scope& scope, uint32_t env, const std::string& member,
                     ir::Loc at) override {
    if (!surface_) throw DeriveError{at, "R016", "field queries need a surface"};
    return surface_->fieldNumber(scope, env, member, at);
  }
  rt::Vec3 fieldVector(const rt::Scope& scope, uint32_t env, const std::string& member,
                       ir::Loc at) override {
    if (!surface_) throw DeriveError{at, "R016", "field queries need a surface"};
    return surface_->fieldVector(scope, env, member, at);
  }

  // ------------------------------------------------------------ ops shared by both modes

  // T: on the plane a vector addition in the scope's frame; on a surface a trace along
  // the first field (FGSG §4.3).
  void translate(rt::Scope& scope, double x, double y, double z) {
    if (surface_)
      surface_->translate(scope, x, y, z);
    else
      rt::translateLocal(scope, x, y, z);
  }

  void turn(rt::Scope& scope, int axis, double degrees) {
    double c, s;
    trig_.cosSin(degrees, c, s);
    rt::rotateLocal(scope, axis, c, s);
  }

  void placeInstance(uint32_t asset, const rt::Scope& scope, uint32_t symbol,
                     const double* params, uint32_t paramCount, ir::Loc loc) {
    rt::Instance inst;
    inst.asset = asset;
    inst.symbol = symbol;
    const rt::Mat4 t = scope.unitBoxToWorld();
    for (int k = 0; k < 16; ++k) {
      inst.transform[k] = t.data()[k];
      if (!std::isfinite(inst.transform[k]))
        throw DeriveError{loc, "R005",
                          "this instance's scope is not finite (a parameter became NaN or "
                          "infinite, e.g. sqrt of a negative number or a division by zero)"};
    }
    if (const double reach = rt::unitBoxReach(t); !(reach <= double(FLT_MAX))) {
      char text[32];
      std::snprintf(text, sizeof text, "%g", reach);
      throw DeriveError{loc, "R005",
                        "this instance of '" + out_.symbols[symbol] + "' reaches coordinate " + text +
                            ", beyond what mesh files store (32-bit floats, up to 3.4e+38): a scale, "
                            "extrusion or translation grew too large"};
    }
    inst.color = symbolColor_[symbol];
    inst.firstParam = static_cast<uint32_t>(out_.params.size());
    inst.paramCount = paramCount;
    out_.params.insert(out_.params.end(), params, params + paramCount);
    out_.instances.push_back(inst);
    if (orderedDirect_) placedBy_.push_back(placingShape_);
    if (usesOcclusion_) occluders_.add(scope);
    if (collisions_) collisions_->placed(scope);
  }

  // I, IC and IM. False when a collision rejected the instance: the caller culls the
  // rest of its production.
  bool placeChecked(const ir::Op& op, const rt::Scope& scope, uint32_t symbol, const double* params,
                    uint32_t paramCount, const double* args) {
    if (!collisions_) {
      placeInstance(op.index, scope, symbol, params, paramCount, op.loc);
      return true;
    }
    const rt::Mat4 t = scope.unitBoxToWorld();
    if (!t.allFinite())  // placeInstance words the error
      placeInstance(op.index, scope, symbol, params, paramCount, op.loc);
    if (op.mode == ir::InstanceMode::Merge) {
      const double maxDist = args[0], maxAngle = args[1];
      if (!(maxDist >= 0) || !(maxAngle >= 0) || !std::isfinite(maxDist) || !std::isfinite(maxAngle))
        throw DeriveError{op.loc, "R014",
                          "IM(\"" + m_.assets[op.index] + "\", maxDist, maxAngle): the thresholds must be "
                          "finite and not negative, got " + std::to_string(maxDist) + " and " +
                          std::to_string(maxAngle)};
      if (collisions_->mergeInto(op.index, t, maxDist, maxAngle)) {
        ++stats_.merges;
        return true;
      }
      placeInstance(op.index, scope, symbol, params, paramCount, op.loc);
      collisions_->placedMergeable(op.index, t);
      return true;
    }
    if (op.mode == ir::InstanceMode::Collide || testAll_) {
      ++stats_.collisionTests;
      if (!collisions_->fits(op.index, t, scope)) {
        ++stats_.collisions;
        return false;
      }
    }
    placeInstance(op.index, scope, symbol, params, paramCount, op.loc);
    return true;
  }

  void turtle(State& st, ir::TurtleOp op, const double* args, uint32_t n, ir::Loc loc) {
    using ir::TurtleOp;
    const double angle = n > 0 ? args[0] : m_.turtle.angle;
    const double step = n > 0 ? args[0] : m_.turtle.step;
    switch (op) {
      case TurtleOp::Forward: {
        // A segment is a cylinder of the turtle's width along the heading (scope Y).
        rt::Scope seg = st.scope;
        seg.P -= 0.5 * st.width * (st.scope.X() + st.scope.Z());
        seg.S = rt::Vec3(st.width, step, st.width);
        placeInstance(segmentAsset_, seg, segmentSymbol_, nullptr, 0, loc);
        st.scope.P += step * st.scope.Y();
        break;
      }
      case TurtleOp::Move: st.scope.P += step * st.scope.Y(); break;
      case TurtleOp::Left: turn(st.scope, 2, angle); break;
      case TurtleOp::Right: turn(st.scope, 2, -angle); break;
      case TurtleOp::PitchDown: turn(st.scope, 0, angle); break;
      case TurtleOp::PitchUp: turn(st.scope, 0, -angle); break;
      case TurtleOp::RollLeft: turn(st.scope, 1, angle); break;
      case TurtleOp::RollRight: turn(st.scope, 1, -angle); break;
      case TurtleOp::TurnAround: turn(st.scope, 2, 180.0); break;
      case TurtleOp::Width:
        if (n > 0) st.width = args[0];
        break;
    }
  }

  // Applies a scope command whose arguments are already evaluated.
  void scopeCommand(State& st, const ir::Op& op, const double* a) {
    switch (op.kind) {
      case ir::OpKind::Translate: translate(st.scope, a[0], a[1], a[2]); break;
      case ir::OpKind::Rotate:
        if (op.index < 3) {
          turn(st.scope, static_cast<int>(op.index), a[0]);
        } else {
          turn(st.scope, 0, a[0]);
          turn(st.scope, 1, a[1]);
          turn(st.scope, 2, a[2]);
        }
        break;
      case ir::OpKind::RotateNormal:
        if (surface_)
          surface_->rotateAboutNormal(st.scope, a[0]);
        else
          rt::rotateAboutNormal(st.scope, kPlaneNormal, a[0]);
        break;
      case ir::OpKind::Scale:
        for (int k = 0; k < 3; ++k)
          st.scope.S[k] = op.sizes[k].kind == ir::Size::Relative ? a[k] * st.scope.S[k] : a[k];
        break;
      case ir::OpKind::Push: stack_.push_back({st.scope, st.geom, st.width, st.line}); break;
      case ir::OpKind::Pop:
        if (stack_.size() <= st.stackBase)
          throw DeriveError{op.loc, "R007", "']' without a matching '[' in this string"};
        st.scope = stack_.back().scope;
        st.geom = stack_.back().geom;
        st.width = stack_.back().width;
        st.line = stack_.back().line;
        stack_.pop_back();
        break;
      default: break;
    }
  }

  // The parameter slots of the shape an Emit op writes (a vector takes three).
  const double* evalSlots(const ir::Op& op, const Frame& f, ArgBuffer& buf) {
    double* slots = buf.reserve(m_.symbols[op.index].slotCount);
    uint32_t slot = 0;
    for (const auto& a : op.args) {
      eval_.store(a, f, slots + slot);
      slot += ir::slotWidth(a.type);
    }
    return slots;
  }

  // Evaluates an op's arguments as compiled code does (runtime/abi.def): op.args, then
  // each size's value, in order. An unsupported op is refused before any of them.
  const double* evalOpArgs(const ir::Op& op, const Frame& f, ArgBuffer& buf, uint32_t& n) {
    n = op.kind == ir::OpKind::Unsupported ? 0 : static_cast<uint32_t>(op.args.size() + op.sizes.size());
    double* out = buf.reserve(n);
    uint32_t k = 0;
    if (op.kind == ir::OpKind::Unsupported) return out;
    for (const auto& a : op.args) out[k++] = eval_.num(a, f);
    for (const auto& sz : op.sizes) out[k++] = eval_.num(sz.value, f);
    return out;
  }

  // ------------------------------------------------------------ sequential derivation

  void runSequential() {
    streetDirection_ = rt::Vec3::UnitZ();
    std::vector<double> none;
    execRoot(0, m_.axiom, surface_ ? surface_->startScope() : rt::Scope{}, rt::GeomRef{},
             rt::rootKey(opt_.seed), 0, 0, none.data(),
             UINT32_MAX);
    WaitingShape shape;
    while (true) {
      auto bucket = buckets_.begin();
      while (bucket != buckets_.end() && bucket->second.empty()) ++bucket;
      if (bucket == buckets_.end()) break;
      // Taken out by copy: the queues grow (and may move) while the shape is derived.
      bucket->second.pop(shape, params_);
      deriveShape(shape);
    }
  }

  void deriveShape(const WaitingShape& shape) {
    const ir::Symbol& sym = m_.symbols[shape.symbol];
    params_.resize(maxSlots_, 0.0);  // room for context parameters of any rule
    const rt::Scope& scope = shape.scope;
    const uint32_t depth = shape.depth;
    rt::RandomStream rng{shape.key, 0};
    Frame f{params_.data(), &rng, &scope, depth, shape.index, this};
    if (depth >= opt_.maxDepth) {
      depthLimit(sym, shape.creator);
      return;
    }
    const ir::Alternative* alt = choose(sym, f);
    if (!alt) {
      ++stats_.terminals;
      drawTurtleSymbol(sym, scope, params_.data());
      return;
    }
    ++stats_.rewrites;
    ++ruleUses_[chosenRule_];
    pollLimits();
    creatorRule_ = chosenRule_;
    execRoot(blockOf(alt), alt->ops, scope, shape.geom, shape.key, depth + 1, shape.index, params_.data(),
             shape.symbol, &rng, shape.line);
    creatorRule_ = UINT32_MAX;
  }

  // The depth limit cuts the derivation tree: deeper shapes stay terminal and the rest
  // of the tree is still derived. Named: the rule that created the shape.
  void depthLimit(const ir::Symbol& sym, uint32_t creator) {
    ++stats_.terminals;
    if (depthLimitHit_) return;
    depthLimitHit_ = true;
    const ir::Rule* r = creator == UINT32_MAX ? nullptr : &m_.rules[creator];
    depthWarning_ = {false, "R004", r ? r->loc.line : 0, r ? r->loc.col : 0,
                     "depth limit " + std::to_string(opt_.maxDepth) + " (--max-depth) reached: " +
                         (r ? "rule '" + r->label + "' keeps creating '" + sym.name + "'"
                            : std::string("the axiom")) +
                         "; shapes at that depth stay terminal"};
  }

  // Derives a shape where its successor writes it, depth-first to the end (an eager
  // symbol, or any shape inside a Lock). True when a collision happened anywhere in
  // its derivation: the shape counts as in collision.
  bool deriveNow(uint32_t symbol, const double* slots, const State& at, const Exec& parent,
                 uint32_t index) {
    const ir::Symbol& sym = m_.symbols[symbol];
    // Simple symbols cannot recurse, but a Lock set can: each level is a native call.
    if (onTheSpot_ >= kMaxOnTheSpotDepth)
      throw DeriveError{m_.rules[creatorRule_ == UINT32_MAX ? sym.rules[0] : creatorRule_].loc, "R017",
                        "a Lock set grew " + std::to_string(kMaxOnTheSpotDepth) +
                            " shapes deep: a set is derived as one unit, so it must end; '" +
                            sym.name + "' keeps creating itself"};
    if (rt::belowStackFloor(stackFloor_)) return deriveNowOnFreshStack(symbol, slots, at, parent, index);
    struct Nesting {
      uint32_t& n;
      explicit Nesting(uint32_t& c) : n(++c) {}
      ~Nesting() { --n; }
    } nesting(onTheSpot_);
    const uint64_t key = rt::childKey(parent.key, index);
    const uint32_t depth = parent.depth;
    std::vector<double> params(std::max(maxSlots_, 1u), 0.0);
    std::copy(slots, slots + sym.slotCount, params.begin());
    rt::RandomStream rng{key, 0};
    Frame f{params.data(), &rng, &at.scope, depth, index, this};
    if (depth >= opt_.maxDepth) {
      depthLimit(sym, creatorRule_);
      return false;
    }
    const ir::Alternative* alt = choose(sym, f);
    if (!alt) {
      ++stats_.terminals;
      drawTurtleSymbol(sym, at.scope, params.data());
      return false;
    }
    ++stats_.rewrites;
    ++ruleUses_[chosenRule_];
    pollLimits();
    const uint32_t outerCreator = creatorRule_;
    creatorRule_ = chosenRule_;
    State st{at.scope, at.geom, m_.turtle.width, stack_.size(), at.line};
    Exec ex{&rng, key, depth + 1, symbol, params.data(), 0};
    f.scope = &st.scope;
    runBlock(blockOf(alt), alt->ops, st, ex, f);
    stack_.resize(st.stackBase);
    creatorRule_ = outerCreator;
    return ex.collided;
  }

  // deriveNow, continued on a stack of its own: Lock sets nest as deep as the grammar
  // makes them (up to kMaxOnTheSpotDepth) whatever the caller's stack.
  bool deriveNowOnFreshStack(uint32_t symbol, const double* slots, const State& at, const Exec& parent,
                             uint32_t index) {
    struct RestoreFloor {
      uintptr_t& floor;
      uintptr_t saved;
      ~RestoreFloor() { floor = saved; }
    } restore{stackFloor_, stackFloor_};
    bool collided = false;
    rt::runOnFreshStack([&] {
      stackFloor_ = rt::stackFloor();
      collided = deriveNow(symbol, slots, at, parent, index);
    });
    return collided;
  }

  // F is a shape symbol when rules rewrite it; where none applies it still draws like the
  // turtle command, as after a parallel derivation. Length: its first parameter, else
  // the turtle step.
  void drawTurtleSymbol(const ir::Symbol& sym, const rt::Scope& scope, const double* params) {
    if (sym.name != "F") return;
    State st;
    st.scope = scope;
    st.width = m_.turtle.width;
    turtle(st, ir::TurtleOp::Forward, params, sym.slotCount > 0 ? 1 : 0, {});
  }

  // A rule with a guard or a context is specific; one without is general. Specific rules
  // that apply are preferred (ABOP's precedence of context-sensitive productions; CGA's
  // guarded rule before its fallback); general rules are candidates only otherwise.
  static bool isSpecific(const ir::Rule& r) {
    return r.hasGuard || !r.left.empty() || !r.right.empty();
  }

  // Picks one alternative among the rules whose guard holds, weights normalised.
  const ir::Alternative* choose(const ir::Symbol& sym, const Frame& f) {
    // The common case: one unguarded rule with one branch of constant positive weight.
    if (sym.rules.size() == 1) {
      const ir::Rule& only = m_.rules[sym.rules[0]];
      if (!isSpecific(only) && only.alternatives.size() == 1 &&
          only.alternatives[0].probability.isConst() && only.alternatives[0].probability.num > 0) {
        chosenRule_ = sym.rules[0];
        return &only.alternatives[0];
      }
    }
    candidates_.clear();
    double total = 0;
    for (int pass = 0; pass < 2 && candidates_.empty(); ++pass)
    for (uint32_t ri : sym.rules) {
      const ir::Rule& r = m_.rules[ri];
      if (isSpecific(r) != (pass == 0)) continue;
      // Context needs a string of neighbours: only a parallel derivation has one.
      if (!r.left.empty() || !r.right.empty()) continue;
      if (r.hasGuard && !guardHolds(ri, f)) continue;
      addCandidates(r, ri, f, total);
    }
    if (candidates_.empty()) return nullptr;
    const Candidate& pick = pickCandidate(*f.rng, total);
    chosenRule_ = pick.rule;
    return pick.alt;
  }

  bool guardHolds(uint32_t rule, const Frame& f) {
    const FgsgValueFn compiled = program_ ? program_->guards[rule] : nullptr;
    return compiled ? callValue(compiled, f) != 0.0 : eval_.truth(m_.rules[rule].guard, f);
  }

  // ------------------------------------------------------------ compiled code

  // The block id of an alternative of the rule just chosen.
  uint32_t blockOf(const ir::Alternative* alt) const {
    if (!program_) return 0;
    const ir::Rule& r = m_.rules[chosenRule_];
    return layout_.alternativeBlock(chosenRule_, static_cast<uint32_t>(alt - r.alternatives.data()));
  }

  // A compiled guard or probability; its query or error turns into the interpreter's.
  double callValue(FgsgValueFn fn, const Frame& f) {
    NativeCall call;
    call.engine = this;
    jit::QueryBridge bridge(m_, f);
    bridge.attach(call);
    const double v = fn(f.params, eval_.attrData(), &call);
    if (call.errorCode != FGSG_OK) throw bridge.error(call);
    return v;
  }

  // Whether direct symbols that place instances may be used: when nothing but the
  // instances' order could tell (no collisions, merges, lines or occlusion queries),
  // and every shape the axiom leads to is direct or has no rules, all of one priority,
  // so that the interpreter's order is that of (depth, preorder) of the placing shapes
  // (breadth-first) or of their preorder (depth-first): orderDirectInstances restores it.
  bool canOrderDirectInstances() const {
    if (!program_->directPlaces || collisions_ || usesOcclusion_ || testAll_) return false;
    // Synthesize creates shapes of the symbols its example names, not written as Emit.
    if (moduleUses([](const ir::Op& op) { return op.kind == ir::OpKind::Synthesize; })) return false;
    std::vector<uint8_t> seen(m_.symbols.size(), 0);
    std::vector<uint32_t> todo;
    std::function<void(const ir::Block&)> scan = [&](const ir::Block& b) {
      for (const auto& op : b) {
        if (op.kind == ir::OpKind::Emit && !seen[op.index]) {
          seen[op.index] = 1;
          todo.push_back(op.index);
        }
        for (const auto& body : op.bodies) scan(body);
      }
    };
    scan(m_.axiom);
    bool first = true;
    int priority = 0;
    while (!todo.empty()) {
      const uint32_t s = todo.back();
      todo.pop_back();
      const ir::Symbol& sym = m_.symbols[s];
      if (sym.rules.empty()) continue;
      if (!program_->direct[s] || (!first && sym.priority != priority)) return false;
      priority = sym.priority;
      first = false;
      for (uint32_t ri : sym.rules)
        for (const auto& alt : m_.rules[ri].alternatives) scan(alt.ops);
    }
    return true;
  }

  // Puts the instances placed while direct shapes were derived into the interpreter's
  // order: by the placing shape's depth, then preorder (breadth-first), or by preorder
  // alone (depth-first); a stable sort keeps each successor's own order.
  void orderDirectInstances() {
    if (!orderedDirect_ || placedBy_.size() != out_.instances.size()) return;
    const bool breadthFirst = m_.mode == ir::DeriveMode::BreadthFirst;
    auto before = [breadthFirst](const PlacingShape& x, const PlacingShape& y) {
      if (breadthFirst && x.depth != y.depth) return x.depth < y.depth;
      return x.preorder < y.preorder;
    };
    // Often already so (depth-first, or every instance placed at one depth).
    if (std::is_sorted(placedBy_.begin(), placedBy_.end(), before)) {
      placedBy_.clear();
      return;
    }
    std::vector<uint32_t> order(out_.instances.size());
    for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return before(placedBy_[a], placedBy_[b]); });
    std::vector<rt::Instance> instances;
    std::vector<double> params;
    instances.reserve(order.size());
    params.reserve(out_.params.size());
    for (uint32_t i : order) {
      rt::Instance inst = out_.instances[i];
      const uint32_t first = inst.firstParam;
      inst.firstParam = static_cast<uint32_t>(params.size());
      params.insert(params.end(), out_.params.begin() + first, out_.params.begin() + first + inst.paramCount);
      instances.push_back(inst);
    }
    out_.instances = std::move(instances);
    out_.params = std::move(params);
    placedBy_.clear();
  }

  // Derives a direct shape and its whole subtree now, in compiled code (FgsgDirectFn):
  // nothing it creates is observable but its counts. What only this engine's own order
  // reports exactly (a limit, an error) makes the whole derivation start again without
  // direct derivation (deriveCompiled).
  void deriveDirect(uint32_t symbol, const double* slots, const rt::Scope& scope, uint64_t key,
                    uint32_t depth) {
    NativeCall call;
    call.engine = this;
    call.shapeBudget = opt_.maxShapes - std::min(opt_.maxShapes, stats_.shapesCreated);
    call.depthLimit = opt_.maxDepth;
    call.visits = visits_;
    call.stackFloor = stackFloor_;
    program_->direct[symbol](&call, &scope, slots, key, depth, eval_.attrData());
    visits_ = call.visits;
    stats_.shapesCreated += call.shapes;
    stats_.rewrites += call.rewrites;
    stats_.terminals += call.terminals;
    placingShape_ = {};
    if (call.thrown) {
      // --max-seconds ends any engine where it is; every other problem is reported in
      // the interpreter's order.
      try {
        std::rethrow_exception(call.thrown);
      } catch (const LimitReached&) {
        throw;
      } catch (const std::bad_alloc&) {
        throw;
      } catch (...) {
        throw InexactDirect{};
      }
    }
    if (call.inexact || call.errorCode != FGSG_OK) throw InexactDirect{};
  }

  // Runs a compiled successor on st; what its ops threw is rethrown once it returned.
  void runNative(uint32_t block, State& st, Exec& ex, Frame& f) {
    f.scope = &st.scope;
    NativeCall call;
    call.engine = this;
    call.st = &st;
    call.ex = &ex;
    call.f = &f;
    jit::QueryBridge bridge(m_, f);
    bridge.attach(call);
    program_->blocks[block](&call, f.params, eval_.attrData());
    f.scope = &st.scope;
    if (call.thrown) std::rethrow_exception(call.thrown);
    if (call.errorCode != FGSG_OK) throw bridge.error(call);
  }

 public:
  // The runtime entry points of compiled code (runtime/abi.def), for a sequential
  // derivation (call.st set) or a parallel rewriting step (call.string set).
  void nativeEmit(NativeCall& call, uint32_t op, const double* slots) {
    if (call.string)
      appendModule(*layout_.ops[op], slots, m_.symbols[layout_.ops[op]->index].slotCount, *call.string);
    else
      emit(*layout_.ops[op], slots, *call.st, *call.ex);
  }
  void nativeOp(NativeCall& call, uint32_t op, const double* args, uint32_t n) {
    if (op >= layout_.ops.size()) throw DeriveError{{}, "R900", "internal: compiled code names op " + std::to_string(op)};
    if (call.string)
      appendModule(*layout_.ops[op], args, n, *call.string);
    else
      applyOp(*layout_.ops[op], args, n, *call.st, *call.ex, *call.f);
  }
  void nativeTranslate(NativeCall& call, double x, double y, double z) { translate(call.st->scope, x, y, z); }
  void nativeRotate(NativeCall& call, uint32_t axis, double degrees) {
    turn(call.st->scope, static_cast<int>(axis), degrees);
  }
  void nativePush(NativeCall& call) {
    const State& st = *call.st;
    stack_.push_back({st.scope, st.geom, st.width, st.line});
  }
  void nativePop(NativeCall& call, uint32_t op) { scopeCommand(*call.st, *layout_.ops[op], nullptr); }
  // Direct derivation turns as turn() does, with the cosine and sine of this memo.
  void directCosSin(double degrees, double* out) { trig_.cosSin(degrees, out[0], out[1]); }
  void directTimeCheck() { checkTime(); }
  void directInstance(rt::Scope& s, uint32_t op, uint32_t symbol, const double* params, uint32_t depth,
                      uint64_t preorder) {
    placingShape_ = {depth, preorder};
    placeInstance(layout_.ops[op]->index, s, symbol, params, m_.symbols[symbol].slotCount, layout_.ops[op]->loc);
  }
  // Whether the last run() stopped because direct derivation could not be exact.
  bool needsExactRun() const { return inexactDirect_; }

 private:
  // Adds the branches of a rule that applies, with their weights, to the candidates.
  void addCandidates(const ir::Rule& r, uint32_t ri, const Frame& f, double& total) {
    for (const auto& alt : r.alternatives) {
      const FgsgValueFn compiled =
          program_ ? program_->weights[layout_.firstAlternative[ri] + (&alt - r.alternatives.data())] : nullptr;
      const double w = compiled ? callValue(compiled, f) : eval_.num(alt.probability, f);
      if (!(w >= 0) || !std::isfinite(w))
        throw DeriveError{alt.probability.loc, "R008",
                          "a probability evaluated to " + std::to_string(w) +
                              "; probabilities must be finite and not negative"};
      if (w > 0) {
        candidates_.push_back({&alt, ri, w});
        total += w;
      }
    }
  }

  // One candidate, chosen with probability proportional to its weight; a single
  // candidate takes no random number, so adding an impossible branch changes nothing.
  const Candidate& pickCandidate(rt::RandomStream& rng, double total) const {
    if (candidates_.size() == 1) return candidates_.front();
    double x = rng.next() * total;
    for (const auto& c : candidates_) {
      if (x < c.weight) return c;
      x -= c.weight;
    }
    return candidates_.back();
  }

  // Runs one successor for a shape (or the axiom) and queues the shapes it creates.
  void execRoot(uint32_t block, const ir::Block& ops, const rt::Scope& scope, const rt::GeomRef& geom,
                uint64_t key, uint32_t depth, uint32_t index, const double* params,
                uint32_t symbol, rt::RandomStream* rng = nullptr, rt::LineCursor line = {}) {
    rt::RandomStream own{key, 0};
    State st{scope, geom, m_.turtle.width, stack_.size(), line};
    Exec ex{rng ? rng : &own, key, depth, symbol, params, 0};
    const bool depthFirst = m_.mode == ir::DeriveMode::DepthFirst;
    if (depthFirst) {
      marks_.clear();
      for (const auto& [priority, queue] : buckets_) marks_.emplace_back(priority, queue.mark());
    }
    Frame f{params, ex.rng, &st.scope, depth == 0 ? 0 : depth - 1, index, this};
    runBlock(block, ops, st, ex, f);
    stack_.resize(st.stackBase);  // a successor may leave '[' open: close it
    if (depthFirst) {
      // A stack gives back the last shape first: reverse what this successor created so
      // its first shape is derived first.
      for (auto& [priority, queue] : buckets_) {
        size_t mark = 0;
        for (const auto& [p, m] : marks_)
          if (p == priority) mark = m;
        queue.reverseSince(mark);
      }
    }
  }

  // Shapes wait in one queue per priority, highest priority first; most grammars have one.
  ShapeQueue& bucketFor(int priority) {
    for (auto& [p, q] : buckets_)
      if (p == priority) return q;
    buckets_.emplace_back(priority, ShapeQueue(paramStride_, m_.mode == ir::DeriveMode::DepthFirst));
    std::sort(buckets_.begin(), buckets_.end(),
              [](const auto& a, const auto& b) { return a.first > b.first; });
    return bucketFor(priority);
  }

  // Runs a block: its compiled code when the derivation has a program, else its IR.
  void runBlock(uint32_t block, const ir::Block& ops, State& st, Exec& ex, Frame& f) {
    if (program_)
      runNative(block, st, ex, f);
    else
      execBlock(ops, st, ex, f);
  }

  void execBlock(const ir::Block& ops, State& st, Exec& ex, Frame& f) {
    ArgBuffer buf;
    for (const ir::Op& op : ops) {
      f.scope = &st.scope;
      switch (op.kind) {
        // The commands of nearly every successor are applied here directly, without
        // going through the argument buffer (the hot path of every derivation).
        case ir::OpKind::Translate: {
          const double x = eval_.num(op.args[0], f), y = eval_.num(op.args[1], f),
                       z = eval_.num(op.args[2], f);
          translate(st.scope, x, y, z);
          break;
        }
        case ir::OpKind::Rotate:
          if (op.index < 3) {
            turn(st.scope, static_cast<int>(op.index), eval_.num(op.args[0], f));
            break;
          }
          applyEvaluated(op, st, ex, f, buf);
          break;
        case ir::OpKind::Push: stack_.push_back({st.scope, st.geom, st.width, st.line}); break;
        case ir::OpKind::Emit: emit(op, evalSlots(op, f, buf), st, ex); break;
        default: applyEvaluated(op, st, ex, f, buf); break;
      }
      if (ex.culled) return;
    }
  }

  void applyEvaluated(const ir::Op& op, State& st, Exec& ex, Frame& f, ArgBuffer& buf) {
    uint32_t n = 0;
    const double* a = evalOpArgs(op, f, buf, n);
    applyOp(op, a, n, st, ex, f);
  }

  // Applies one op of a successor with its arguments evaluated (evalOpArgs' layout):
  // shared by the IR walk above and compiled code (fgsg_rt_op).
  void applyOp(const ir::Op& op, const double* a, uint32_t n, State& st, Exec& ex, Frame& f) {
    switch (op.kind) {
      case ir::OpKind::Translate: translate(st.scope, a[0], a[1], a[2]); break;
      case ir::OpKind::Rotate:
      case ir::OpKind::RotateNormal:
      case ir::OpKind::Scale:
      case ir::OpKind::Push:
      case ir::OpKind::Pop: scopeCommand(st, op, a); break;
      case ir::OpKind::Turtle: turtle(st, static_cast<ir::TurtleOp>(op.index), a, n, op.loc); break;
      case ir::OpKind::Instance: {
        const uint32_t sym = ex.symbol == UINT32_MAX ? axiomSymbol_ : ex.symbol;
        const uint32_t count = ex.symbol == UINT32_MAX ? 0 : m_.symbols[sym].slotCount;
        if (!placeChecked(op, st.scope, sym, ex.params, count, a)) ex.culled = ex.collided = true;
        break;
      }
      case ir::OpKind::Emit: emit(op, a, st, ex); break;
      case ir::OpKind::Subdiv:
      case ir::OpKind::Repeat:
      case ir::OpKind::Comp: split(op, a, st, ex, f); break;
      case ir::OpKind::Extrude: {
        rt::cga::Part part;
        std::string error;
        if (!rt::cga::extrude(st.scope, st.geom, a[0], arena_, part, error))
          throw DeriveError{op.loc, "R002", error};
        st.scope = part.scope;
        st.geom = part.geom;
        break;
      }
      case ir::OpKind::Roof: {
        rt::cga::Part part;
        std::string error;
        if (!rt::cga::roof(st.scope, st.geom, m_.strings[op.str], a[0], arena_, part, error))
          throw DeriveError{op.loc, "R002", error};
        runBody(op, 0, part.scope, part.geom, st, ex, f);
        break;
      }
      case ir::OpKind::Lock: lockedSet(op, st, ex, f); break;
      case ir::OpKind::Line: startLine(op, a, st, ex); break;
      case ir::OpKind::LineSeg: extendLine(op, n > 0 ? a : nullptr, st, ex); break;
      case ir::OpKind::Synthesize: synthesizeInto(op, a, st, ex, f); break;
      case ir::OpKind::Unsupported: unsupported(op);
    }
  }

  // Lock{ A | B | ... }: the parts and everything derived from them are placed as one
  // unit, depth-first; a collision anywhere in the set removes all of it and culls the
  // rest of the production.
  void lockedSet(const ir::Op& op, State& st, Exec& ex, Frame& f) {
    const CollisionPlacement::Transaction undo = collisions_->begin(lines_);
    const size_t occluders = occluders_.size();
    ++lockDepth_;
    for (size_t k = 0; k < op.bodies.size(); ++k) {
      runBody(op, k, st.scope, st.geom, st, ex, f);
      if (ex.culled) break;
    }
    --lockDepth_;
    if (ex.collided) {
      collisions_->rollback(undo, lines_);
      occluders_.truncate(occluders);
      ++stats_.locksRemoved;
    }
  }

  // Line(width, merge): a new line starts at the scope's origin.
  void startLine(const ir::Op& op, const double* a, State& st, Exec& ex) {
    const double width = a[0];
    const bool merge = a[1] != 0.0;
    if (!(width > 0) || !std::isfinite(width))
      throw DeriveError{op.loc, "R014",
                        "Line(width, merge): the width must be a positive number, got " +
                            std::to_string(width)};
    if (!st.scope.P.allFinite())
      throw DeriveError{op.loc, "R005", "this line's start point is not finite"};
    st.line = lines_.start(st.scope.P, {width, merge},
                           ex.symbol == UINT32_MAX ? axiomSymbol_ : ex.symbol);
  }

  // LineSeg(length?): moves `length` along the scope's X first, then extends the line to
  // the scope's origin. Reaching another line ends this one there: the rest of the
  // production (which would continue it) is culled.
  void extendLine(const ir::Op& op, const double* length, State& st, Exec& ex) {
    if (length) st.scope.P += *length * st.scope.X();
    if (!st.line.valid())
      throw DeriveError{op.loc, "R014",
                        "LineSeg outside a line: start one with Line(width) in this successor or in "
                        "one that created this shape"};
    if (!st.scope.P.allFinite())
      throw DeriveError{op.loc, "R005",
                        "this line segment's end is not finite (a parameter became NaN or infinite)"};
    rt::Vec3 end;
    const size_t before = lines_.segmentCount();  // a zero-length step adds nothing
    const rt::SegmentOutcome outcome = lines_.extend(st.line, st.scope.P, &end);
    stats_.lineSegments += lines_.segmentCount() - before;
    switch (outcome) {
      case rt::SegmentOutcome::Added: break;
      case rt::SegmentOutcome::Joined:
        ++stats_.linesJoined;
        st.scope.P = end;
        ex.culled = true;
        break;
      case rt::SegmentOutcome::Stopped:
        ++stats_.linesJoined;
        ex.culled = ex.collided = true;
        break;
      case rt::SegmentOutcome::Ended: ex.culled = true; break;
    }
  }

  // Synthesize("example", nx, ny, nz): Merrell's model synthesis fills the scope with an
  // nx x ny x nz grid of pieces (grid z along the scope's Y, grid y against its Z). A
  // piece whose label names a symbol with rules becomes a shape of that symbol in its
  // cell, to be derived further; any other piece places its asset.
  void synthesizeInto(const ir::Op& op, const double* a, State& st, Exec& ex, Frame& f) {
    const std::string& name = m_.strings[op.str];
    const rt::synthesis::Example& example = loadExample(name, op.loc);
    rt::synthesis::SynthesisOptions so;
    int n[3];
    for (int k = 0; k < 3; ++k) {
      const double v = a[k];
      if (!(v >= 1) || v > 4096 || v != std::floor(v))
        throw DeriveError{op.loc, "R012", "Synthesize: grid sizes must be whole numbers from 1 to 4096"};
      n[k] = static_cast<int>(v);
    }
    so.size = {n[0], n[1], n[2]};
    so.seed = rt::childKey(ex.key, 0x8000000000000000ull | (uint64_t(op.loc.line) << 20) | op.loc.col);
    so.attempts = 10;  // whole-grid synthesis restarts after a contradiction
    so.timeLimitSeconds = std::max(1.0, opt_.maxSeconds);
    so.deadline = &deadline_;  // and with the derivation's own clock
    const rt::synthesis::SynthesisResult result = rt::synthesis::synthesize(example, so);
    if (!result.ok && deadline_.expiredNow()) throw timeLimit();
    if (!result.ok)
      throw DeriveError{op.loc, "R013", "Synthesize(\"" + name + "\"): " + result.failure.message};
    rt::synthesis::PlacementFrame frame;
    frame.cellSize = {st.scope.S.x() / n[0], st.scope.S.z() / n[1], st.scope.S.y() / n[2]};
    // The frame's grid y runs towards -Z: shift it back into the scope box.
    rt::Mat4 toScope = rt::Mat4::Identity();
    toScope.block<3, 3>(0, 0) = st.scope.axes;
    toScope.block<3, 1>(0, 3) = st.scope.P + st.scope.axes * rt::Vec3(0, 0, st.scope.S.z());
    for (const auto& place : rt::synthesis::piecePlacements(result.labels, example, frame)) {
      const rt::Mat4 local = Eigen::Map<const rt::Mat4>(place.transform.data());
      const rt::Mat4 world = toScope * local;
      const int sym = m_.findSymbol(example.labels[place.label].name);
      rt::Scope cell;
      cell.P = world.block<3, 1>(0, 3);
      for (int k = 0; k < 3; ++k) {
        cell.S[k] = world.block<3, 1>(0, k).norm();
        cell.axes.col(k) = cell.S[k] > 0 ? rt::Vec3(world.block<3, 1>(0, k) / cell.S[k]) : st.scope.axes.col(k);
      }
      if (sym >= 0 && !m_.symbols[sym].rules.empty() && m_.symbols[sym].slotCount == 0) {
        State piece;
        piece.scope = cell;
        piece.stackBase = stack_.size();
        ir::Op emitOp;
        emitOp.kind = ir::OpKind::Emit;
        emitOp.index = static_cast<uint32_t>(sym);
        emitOp.loc = op.loc;
        const double noSlots = 0;
        emit(emitOp, &noSlots, piece, ex);
      } else if (!place.asset.empty()) {
        placeInstance(pieceAsset(place.asset, op.loc), cell, ex.symbol == UINT32_MAX ? axiomSymbol_ : ex.symbol,
                      nullptr, 0, op.loc);
        out_.instances.back().color = place.color;
      }
    }
  }

  const rt::synthesis::Example& loadExample(const std::string& name, ir::Loc at) {
    auto it = examples_.find(name);
    if (it != examples_.end()) return it->second;
    rt::synthesis::Example example;
    std::string message;
    if (!loadSynthesisExample(name, opt_.assetDirs, example, message)) throw DeriveError{at, "R013", message};
    return examples_.emplace(name, std::move(example)).first->second;
  }

  uint32_t pieceAsset(const std::string& asset, ir::Loc at) {
    for (uint32_t i = 0; i < out_.assets.size(); ++i)
      if (out_.assets[i] == asset) return i;
    std::string error;
    if (assets_.resolve(asset, error) < 0) throw DeriveError{at, "R003", error};
    out_.assets.push_back(asset);
    return static_cast<uint32_t>(out_.assets.size() - 1);
  }

  [[noreturn]] void sequentialOnly(const ir::Op& op) {
    throw DeriveError{op.loc, "R009",
                      "'" + op.name + "' cannot appear in a parallel (L-system) derivation: a "
                      "collision or a line ending culls the rest of one production, which needs a "
                      "sequential derivation"};
  }

  [[noreturn]] void unsupported(const ir::Op& op) {
    throw DeriveError{op.loc, "R001",
                      "'" + op.name + "' is not yet supported when running: it arrives with " +
                          op.why + " (this grammar parses and type-checks)"};
  }

  // Writes a shape of op's symbol with its parameter slots evaluated.
  void emit(const ir::Op& op, const double* slots, State& st, Exec& ex) {
    const ir::Symbol& target = m_.symbols[op.index];
    if (stats_.shapesCreated >= opt_.maxShapes) shapeLimit(op);
    const uint32_t index = ex.childCount++;
    ++stats_.shapesCreated;
    if (target.rules.empty()) {  // a terminal: nothing will ever read it again
      ++stats_.terminals;
      return;
    }
    if (direct_ && program_->direct[op.index] && (orderedDirect_ || !program_->directPlaces[op.index])) {
      deriveDirect(op.index, slots, st.scope, rt::childKey(ex.key, index), ex.depth);
      return;
    }
    if (eager_[op.index] || lockDepth_ > 0) {
      if (deriveNow(op.index, slots, st, ex, index)) ex.culled = ex.collided = true;
      return;
    }
    WaitingShape& shape = bucketFor(target.priority).push(slots, target.slotCount);
    shape.key = rt::childKey(ex.key, index);
    shape.symbol = op.index;
    shape.depth = ex.depth;
    shape.index = index;
    shape.creator = creatorRule_;
    shape.line = st.line;
    shape.geom = st.geom;
    shape.scope = st.scope;
  }

  // The most applied rule, named for a limit message, and where it is (`axiomAt` when
  // no rule was applied).
  std::pair<std::string, ir::Loc> runaway(ir::Loc axiomAt) const {
    uint32_t worst = 0;
    uint64_t uses = 0;
    for (uint32_t rule = 0; rule < ruleUses_.size(); ++rule)
      if (ruleUses_[rule] > uses) worst = rule, uses = ruleUses_[rule];
    if (uses == 0) return {"the axiom", axiomAt};
    return {"rule '" + m_.rules[worst].label + "' (applied " + std::to_string(uses) + " times)",
            m_.rules[worst].loc};
  }

  [[noreturn]] void shapeLimit(const ir::Op& op) {
    const auto [who, loc] = runaway(op.loc);
    throw LimitReached{"derivation stopped at " + std::to_string(opt_.maxShapes) +
                           " shapes (--max-shapes): " + who +
                           " ran away; the shapes derived so far are kept",
                       loc};
  }

  LimitReached timeLimit() const {
    return {"derivation stopped after " + std::to_string(opt_.maxSeconds) +
                " s (--max-seconds); the shapes derived so far are kept",
            {}};
  }

  // --max-seconds and --max-memory, asked at every unit of work (a rewrite, a module):
  // the deadline reads the clock about every 0.1 ms, the memory is read every 10 ms.
  std::optional<LimitReached> limitsReached() {
    if (deadline_.expired()) return timeLimit();
    if (deadline_.lastRead() - memoryCheckedAt_ >= std::chrono::milliseconds(10)) return memoryLimit();
    return std::nullopt;
  }
  void pollLimits() {
    if (auto limit = limitsReached()) throw *limit;
  }
  // The same, reading the clock now: for callers that are already rare (every 4096
  // directly derived shapes, a parallel step).
  void checkTime() {
    if (deadline_.expiredNow()) throw timeLimit();
    if (deadline_.lastRead() - memoryCheckedAt_ >= std::chrono::milliseconds(10))
      if (auto limit = memoryLimit()) throw *limit;
  }

  // What the derivation holds: resident memory, plus the mesh and file the instances
  // placed so far will become (counted once per instance, as they come).
  std::optional<LimitReached> memoryLimit() {
    memoryCheckedAt_ = deadline_.lastRead();
    for (; instancesCounted_ < out_.instances.size(); ++instancesCounted_)
      instanceBytes_ += assetOutputBytes(out_.instances[instancesCounted_].asset);
    const uint64_t held = rt::residentMemoryBytes() + instanceBytes_;
    if (held <= memoryBudget_) return std::nullopt;
    const auto [who, loc] = runaway(ir::Loc{});
    return LimitReached{"derivation stopped at " + rt::formatMemorySize(held) + " of memory (--max-memory " +
                            rt::formatMemorySize(memoryBudget_) + ", with the instances' mesh to come): " + who +
                            " ran away; the shapes derived so far are kept",
                        loc};
  }
  uint64_t assetOutputBytes(uint32_t asset) {
    while (assetBytes_.size() <= asset && assetBytes_.size() < out_.assets.size()) {
      std::string error;
      const int index = assets_.resolve(out_.assets[assetBytes_.size()], error);
      const rt::Mesh* mesh = index >= 0 ? &assets_.mesh(index) : nullptr;
      assetBytes_.push_back(mesh ? rt::outputBytes(mesh->vertexCount(), mesh->triangleCount()) : 0);
    }
    return asset < assetBytes_.size() ? assetBytes_[asset] : 0;
  }

  // Runs body k of op (a split part, a roof, a Lock alternative) on its own scope.
  void runBody(const ir::Op& op, size_t k, const rt::Scope& scope, const rt::GeomRef& geom,
               const State& outer, Exec& ex, Frame& f) {
    State inner{scope, geom, outer.width, stack_.size(), outer.line};
    runBlock(program_ ? layout_.bodyBlock(op, k) : 0, op.bodies[k], inner, ex, f);
    stack_.resize(inner.stackBase);
    f.scope = &outer.scope;
  }

  void split(const ir::Op& op, const double* a, State& st, Exec& ex, Frame& f) {
    std::vector<rt::cga::Part> parts;
    std::string error;
    bool ok = false;
    if (op.kind == ir::OpKind::Subdiv) {
      std::vector<rt::cga::SizeValue> sizes;
      for (size_t k = 0; k < op.sizes.size(); ++k)
        sizes.push_back({static_cast<rt::cga::SizeValue::Kind>(op.sizes[k].kind), a[k]});
      ok = rt::cga::subdivide(st.scope, st.geom, static_cast<int>(op.index), sizes, arena_, parts, error);
    } else if (op.kind == ir::OpKind::Repeat) {
      std::vector<double> sizes(a, a + op.sizes.size());
      ok = rt::cga::repeat(st.scope, st.geom, op.index, sizes, arena_, parts, error);
    } else {
      ok = rt::cga::components(st.scope, st.geom, m_.strings[op.str], arena_, parts, error);
    }
    if (!ok) throw DeriveError{op.loc, "R002", error};
    for (size_t i = 0; i < parts.size(); ++i) {
      if (parts[i].empty) continue;
      runBody(op, op.kind == ir::OpKind::Subdiv ? i : 0, parts[i].scope, parts[i].geom, st, ex, f);
      if (ex.culled) return;
    }
  }

  // ------------------------------------------------------------ parallel derivation

  void runParallel() {
    std::vector<Module> str, next;
    std::vector<double> args, nextArgs;
    std::vector<double> none;
    Frame f{none.data(), nullptr, nullptr, 0, 0, this};
    rt::RandomStream rng{rt::rootKey(opt_.seed), 0};
    f.rng = &rng;
    appendModules(0, m_.axiom, f, rt::rootKey(opt_.seed), str, args);
    bool limitHit = false;
    std::optional<LimitReached> stopped;  // --max-seconds or --max-memory, mid-step
    for (int step = 0; step < m_.steps && !limitHit; ++step) {
      next.clear();
      nextArgs.clear();
      for (size_t i = 0; i < str.size(); ++i) {
        const Module& mod = str[i];
        if (limitHit || mod.op->kind != ir::OpKind::Emit || m_.symbols[mod.op->index].rules.empty()) {
          copyModule(mod, args, next, nextArgs);
          continue;
        }
        const ir::Symbol& sym = m_.symbols[mod.op->index];
        rt::RandomStream modRng{mod.key, 0};
        const ir::Alternative* alt = chooseInString(sym, str, args, i, modRng, static_cast<uint32_t>(step));
        if (!alt) {
          copyModule(mod, args, next, nextArgs);
          continue;
        }
        ++stats_.rewrites;
        ++ruleUses_[chosenRule_];
        Frame rf{params_.data(), &modRng, nullptr, static_cast<uint32_t>(step), mod.index, this};
        appendModules(blockOf(alt), alt->ops, rf, mod.key, next, nextArgs, mod.op->index);
        // At the limit the rest of this step's string is kept unrewritten, so the
        // turtle still draws the whole (partly older) plant.
        if (next.size() >= opt_.maxShapes) limitHit = true;
        if (!limitHit && (stopped = limitsReached())) limitHit = true;
      }
      str.swap(next);
      args.swap(nextArgs);
      if (!limitHit && deadline_.expiredNow()) stopped = timeLimit(), limitHit = true;
    }
    interpretString(str, args);
    if (stopped) throw *stopped;
    if (limitHit) shapeLimit(ir::Op{});
  }

  static void copyModule(const Module& mod, const std::vector<double>& args,
                         std::vector<Module>& out, std::vector<double>& outArgs) {
    Module copy = mod;
    copy.firstArg = static_cast<uint32_t>(outArgs.size());
    outArgs.insert(outArgs.end(), args.begin() + mod.firstArg,
                   args.begin() + mod.firstArg + mod.argCount);
    out.push_back(copy);
  }

  // Flattens a successor into string modules, evaluating every argument now.
  void appendModules(uint32_t block, const ir::Block& ops, Frame& f, uint64_t key, std::vector<Module>& out,
                     std::vector<double>& outArgs, uint32_t owner = UINT32_MAX) {
    StringTarget target{&out, &outArgs, key, owner};
    if (program_) {
      NativeCall call;
      call.engine = this;
      call.f = &f;
      call.string = &target;
      jit::QueryBridge bridge(m_, f);
      bridge.attach(call);
      program_->blocks[block](&call, f.params, eval_.attrData());
      if (call.thrown) std::rethrow_exception(call.thrown);
      if (call.errorCode != FGSG_OK) throw bridge.error(call);
      return;
    }
    ArgBuffer buf;
    for (const ir::Op& op : ops) {
      if (op.kind == ir::OpKind::Emit) {
        appendModule(op, evalSlots(op, f, buf), m_.symbols[op.index].slotCount, target);
        continue;
      }
      checkParallelOp(op);
      uint32_t n = 0;
      const double* a = evalOpArgs(op, f, buf, n);
      appendModule(op, a, n, target);
    }
  }

  // Ops a string can hold: symbols, scope and turtle commands, plain instances.
  void checkParallelOp(const ir::Op& op) {
    switch (op.kind) {
      case ir::OpKind::Emit:
      case ir::OpKind::Translate:
      case ir::OpKind::Rotate:
      case ir::OpKind::RotateNormal:
      case ir::OpKind::Scale:
      case ir::OpKind::Push:
      case ir::OpKind::Pop:
      case ir::OpKind::Turtle: return;
      case ir::OpKind::Instance:
        if (op.mode != ir::InstanceMode::Plain) sequentialOnly(op);
        return;
      case ir::OpKind::Unsupported: unsupported(op);
      case ir::OpKind::Lock:
      case ir::OpKind::Line:
      case ir::OpKind::LineSeg: sequentialOnly(op);
      default:
        throw DeriveError{op.loc, "R009",
                          "'" + op.name + "' cannot appear in a parallel (L-system) derivation: "
                          "split and component commands need a sequential derivation"};
    }
  }

  // Appends one module with its evaluated arguments (a symbol's: its parameter slots).
  void appendModule(const ir::Op& op, const double* args, uint32_t n, StringTarget& t) {
    checkParallelOp(op);
    Module mod;
    mod.op = &op;
    mod.owner = t.owner;
    mod.firstArg = static_cast<uint32_t>(t.args->size());
    mod.argCount = n;
    t.args->insert(t.args->end(), args, args + n);
    if (op.kind == ir::OpKind::Emit) {
      mod.index = t.child;
      mod.key = rt::childKey(t.key, t.child++);
    }
    t.out->push_back(mod);
  }

  // Rule choice for one module of the string: context must match, then the guard.
  const ir::Alternative* chooseInString(const ir::Symbol& sym, const std::vector<Module>& str,
                                        const std::vector<double>& args, size_t at,
                                        rt::RandomStream& rng, uint32_t step) {
    candidates_.clear();
    double total = 0;
    for (int pass = 0; pass < 2 && candidates_.empty(); ++pass)
    for (uint32_t ri : sym.rules) {
      const ir::Rule& r = m_.rules[ri];
      if (isSpecific(r) != (pass == 0)) continue;
      params_.assign(r.slotCount, 0.0);
      std::copy(args.begin() + str[at].firstArg, args.begin() + str[at].firstArg + sym.slotCount,
                params_.begin());
      if (!matchLeft(r, str, args, at) || !matchRight(r, str, args, at)) continue;
      Frame f{params_.data(), &rng, nullptr, step, str[at].index, this};
      if (r.hasGuard && !guardHolds(ri, f)) continue;
      addCandidates(r, ri, f, total);
    }
    if (candidates_.empty()) return nullptr;
    const Candidate* pick = &pickCandidate(rng, total);
    chosenRule_ = pick->rule;
    // Rebuild the chosen rule's parameter block (another rule may have overwritten it).
    const ir::Rule& r = m_.rules[pick->rule];
    params_.assign(r.slotCount, 0.0);
    std::copy(args.begin() + str[at].firstArg, args.begin() + str[at].firstArg + sym.slotCount,
              params_.begin());
    matchLeft(r, str, args, at);
    matchRight(r, str, args, at);
    return pick->alt;
  }

  bool isSymbol(const Module& m) const { return m.op->kind == ir::OpKind::Emit; }

  void bind(const ir::ContextModule& cm, const Module& mod, const std::vector<double>& args) {
    const ir::Symbol& s = m_.symbols[cm.symbol];
    uint32_t src = mod.firstArg;
    for (size_t k = 0; k < cm.paramSlots.size() && k < s.paramTypes.size(); ++k) {
      const int w = ir::slotWidth(s.paramTypes[k]);
      for (int c = 0; c < w; ++c) params_[cm.paramSlots[k] + c] = args[src + c];
      src += w;
    }
  }

  // ABOP left context: walk left over symbols, skipping commands and whole branches,
  // and stepping out of the current branch into its parent.
  bool matchLeft(const ir::Rule& r, const std::vector<Module>& str, const std::vector<double>& args,
                 size_t at) {
    long j = static_cast<long>(at) - 1;
    for (long p = static_cast<long>(r.left.size()) - 1; p >= 0; --p) {
      const ir::ContextModule& cm = r.left[p];
      if (cm.bracket != 0) return false;
      while (j >= 0) {
        const ir::OpKind k = str[j].op->kind;
        if (k == ir::OpKind::Pop) {
          int depth = 0;
          for (; j >= 0; --j) {
            if (str[j].op->kind == ir::OpKind::Pop) ++depth;
            if (str[j].op->kind == ir::OpKind::Push && --depth == 0) break;
          }
          --j;
        } else if (k == ir::OpKind::Emit) {
          break;
        } else {
          --j;
        }
      }
      if (j < 0 || str[j].op->index != cm.symbol) return false;
      bind(cm, str[j], args);
      --j;
    }
    return true;
  }

  // ABOP right context: a pattern symbol may descend into branches of the string that
  // the pattern skips; a pattern ']' skips to the end of the current branch.
  bool matchRight(const ir::Rule& r, const std::vector<Module>& str, const std::vector<double>& args,
                  size_t at) {
    size_t j = at + 1;
    const size_t n = str.size();
    auto skipBranch = [&](size_t from) {  // from is a '['; returns the index after its ']'
      int depth = 0;
      for (size_t x = from; x < n; ++x) {
        if (str[x].op->kind == ir::OpKind::Push) ++depth;
        if (str[x].op->kind == ir::OpKind::Pop && --depth == 0) return x + 1;
      }
      return n;
    };
    for (const auto& cm : r.right) {
      if (cm.bracket == 1) {
        while (j < n && !isSymbol(str[j]) && str[j].op->kind != ir::OpKind::Push &&
               str[j].op->kind != ir::OpKind::Pop)
          ++j;
        if (j >= n || str[j].op->kind != ir::OpKind::Push) return false;
        ++j;
      } else if (cm.bracket == -1) {
        int depth = 0;
        while (j < n) {
          if (str[j].op->kind == ir::OpKind::Push) ++depth;
          if (str[j].op->kind == ir::OpKind::Pop) {
            if (depth == 0) break;
            --depth;
          }
          ++j;
        }
        if (j >= n) return false;
        ++j;
      } else {
        while (j < n && !isSymbol(str[j])) {
          if (str[j].op->kind == ir::OpKind::Push)
            j = skipBranch(j);
          else if (str[j].op->kind == ir::OpKind::Pop)
            return false;
          else
            ++j;
        }
        if (j >= n || str[j].op->index != cm.symbol) return false;
        bind(cm, str[j], args);
        ++j;
      }
    }
    return true;
  }

  // The turtle interpretation of the final string: commands act on one scope.
  void interpretString(const std::vector<Module>& str, const std::vector<double>& args) {
    streetDirection_ = rt::Vec3::UnitZ();
    State st;
    st.width = m_.turtle.width;
    st.stackBase = stack_.size();
    stats_.stringLength = str.size();
    for (const Module& mod : str) {
      const ir::Op& op = *mod.op;
      const double* a = args.data() + mod.firstArg;
      switch (op.kind) {
        case ir::OpKind::Emit: {
          ++stats_.terminals;
          ++stats_.shapesCreated;
          // ABOP: F and f are rewritten by rules and still draw and move when the turtle
          // reads the final string; their first parameter is the length.
          const std::string& name = m_.symbols[op.index].name;
          if (name == "F" || name == "f") {
            const ir::TurtleOp t = name == "F" ? ir::TurtleOp::Forward : ir::TurtleOp::Move;
            turtle(st, t, a, std::min<uint32_t>(mod.argCount, 1), op.loc);
          }
          break;
        }
        case ir::OpKind::Turtle:
          turtle(st, static_cast<ir::TurtleOp>(op.index), a, mod.argCount, op.loc);
          break;
        case ir::OpKind::Instance:
          placeInstance(op.index, st.scope, mod.owner == UINT32_MAX ? axiomSymbol_ : mod.owner,
                        nullptr, 0, op.loc);
          break;
        default: scopeCommand(st, op, a); break;
      }
    }
  }

  const ir::Module& m_;
  const rt::DeriveOptions& opt_;
  rt::AssetLibrary& assets_;
  Evaluator eval_;
  rt::Deadline deadline_;                // --max-seconds, passed down to traces and fields
  uint64_t memoryBudget_ = 0;            // --max-memory
  Clock::time_point memoryCheckedAt_{};  // the last memory reading
  size_t instancesCounted_ = 0;          // instances whose output bytes are in instanceBytes_
  uint64_t instanceBytes_ = 0;
  std::vector<uint64_t> assetBytes_;     // output bytes of one instance, per out_.assets entry
  rt::InstanceList out_;
  rt::DeriveStats stats_;
  uint32_t paramStride_ = 0;  // the largest parameter block of any symbol
  rt::GeometryArena arena_;
  rt::OcclusionIndex occluders_;
  std::vector<std::pair<int, ShapeQueue>> buckets_;
  std::vector<std::pair<int, size_t>> marks_;  // depth-first: queue sizes before a successor
  std::vector<Saved> stack_;
  rt::TrigMemo trig_;
  std::map<std::string, rt::synthesis::Example> examples_;
  std::vector<double> params_;
  std::vector<Candidate> candidates_;
  std::vector<uint64_t> ruleUses_;  // applications per rule, to name a runaway one
  uint32_t maxSlots_ = 0;           // the largest parameter block of any rule
  uint32_t chosenRule_ = 0;
  uint32_t creatorRule_ = UINT32_MAX;  // the rule whose successor is running
  bool depthLimitHit_ = false;
  rt::DeriveMessage depthWarning_;
  std::vector<std::array<float, 3>> symbolColor_;
  uint32_t segmentAsset_ = 0, segmentSymbol_ = 0, axiomSymbol_ = 0;
  bool usesOcclusion_ = false;
  std::unique_ptr<SurfaceWorld> surface_;  // null: the grammar grows on the plane
  // Collision-tested instancing, merging, Lock and lines (FGSG §4.4).
  std::unique_ptr<CollisionPlacement> collisions_;  // null: the grammar never collides
  bool testAll_ = false;        // every I() is tested (`collision all;`, --collide-all)
  std::vector<uint8_t> eager_;  // per symbol: derived where it is written (findEagerSymbols)
  uint32_t lockDepth_ = 0;      // inside a Lock every shape is derived where it is written
  uint32_t onTheSpot_ = 0;      // shapes being derived where they are written, nested
  rt::LineNetwork lines_;
  double noneId_ = -1, partId_ = -1, fullId_ = -1;
  rt::Vec3 streetDirection_ = rt::Vec3::UnitZ();
  const FgsgProgram* program_ = nullptr;  // compiled code (deriveCompiled), else the IR is walked
  bool direct_ = false;          // direct symbols are derived by their compiled code at once
  bool orderedDirect_ = false;   // ... including those placing instances (canOrderDirectInstances)
  struct PlacingShape {
    uint32_t depth = 0;
    uint64_t preorder = 0;  // the axiom: 0; direct shapes from 1 on
  };
  PlacingShape placingShape_;            // the shape whose instance is being placed
  std::vector<PlacingShape> placedBy_;   // per instance, while orderedDirect_
  uint64_t visits_ = 1;                  // direct shapes visited so far, plus one
  bool inexactDirect_ = false;   // ... and one of them gave up (see deriveDirect)
  uintptr_t stackFloor_ = 0;     // recursion (direct code, Lock sets) stays above this frame address
  ir::ProgramLayout layout_;               // how program_ numbers blocks and ops
};

template <class Fn>
void NativeCall::guard(Fn&& fn) noexcept {
  try {
    fn();
    if (ex && ex->culled) stop = 1;
  } catch (...) {
    thrown = std::current_exception();
    stop = 1;
  }
}

}  // namespace

namespace {

// The module as one derivation reads it (--set may add strings to its table) and the
// attribute slots; false with the error in `failed`.
bool prepare(const ir::Module& module, const rt::DeriveOptions& options, ir::Module& local,
             std::vector<double>& attrs, rt::DeriveResult& failed) {
  local = module;
  try {
    attrs = attributeSlots(local, options.attrOverrides);
    return true;
  } catch (const DeriveError& e) {
    failed.messages.push_back({true, e.code, e.loc.line, e.loc.col, e.message});
    return false;
  }
}

// What escapes a derivation (no memory; a bug) becomes its one error here, so every
// caller — fgsg run, the REPL, the C API — reports it alike and none aborts.
rt::DeriveResult escapedFailure(std::exception_ptr thrown) {
  rt::DeriveResult failed;
  try {
    std::rethrow_exception(thrown);
  } catch (const std::bad_alloc&) {
    failed.messages.push_back({true, "R020", 0, 0,
                               "out of memory while deriving: the grammar needs more memory than this "
                               "machine gives it (--max-memory stops a derivation earlier and keeps its "
                               "shapes); nothing is written"});
  } catch (const std::exception& e) {
    failed.messages.push_back({true, "R900", 0, 0, std::string("internal error while deriving: ") + e.what()});
  } catch (...) {
    failed.messages.push_back({true, "R900", 0, 0, "internal error while deriving"});
  }
  return failed;
}

}  // namespace

rt::DeriveResult interpret(const ir::Module& module, const rt::DeriveOptions& options,
                           rt::AssetLibrary& assets) {
  try {
    ir::Module local;
    std::vector<double> attrs;
    rt::DeriveResult failed;
    if (!prepare(module, options, local, attrs, failed)) return failed;
    return Interpreter(local, options, assets, std::move(attrs)).run();
  } catch (...) {
    return escapedFailure(std::current_exception());
  }
}

rt::DeriveResult deriveCompiled(const ir::Module& module, const FgsgProgram& program,
                                const rt::DeriveOptions& options, rt::AssetLibrary& assets) {
  try {
    ir::Module local;
    std::vector<double> attrs;
    rt::DeriveResult failed;
    if (!prepare(module, options, local, attrs, failed)) return failed;
    // Direct derivation first; where it could not be exact, the engine's own order, within
    // the same --max-seconds.
    rt::DeriveOptions timed = options;
    if (timed.startedAt == std::chrono::steady_clock::time_point{}) timed.startedAt = std::chrono::steady_clock::now();
    {
      Interpreter fast(local, timed, assets, attrs, &program, true);
      rt::DeriveResult result = fast.run();
      if (!fast.needsExactRun()) return result;
    }
    return Interpreter(local, timed, assets, std::move(attrs), &program, false).run();
  } catch (...) {
    return escapedFailure(std::current_exception());
  }
}

}  // namespace fgsg::backend

// ---------------------------------------------------------------- runtime entry points
// Called by compiled successors (runtime/abi.def); each forwards to the engine that
// runs the block and keeps whatever it throws in the call's context.

using fgsg::backend::NativeCall;

extern "C" {

void fgsg_rt_emit(FgsgContext* ctx, uint32_t op, const double* slots) noexcept {
  auto& call = *static_cast<NativeCall*>(ctx);
  call.guard([&] { call.engine->nativeEmit(call, op, slots); });
}

void fgsg_rt_op(FgsgContext* ctx, uint32_t op, const double* args, uint32_t n) noexcept {
  auto& call = *static_cast<NativeCall*>(ctx);
  call.guard([&] { call.engine->nativeOp(call, op, args, n); });
}

void fgsg_rt_translate(FgsgContext* ctx, double x, double y, double z) noexcept {
  auto& call = *static_cast<NativeCall*>(ctx);
  call.guard([&] { call.engine->nativeTranslate(call, x, y, z); });
}

void fgsg_rt_rotate(FgsgContext* ctx, uint32_t axis, double degrees) noexcept {
  auto& call = *static_cast<NativeCall*>(ctx);
  call.engine->nativeRotate(call, axis, degrees);
}

void fgsg_rt_push(FgsgContext* ctx) noexcept {
  auto& call = *static_cast<NativeCall*>(ctx);
  call.guard([&] { call.engine->nativePush(call); });
}

void fgsg_rt_pop(FgsgContext* ctx, uint32_t op) noexcept {
  auto& call = *static_cast<NativeCall*>(ctx);
  call.guard([&] { call.engine->nativePop(call, op); });
}

void fgsg_rt_direct_cos_sin(FgsgContext* ctx, double degrees, double* out) noexcept {
  static_cast<NativeCall*>(ctx)->engine->directCosSin(degrees, out);
}

void fgsg_rt_direct_rotate_normal(FgsgContext*, void* scope, double degrees) noexcept {
  fgsg::rt::rotateAboutNormal(*static_cast<fgsg::rt::Scope*>(scope), fgsg::rt::Vec3::UnitZ(), degrees);
}

void fgsg_rt_direct_scale(FgsgContext*, void* scope, const double* sizes, uint32_t relative) noexcept {
  auto& s = *static_cast<fgsg::rt::Scope*>(scope);
  for (int k = 0; k < 3; ++k) s.S[k] = (relative >> k) & 1 ? sizes[k] * s.S[k] : sizes[k];
}

void fgsg_rt_direct_instance(FgsgContext* ctx, void* scope, uint32_t op, uint32_t symbol, const double* params,
                             uint32_t depth, uint64_t preorder) noexcept {
  auto& call = *static_cast<NativeCall*>(ctx);
  call.guard([&] {
    call.engine->directInstance(*static_cast<fgsg::rt::Scope*>(scope), op, symbol, params, depth, preorder);
  });
}

void fgsg_rt_check_time(FgsgContext* ctx) noexcept {
  auto& call = *static_cast<NativeCall*>(ctx);
  call.guard([&] { call.engine->directTimeCheck(); });
}

}  // extern "C"
