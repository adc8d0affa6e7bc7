// The bridge between the engine and compiled code (a JIT unit or a compiled library,
// runtime/abi.h): compiled blocks, guards and weights run inside the engine, and direct
// code derives whole subtrees at once. The C entry points at the bottom are what
// generated code calls; each forwards to the engine that runs the block and keeps
// whatever it throws in the call's context (native_call.h).
#include "backend/engine/derivation.h"

#include "backend/native/query_bridge.h"

#include <algorithm>
#include <new>

namespace fgsg::backend {

// The block id of an alternative of the rule just chosen (0 where no layout was made:
// the interpreter's sequential derivation needs none).
uint32_t Derivation::blockOf(const ir::Alternative* alt) const {
  if (layout_.blocks.empty()) return 0;
  const ir::Rule& r = m_.rules[chosenRule_];
  return layout_.alternativeBlock(chosenRule_, static_cast<uint32_t>(alt - r.alternatives.data()));
}

// A compiled guard or probability; its query or error turns into the interpreter's.
double Derivation::callValue(FgsgValueFn fn, const Frame& f) {
  NativeCall call;
  call.engine = this;
  native::QueryBridge bridge(m_, f);
  bridge.attach(call);
  const double v = fn(f.params, eval_.attrData(), &call);
  if (call.errorCode != FGSG_OK) throw bridge.error(call);
  return v;
}

// Derives a direct shape and its whole subtree now, in compiled code (FgsgDirectFn):
// nothing it creates is observable but its counts. What only this engine's own order
// reports exactly (a limit, an error) makes the whole derivation start again without
// direct derivation (deriveCompiled).
void Derivation::deriveDirect(uint32_t symbol, const double* slots, const rt::Scope& scope, uint64_t key,
                              uint32_t depth) {
  NativeCall call;
  call.engine = this;
  call.shapeBudget = opt_.maxShapes - std::min(opt_.maxShapes, stats_.shapesCreated);
  call.depthLimit = maxDepth_;
  call.depthLimitQuiet = depthBoundIsGrammars_ ? 1 : 0;
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
void Derivation::runNative(uint32_t block, State& st, Exec& ex, Frame& f) {
  f.scope = &st.scope;
  f.geom = &st.geom;
  NativeCall call;
  call.engine = this;
  call.st = &st;
  call.ex = &ex;
  call.f = &f;
  native::QueryBridge bridge(m_, f);
  bridge.attach(call);
  program_->blocks[block](&call, f.params, eval_.attrData());
  f.scope = &st.scope;
  f.geom = &st.geom;
  if (call.thrown) std::rethrow_exception(call.thrown);
  if (call.errorCode != FGSG_OK) throw bridge.error(call);
}

// The runtime entry points of compiled code (runtime/abi.def), for a sequential
// derivation (call.st set) or a parallel rewriting step (call.string set).
void Derivation::nativeEmit(NativeCall& call, uint32_t op, const double* slots) {
  if (call.string)
    appendModule(op, slots, m_.symbols[layout_.ops[op]->index].slotCount, *call.string);
  else
    emit(*layout_.ops[op], slots, *call.st, *call.ex);
}

void Derivation::nativeOp(NativeCall& call, uint32_t op, const double* args, uint32_t n) {
  if (op >= layout_.ops.size())
    throw DeriveError{{}, "R900", "internal: compiled code names op " + std::to_string(op)};
  if (call.string)
    appendModule(op, args, n, *call.string);
  else
    applyOp(*layout_.ops[op], args, n, *call.st, *call.ex, *call.f);
}

void Derivation::directInstance(rt::Scope& s, uint32_t op, uint32_t symbol, const double* params, uint32_t depth,
                                uint64_t preorder) {
  placingShape_ = {depth, preorder};
  const uint32_t outerDepth = placingDepth_;
  placingDepth_ = depth;
  const ir::Op& placed = *layout_.ops[op];
  // CityEngine's insert mode: a kept size sets the scope to the asset's box.
  if (placed.insertFit != ir::InsertFit::AlignSizeAndPosition) s = insertFitted(placed, s);
  const rt::Scope& fitted = s;
  if (placed.recordAs != ir::Op::kPlacingSymbol)  // a .cga leaf after the insert: CollisionCommands::apply
    placeInstance(placed.index, fitted, placed.recordAs, nullptr, 0, placed.loc, placed.zUp);
  else
    placeInstance(placed.index, fitted, symbol, params, m_.symbols[symbol].slotCount, placed.loc, placed.zUp);
  placingDepth_ = outerDepth;
}

}  // namespace fgsg::backend


// Called by compiled successors (runtime/abi.def).
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

double fgsg_rt_join(FgsgContext* ctx, double a, uint32_t ta, double b, uint32_t tb) noexcept {
  auto& call = *static_cast<NativeCall*>(ctx);
  double id = -1;
  call.guard([&] { id = call.engine->nativeJoin(a, ta, b, tb); });
  return id;
}

void fgsg_rt_check_time(FgsgContext* ctx) noexcept {
  auto& call = *static_cast<NativeCall*>(ctx);
  call.guard([&] { call.engine->directTimeCheck(); });
}

}  // extern "C"
