#include "backend/codegen/program_codegen.h"

#include "backend/codegen/expr_codegen.h"
#include "ir/program_layout.h"
#include "runtime/abi.h"
#include "runtime/scope.h"

#include <llvm/IR/Constants.h>
#include <llvm/IR/Function.h>
#include <llvm/IR/IRBuilder.h>
#include <llvm/IR/LLVMContext.h>
#include <llvm/IR/LegacyPassManager.h>
#include <llvm/IR/Module.h>
#include <llvm/IR/Verifier.h>
#include <llvm/MC/TargetRegistry.h>
#include <llvm/Passes/PassBuilder.h>
#include <llvm/Support/TargetSelect.h>
#include <llvm/Support/raw_ostream.h>
#include <llvm/Target/TargetMachine.h>
#include <llvm/TargetParser/Host.h>
#include <llvm/Transforms/InstCombine/InstCombine.h>
#include <llvm/Transforms/Scalar/EarlyCSE.h>
#include <llvm/Transforms/Scalar/SROA.h>
#include <llvm/Transforms/Scalar/SimplifyCFG.h>

#include <chrono>
#include <cmath>
#include <cstddef>
#include <mutex>
#include <stdexcept>

namespace fgsg::backend::codegen {
namespace {

using ir::OpKind;

// Only queries report errors at run time (the IR is type-checked and verified, so the
// code generator's internal-error paths are unreachable); anything else cannot fail.
bool cannotFail(const ir::Expr& e) {
  if (e.op == ir::ExprOp::Query) return false;
  for (const auto& a : e.args)
    if (!cannotFail(a)) return false;
  return true;
}

bool hasQuery(const ir::Expr& e) {
  if (e.op == ir::ExprOp::Query) return true;
  for (const auto& a : e.args)
    if (hasQuery(a)) return true;
  return false;
}

// Rules that a sequential derivation can choose: those without context.
bool choosable(const ir::Rule& r) { return r.left.empty() && r.right.empty(); }

// The direct symbols (runtime/abi.h, FgsgDirectFn): the largest set whose successors
// only use scope commands, place plain instances and create shapes of ruleless or
// direct symbols, with brackets that balance, and no query anywhere. Sequential
// derivations only. `places`: the symbol's shapes may place instances.
std::vector<bool> findDirectSymbols(const ir::Module& m, std::vector<bool>& places) {
  std::vector<bool> direct(m.symbols.size(), false);
  places.assign(m.symbols.size(), false);
  if (m.mode == ir::DeriveMode::Parallel) return direct;
  for (size_t s = 0; s < m.symbols.size(); ++s) {
    const ir::Symbol& sym = m.symbols[s];
    bool ok = !sym.rules.empty() && sym.name != "F";  // F draws when no rule applies
    for (uint32_t ri : sym.rules) {
      const ir::Rule& r = m.rules[ri];
      if (!choosable(r)) continue;
      if (r.hasGuard && hasQuery(r.guard)) ok = false;
      for (const auto& alt : r.alternatives) {
        if (hasQuery(alt.probability)) ok = false;
        int depth = 0;
        for (const ir::Op& op : alt.ops) {
          switch (op.kind) {
            case OpKind::Translate:
            case OpKind::Rotate:
            case OpKind::RotateNormal:
            case OpKind::Scale:
            case OpKind::Emit: break;
            case OpKind::Instance:
              ok &= op.mode == ir::InstanceMode::Plain;
              places[s] = true;
              break;
            case OpKind::Push: ++depth; break;
            case OpKind::Pop: ok &= --depth >= 0; break;
            default: ok = false;
          }
          for (const auto& a : op.args) ok &= !hasQuery(a);
          for (const auto& sz : op.sizes) ok &= !hasQuery(sz.value);
        }
        ok &= depth == 0;
      }
    }
    direct[s] = ok;
  }
  // A symbol creating a shape that is neither ruleless nor direct is not direct.
  for (bool changed = true; changed;) {
    changed = false;
    for (size_t s = 0; s < m.symbols.size(); ++s) {
      if (!direct[s]) continue;
      for (uint32_t ri : m.symbols[s].rules)
        for (const auto& alt : m.rules[ri].alternatives)
          for (const ir::Op& op : alt.ops)
            if (op.kind == OpKind::Emit && !m.symbols[op.index].rules.empty() && !direct[op.index] &&
                direct[s]) {
              direct[s] = false;
              changed = true;
            }
    }
  }
  // Placing spreads to the symbols whose shapes create placing ones.
  for (bool changed = true; changed;) {
    changed = false;
    for (size_t s = 0; s < m.symbols.size(); ++s) {
      if (!direct[s] || places[s]) continue;
      for (uint32_t ri : m.symbols[s].rules)
        for (const auto& alt : m.rules[ri].alternatives)
          for (const ir::Op& op : alt.ops)
            if (op.kind == OpKind::Emit && direct[op.index] && places[op.index] && !places[s]) {
              places[s] = true;
              changed = true;
            }
    }
  }
  return direct;
}

class ProgramCodegen {
 public:
  ProgramCodegen(llvm::Module& out, const ir::Module& m, const ProgramCodegenOptions& o)
      : m_(out), c_(out.getContext()), b_(c_), ir_(m), opt_(o), layout_(ir::layoutProgram(m)) {
    declareRuntime(out);
    ptr_ = llvm::PointerType::getUnqual(c_);
  }

  void run() {
    std::vector<llvm::Constant*> blocks, guards, weights;
    for (uint32_t id = 0; id < layout_.blocks.size(); ++id) blocks.push_back(block(id));
    for (size_t r = 0; r < ir_.rules.size(); ++r) {
      const ir::Rule& rule = ir_.rules[r];
      guards.push_back(rule.hasGuard ? value(rule.guard, "fgsg_guard_" + std::to_string(r)) : nullPtr());
      for (size_t a = 0; a < rule.alternatives.size(); ++a) {
        const ir::Expr& p = rule.alternatives[a].probability;
        weights.push_back(p.isConst() ? nullPtr()
                                      : value(p, "fgsg_weight_" + std::to_string(r) + "_" + std::to_string(a)));
      }
    }
    std::vector<bool> places;
    const std::vector<bool> isDirect = findDirectSymbols(ir_, places);
    directFns_.assign(ir_.symbols.size(), nullptr);
    auto* directType = llvm::FunctionType::get(b_.getVoidTy(), {ptr_, ptr_, ptr_, b_.getInt64Ty(), b_.getInt32Ty(), ptr_}, false);
    for (size_t s = 0; s < ir_.symbols.size(); ++s)
      if (isDirect[s])
        directFns_[s] = llvm::Function::Create(directType, llvm::Function::InternalLinkage,
                                               "fgsg_direct_" + ir_.symbols[s].name, m_);
    std::vector<llvm::Constant*> direct, placing;
    for (size_t s = 0; s < ir_.symbols.size(); ++s) {
      if (directFns_[s]) directSymbol(static_cast<uint32_t>(s));
      direct.push_back(directFns_[s] ? static_cast<llvm::Constant*>(directFns_[s]) : nullPtr());
      placing.push_back(b_.getInt8(isDirect[s] && places[s] ? 1 : 0));
    }
    table(blocks, guards, weights, direct, placing);
  }

 private:
  llvm::Constant* nullPtr() { return llvm::ConstantPointerNull::get(ptr_); }

  // A guard or probability: an expression function of its own, internal to the unit.
  llvm::Function* value(const ir::Expr& e, const std::string& name) {
    llvm::Function* f = emitExpr(m_, e, name);
    f->setLinkage(llvm::GlobalValue::InternalLinkage);
    return f;
  }

  llvm::Function* block(uint32_t id) {
    auto* type = llvm::FunctionType::get(b_.getVoidTy(), {ptr_, ptr_, ptr_}, false);
    fn_ = llvm::Function::Create(type, llvm::Function::InternalLinkage, "fgsg_block_" + std::to_string(id), m_);
    fn_->addFnAttr(llvm::Attribute::NoUnwind);
    ctx_ = fn_->getArg(0);
    params_ = fn_->getArg(1);
    attrs_ = fn_->getArg(2);
    ctx_->setName("ctx");
    params_->setName("params");
    attrs_->setName("attrs");
    entry_ = llvm::BasicBlock::Create(c_, "entry", fn_);
    exit_ = llvm::BasicBlock::Create(c_, "return", fn_);
    llvm::BasicBlock* body = llvm::BasicBlock::Create(c_, "ops", fn_, exit_);
    b_.SetInsertPoint(exit_);
    b_.CreateRetVoid();
    b_.SetInsertPoint(body);
    for (const ir::Op& op : *layout_.blocks[id]) this->op(op);
    b_.CreateBr(exit_);
    b_.SetInsertPoint(entry_);
    b_.CreateBr(body);
    return fn_;
  }

  // A buffer of n doubles in the entry block (stack slots for arguments).
  llvm::Value* buffer(uint32_t n) {
    llvm::IRBuilderBase::InsertPointGuard guard(b_);
    b_.SetInsertPoint(entry_, entry_->begin());
    return b_.CreateAlloca(b_.getDoubleTy(), b_.getInt32(std::max(n, 1u)));
  }

  llvm::Value* call(const char* name, std::initializer_list<llvm::Value*> args) {
    return b_.CreateCall(m_.getFunction(name), args);
  }

  // Returns from the block when the engine or an expression asked it to stop.
  void checkStop() {
    llvm::Value* stop = b_.CreateLoad(b_.getInt32Ty(), ctx_, "stop");
    llvm::BasicBlock* go = llvm::BasicBlock::Create(c_, "go", fn_, exit_);
    b_.CreateCondBr(b_.CreateICmpNE(stop, b_.getInt32(0)), exit_, go);
    b_.SetInsertPoint(go);
  }

  // Expressions are emitted in place; an error they report makes the block return.
  InlineSite site() { return {params_, attrs_, ctx_, entry_, exit_}; }

  llvm::Value* num(const ir::Expr& e) { return emitNumInline(m_, b_, site(), e); }

  // Writes e (1 or 3 slots) at out[slot].
  void store(const ir::Expr& e, llvm::Value* out, uint32_t slot) {
    emitStoreInline(m_, b_, site(), e, b_.CreateConstInBoundsGEP1_64(b_.getDoubleTy(), out, slot));
  }

  llvm::Value* u32(uint32_t v) { return b_.getInt32(v); }

  // The parameter slots of the shape an Emit op writes, in a stack buffer.
  llvm::Value* emitSlots(const ir::Op& op) {
    llvm::Value* slots = buffer(ir_.symbols[op.index].slotCount);
    uint32_t slot = 0;
    for (const auto& a : op.args) {
      store(a, slots, slot);
      slot += ir::slotWidth(a.type);
    }
    return slots;
  }

  void op(const ir::Op& op) {
    const uint32_t id = layout_.opId(op);
    const bool sequential = ir_.mode != ir::DeriveMode::Parallel;
    bool mayFail = false;
    for (const auto& a : op.args) mayFail |= !cannotFail(a);
    for (const auto& s : op.sizes) mayFail |= !cannotFail(s.value);
    switch (op.kind) {
      case OpKind::Emit: {
        llvm::Value* slots = emitSlots(op);
        if (mayFail) checkStop();
        call("fgsg_rt_emit", {ctx_, u32(id), slots});
        checkStop();
        return;
      }
      case OpKind::Translate:
        if (!sequential) break;
        {
          llvm::Value* x = num(op.args[0]);
          llvm::Value* y = num(op.args[1]);
          llvm::Value* z = num(op.args[2]);
          if (mayFail) checkStop();
          call("fgsg_rt_translate", {ctx_, x, y, z});
          checkStop();  // on a surface T traces, which can fail
        }
        return;
      case OpKind::Rotate:
        if (!sequential || op.index >= 3) break;
        {
          llvm::Value* degrees = num(op.args[0]);
          if (mayFail) checkStop();
          call("fgsg_rt_rotate", {ctx_, u32(op.index), degrees});
        }
        return;
      case OpKind::Push:
        if (!sequential) break;
        call("fgsg_rt_push", {ctx_});
        return;
      case OpKind::Pop:
        if (!sequential) break;
        call("fgsg_rt_pop", {ctx_, u32(id)});
        checkStop();
        return;
      case OpKind::Unsupported:
        // The engine refuses it before evaluating anything.
        call("fgsg_rt_op", {ctx_, u32(id), llvm::ConstantPointerNull::get(ptr_), u32(0)});
        checkStop();
        return;
      default: break;
    }
    // Every other op: its arguments in IR order, then the engine applies it.
    const uint32_t n = static_cast<uint32_t>(op.args.size() + op.sizes.size());
    llvm::Value* args = n ? buffer(n) : llvm::ConstantPointerNull::get(ptr_);
    uint32_t k = 0;
    for (const auto& a : op.args) store(a, args, k++);
    for (const auto& s : op.sizes) store(s.value, args, k++);
    if (mayFail) checkStop();
    call("fgsg_rt_op", {ctx_, u32(id), args, u32(n)});
    checkStop();
  }

  llvm::Constant* array(const std::vector<llvm::Constant*>& items, const char* name) {
    if (items.empty()) return nullPtr();
    auto* type = llvm::ArrayType::get(ptr_, items.size());
    return new llvm::GlobalVariable(m_, type, true, llvm::GlobalValue::PrivateLinkage,
                                    llvm::ConstantArray::get(type, items), name);
  }

  llvm::Constant* string(const std::string& s, const char* name) {
    auto* init = llvm::ConstantDataArray::getString(c_, s, true);
    return new llvm::GlobalVariable(m_, init->getType(), true, llvm::GlobalValue::PrivateLinkage, init, name);
  }

  // The FgsgProgram constant (runtime/abi.h), field for field.
  void table(const std::vector<llvm::Constant*>& blocks, const std::vector<llvm::Constant*>& guards,
             const std::vector<llvm::Constant*>& weights, const std::vector<llvm::Constant*>& direct,
             const std::vector<llvm::Constant*>& placing) {
    llvm::Type* i32 = b_.getInt32Ty();
    auto* type = llvm::StructType::get(c_, {i32, i32, ptr_, i32, ptr_, i32, ptr_, ptr_, ptr_, i32, ptr_, ptr_, i32});
    llvm::Constant* placingArray = nullPtr();
    if (!placing.empty()) {
      auto* bytes = llvm::ArrayType::get(b_.getInt8Ty(), placing.size());
      placingArray = new llvm::GlobalVariable(m_, bytes, true, llvm::GlobalValue::PrivateLinkage,
                                              llvm::ConstantArray::get(bytes, placing), "fgsg_direct_places");
    }
    auto count = [&](size_t n) { return llvm::ConstantInt::get(i32, n); };
    llvm::Constant* init = llvm::ConstantStruct::get(
        type, {count(FGSG_ABI_VERSION), count(blocks.size()), array(blocks, "fgsg_blocks"),
               count(guards.size()), array(guards, "fgsg_guards"), count(weights.size()),
               array(weights, "fgsg_weights"),
               opt_.embedSource ? string(opt_.source, "fgsg_source") : nullPtr(),
               opt_.embedSource ? string(opt_.sourceName, "fgsg_source_name") : nullPtr(),
               count(direct.size()), array(direct, "fgsg_direct"), placingArray, count(sizeof(rt::Scope))});
    new llvm::GlobalVariable(m_, type, true, llvm::GlobalValue::ExternalLinkage, init, opt_.tableSymbol);
  }

  // ---------------------------------------------------------------- direct derivation

  // Fields of FgsgContext generated code uses (offsets checked in runtime/abi.h).
  enum ContextField : uint64_t { kStop = 0, kInexact = 4, kShapes = 8, kRewrites = 16,
                                 kTerminals = 24, kShapeBudget = 32, kDepthLimit = 40, kRng = 48,
                                 kVisits = 56, kStackFloor = 64 };
  llvm::Value* field(uint64_t offset) { return b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), ctx_, offset); }
  llvm::Value* loadU64(uint64_t offset) { return b_.CreateLoad(b_.getInt64Ty(), field(offset)); }
  void bump(uint64_t offset) { b_.CreateStore(b_.CreateAdd(loadU64(offset), b_.getInt64(1)), field(offset)); }
  llvm::Value* zero() { return llvm::ConstantFP::get(b_.getDoubleTy(), 0.0); }
  llvm::BasicBlock* newBlock(const char* name) { return llvm::BasicBlock::Create(c_, name, fn_, exit_); }

  // Marks the derivation inexact (the engine derives it again its own way) and returns:
  // one block per function that every such place branches to.
  void giveUpIf(llvm::Value* cond) {
    if (!giveUp_) {
      llvm::IRBuilderBase::InsertPointGuard guard(b_);
      giveUp_ = newBlock("inexact");
      b_.SetInsertPoint(giveUp_);
      b_.CreateStore(b_.getInt32(1), field(kInexact));
      b_.CreateStore(b_.getInt32(1), field(kStop));
      b_.CreateBr(exit_);
    }
    llvm::BasicBlock* go = newBlock("go");
    b_.CreateCondBr(cond, giveUp_, go);
    b_.SetInsertPoint(go);
  }

  llvm::Value* frameSlots(llvm::Type* type, size_t n) {
    llvm::IRBuilderBase::InsertPointGuard guard(b_);
    b_.SetInsertPoint(entry_, entry_->begin());
    llvm::AllocaInst* a = b_.CreateAlloca(type, b_.getInt32(static_cast<uint32_t>(n)));
    a->setAlignment(llvm::Align(16));  // an rt::Scope lives in some of them
    return a;
  }

  // What Interpreter::deriveShape and choose do for one shape, with the successor's ops
  // applied to a scope in this frame and created direct shapes derived by a call.
  void directSymbol(uint32_t s) {
    const ir::Symbol& sym = ir_.symbols[s];
    fn_ = directFns_[s];
    fn_->addFnAttr(llvm::Attribute::NoUnwind);
    // Direct symbols call each other, often in cycles: inlining them into one another
    // multiplies code (and compile time) for little gain.
    fn_->addFnAttr(llvm::Attribute::NoInline);
    ctx_ = fn_->getArg(0);
    llvm::Value* scopeIn = fn_->getArg(1);
    llvm::Value* slots = fn_->getArg(2);
    key_ = fn_->getArg(3);
    depth_ = fn_->getArg(4);
    attrs_ = fn_->getArg(5);
    entry_ = llvm::BasicBlock::Create(c_, "entry", fn_);
    exit_ = llvm::BasicBlock::Create(c_, "return", fn_);
    giveUp_ = nullptr;
    cosSin_ = nullptr;
    b_.SetInsertPoint(exit_);
    b_.CreateRetVoid();
    llvm::BasicBlock* body = newBlock("shape");
    b_.SetInsertPoint(body);

    // A shape at the depth limit stays terminal and the engine warns: its order matters.
    giveUpIf(b_.CreateICmpUGE(depth_, b_.CreateLoad(b_.getInt32Ty(), field(kDepthLimit))));
    // Native recursion stops before the thread's stack runs out; the engine's own order
    // needs no stack per level.
    llvm::Value* frame = b_.CreateIntrinsic(llvm::Intrinsic::frameaddress, {ptr_}, {b_.getInt32(0)});
    giveUpIf(b_.CreateICmpULT(b_.CreatePtrToInt(frame, b_.getInt64Ty()), loadU64(kStackFloor)));
    symbol_ = s;
    preorder_ = loadU64(kVisits);
    b_.CreateStore(b_.CreateAdd(preorder_, b_.getInt64(1)), field(kVisits));
    uint32_t slotsNeeded = std::max(sym.slotCount, 1u);
    size_t alternatives = 0;
    for (uint32_t ri : sym.rules) {
      slotsNeeded = std::max(slotsNeeded, ir_.rules[ri].slotCount);
      alternatives += ir_.rules[ri].alternatives.size();
    }
    params_ = frameSlots(b_.getDoubleTy(), slotsNeeded);
    for (uint32_t k = 0; k < slotsNeeded; ++k)
      b_.CreateStore(k < sym.slotCount ? b_.CreateLoad(b_.getDoubleTy(), b_.CreateConstInBoundsGEP1_64(b_.getDoubleTy(), slots, k))
                                       : zero(),
                     b_.CreateConstInBoundsGEP1_64(b_.getDoubleTy(), params_, k));
    rng_ = frameSlots(b_.getInt64Ty(), 2);  // rt::RandomStream{key, counter 0}
    b_.CreateStore(key_, rng_);
    b_.CreateStore(b_.getInt64(0), b_.CreateConstInBoundsGEP1_64(b_.getInt64Ty(), rng_, 1));
    b_.CreateStore(rng_, field(kRng));
    scope_ = frameSlots(b_.getInt8Ty(), sizeof(rt::Scope));
    b_.CreateMemCpy(scope_, llvm::MaybeAlign(8), scopeIn, llvm::MaybeAlign(8), sizeof(rt::Scope));

    llvm::Value* chosen = frameSlots(b_.getInt32Ty(), 1);
    llvm::BasicBlock* apply = newBlock("apply");
    if (constantChoice(sym))
      chooseStatic(sym, chosen, apply);
    else
      chooseDynamic(sym, chosen, apply, alternatives);
    b_.SetInsertPoint(apply);
    // Every 4096 rewrites the engine checks --max-seconds.
    bump(kRewrites);
    {
      llvm::Value* low = b_.CreateAnd(loadU64(kRewrites), b_.getInt64(4095));
      llvm::BasicBlock* check = newBlock("check_time");
      llvm::BasicBlock* go = newBlock("go");
      b_.CreateCondBr(b_.CreateICmpEQ(low, b_.getInt64(0)), check, go);
      b_.SetInsertPoint(check);
      call("fgsg_rt_check_time", {ctx_});
      checkStop();
      b_.CreateBr(go);
      b_.SetInsertPoint(go);
    }
    llvm::SwitchInst* sw = b_.CreateSwitch(b_.CreateLoad(b_.getInt32Ty(), chosen), exit_);
    for (uint32_t ri : sym.rules) {
      const ir::Rule& r = ir_.rules[ri];
      if (!choosable(r)) continue;
      for (size_t a = 0; a < r.alternatives.size(); ++a) {
        llvm::BasicBlock* alt = newBlock("alternative");
        sw->addCase(b_.getInt32(layout_.firstAlternative[ri] + static_cast<uint32_t>(a)), alt);
        b_.SetInsertPoint(alt);
        directSuccessor(r.alternatives[a].ops);
        b_.CreateBr(exit_);
      }
    }
    b_.SetInsertPoint(entry_);
    b_.CreateBr(body);
  }

  // Weights all constant and valid, at most one rule with a guard: which alternatives
  // are candidates depends only on that guard, so the choice is decided in code.
  bool constantChoice(const ir::Symbol& sym) const {
    int guarded = 0;
    for (uint32_t ri : sym.rules) {
      const ir::Rule& r = ir_.rules[ri];
      if (!choosable(r)) continue;
      guarded += r.hasGuard;
      for (const auto& alt : r.alternatives)
        if (!alt.probability.isConst() || !(alt.probability.num >= 0) || !std::isfinite(alt.probability.num))
          return false;
    }
    return guarded <= 1;
  }

  // Interpreter::choose with the candidate lists known: the guarded rule's positive
  // alternatives when its guard holds, else those of the rules without a guard; with
  // several, x = next() * total and the walk of pickCandidate over constant weights.
  void chooseStatic(const ir::Symbol& sym, llvm::Value* chosen, llvm::BasicBlock* apply) {
    struct Candidate {
      uint32_t alt;
      double weight;
    };
    auto pick = [&](const std::vector<Candidate>& list) {
      if (list.size() == 1) {
        b_.CreateStore(b_.getInt32(list[0].alt), chosen);
        b_.CreateBr(apply);
        return;
      }
      double total = 0;
      for (const auto& c : list) total += c.weight;
      llvm::Value* x = b_.CreateFMul(call("fgsg_rt_next", {ctx_}), llvm::ConstantFP::get(b_.getDoubleTy(), total));
      for (size_t i = 0; i + 1 < list.size(); ++i) {
        llvm::Value* w = llvm::ConstantFP::get(b_.getDoubleTy(), list[i].weight);
        llvm::BasicBlock* found = newBlock("found");
        llvm::BasicBlock* next = newBlock("walk_next");
        b_.CreateCondBr(b_.CreateFCmpOLT(x, w), found, next);
        b_.SetInsertPoint(found);
        b_.CreateStore(b_.getInt32(list[i].alt), chosen);
        b_.CreateBr(apply);
        b_.SetInsertPoint(next);
        x = b_.CreateFSub(x, w);
      }
      b_.CreateStore(b_.getInt32(list.back().alt), chosen);  // also when rounding leaves x beyond all
      b_.CreateBr(apply);
    };
    auto positive = [&](uint32_t ri, std::vector<Candidate>& list) {
      const ir::Rule& r = ir_.rules[ri];
      for (size_t a = 0; a < r.alternatives.size(); ++a)
        if (r.alternatives[a].probability.num > 0)
          list.push_back({layout_.firstAlternative[ri] + static_cast<uint32_t>(a), r.alternatives[a].probability.num});
    };
    std::vector<Candidate> general;
    for (uint32_t ri : sym.rules)
      if (choosable(ir_.rules[ri]) && !ir_.rules[ri].hasGuard) positive(ri, general);
    for (uint32_t ri : sym.rules) {
      const ir::Rule& r = ir_.rules[ri];
      if (!choosable(r) || !r.hasGuard) continue;
      std::vector<Candidate> specific;
      positive(ri, specific);
      llvm::Value* g = num(r.guard);  // evaluated in any case: it may draw random numbers
      if (!cannotFail(r.guard)) checkStop();
      if (specific.empty()) continue;  // a guard that holds still leaves no candidate
      llvm::BasicBlock* holds = newBlock("holds");
      llvm::BasicBlock* otherwise = newBlock("general");
      b_.CreateCondBr(b_.CreateFCmpUNE(g, zero()), holds, otherwise);
      b_.SetInsertPoint(holds);
      pick(specific);
      b_.SetInsertPoint(otherwise);
    }
    if (general.empty()) {  // no rule applies: the shape is terminal
      bump(kTerminals);
      b_.CreateBr(exit_);
      return;
    }
    pick(general);
  }

  // Interpreter::choose in general: candidates (global alternative index, weight)
  // collected at run time, rules with a guard first, those without only when none
  // applies.
  void chooseDynamic(const ir::Symbol& sym, llvm::Value* chosen, llvm::BasicBlock* apply, size_t alternatives) {
    const size_t room = std::max<size_t>(alternatives, 1);
    llvm::Value* candAlt = frameSlots(b_.getInt32Ty(), room);
    llvm::Value* candWeight = frameSlots(b_.getDoubleTy(), room);
    llvm::Value* count = frameSlots(b_.getInt32Ty(), 1);
    llvm::Value* total = frameSlots(b_.getDoubleTy(), 1);
    b_.CreateStore(b_.getInt32(0), count);
    b_.CreateStore(zero(), total);
    for (int pass = 0; pass < 2; ++pass) {
      llvm::BasicBlock* passBlock = newBlock(pass == 0 ? "specific" : "general");
      llvm::BasicBlock* after = newBlock("collected");
      if (pass == 1)
        b_.CreateCondBr(b_.CreateICmpEQ(b_.CreateLoad(b_.getInt32Ty(), count), b_.getInt32(0)), passBlock, after);
      else
        b_.CreateBr(passBlock);
      b_.SetInsertPoint(passBlock);
      for (uint32_t ri : sym.rules) {
        const ir::Rule& r = ir_.rules[ri];
        if (!choosable(r) || r.hasGuard != (pass == 0)) continue;
        llvm::BasicBlock* next = newBlock("next_rule");
        if (r.hasGuard) {
          llvm::Value* g = num(r.guard);
          if (!cannotFail(r.guard)) checkStop();
          llvm::BasicBlock* holds = newBlock("holds");
          b_.CreateCondBr(b_.CreateFCmpUNE(g, zero()), holds, next);
          b_.SetInsertPoint(holds);
        }
        for (size_t a = 0; a < r.alternatives.size(); ++a) {
          const ir::Expr& weight = r.alternatives[a].probability;
          llvm::BasicBlock* skip = newBlock("no_candidate");
          llvm::Value* w = num(weight);
          if (weight.isConst()) {
            // Known now: an invalid weight always gives up, zero is never a candidate.
            if (!(weight.num >= 0) || !std::isfinite(weight.num)) {
              giveUpIf(b_.getTrue());
            } else if (weight.num == 0) {
              b_.CreateBr(skip);
              b_.SetInsertPoint(skip);
              continue;
            }
          } else {
            if (!cannotFail(weight)) checkStop();
            // R008 (a negative or non-finite weight) is the engine's to report.
            llvm::Value* finite = b_.CreateFCmpONE(b_.CreateUnaryIntrinsic(llvm::Intrinsic::fabs, w),
                                                   llvm::ConstantFP::getInfinity(b_.getDoubleTy()));
            giveUpIf(b_.CreateNot(b_.CreateAnd(b_.CreateFCmpOGE(w, zero()), finite)));
            llvm::BasicBlock* positive = newBlock("candidate");
            b_.CreateCondBr(b_.CreateFCmpOGT(w, zero()), positive, skip);
            b_.SetInsertPoint(positive);
          }
          llvm::Value* n = b_.CreateLoad(b_.getInt32Ty(), count);
          b_.CreateStore(b_.getInt32(layout_.firstAlternative[ri] + static_cast<uint32_t>(a)),
                         b_.CreateInBoundsGEP(b_.getInt32Ty(), candAlt, n));
          b_.CreateStore(w, b_.CreateInBoundsGEP(b_.getDoubleTy(), candWeight, n));
          b_.CreateStore(b_.CreateAdd(n, b_.getInt32(1)), count);
          b_.CreateStore(b_.CreateFAdd(b_.CreateLoad(b_.getDoubleTy(), total), w), total);
          b_.CreateBr(skip);
          b_.SetInsertPoint(skip);
        }
        b_.CreateBr(next);
        b_.SetInsertPoint(next);
      }
      b_.CreateBr(after);
      b_.SetInsertPoint(after);
    }
    // No rule applies: the shape is terminal.
    llvm::Value* n = b_.CreateLoad(b_.getInt32Ty(), count);
    llvm::BasicBlock* terminal = newBlock("terminal");
    llvm::BasicBlock* rewrite = newBlock("rewrite");
    b_.CreateCondBr(b_.CreateICmpEQ(n, b_.getInt32(0)), terminal, rewrite);
    b_.SetInsertPoint(terminal);
    bump(kTerminals);
    b_.CreateBr(exit_);
    // One candidate takes no random number; several: x = next() * total, then the walk
    // of Interpreter::pickCandidate (the last one when rounding leaves x beyond all).
    b_.SetInsertPoint(rewrite);
    b_.CreateStore(b_.CreateLoad(b_.getInt32Ty(), candAlt), chosen);
    llvm::BasicBlock* pick = newBlock("pick");
    b_.CreateCondBr(b_.CreateICmpUGT(n, b_.getInt32(1)), pick, apply);
    b_.SetInsertPoint(pick);
    {
      llvm::Value* x = frameSlots(b_.getDoubleTy(), 1);
      llvm::Value* i = frameSlots(b_.getInt32Ty(), 1);
      b_.CreateStore(b_.CreateFMul(call("fgsg_rt_next", {ctx_}), b_.CreateLoad(b_.getDoubleTy(), total)), x);
      b_.CreateStore(b_.getInt32(0), i);
      b_.CreateStore(b_.CreateLoad(b_.getInt32Ty(), b_.CreateInBoundsGEP(b_.getInt32Ty(), candAlt, b_.CreateSub(n, b_.getInt32(1)))), chosen);
      llvm::BasicBlock* loop = newBlock("walk");
      llvm::BasicBlock* test = newBlock("walk_test");
      llvm::BasicBlock* found = newBlock("found");
      llvm::BasicBlock* step = newBlock("walk_next");
      b_.CreateBr(loop);
      b_.SetInsertPoint(loop);
      llvm::Value* iv = b_.CreateLoad(b_.getInt32Ty(), i);
      b_.CreateCondBr(b_.CreateICmpULT(iv, n), test, apply);
      b_.SetInsertPoint(test);
      llvm::Value* w = b_.CreateLoad(b_.getDoubleTy(), b_.CreateInBoundsGEP(b_.getDoubleTy(), candWeight, iv));
      llvm::Value* xv = b_.CreateLoad(b_.getDoubleTy(), x);
      b_.CreateCondBr(b_.CreateFCmpOLT(xv, w), found, step);
      b_.SetInsertPoint(found);
      b_.CreateStore(b_.CreateLoad(b_.getInt32Ty(), b_.CreateInBoundsGEP(b_.getInt32Ty(), candAlt, iv)), chosen);
      b_.CreateBr(apply);
      b_.SetInsertPoint(step);
      b_.CreateStore(b_.CreateFSub(xv, w), x);
      b_.CreateStore(b_.CreateAdd(iv, b_.getInt32(1)), i);
      b_.CreateBr(loop);
    }
  }

  // The frame scope's doubles: P (0..2), then axes column by column (3 + 3 column + row).
  static_assert(offsetof(rt::Scope, P) == 0 && offsetof(rt::Scope, axes) == 24, "rt::Scope's layout");
  llvm::Value* scopeSlot(uint32_t index) { return b_.CreateConstInBoundsGEP1_64(b_.getDoubleTy(), scope_, index); }
  llvm::Value* scopeLoad(uint32_t index) { return b_.CreateLoad(b_.getDoubleTy(), scopeSlot(index)); }

  // rt::translateLocal, operation for operation.
  void translateLocal(llvm::Value* x, llvm::Value* y, llvm::Value* z) {
    for (uint32_t k = 0; k < 3; ++k) {
      llvm::Value* sum = b_.CreateFAdd(b_.CreateFMul(scopeLoad(3 + k), x), b_.CreateFMul(scopeLoad(6 + k), y));
      sum = b_.CreateFAdd(sum, b_.CreateFMul(scopeLoad(9 + k), z));
      b_.CreateStore(b_.CreateFAdd(scopeLoad(k), sum), scopeSlot(k));
    }
  }

  // Interpreter::turn: cos and sin (from the engine's memo for a constant angle, which
  // it will hold; computed afresh for one that varies), then rt::rotateLocal in place.
  void rotateLocal(uint32_t axis, llvm::Value* degrees) {
    if (!cosSin_) cosSin_ = buffer(2);
    if (llvm::isa<llvm::Constant>(degrees))
      call("fgsg_rt_direct_cos_sin", {ctx_, degrees, cosSin_});
    else
      call("fgsg_rt_cos_sin_deg", {degrees, cosSin_});
    llvm::Value* c = b_.CreateLoad(b_.getDoubleTy(), cosSin_);
    llvm::Value* sn = b_.CreateLoad(b_.getDoubleTy(), b_.CreateConstInBoundsGEP1_64(b_.getDoubleTy(), cosSin_, 1));
    const uint32_t i = (axis + 1) % 3, j = (axis + 2) % 3;
    llvm::Value* a[3];
    llvm::Value* b[3];
    for (uint32_t k = 0; k < 3; ++k) {
      a[k] = scopeLoad(3 + 3 * i + k);
      b[k] = scopeLoad(3 + 3 * j + k);
    }
    for (uint32_t k = 0; k < 3; ++k) {
      b_.CreateStore(b_.CreateFAdd(b_.CreateFMul(c, a[k]), b_.CreateFMul(sn, b[k])), scopeSlot(3 + 3 * i + k));
      b_.CreateStore(b_.CreateFSub(b_.CreateFMul(c, b[k]), b_.CreateFMul(sn, a[k])), scopeSlot(3 + 3 * j + k));
    }
  }

  // rt::childKey(parent, index) in place: mix64(parent ^ mix64(index + constant)), the
  // inner mix folded now. Integer arithmetic: the same bits as the runtime's.
  llvm::Value* childKey(llvm::Value* parent, uint64_t index) {
    llvm::Value* x = b_.CreateXor(parent, b_.getInt64(rt::mix64(index + 0x632be59bd9b4e019ull)));
    x = b_.CreateAdd(x, b_.getInt64(0x9e3779b97f4a7c15ull));
    x = b_.CreateMul(b_.CreateXor(x, b_.CreateLShr(x, 30)), b_.getInt64(0xbf58476d1ce4e5b9ull));
    x = b_.CreateMul(b_.CreateXor(x, b_.CreateLShr(x, 27)), b_.getInt64(0x94d049bb133111ebull));
    return b_.CreateXor(x, b_.CreateLShr(x, 31));
  }

  // A successor's ops on the frame's scope; [ ] save and restore it in frame slots.
  void directSuccessor(const ir::Block& ops) {
    std::vector<llvm::Value*> saved;
    int depth = 0;
    uint32_t child = 0;
    for (const ir::Op& op : ops) {
      bool mayFail = false;
      for (const auto& a : op.args) mayFail |= !cannotFail(a);
      for (const auto& sz : op.sizes) mayFail |= !cannotFail(sz.value);
      switch (op.kind) {
        case OpKind::Translate: {
          llvm::Value* x = num(op.args[0]);
          llvm::Value* y = num(op.args[1]);
          llvm::Value* z = num(op.args[2]);
          if (mayFail) checkStop();
          translateLocal(x, y, z);
          break;
        }
        case OpKind::Rotate: {
          std::vector<llvm::Value*> angles;
          for (const auto& a : op.args) angles.push_back(num(a));
          if (mayFail) checkStop();
          if (op.index < 3)
            rotateLocal(op.index, angles[0]);
          else
            for (uint32_t k = 0; k < 3; ++k) rotateLocal(k, angles[k]);
          break;
        }
        case OpKind::RotateNormal: {
          llvm::Value* a = num(op.args[0]);
          if (mayFail) checkStop();
          call("fgsg_rt_direct_rotate_normal", {ctx_, scope_, a});
          break;
        }
        case OpKind::Scale: {
          llvm::Value* sizes = buffer(3);
          uint32_t relative = 0;
          for (uint32_t k = 0; k < 3; ++k) {
            store(op.sizes[k].value, sizes, k);
            if (op.sizes[k].kind == ir::Size::Relative) relative |= 1u << k;
          }
          if (mayFail) checkStop();
          call("fgsg_rt_direct_scale", {ctx_, scope_, sizes, u32(relative)});
          break;
        }
        case OpKind::Instance:  // plain: no arguments
          call("fgsg_rt_direct_instance", {ctx_, scope_, u32(layout_.opId(op)), u32(symbol_), params_, depth_,
                                           preorder_});
          checkStop();
          break;
        case OpKind::Push:
          if (depth == static_cast<int>(saved.size())) saved.push_back(frameSlots(b_.getInt8Ty(), sizeof(rt::Scope)));
          b_.CreateMemCpy(saved[depth++], llvm::MaybeAlign(8), scope_, llvm::MaybeAlign(8), sizeof(rt::Scope));
          break;
        case OpKind::Pop:
          b_.CreateMemCpy(scope_, llvm::MaybeAlign(8), saved[--depth], llvm::MaybeAlign(8), sizeof(rt::Scope));
          break;
        case OpKind::Emit: {
          const ir::Symbol& target = ir_.symbols[op.index];
          llvm::Value* args = emitSlots(op);
          if (mayFail) checkStop();
          // Interpreter::emit: the shape limit first, then the shape is counted.
          giveUpIf(b_.CreateICmpUGE(loadU64(kShapes), loadU64(kShapeBudget)));
          bump(kShapes);
          const uint32_t index = child++;
          if (target.rules.empty()) {
            bump(kTerminals);
            break;
          }
          llvm::Value* key = childKey(key_, index);
          b_.CreateCall(directFns_[op.index], {ctx_, scope_, args, key, b_.CreateAdd(depth_, b_.getInt32(1)), attrs_});
          checkStop();
          b_.CreateStore(rng_, field(kRng));  // the child drew from its own stream
          break;
        }
        default: break;  // not in a direct symbol (findDirectSymbols)
      }
    }
  }

  llvm::Module& m_;
  llvm::LLVMContext& c_;
  llvm::IRBuilder<> b_;
  const ir::Module& ir_;
  const ProgramCodegenOptions& opt_;
  ir::ProgramLayout layout_;
  llvm::PointerType* ptr_ = nullptr;
  llvm::Function* fn_ = nullptr;
  llvm::Value* ctx_ = nullptr;
  llvm::Value* params_ = nullptr;
  llvm::Value* attrs_ = nullptr;
  llvm::BasicBlock* entry_ = nullptr;
  llvm::BasicBlock* exit_ = nullptr;
  std::vector<llvm::Function*> directFns_;  // by symbol: null unless direct
  llvm::Value* key_ = nullptr;    // direct code: the shape's key, depth, stream and scope
  llvm::Value* depth_ = nullptr;
  llvm::Value* rng_ = nullptr;
  llvm::Value* scope_ = nullptr;
  llvm::BasicBlock* giveUp_ = nullptr;  // direct code: where an inexact derivation leaves
  uint32_t symbol_ = 0;                  // direct code: the symbol derived
  llvm::Value* cosSin_ = nullptr;        // direct code: the memo's answer for a turn
  llvm::Value* preorder_ = nullptr;      // ... and the shape's preorder number
};

void initTargets() {
  static std::once_flag once;
  std::call_once(once, [] {
    llvm::InitializeNativeTarget();
    llvm::InitializeNativeTargetAsmPrinter();
  });
}

std::unique_ptr<llvm::TargetMachine> targetMachine(CpuTarget cpu, CodeQuality quality) {
  initTargets();
  const std::string triple = llvm::sys::getProcessTriple();
  std::string error;
  const llvm::Target* target = llvm::TargetRegistry::lookupTarget(triple, error);
  if (!target) throw std::runtime_error("LLVM has no target for " + triple + ": " + error);
  std::string name = "generic", features;
  if (cpu == CpuTarget::Host) {
    name = llvm::sys::getHostCPUName().str();
    for (const auto& [feature, on] : llvm::sys::getHostCPUFeatures())
      features += (features.empty() ? "" : ",") + std::string(on ? "+" : "-") + feature.str();
  } else if (llvm::Triple(triple).getArch() == llvm::Triple::x86_64) {
    name = "x86-64";
  }
  std::unique_ptr<llvm::TargetMachine> tm(target->createTargetMachine(
      triple, name, features, llvm::TargetOptions(), llvm::Reloc::PIC_, std::nullopt,
      quality == CodeQuality::Baseline ? llvm::CodeGenOptLevel::None : llvm::CodeGenOptLevel::Default));
  if (!tm) throw std::runtime_error("LLVM cannot make a target machine for " + triple);
  return tm;
}

// Optimized: the O2 pipeline. Baseline: what the generated code needs most, in one
// pass over each function (stack slots into registers, redundant loads and constant
// branches gone), for a first tier that compiles in a fraction of O2's time.
void optimize(llvm::Module& m, llvm::TargetMachine& tm, CodeQuality quality) {
  llvm::LoopAnalysisManager lam;
  llvm::FunctionAnalysisManager fam;
  llvm::CGSCCAnalysisManager cgam;
  llvm::ModuleAnalysisManager mam;
  llvm::PassBuilder pb(&tm);
  pb.registerModuleAnalyses(mam);
  pb.registerCGSCCAnalyses(cgam);
  pb.registerFunctionAnalyses(fam);
  pb.registerLoopAnalyses(lam);
  pb.crossRegisterProxies(lam, fam, cgam, mam);
  if (quality == CodeQuality::Optimized) {
    pb.buildPerModuleDefaultPipeline(llvm::OptimizationLevel::O2).run(m, mam);
    return;
  }
  llvm::FunctionPassManager fpm;
  fpm.addPass(llvm::SROAPass(llvm::SROAOptions::ModifyCFG));
  fpm.addPass(llvm::EarlyCSEPass());
  fpm.addPass(llvm::InstCombinePass());
  fpm.addPass(llvm::SimplifyCFGPass());
  llvm::ModulePassManager mpm;
  mpm.addPass(llvm::createModuleToFunctionPassAdaptor(std::move(fpm)));
  mpm.run(m, mam);
}

}  // namespace

void emitProgram(llvm::Module& out, const ir::Module& m, const ProgramCodegenOptions& options) {
  ProgramCodegen(out, m, options).run();
}

std::string programLLVMText(const ir::Module& m) {
  std::unique_ptr<llvm::TargetMachine> tm = targetMachine(CpuTarget::Host, CodeQuality::Optimized);
  llvm::LLVMContext context;
  llvm::Module module("fgsg_program", context);
  module.setDataLayout(tm->createDataLayout());
  module.setTargetTriple(tm->getTargetTriple().str());
  emitProgram(module, m, {});
  optimize(module, *tm, CodeQuality::Optimized);
  std::string text;
  llvm::raw_string_ostream out(text);
  module.print(out, nullptr);
  return text;
}

std::string compileProgramObject(const ir::Module& m, const ProgramCodegenOptions& options,
                                 CpuTarget cpu, CodeQuality quality, ObjectCompileTimes* times) {
  using Clock = std::chrono::steady_clock;
  auto t = Clock::now();
  auto lap = [&t](double* into) {
    const auto now = Clock::now();
    if (into) *into = std::chrono::duration<double>(now - t).count();
    t = now;
  };
  std::unique_ptr<llvm::TargetMachine> tm = targetMachine(cpu, quality);
  llvm::LLVMContext context;
  llvm::Module module("fgsg_program", context);
  module.setDataLayout(tm->createDataLayout());
  module.setTargetTriple(tm->getTargetTriple().str());
  emitProgram(module, m, options);
  std::string problems;
  llvm::raw_string_ostream problemStream(problems);
  if (llvm::verifyModule(module, &problemStream))
    throw std::logic_error("internal: the code generator made invalid LLVM IR: " + problems);
  lap(times ? &times->emit : nullptr);
  optimize(module, *tm, quality);
  lap(times ? &times->optimize : nullptr);
  llvm::SmallVector<char, 0> object;
  llvm::raw_svector_ostream stream(object);
  llvm::legacy::PassManager passes;
  if (tm->addPassesToEmitFile(passes, stream, nullptr, llvm::CodeGenFileType::ObjectFile))
    throw std::runtime_error("LLVM cannot emit object files for " + module.getTargetTriple());
  passes.run(module);
  lap(times ? &times->machine : nullptr);
  return std::string(object.begin(), object.end());
}

}  // namespace fgsg::backend::codegen
