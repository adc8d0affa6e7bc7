// Direct (inlined) derivation: a direct symbol's function derives one shape the way
// the interpreter does, giving up to the engine (inexact) at --max-depth or near the
// thread's stack floor, applying the chosen successor's ops to a scope in its own frame
// (T and turns written out as the runtime's, [ ] by copies) and calling the direct
// functions of the shapes it creates. The choice of alternative: direct_choice.cpp.
#include "backend/codegen/program_codegen_internal.h"
#include "runtime/random.h"

#include <vector>

namespace fgsg::backend::codegen::detail {

using ir::OpKind;

// Marks the derivation inexact (the engine derives it again its own way) and returns:
// one block per function that every such place branches to.
void ProgramCodegen::giveUpIf(llvm::Value* cond) {
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

llvm::Value* ProgramCodegen::frameSlots(llvm::Type* type, size_t n) {
  llvm::IRBuilderBase::InsertPointGuard guard(b_);
  b_.SetInsertPoint(entry_, entry_->begin());
  llvm::AllocaInst* a = b_.CreateAlloca(type, b_.getInt32(static_cast<uint32_t>(n)));
  a->setAlignment(llvm::Align(16));  // an rt::Scope lives in some of them
  return a;
}

// What Interpreter::deriveShape and choose do for one shape, with the successor's ops
// applied to a scope in this frame and created direct shapes derived by a call.
void ProgramCodegen::directSymbol(uint32_t s) {
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

  // A shape at the depth limit stays terminal. At --max-depth the engine warns, in its
  // own order: give up. At the grammar's own bound (`derive breadthfirst N;`) no warning
  // comes: count the terminal here.
  {
    llvm::BasicBlock* atLimit = newBlock("at_depth_limit");
    llvm::BasicBlock* below = newBlock("below_depth_limit");
    b_.CreateCondBr(b_.CreateICmpUGE(depth_, b_.CreateLoad(b_.getInt32Ty(), field(kDepthLimit))), atLimit, below);
    b_.SetInsertPoint(atLimit);
    giveUpIf(b_.CreateICmpEQ(b_.CreateLoad(b_.getInt32Ty(), field(kDepthLimitQuiet)), b_.getInt32(0)));
    bump(kTerminals);
    b_.CreateBr(exit_);
    b_.SetInsertPoint(below);
  }
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

// rt::translateLocal, operation for operation.
void ProgramCodegen::translateLocal(llvm::Value* x, llvm::Value* y, llvm::Value* z) {
  for (uint32_t k = 0; k < 3; ++k) {
    llvm::Value* sum = b_.CreateFAdd(b_.CreateFMul(scopeLoad(3 + k), x), b_.CreateFMul(scopeLoad(6 + k), y));
    sum = b_.CreateFAdd(sum, b_.CreateFMul(scopeLoad(9 + k), z));
    b_.CreateStore(b_.CreateFAdd(scopeLoad(k), sum), scopeSlot(k));
  }
}

// Interpreter::turn: cos and sin (from the engine's memo for a constant angle, which
// it will hold; computed afresh for one that varies), then rt::rotateLocal in place.
void ProgramCodegen::rotateLocal(uint32_t axis, llvm::Value* degrees) {
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
llvm::Value* ProgramCodegen::childKey(llvm::Value* parent, uint64_t index) {
  llvm::Value* x = b_.CreateXor(parent, b_.getInt64(rt::mix64(index + 0x632be59bd9b4e019ull)));
  x = b_.CreateAdd(x, b_.getInt64(0x9e3779b97f4a7c15ull));
  x = b_.CreateMul(b_.CreateXor(x, b_.CreateLShr(x, 30)), b_.getInt64(0xbf58476d1ce4e5b9ull));
  x = b_.CreateMul(b_.CreateXor(x, b_.CreateLShr(x, 27)), b_.getInt64(0x94d049bb133111ebull));
  return b_.CreateXor(x, b_.CreateLShr(x, 31));
}

// A successor's ops on the frame's scope; [ ] save and restore it in frame slots.
void ProgramCodegen::directSuccessor(const ir::Block& ops) {
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

}  // namespace fgsg::backend::codegen::detail
