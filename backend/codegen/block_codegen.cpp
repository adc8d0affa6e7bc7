// A block's function (the axiom, a rule alternative, a split / roof / Lock body): its
// ops in order, each calling the runtime's entry point (runtime/abi.def) with its
// arguments computed inline in the interpreter's order, and returning as soon as the
// engine or an expression asks it to stop.
#include "backend/codegen/program_codegen_internal.h"

#include <string>

namespace fgsg::backend::codegen::detail {

using ir::OpKind;

llvm::Function* ProgramCodegen::block(uint32_t id) {
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

// The parameter slots of the shape an Emit op writes, in a stack buffer.
llvm::Value* ProgramCodegen::emitSlots(const ir::Op& op) {
  llvm::Value* slots = buffer(ir_.symbols[op.index].slotCount);
  uint32_t slot = 0;
  for (const auto& a : op.args) {
    store(a, slots, slot);
    slot += ir::slotWidth(a.type);
  }
  return slots;
}

void ProgramCodegen::op(const ir::Op& op) {
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

}  // namespace fgsg::backend::codegen::detail
