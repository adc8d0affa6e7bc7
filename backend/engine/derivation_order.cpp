// The sequential derivation order (CGA/FGSG): shapes wait in one queue per priority,
// highest first, and are taken breadth- or depth-first; a successor's ops run in order,
// Emit writes shapes (queued, derived where written, or by direct code), every other op
// goes to its command family. Lock sets and eager symbols are derived on the spot.
#include "backend/engine/derivation.h"

#include "runtime/cga/cga.h"
#include "runtime/fresh_stack.h"
#include "runtime/stack_budget.h"

#include <algorithm>

namespace fgsg::backend {
namespace {

// Shapes derived where they are written (Lock sets) nest native calls: beyond this depth
// the set is refused rather than the stack overflowing.
constexpr uint32_t kMaxOnTheSpotDepth = 2000;

}  // namespace

void Derivation::runSequential() {
  streetDirection_ = rt::Vec3::UnitZ();
  std::vector<double> none;
  const uint64_t root = rt::rootKey(opt_.seed);
  if ((!opt_.seeds.empty() || opt_.seedCount > 0) && !surface_)
    throw DeriveError{{}, "R022", "seeds (--seed-points, --seed-density) stand on a surface, and this grammar grows on the plane"};
  std::vector<rt::Scope> starts;
  for (const auto& seed : opt_.seeds) {
    const rt::Vec3 at(seed.point[0], seed.point[1], seed.point[2]);
    const rt::Vec3 heading(seed.direction[0], seed.direction[1], seed.direction[2]);
    starts.push_back(surface_->startScopeAt(at, seed.hasDirection ? &heading : nullptr));
  }
  if (opt_.seedCount > 0)
    for (const rt::Vec3& p : marching_.densitySeeds(opt_.seedDensity, opt_.seedCount, rt::childKey(root, ~0ull)))
      starts.push_back(surface_->startScopeAt(p, nullptr));
  if (!opt_.lots.empty()) {
    if (!starts.empty() || surface_)
      throw DeriveError{{}, "R022", "lots (--lots) stand on the plane: they cannot go with a surface or seeds"};
    deriveLots(root);
    return;
  }
  if (starts.empty()) {
    execRoot(0, m_.axiom, surface_ ? surface_->startScope() : rt::Scope{}, rt::GeomRef{}, root, 0, 0, none.data(),
             UINT32_MAX);
  } else if (starts.size() > 1 && seedsGrowApart()) {
    deriveSeedsApart(starts, root);
    return;
  } else {
    // One axiom per seed (on-mesh marching's plants), each with a random stream of its
    // own; plants that can meet (collisions, lines, occlusion) grow in one queue.
    for (size_t k = 0; k < starts.size(); ++k)
      execRoot(0, m_.axiom, starts[k], rt::GeomRef{}, rt::childKey(root, static_cast<uint32_t>(k)), 0,
               static_cast<uint32_t>(k), none.data(), UINT32_MAX);
  }
  deriveWaitingShapes();
}

// Takes the waiting shapes by priority, highest first, until none is left.
void Derivation::deriveWaitingShapes() {
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

void Derivation::deriveShape(const WaitingShape& shape) {
  const ir::Symbol& sym = m_.symbols[shape.symbol];
  params_.resize(maxSlots_, 0.0);  // room for context parameters of any rule
  const rt::Scope& scope = shape.scope;
  const uint32_t depth = shape.depth;
  rt::RandomStream rng{shape.key, 0};
  Frame f{params_.data(), &rng, &scope, depth, shape.index, this, &shape.geom};
  if (depth >= maxDepth_) {
    depthLimit(sym, shape.creator);
    return;
  }
  currentNode_ = shape.key;  // its guards may ask context queries
  const ir::Alternative* alt = choose(sym, f, shape.node, params_.data());
  if (!alt) {
    ++stats_.terminals;
    turtle_.drawSymbol(sym, scope, params_.data());
    return;
  }
  ++stats_.rewrites;
  ++ruleUses_[chosenRule_];
  pollLimits();
  creatorRule_ = chosenRule_;
  const auto writing = sequentialString_ ? sequentialString_->beginRewrite(shape.node) : SequentialString::Writing{};
  execRoot(blockOf(alt), alt->ops, scope, shape.geom, shape.key, depth + 1, shape.index, params_.data(),
           shape.symbol, &rng, shape.line);
  if (sequentialString_) sequentialString_->endRewrite(writing);
  creatorRule_ = UINT32_MAX;
}

// Derives a shape where its successor writes it, depth-first to the end (an eager
// symbol, or any shape inside a Lock). True when a collision happened anywhere in
// its derivation: the shape counts as in collision.
bool Derivation::deriveNow(uint32_t symbol, const double* slots, const State& at, const Exec& parent,
                           uint32_t index, uint32_t node) {
  const ir::Symbol& sym = m_.symbols[symbol];
  // Simple symbols cannot recurse, but a Lock set can: each level is a native call.
  if (onTheSpot_ >= kMaxOnTheSpotDepth)
    throw DeriveError{m_.rules[creatorRule_ == UINT32_MAX ? sym.rules[0] : creatorRule_].loc, "R017",
                      "a Lock set grew " + std::to_string(kMaxOnTheSpotDepth) +
                          " shapes deep: a set is derived as one unit, so it must end; '" +
                          sym.name + "' keeps creating itself"};
  if (rt::belowStackFloor(stackFloor_)) return deriveNowOnFreshStack(symbol, slots, at, parent, index, node);
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
  Frame f{params.data(), &rng, &at.scope, depth, index, this, &at.geom};
  if (depth >= maxDepth_) {
    depthLimit(sym, creatorRule_);
    return false;
  }
  struct RestoreNode {
    uint64_t& node;
    uint64_t outer;
    ~RestoreNode() { node = outer; }
  } restoreNode{currentNode_, currentNode_};
  currentNode_ = key;
  const ir::Alternative* alt = choose(sym, f, node, params.data());
  if (!alt) {
    ++stats_.terminals;
    turtle_.drawSymbol(sym, at.scope, params.data());
    return false;
  }
  ++stats_.rewrites;
  ++ruleUses_[chosenRule_];
  pollLimits();
  const uint32_t outerCreator = creatorRule_, outerDepth = placingDepth_;
  creatorRule_ = chosenRule_;
  placingDepth_ = depth;
  State st{at.scope, at.geom, m_.turtle.width, stack_.size(), at.line, &at.scope, {}};
  Exec ex{&rng, key, depth + 1, symbol, params.data(), 0};
  f.scope = &st.scope;
  f.geom = &st.geom;
  const auto writing = sequentialString_ ? sequentialString_->beginRewrite(node) : SequentialString::Writing{};
  runBlock(blockOf(alt), alt->ops, st, ex, f);
  stack_.resize(st.stackBase);
  if (sequentialString_) sequentialString_->endRewrite(writing);
  creatorRule_ = outerCreator;
  placingDepth_ = outerDepth;
  return ex.collided;
}

// deriveNow, continued on a stack of its own: Lock sets nest as deep as the grammar
// makes them (up to kMaxOnTheSpotDepth) whatever the caller's stack.
bool Derivation::deriveNowOnFreshStack(uint32_t symbol, const double* slots, const State& at, const Exec& parent,
                                       uint32_t index, uint32_t node) {
  struct RestoreFloor {
    uintptr_t& floor;
    uintptr_t saved;
    ~RestoreFloor() { floor = saved; }
  } restore{stackFloor_, stackFloor_};
  bool collided = false;
  rt::runOnFreshStack([&] {
    stackFloor_ = rt::stackFloor();
    collided = deriveNow(symbol, slots, at, parent, index, node);
  });
  return collided;
}

// Runs one successor for a shape (or the axiom) and queues the shapes it creates.
void Derivation::execRoot(uint32_t block, const ir::Block& ops, const rt::Scope& scope, const rt::GeomRef& geom,
                          uint64_t key, uint32_t depth, uint32_t index, const double* params,
                          uint32_t symbol, rt::RandomStream* rng, rt::LineCursor line) {
  rt::RandomStream own{key, 0};
  State st{scope, geom, m_.turtle.width, stack_.size(), line, &scope, {}};
  Exec ex{rng ? rng : &own, key, depth, symbol, params, 0};
  const bool depthFirst = m_.mode == ir::DeriveMode::DepthFirst;
  if (depthFirst) {
    marks_.clear();
    for (const auto& [priority, queue] : buckets_) marks_.emplace_back(priority, queue.mark());
  }
  Frame f{params, ex.rng, &st.scope, depth == 0 ? 0 : depth - 1, index, this, &st.geom};
  const uint32_t outerDepth = placingDepth_;
  const uint64_t outerNode = currentNode_;
  placingDepth_ = f.depth;
  currentNode_ = key;
  runBlock(block, ops, st, ex, f);
  placingDepth_ = outerDepth;
  currentNode_ = outerNode;
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
ShapeQueue& Derivation::bucketFor(int priority) {
  for (auto& [p, q] : buckets_)
    if (p == priority) return q;
  buckets_.emplace_back(priority, ShapeQueue(paramStride_, m_.mode == ir::DeriveMode::DepthFirst));
  std::sort(buckets_.begin(), buckets_.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });
  return bucketFor(priority);
}

// Runs a block: its compiled code when the derivation has a program, else its IR.
void Derivation::runBlock(uint32_t block, const ir::Block& ops, State& st, Exec& ex, Frame& f) {
  if (program_)
    runNative(block, st, ex, f);
  else
    execBlock(ops, st, ex, f);
}

void Derivation::execBlock(const ir::Block& ops, State& st, Exec& ex, Frame& f) {
  ArgBuffer buf;
  for (const ir::Op& op : ops) {
    f.scope = &st.scope;
    f.geom = &st.geom;
    switch (op.kind) {
      // The commands of nearly every successor are applied here directly, without
      // going through the argument buffer (the hot path of every derivation).
      case ir::OpKind::Translate: {
        const double x = eval_.num(op.args[0], f), y = eval_.num(op.args[1], f),
                     z = eval_.num(op.args[2], f);
        scope_.translate(st.scope, x, y, z);
        break;
      }
      case ir::OpKind::Rotate:
        if (op.index < 3) {
          scope_.turn(st.scope, static_cast<int>(op.index), eval_.num(op.args[0], f));
          break;
        }
        applyEvaluated(op, st, ex, f, buf);
        break;
      case ir::OpKind::Push: scope_.push(st); break;
      case ir::OpKind::Emit: emit(op, evalSlots(op, f, buf), st, ex); break;
      default: applyEvaluated(op, st, ex, f, buf); break;
    }
    if (ex.culled) return;
  }
}

void Derivation::applyEvaluated(const ir::Op& op, State& st, Exec& ex, Frame& f, ArgBuffer& buf) {
  uint32_t n = 0;
  const double* a = evalOpArgs(op, f, buf, n);
  applyOp(op, a, n, st, ex, f);
}

// Applies one op of a successor with its arguments evaluated (evalOpArgs' layout):
// shared by the IR walk above and compiled code (fgsg_rt_op). Emit is the core's own;
// every other op goes to the family that registered its kind.
void Derivation::applyOp(const ir::Op& op, const double* a, uint32_t n, State& st, Exec& ex, Frame& f) {
  if (op.kind == ir::OpKind::Emit) return emit(op, a, st, ex);
  if (op.kind == ir::OpKind::Unsupported) unsupported(op);
  if (op.kind == ir::OpKind::Label) return label(eval_.string(a[0]), st);  // label("L" + n) too
  familyOf_[static_cast<size_t>(op.kind)]->apply(op, a, n, st, ex, f);
}

// Runs body k of op (a split part, a roof, a Lock alternative) on its own scope.
void Derivation::runBody(const ir::Op& op, size_t k, const rt::Scope& scope, const rt::GeomRef& geom,
                         const State& outer, Exec& ex, Frame& f, const rt::Scope::Place* place,
                         const uint16_t* frame) {
  State inner{scope, geom, outer.width, stack_.size(), outer.line, &scope, {}};
  // A part's scope is made anew (a Comp face, a feature's frame): it keeps the colour, the
  // pivot and trim planes (`frame`, else the outer shape's), the trim attribute and the split
  // and comp indices (those of this split, when it is one).
  inner.scope.colored = outer.scope.colored, inner.scope.color = outer.scope.color;
  inner.scope.pivot = frame ? *frame : outer.scope.pivot;
  inner.scope.trim = outer.scope.trim;
  inner.scope.place = place ? *place : outer.scope.place;
  const uint64_t outerNode = enterBody(ex);
  runBlock(program_ ? layout_.bodyBlock(op, k) : 0, op.bodies[k], inner, ex, f);
  leaveBody(outerNode);
  stack_.resize(inner.stackBase);
  f.scope = &outer.scope;
  f.geom = &outer.geom;
}

// Writes a shape of op's symbol with its parameter slots evaluated.
void Derivation::emit(const ir::Op& op, const double* slots, State& st, Exec& ex) {
  const ir::Symbol& target = m_.symbols[op.index];
  if (stats_.shapesCreated >= opt_.maxShapes) shapeLimit(op);
  const uint32_t index = ex.childCount++;
  ++stats_.shapesCreated;
  if (contextMode_ != ContextMode::Off) parentOf_[rt::childKey(ex.key, index)] = currentNode_;
  const uint32_t node =
      sequentialString_ ? sequentialString_->addShape(op.index, slots, target.slotCount) : SequentialString::kNone;
  if (target.rules.empty()) {  // a terminal: nothing will ever read it again (but a context)
    ++stats_.terminals;
    if (terminalPieces_)
      for (auto& polygon : rt::cga::surfacePolygons(st.scope, st.geom, arena_))
        terminalPieces_->push_back({target.name, std::move(polygon)});
    else if (leavesOutput_)
      outputLeaf(op.index, st, slots, op.loc);
    if (leavesOutput_ && contextMode_ == ContextMode::Record) noteOccluder(st, rt::childKey(ex.key, index));
    return;
  }
  // Compiled direct code drops terminal shapes, so a base part being recorded is walked.
  if (direct_ && !terminalPieces_ && program_->direct[op.index] && (orderedDirect_ || !program_->directPlaces[op.index])) {
    deriveDirect(op.index, slots, st.scope, rt::childKey(ex.key, index), ex.depth);
    return;
  }
  if (eager_[op.index] || lockDepth_ > 0) {
    if (deriveNow(op.index, slots, st, ex, index, node)) ex.culled = ex.collided = true;
    return;
  }
  WaitingShape& shape = bucketFor(target.priority).push(slots, target.slotCount);
  shape.key = rt::childKey(ex.key, index);
  shape.symbol = op.index;
  shape.depth = ex.depth;
  shape.index = index;
  shape.creator = creatorRule_;
  shape.node = node;
  shape.line = st.line;
  shape.geom = st.geom;
  shape.scope = st.scope;
}

void Derivation::emitShape(uint32_t symbol, const rt::Scope& scope, Exec& ex, ir::Loc at, const rt::GeomRef& geom) {
  State piece;
  piece.scope = scope;
  piece.geom = geom;
  piece.stackBase = stack_.size();
  ir::Op op;
  op.kind = ir::OpKind::Emit;
  op.index = symbol;
  op.loc = at;
  const double noSlots = 0;
  emit(op, &noSlots, piece, ex);
}

// The parameter slots of the shape an Emit op writes (a vector takes three).
const double* Derivation::evalSlots(const ir::Op& op, const Frame& f, ArgBuffer& buf) {
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
const double* Derivation::evalOpArgs(const ir::Op& op, const Frame& f, ArgBuffer& buf, uint32_t& n) {
  n = op.kind == ir::OpKind::Unsupported ? 0 : static_cast<uint32_t>(op.args.size() + op.sizes.size());
  double* out = buf.reserve(n);
  uint32_t k = 0;
  if (op.kind == ir::OpKind::Unsupported) return out;
  for (const auto& a : op.args) out[k++] = eval_.num(a, f);
  for (const auto& sz : op.sizes) out[k++] = eval_.num(sz.value, f);
  return out;
}

void Derivation::unsupported(const ir::Op& op) {
  throw DeriveError{op.loc, "R001",
                    "'" + op.name + "' is not yet supported when running: it arrives with " +
                        op.why + " (this grammar parses and type-checks)"};
}

}  // namespace fgsg::backend
